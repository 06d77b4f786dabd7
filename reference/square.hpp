#pragma once

namespace reference {

// The isobaric square (2D) or cube (3D) of Saitoh & Makino 2013 (ApJ 768, 44) and Hopkins 2015
// (MNRAS 450, 53): in the periodic unit box [0, 1)^d a dense square of side 1/2 centred at
// (1/2, ..., 1/2) and density rho_in = contrast rho_out sits in a light gas of density rho_out, the
// pressure p0 the same everywhere and the whole moving with a uniform velocity v_adv along every
// axis (0: at rest). Uniform pressure and velocity make every term of the Euler equations zero
// (grad p = 0, div v = 0), so the exact solution is the initial state carried along by v_adv:
//   rho(x, t) = rho_0(x - v_adv t (1, ..., 1)) (periodic), v = v_adv, p = p0.
// width > 0 replaces the step by a smooth one: along each axis s(y) = (tanh((y - 1/4) / width) -
// tanh((y - 3/4) / width)) / 2 and rho = rho_out (1 + (contrast - 1) prod_d s(x_d)), the same
// equilibrium (any density at uniform p and v is one), a profile a resolution can resolve.
class IsobaricSquare {
 public:
  IsobaricSquare(int dim, double contrast, double rho_out, double p0, double gamma, double v_adv, double width);
  int dim() const { return dim_; }
  double rho_in() const { return contrast_ * rho_out_; }
  double rho_out() const { return rho_out_; }
  double pressure() const { return p0_; }
  double advection_speed() const { return v_adv_; }
  double width() const { return width_; }
  // The adiabatic sound speed sqrt(gamma p0 / rho) of the light and the dense gas.
  double sound_speed_out() const;
  double sound_speed_in() const;
  // Whether the point (x[0], ..., x[dim-1]) lies inside the carried square at time t (the
  // half-open square [1/4, 3/4)^d carried by v_adv t, periodic).
  bool inside(const double* x, double t) const;
  // The exact density at x and t (the step, or the smooth profile where width > 0).
  double density(const double* x, double t) const;
  // The specific internal energy p0 / ((gamma - 1) rho) at x and t.
  double internal_energy(const double* x, double t) const;
  // The fraction of the cube of side s centred at x that lies inside the carried square at t
  // (s <= 1/4: the cube meets at most the square's nearest periodic image).
  double inside_fraction(const double* x, double s, double t) const;
  // A coordinate carried back to t = 0, in [0, 1).
  double origin(double x, double t) const;

 private:
  int dim_;
  double contrast_, rho_out_, p0_, gamma_, v_adv_, width_;
};

}  // namespace reference
