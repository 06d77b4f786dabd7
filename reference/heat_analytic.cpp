#include "reference/heat_analytic.hpp"

#include <cmath>
#include <numbers>

namespace reference {

double sine_mode(const std::vector<double>& x, double t, double chi, double T0, double A, int m) {
  const double k = 2.0 * std::numbers::pi * m;
  double s = A * std::exp(-chi * k * k * static_cast<double>(x.size()) * t);
  for (double xa : x) s *= std::sin(k * xa);
  return T0 + s;
}

double gaussian_pulse(const std::vector<double>& x, double t, double chi, double T0, double A, double s0,
                      double c) {
  const double var = s0 * s0 + 2.0 * chi * t;
  // Images beyond +-6 widths contribute < exp(-18) relative: |m| <= 6 sqrt(var) + 1 suffices.
  const int images = static_cast<int>(std::ceil(6.0 * std::sqrt(var))) + 1;
  double prod = A;
  for (double xa : x) {
    double g = 0.0;
    for (int m = -images; m <= images; ++m) {
      const double d = xa - c + m;
      g += std::exp(-0.5 * d * d / var);
    }
    prod *= g * s0 / std::sqrt(var);
  }
  return T0 + prod;
}

}  // namespace reference
