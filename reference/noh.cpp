#include "reference/noh.hpp"

#include <cmath>
#include <stdexcept>

namespace reference {

Noh::Noh(int d, double gamma, double rho0, double u0) : d_(d), gamma_(gamma), rho0_(rho0), u0_(u0) {
  if (d < 1 || d > 3) throw std::invalid_argument("Noh: dimension must be 1, 2 or 3");
  if (!(gamma > 1.0)) throw std::invalid_argument("Noh: gamma must exceed 1");
}

double Noh::shock_speed() const { return 0.5 * (gamma_ - 1.0) * u0_; }

double Noh::post_shock_density() const {
  return rho0_ * std::pow((gamma_ + 1.0) / (gamma_ - 1.0), d_);
}

double Noh::post_shock_pressure() const { return 0.5 * (gamma_ - 1.0) * post_shock_density() * u0_ * u0_; }

NohState Noh::at(double r, double t) const {
  if (r < shock_radius(t)) return {post_shock_density(), 0.0, post_shock_pressure()};
  // Ahead of the shock; at r = 0 (t = 0) the flow is undisturbed.
  const double compression = r > 0.0 ? std::pow(1.0 + u0_ * t / r, d_ - 1) : 1.0;
  return {rho0_ * compression, -u0_, 0.0};
}

}  // namespace reference
