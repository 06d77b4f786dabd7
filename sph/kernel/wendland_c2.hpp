#pragma once
#include <algorithm>
#include <array>
#include <numbers>

#include "sph/core/vec.hpp"
#include "sph/kernel/radial_gradient.hpp"
#include "sph/kernel/power.hpp"

namespace sph {

// Wendland C2 (Wendland 1995), h the full support radius, q = r/h, a = (1-q)_+. The function is the
// one positive definite in the dimension (Dehnen & Aly 2012, MNRAS 425, 1068, Table 1):
//   1D: psi_{1,1} = a^3 (1 + 3q);      2D, 3D: psi_{3,1} = a^4 (1 + 4q).
// One piece (knot q = 1); a polynomial in r with a q^3 term, so not smooth at r = 0 either.
template <int D>
struct WendlandC2 : RadialGradient<WendlandC2<D>, D> {
  static_assert(D >= 1 && D <= 3);
  static constexpr const char* name = "wendland_c2";
  static constexpr std::array<double, 1> knots{1.0};
  // Normalisation (Dehnen & Aly 2012, Table 1): 5/4, 7/pi, 21/(2 pi).
  static constexpr double sigma = D == 1   ? 5.0 / 4.0
                                  : D == 2 ? 7.0 / std::numbers::pi
                                           : 21.0 / (2.0 * std::numbers::pi);

  static double W(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv, a = std::max(1.0 - q, 0.0);
    if constexpr (D == 1) return sigma * hinv * a * a * a * (1.0 + 3.0 * q);
    else return sigma * kernel_power<D>(hinv) * (a * a) * (a * a) * (1.0 + 4.0 * q);
  }

  // dW/dr = sigma / h^(D+1) dpsi/dq: 1D -12 q a^2; 2D, 3D -20 q a^3.
  static double dWdr(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv, a = std::max(1.0 - q, 0.0);
    if constexpr (D == 1) return -12.0 * sigma * hinv * hinv * q * a * a;
    else return -20.0 * sigma * kernel_power<D>(hinv) * hinv * q * a * a * a;
  }
};

}  // namespace sph
