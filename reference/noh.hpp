#pragma once

namespace reference {

// Exact solution of the Noh problem (Noh 1987) in d = 1, 2, 3 dimensions (planar, cylindrical,
// spherical): cold gas (p = 0) of density rho0 moving towards the centre at speed u0. A shock
// leaves the centre at speed D = (gamma - 1) u0 / 2; behind it the gas is at rest with density
// rho0 ((gamma + 1)/(gamma - 1))^d and pressure (gamma - 1) rho_post u0^2 / 2 (all inflow kinetic
// energy turned into heat); ahead of it the converging flow compresses the gas as
// rho0 (1 + u0 t / r)^(d - 1).
struct NohState {
  double rho, v, p;  // v is the radial velocity
};

class Noh {
 public:
  Noh(int d, double gamma, double rho0 = 1.0, double u0 = 1.0);
  double shock_speed() const;
  double shock_radius(double t) const { return shock_speed() * t; }
  double post_shock_density() const;
  double post_shock_pressure() const;
  NohState at(double r, double t) const;

 private:
  int d_;
  double gamma_, rho0_, u0_;
};

}  // namespace reference
