#include "reference/sound_wave.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace reference {

AcousticWave::AcousticWave(double rho0, double c_s, double gamma, double amplitude, double wavelength)
    : rho0_(rho0), c_s_(c_s), gamma_(gamma), A_(amplitude), L_(wavelength) {
  if (!(rho0 > 0.0) || !(c_s > 0.0)) throw std::invalid_argument("AcousticWave: rho0 and c_s must be > 0");
  if (!(gamma > 1.0)) throw std::invalid_argument("AcousticWave: gamma must exceed 1");
  if (!(wavelength > 0.0)) throw std::invalid_argument("AcousticWave: the wavelength must be > 0");
}

double AcousticWave::wave_number() const { return 2.0 * std::numbers::pi / L_; }

double AcousticWave::phase(double x, double t) const { return wave_number() * (x - c_s_ * t); }

AcousticState AcousticWave::at(double x, double t) const {
  const double s = A_ * std::sin(phase(x, t));
  return {rho0_ * (1.0 + s), c_s_ * s, pressure0() * (1.0 + gamma_ * s), internal_energy0() * (1.0 + (gamma_ - 1.0) * s)};
}

double AcousticWave::nonlinear_error(double t) const {
  return 0.5 * (gamma_ + 1.0) * std::abs(A_) * wave_number() * c_s_ * t;
}

}  // namespace reference
