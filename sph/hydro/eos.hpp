#pragma once
#include <cmath>

#include "sph/core/particles.hpp"
#include "sph/hydro/scene.hpp"

namespace sph {

// Ideal gas: p = (gamma - 1) rho u, c^2 = gamma p / rho.
struct IdealGas {
  double gamma = 1.4;
  double pressure(double rho, double u) const { return (gamma - 1.0) * rho * u; }
  double sound_speed(double, double u) const { return std::sqrt(gamma * (gamma - 1.0) * u); }
};

// Polytrope (35): p = K rho^gamma (the chapter writes the constant K as rho_0, see errata);
// sound speed (47): c^2 = gamma K rho^(gamma - 1). Independent of u.
struct Polytropic {
  double K = 1.0, gamma = 2.0;
  double pressure(double rho, double) const { return K * std::pow(rho, gamma); }
  double sound_speed(double rho, double) const { return std::sqrt(gamma * K * std::pow(rho, gamma - 1.0)); }
};

// Scene term: sets p_i and c_i from rho_i and u_i before the pair loop. List it after the
// density term so it sees the current density.
template <int D, class Eos>
struct EquationOfState {
  Eos eos;
  void prepare(Particles<D>& p, const Neighbourhood<D>&) const {
    const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) {
      p.p[i] = eos.pressure(p.rho[i], p.u[i]);
      p.c[i] = eos.sound_speed(p.rho[i], p.u[i]);
    }
  }
};

}  // namespace sph
