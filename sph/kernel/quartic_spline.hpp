#pragma once
#include <algorithm>
#include <array>
#include <numbers>

#include "sph/core/vec.hpp"
#include "sph/kernel/radial_gradient.hpp"
#include "sph/kernel/power.hpp"

namespace sph {

// Quartic B-spline M5 (Schoenberg 1946; Monaghan 2005, Rep. Prog. Phys. 68, 1703, eq. 2.4), with h
// the full support radius (Monaghan's support 2.5 h_M = h), q = r/h:
//   W = sigma / h^D [(1-q)_+^4 - 5 (3/5-q)_+^4 + 10 (1/5-q)_+^4].
// C^2; its pieces end at q = 1/5, 3/5, 1.
template <int D>
struct QuarticSpline : RadialGradient<QuarticSpline<D>, D> {
  static_assert(D >= 1 && D <= 3);
  static constexpr const char* name = "quartic_spline";
  static constexpr std::array<double, 3> knots{0.2, 0.6, 1.0};
  // Normalisation at support h (Dehnen & Aly 2012, MNRAS 425, 1068, Table 1: 5^5/768, 3 5^6/(2398 pi),
  // 5^6/(512 pi)); Monaghan's 1/24, 96/(1199 pi), 1/(20 pi) at h_M, times 2.5^(4+D).
  static constexpr double sigma = D == 1   ? 3125.0 / 768.0
                                  : D == 2 ? 46875.0 / (2398.0 * std::numbers::pi)
                                           : 15625.0 / (512.0 * std::numbers::pi);

  static double W(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv;
    const double a = std::max(1.0 - q, 0.0), b = std::max(0.6 - q, 0.0), c = std::max(0.2 - q, 0.0);
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    return sigma * kernel_power<D>(hinv) * (a2 * a2 - 5.0 * b2 * b2 + 10.0 * c2 * c2);
  }

  // dW/dr = -(4 sigma / h^(D+1)) [(1-q)_+^3 - 5 (3/5-q)_+^3 + 10 (1/5-q)_+^3].
  static double dWdr(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv;
    const double a = std::max(1.0 - q, 0.0), b = std::max(0.6 - q, 0.0), c = std::max(0.2 - q, 0.0);
    return -4.0 * sigma * kernel_power<D>(hinv) * hinv * (a * a * a - 5.0 * b * b * b + 10.0 * c * c * c);
  }
};

}  // namespace sph
