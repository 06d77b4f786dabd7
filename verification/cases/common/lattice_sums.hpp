#pragma once
// The kernel K's sums over a cubic lattice of unit spacing at support radius h (= h/dx): S0, the
// density sum (27) of a uniform lattice over its exact density, and S1, the pressure force's
// momentum flux through the lattice over its continuum value (the first moment
// -(1/D) sum_j |x_j| W'(|x_j|)). Both are 1 in the continuum; on a lattice at fixed h/dx they
// carry an error that no resolution removes (errata: in 1D they are exact at h/dx = 2 and 4).
#include <cmath>

#include "sph/kernel/cubic_spline.hpp"

namespace sphv {

struct LatticeSums {
  double S0 = 0.0, S1 = 0.0;
};

template <int D, class K = sph::CubicSpline<D>>
LatticeSums lattice_sums(double h) {
  LatticeSums s;
  const int k = static_cast<int>(std::ceil(h));
  int j[3] = {0, 0, 0};
  const int count = static_cast<int>(std::pow(2 * k + 1, D));
  for (int idx = 0; idx < count; ++idx) {
    int rest = idx;
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) j[d] = rest % (2 * k + 1) - k, rest /= 2 * k + 1, r2 += double(j[d]) * j[d];
    const double r = std::sqrt(r2);
    s.S0 += K::W(r, h);
    s.S1 -= r * K::dWdr(r, h) / D;
  }
  return s;
}

}  // namespace sphv
