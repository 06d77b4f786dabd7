#pragma once
#include <algorithm>
#include <array>
#include <numbers>

#include "sph/core/vec.hpp"
#include "sph/kernel/radial_gradient.hpp"
#include "sph/kernel/power.hpp"

namespace sph {

// Wendland C4 (Wendland 1995), h the full support radius, q = r/h, a = (1-q)_+. The function is the
// one positive definite in the dimension (Dehnen & Aly 2012, MNRAS 425, 1068, Table 1):
//   1D: psi_{1,2} = a^5 (1 + 5q + 8q^2);      2D, 3D: psi_{3,2} = a^6 (1 + 6q + 35/3 q^2).
// One piece (knot q = 1).
template <int D>
struct WendlandC4 : RadialGradient<WendlandC4<D>, D> {
  static_assert(D >= 1 && D <= 3);
  static constexpr const char* name = "wendland_c4";
  static constexpr std::array<double, 1> knots{1.0};
  // Normalisation (Dehnen & Aly 2012, Table 1): 3/2, 9/pi, 495/(32 pi).
  static constexpr double sigma = D == 1   ? 3.0 / 2.0
                                  : D == 2 ? 9.0 / std::numbers::pi
                                           : 495.0 / (32.0 * std::numbers::pi);

  static double W(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv, a = std::max(1.0 - q, 0.0), a2 = a * a;
    if constexpr (D == 1) return sigma * hinv * a2 * a2 * a * (1.0 + q * (5.0 + 8.0 * q));
    else return sigma * kernel_power<D>(hinv) * a2 * a2 * a2 * (1.0 + q * (6.0 + 35.0 / 3.0 * q));
  }

  // dW/dr = sigma / h^(D+1) dpsi/dq: 1D -14 q (1 + 4q) a^4; 2D, 3D -56/3 q (1 + 5q) a^5.
  static double dWdr(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv, a = std::max(1.0 - q, 0.0), a2 = a * a;
    if constexpr (D == 1) return -14.0 * sigma * hinv * hinv * q * (1.0 + 4.0 * q) * a2 * a2;
    else return -56.0 / 3.0 * sigma * kernel_power<D>(hinv) * hinv * q * (1.0 + 5.0 * q) * a2 * a2 * a;
  }
};

}  // namespace sph
