#pragma once
#include <algorithm>
#include <array>
#include <numbers>

#include "sph/core/vec.hpp"
#include "sph/kernel/radial_gradient.hpp"
#include "sph/kernel/power.hpp"

namespace sph {

// Wendland C6 (Wendland 1995), h the full support radius, q = r/h, a = (1-q)_+. The function is the
// one positive definite in the dimension (Dehnen & Aly 2012, MNRAS 425, 1068, Table 1):
//   1D: psi_{1,3} = a^7 (1 + 7q + 19q^2 + 21q^3);      2D, 3D: psi_{3,3} = a^8 (1 + 8q + 25q^2 + 32q^3).
// One piece (knot q = 1).
template <int D>
struct WendlandC6 : RadialGradient<WendlandC6<D>, D> {
  static_assert(D >= 1 && D <= 3);
  static constexpr const char* name = "wendland_c6";
  static constexpr std::array<double, 1> knots{1.0};
  // Normalisation (Dehnen & Aly 2012, Table 1): 55/32, 78/(7 pi), 1365/(64 pi).
  static constexpr double sigma = D == 1   ? 55.0 / 32.0
                                  : D == 2 ? 78.0 / (7.0 * std::numbers::pi)
                                           : 1365.0 / (64.0 * std::numbers::pi);

  static double W(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv, a = std::max(1.0 - q, 0.0), a2 = a * a, a4 = a2 * a2;
    if constexpr (D == 1) return sigma * hinv * a4 * a2 * a * (1.0 + q * (7.0 + q * (19.0 + 21.0 * q)));
    else return sigma * kernel_power<D>(hinv) * a4 * a4 * (1.0 + q * (8.0 + q * (25.0 + 32.0 * q)));
  }

  // dW/dr = sigma / h^(D+1) dpsi/dq: 1D -6 q (3 + 18q + 35q^2) a^6; 2D, 3D -22 q (1 + 7q + 16q^2) a^7.
  static double dWdr(double r, double h) {
    const double hinv = 1.0 / h, q = r * hinv, a = std::max(1.0 - q, 0.0), a2 = a * a, a4 = a2 * a2;
    if constexpr (D == 1) return -6.0 * sigma * hinv * hinv * q * (3.0 + q * (18.0 + 35.0 * q)) * a4 * a2;
    else return -22.0 * sigma * kernel_power<D>(hinv) * hinv * q * (1.0 + q * (7.0 + 16.0 * q)) * a4 * a2 * a;
  }
};

}  // namespace sph
