#pragma once
#include <algorithm>
#include <array>
#include <numbers>

#include "sph/core/vec.hpp"
#include "sph/kernel/radial_gradient.hpp"
#include "sph/kernel/power.hpp"

namespace sph {

// Quintic B-spline M6 (Schoenberg 1946; Morris 1996; Monaghan 2005, Rep. Prog. Phys. 68, 1703), with
// h the full support radius (Monaghan's support 3 h_M = h), q = r/h:
//   W = sigma / h^D [(1-q)_+^5 - 6 (2/3-q)_+^5 + 15 (1/3-q)_+^5].
// C^4; its pieces end at q = 1/3, 2/3, 1.
template <int D>
struct QuinticSpline : RadialGradient<QuinticSpline<D>, D> {
  static_assert(D >= 1 && D <= 3);
  static constexpr const char* name = "quintic_spline";
  static constexpr std::array<double, 3> knots{1.0 / 3.0, 2.0 / 3.0, 1.0};
  // Normalisation at support h (Dehnen & Aly 2012, MNRAS 425, 1068, Table 1: 3^5/40, 3^7 7/(478 pi),
  // 3^7/(40 pi)); Monaghan's 1/120, 7/(478 pi), 1/(120 pi) at h_M, times 3^(5+D).
  static constexpr double sigma = D == 1   ? 243.0 / 40.0
                                  : D == 2 ? 15309.0 / (478.0 * std::numbers::pi)
                                           : 2187.0 / (40.0 * std::numbers::pi);

  static double W(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv;
    const double a = std::max(1.0 - q, 0.0), b = std::max(2.0 / 3.0 - q, 0.0), c = std::max(1.0 / 3.0 - q, 0.0);
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    return sigma * kernel_power<D>(hinv) * (a2 * a2 * a - 6.0 * b2 * b2 * b + 15.0 * c2 * c2 * c);
  }

  // dW/dr = -(5 sigma / h^(D+1)) [(1-q)_+^4 - 6 (2/3-q)_+^4 + 15 (1/3-q)_+^4].
  static double dWdr(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv;
    const double a = std::max(1.0 - q, 0.0), b = std::max(2.0 / 3.0 - q, 0.0), c = std::max(1.0 / 3.0 - q, 0.0);
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    return -5.0 * sigma * kernel_power<D>(hinv) * hinv * (a2 * a2 - 6.0 * b2 * b2 + 15.0 * c2 * c2);
  }
};

}  // namespace sph
