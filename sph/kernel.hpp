#pragma once
#include <numbers>

#include "sph/vec.hpp"

namespace sph {

// Cubic spline kernel of the chapter, eqs (6)-(8). h is the full support radius:
// W = 0 for r > h (not Monaghan's 2h convention, see errata).
template <int D>
struct CubicSpline {
  static_assert(D >= 1 && D <= 3);
  // Normalisation (7): 4/3, 40/(7 pi), 8/pi.
  static constexpr double sigma = D == 1   ? 4.0 / 3.0
                                  : D == 2 ? 40.0 / (7.0 * std::numbers::pi)
                                           : 8.0 / std::numbers::pi;

  static constexpr double hpow(double h) {
    double p = h;
    for (int k = 1; k < D; ++k) p *= h;
    return p;
  }

  // (6)
  static double W(double r, double h) {
    const double q = r / h;
    const double s = sigma / hpow(h);
    if (q < 0.5) return s * (6.0 * q * q * (q - 1.0) + 1.0);
    if (q <= 1.0) {
      const double t = 1.0 - q;
      return s * 2.0 * t * t * t;
    }
    return 0.0;
  }

  // (8): dW/dr.
  static double dWdr(double r, double h) {
    const double q = r / h;
    const double s = 6.0 * sigma / (hpow(h) * h);
    if (q < 0.5) return s * q * (3.0 * q - 2.0);
    if (q <= 1.0) {
      const double t = 1.0 - q;
      return -s * t * t;
    }
    return 0.0;
  }

  // (9): grad_i W_ij = r_ij / |r_ij| dW/dr, with r_ij = r_i - r_j; zero at r = 0.
  static Vec<D> gradW(const Vec<D>& rij, double r, double h) {
    return r > 0.0 ? Vec<D>(rij * (dWdr(r, h) / r)) : Vec<D>::Zero();
  }
};

}  // namespace sph
