#pragma once
#include <vector>

namespace reference {

// Sedov-Taylor point blast in a uniform gas of density rho0 at rest and zero pressure, in
// d = 1 (planar, energy E per unit area counting both sides), 2 (cylindrical, E per unit
// length) or 3 (spherical) dimensions, for any gamma > 1.
//
// Self-similar form with xi = r / R(t), R = xi_0 (E t^2 / rho0)^(1/(d+2)), U = dR/dt:
//   v = U f(xi), rho = rho0 g(xi), p = rho0 U^2 h(xi).
// The Euler equations reduce to three ODEs in xi, integrated (GSL rk8pd) from the strong-shock
// jump conditions at xi = 1 inwards; xi_0 follows from the energy integral
//   1 = sigma_d alpha^2 xi_0^(d+2) int_0^1 (g f^2 / 2 + h / (gamma - 1)) xi^(d-1) dxi,
// alpha = 2 / (d + 2), sigma_d = 2, 2 pi, 4 pi.
class Sedov {
 public:
  Sedov(int d, double gamma);

  int dimension() const { return d_; }
  double gamma() const { return gamma_; }
  double xi0() const { return xi0_; }

  // Shock radius and speed at time t.
  double shock_radius(double E, double rho0, double t) const;
  double shock_speed(double E, double rho0, double t) const;

  // Dimensionless profiles at xi = r / R in [0, 1] (zero pressure, rho0 and rest outside).
  double f(double xi) const;  // v / U
  double g(double xi) const;  // rho / rho0
  double h(double xi) const;  // p / (rho0 U^2)

  // Physical fields at radius r and time t.
  double density(double r, double E, double rho0, double t) const;
  double velocity(double r, double E, double rho0, double t) const;
  double pressure(double r, double E, double rho0, double t) const;

 private:
  int d_;
  double gamma_;
  double xi0_ = 0.0;
  std::vector<double> xi_, f_, g_, h_;  // tabulated on increasing xi in (0, 1]
};

}  // namespace reference
