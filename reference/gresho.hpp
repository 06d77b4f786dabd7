#pragma once
#include <vector>

namespace reference {

// The Gresho-Chan triangular vortex (Gresho & Chan 1990; Liska & Wendroff 2003, 4.6): a stationary
// solution of the Euler equations in 2D with uniform density rho0 and the azimuthal velocity
//   v_phi(r) = 5 r (r < 0.2),  2 - 5 r (0.2 <= r < 0.4),  0 (r >= 0.4)
// (peak 1 at r = 0.2), held by the pressure of radial equilibrium dp/dr = rho0 v_phi^2 / r:
//   p(r) = p0 + 12.5 rho0 r^2                                   (r < 0.2)
//        = p0 + rho0 (4 + 12.5 r^2 - 20 r + 4 ln(5 r))          (0.2 <= r < 0.4)
//        = p0 + rho0 (4 ln 2 - 2)                               (r >= 0.4)
// with p0 the central pressure (5 in the standard set-up: p = 9 + 12.5 r^2 - 20 r + 4 ln(5 r) in
// the ring, 3 + 4 ln 2 beyond). Any p0 > 0 is a solution; the standard 5 makes the flow subsonic
// (peak Mach number 1 / sqrt(gamma p / rho0) ~ 0.34 at gamma 5/3).
class GreshoVortex {
 public:
  GreshoVortex(double rho0, double p0, double gamma);
  double density() const { return rho0_; }
  double gamma() const { return gamma_; }
  // The exact profile, the same at every time (the flow is stationary).
  double v_phi(double r) const;
  double pressure(double r) const;
  double internal_energy(double r) const { return pressure(r) / ((gamma_ - 1.0) * rho0_); }
  // p(r) from p0 by adaptive quadrature of dp/dr = rho0 v_phi^2 / r (breakpoints at the kinks
  // 0.2 and 0.4): an independent check of the closed form above.
  double pressure_by_quadrature(double r) const;

 private:
  double rho0_, p0_, gamma_;
};

}  // namespace reference
