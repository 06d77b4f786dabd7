#include "reference/polytrope.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace reference {

namespace {
// sin x - x cos x, by its series near 0 (x^3 / 3 - x^5 / 30 + x^7 / 840), where the difference
// cancels to round-off.
double shell(double x) {
  if (x < 1e-2) {
    const double x2 = x * x;
    return x * x2 * (1.0 / 3.0 - x2 / 30.0 + x2 * x2 / 840.0);
  }
  return std::sin(x) - x * std::cos(x);
}
}  // namespace

Polytrope1::Polytrope1(double M, double K, double G) : M_(M), K_(K), G_(G) {
  if (!(M > 0.0) || !(K > 0.0) || !(G > 0.0) || !std::isfinite(M) || !std::isfinite(K) || !std::isfinite(G))
    throw std::invalid_argument("Polytrope1: M, K and G must be positive and finite");
  R_ = std::sqrt(std::numbers::pi * K / (2.0 * G));
  rho_c_ = std::numbers::pi * M / (4.0 * R_ * R_ * R_);
}

double Polytrope1::density(double r) const {
  if (r >= R_) return 0.0;
  const double xi = std::numbers::pi * std::abs(r) / R_;
  return xi < 1e-4 ? rho_c_ * (1.0 - xi * xi / 6.0) : rho_c_ * std::sin(xi) / xi;
}

double Polytrope1::pressure(double r) const {
  const double rho = density(r);
  return K_ * rho * rho;
}

double Polytrope1::mass_within(double r) const {
  if (r >= R_) return M_;
  if (r <= 0.0) return 0.0;
  return M_ / std::numbers::pi * shell(std::numbers::pi * r / R_);
}

double Polytrope1::radius_of_mass_fraction(double q) const {
  if (!(q >= 0.0 && q <= 1.0)) throw std::invalid_argument("Polytrope1: mass fraction outside [0, 1]");
  if (q == 0.0) return 0.0;
  if (q == 1.0) return R_;
  // f(xi) = shell(xi) - pi q rises monotonically on (0, pi), f' = xi sin xi.
  const double target = std::numbers::pi * q;
  double lo = 0.0, hi = std::numbers::pi, xi = std::cbrt(3.0 * target);  // the small-xi limit
  if (!(xi > lo && xi < hi)) xi = 0.5 * (lo + hi);
  for (int k = 0; k < 200; ++k) {
    const double f = shell(xi) - target;
    if (f > 0.0) hi = xi;
    else lo = xi;
    const double step = f / (xi * std::sin(xi));
    double next = xi - step;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(next - xi) <= 1e-15 * xi || hi - lo <= 1e-15 * hi) return next * R_ / std::numbers::pi;
    xi = next;
  }
  return xi * R_ / std::numbers::pi;
}

double Polytrope1::mean_density_within_mass_fraction(double q) const {
  if (!(q > 0.0 && q <= 1.0)) throw std::invalid_argument("Polytrope1: mass fraction outside (0, 1]");
  const double a = std::numbers::pi / R_, xi = a * radius_of_mass_fraction(q);
  // xi / 2 - sin(2 xi) / 4 = xi^3 / 3 - xi^5 / 15 + ... cancels near 0: its series there.
  const double x2 = xi * xi;
  const double s = xi < 1e-2 ? xi * x2 * (1.0 / 3.0 - x2 / 15.0) : 0.5 * xi - 0.25 * std::sin(2.0 * xi);
  return 4.0 * std::numbers::pi * rho_c_ * rho_c_ / (a * a * a) * s / (q * M_);
}

double Polytrope1::potential_energy() const { return -0.75 * G_ * M_ * M_ / R_; }

}  // namespace reference
