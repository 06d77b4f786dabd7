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
  double S1_across = 0.0;  // the momentum flux across the first axis (equal to S1 on a cubic lattice)
};

// The sums on a lattice compressed c times along its first axis (spacing 1/c there, 1 across, as
// behind a planar shock that compressed a cubic lattice), with h from (50) at that lattice's
// density: h = hfact c^(-1/D). S1 is the flux along the first axis, S1_across that across it;
// each is 1 in the continuum (on the cubic lattice, c = 1, the two are equal and S1 is the first
// moment above).
template <int D, class K = sph::CubicSpline<D>>
LatticeSums compressed_lattice_sums(double hfact, double c) {
  LatticeSums s;
  const double a = 1.0 / c, h = hfact * std::pow(a, 1.0 / D);
  const int k0 = static_cast<int>(std::ceil(h / a)), k = static_cast<int>(std::ceil(h));
  const int n0 = 2 * k0 + 1, n = 2 * k + 1;
  const int count = n0 * static_cast<int>(std::pow(n, D - 1));
  for (int idx = 0; idx < count; ++idx) {
    const double x = a * (idx % n0 - k0);
    int rest = idx / n0;
    double r2 = x * x, y2 = 0.0;
    for (int d = 1; d < D; ++d) {
      const double y = rest % n - k;
      rest /= n;
      r2 += y * y;
      if (d == 1) y2 = y * y;
    }
    const double r = std::sqrt(r2);
    s.S0 += a * K::W(r, h);
    if (r > 0.0) {
      s.S1 -= a * x * x / r * K::dWdr(r, h);
      s.S1_across -= a * (D > 1 ? y2 : x * x) / r * K::dWdr(r, h);
    }
  }
  return s;
}

// The sums on the cubic lattice of unit spacing at support radius h (= h/dx).
template <int D, class K = sph::CubicSpline<D>>
LatticeSums lattice_sums(double h) {
  return compressed_lattice_sums<D, K>(h, 1.0);
}

}  // namespace sphv
