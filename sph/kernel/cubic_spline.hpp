#pragma once
#include <algorithm>
#include <array>
#include <numbers>

#include "sph/core/vec.hpp"
#include "sph/kernel/power.hpp"
#include "sph/kernel/radial_gradient.hpp"

namespace sph {

// Cubic spline kernel of the chapter, eqs (6)-(8). h is the full support radius:
// W = 0 for r > h (not Monaghan's 2h convention, see errata).
// The interface every kernel of sph/kernel/kernels.hpp has: name, knots (the q = r/h where a
// piece ends, 1 last: quadrature and the kernel case split there), sigma, W, dWdr, gradW.
template <int D>
struct CubicSpline : RadialGradient<CubicSpline<D>, D> {
  static_assert(D >= 1 && D <= 3);
  static constexpr const char* name = "cubic_spline";
  static constexpr std::array<double, 2> knots{0.5, 1.0};
  // Normalisation (7): 4/3, 40/(7 pi), 8/pi.
  static constexpr double sigma = D == 1   ? 4.0 / 3.0
                                  : D == 2 ? 40.0 / (7.0 * std::numbers::pi)
                                           : 8.0 / std::numbers::pi;

  // (6), written as truncated powers, s (2 (1-q)_+^3 - 8 (1/2-q)_+^3) with (x)_+ = max(x, 0):
  // the same polynomial on each piece, without branches the pair loops would mispredict.
  static double W(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv;
    const double a = std::max(1.0 - q, 0.0), b = std::max(0.5 - q, 0.0);
    return sigma * kernel_power<D>(hinv) * (2.0 * a * a * a - 8.0 * b * b * b);
  }

  // (8): dW/dr = (6 sigma / h^(D+1)) (-(1-q)_+^2 + 4 (1/2-q)_+^2).
  static double dWdr(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv;
    const double a = std::max(1.0 - q, 0.0), b = std::max(0.5 - q, 0.0);
    return 6.0 * sigma * kernel_power<D>(hinv) * hinv * (4.0 * b * b - a * a);
  }
};

}  // namespace sph
