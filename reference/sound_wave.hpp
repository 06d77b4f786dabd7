#pragma once

namespace reference {

// The linear travelling acoustic wave of an ideal gas (Landau & Lifshitz, Fluid Mechanics, 64):
// a uniform state rho0, p0 at rest perturbed by a wave of relative density amplitude A and wave
// number k = 2 pi / L moving along +x at the adiabatic sound speed c_s = sqrt(gamma p0 / rho0).
// With phi = k (x - c_s t), to first order in A:
//   rho = rho0 (1 + A sin phi),  v_x = A c_s sin phi,  p = p0 (1 + gamma A sin phi),
//   u = u0 (1 + (gamma - 1) A sin phi),  u0 = p0 / ((gamma - 1) rho0)
// (adiabatic: p / rho^gamma and u / rho^(gamma - 1) constant to first order; the velocity from
// the linearised continuity equation d rho / dt = -rho0 dv/dx: v = c_s (rho - rho0) / rho0). The first
// neglected term, the wave's steepening, is of relative size (gamma + 1)/2 A k c_s t (the
// characteristic speed v + c varies by (gamma + 1)/2 A c_s along the wave): nonlinear_error.
struct AcousticState {
  double rho, v, p, u;
};

class AcousticWave {
 public:
  AcousticWave(double rho0, double c_s, double gamma, double amplitude, double wavelength);
  double sound_speed() const { return c_s_; }
  double pressure0() const { return rho0_ * c_s_ * c_s_ / gamma_; }
  double internal_energy0() const { return pressure0() / ((gamma_ - 1.0) * rho0_); }
  double wave_number() const;
  double wavelength() const { return L_; }
  double period() const { return L_ / c_s_; }
  // The phase k (x - c_s t) at x and t.
  double phase(double x, double t) const;
  AcousticState at(double x, double t) const;
  // Relative size of the first neglected (second-order) term at time t, (gamma + 1)/2 A k c_s t.
  double nonlinear_error(double t) const;

 private:
  double rho0_, c_s_, gamma_, A_, L_;
};

}  // namespace reference
