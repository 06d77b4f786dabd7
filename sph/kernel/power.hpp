#pragma once

namespace sph {

// x^D for the kernels' h^-D, as repeated products (std::pow is a call the pair loops would keep).
template <int D>
constexpr double kernel_power(double x) {
  double p = x;
  for (int k = 1; k < D; ++k) p *= x;
  return p;
}

}  // namespace sph
