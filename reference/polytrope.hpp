#pragma once

namespace reference {

// The n = 1 polytrope in hydrostatic equilibrium (Chandrasekhar, An Introduction to the Study of
// Stellar Structure, IV): a self-gravitating gas sphere with p = K rho^2. With rho = rho_c theta
// and r = a xi, a^2 = K / (2 pi G), hydrostatic equilibrium dp/dr = -G M(<r) rho / r^2 becomes
// the Lane-Emden equation of index 1, (1 / xi^2) d/dxi (xi^2 dtheta/dxi) = -theta, whose solution
// regular at the centre is theta = sin(xi) / xi. Its first zero xi = pi is the surface:
//   R = pi a = sqrt(pi K / (2 G)),  rho(r) = rho_c sin(pi r / R) / (pi r / R)  (0 outside),
//   M(<r) = (4 rho_c R^3 / pi^2) (sin xi - xi cos xi),  M = 4 rho_c R^3 / pi.
// The radius depends on K and G only; the mass sets rho_c.
class Polytrope1 {
 public:
  // Throws std::invalid_argument unless M, K and G are positive and finite.
  Polytrope1(double M, double K, double G = 1.0);
  double radius() const { return R_; }
  double mass() const { return M_; }
  double central_density() const { return rho_c_; }
  double K() const { return K_; }
  double G() const { return G_; }
  // rho(r) for r >= 0 (rho_c at r = 0, 0 for r >= R).
  double density(double r) const;
  // p = K rho^2.
  double pressure(double r) const;
  // M(<r), M for r >= R.
  double mass_within(double r) const;
  // The radius enclosing the mass fraction q in [0, 1] (the inverse of mass_within / M), solved
  // by bracketed Newton iterations to round-off.
  double radius_of_mass_fraction(double q) const;
  // The mass-weighted mean density of the innermost mass fraction q, int rho dM / (q M) over
  // M(<r) <= q M: (4 pi rho_c^2 / a^3) (xi / 2 - sin(2 xi) / 4) / (q M), xi = pi r_q / R, a = pi / R.
  double mean_density_within_mass_fraction(double q) const;
  // The gravitational potential energy W = -G int M(<r) dM / r = -3 G M^2 / (4 R) (Chandrasekhar's
  // W = -3 G M^2 / ((5 - n) R) for n = 1).
  double potential_energy() const;

 private:
  double M_, K_, G_, R_, rho_c_;
};

}  // namespace reference
