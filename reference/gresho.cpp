#include "reference/gresho.hpp"

#include <cmath>
#include <stdexcept>

#include "reference/quadrature.hpp"

namespace reference {

GreshoVortex::GreshoVortex(double rho0, double p0, double gamma) : rho0_(rho0), p0_(p0), gamma_(gamma) {
  if (!(rho0 > 0.0) || !(p0 > 0.0)) throw std::invalid_argument("GreshoVortex: rho0 and p0 must be > 0");
  if (!(gamma > 1.0)) throw std::invalid_argument("GreshoVortex: gamma must exceed 1");
}

double GreshoVortex::v_phi(double r) const {
  if (r < 0.2) return 5.0 * r;
  if (r < 0.4) return 2.0 - 5.0 * r;
  return 0.0;
}

double GreshoVortex::pressure(double r) const {
  if (r < 0.2) return p0_ + 12.5 * rho0_ * r * r;
  if (r < 0.4) return p0_ + rho0_ * (4.0 + 12.5 * r * r - 20.0 * r + 4.0 * std::log(5.0 * r));
  return p0_ + rho0_ * (4.0 * std::log(2.0) - 2.0);
}

double GreshoVortex::pressure_by_quadrature(double r) const {
  if (!(r > 0.0)) return p0_;
  std::vector<double> points = {0.0};
  for (double kink : {0.2, 0.4})
    if (kink < r) points.push_back(kink);
  points.push_back(r);
  // v_phi^2 / r = 25 r near the axis: no singularity at r = 0.
  const auto integrand = [this](double s) { return s > 0.0 ? rho0_ * v_phi(s) * v_phi(s) / s : 0.0; };
  return p0_ + integrate(integrand, points).value;
}

}  // namespace reference
