#pragma once
#include <array>
#include <cmath>
#include <numbers>

namespace reference {

// Smooth periodic test field on the unit box: f(x) = prod_d sin(2 pi k x_d + phi_d), with
// phases that break the lattice's mirror symmetries, and its exact gradient.
template <int D>
struct SineProduct {
  int k = 1;
  static constexpr std::array<double, 3> phase{0.3, 1.1, 2.0};

  double value(const double* x) const {
    double f = 1.0;
    for (int d = 0; d < D; ++d) f *= std::sin(arg(x, d));
    return f;
  }
  // df/dx_a = 2 pi k cos(arg_a) prod_{d != a} sin(arg_d)
  std::array<double, D> gradient(const double* x) const {
    std::array<double, D> g;
    for (int a = 0; a < D; ++a) {
      g[a] = 2.0 * std::numbers::pi * k * std::cos(arg(x, a));
      for (int d = 0; d < D; ++d)
        if (d != a) g[a] *= std::sin(arg(x, d));
    }
    return g;
  }

 private:
  double arg(const double* x, int d) const { return 2.0 * std::numbers::pi * k * x[d] + phase[d]; }
};

}  // namespace reference
