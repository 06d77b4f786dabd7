#pragma once
// Artificial conduction of the internal energy (Price 2008, JCP 227, 10040, Sec. 3-4; Price 2012,
// JCP 231, 759, Sec. 4.2): the dissipation term of an SPH Riemann-solver analogue for u, which
// smooths the jump of u at a contact where the pressure is continuous, so that the pressure blip
// there and the surface tension that stops a Kelvin-Helmholtz roll-up go away:
//   du_i/dt = sum_j m_j alpha_u v_sig,ij^u (u_i - u_j) F_ij / rho_ij,
//   v_sig,ij^u = sqrt(|P_i - P_j| / rho_ij),   rho_ij = (rho_i + rho_j) / 2,
// or, as Wadsley, Veeravalli & Couchman 2008 (MNRAS 387, 427) and Phantom with self-gravity
// (Price et al. 2018, Sec. 2.2.9) take it, v_sig,ij^u = |v_ij . r_ij| / |r_ij|,
// with F_ij = r_ij . gbar_ij / |r_ij| <= 0 the kernels' mean radial derivative (gbar_ij as in
// hydro/signal_viscosity.hpp), so heat flows from the hotter particle to the colder. The pair term
// is antisymmetric in i, j (F_ij is symmetric): sum_i m_i du_i/dt = 0, total energy is conserved.
// The pressure-based signal velocity vanishes where the pressure is uniform: conduction acts at a
// contact, and not in a gas in pressure equilibrium whose u varies (a hydrostatic contact stays
// put). Where the pressure is uniform only to its discretisation error, it grows as that error's
// square root; the velocity-based one vanishes in a gas at rest and moves no heat across a
// contact that a steady pressure holds (docs/cases/square.md).
#include <cmath>

#include "sph/hydro/scene.hpp"

namespace sph {

// alpha_u = 1: Price 2008's value (his Kelvin-Helmholtz and shock-tube tests); the scheme's option.
// The signal velocity is by_pressure times the first form plus by_velocity times the second: (1, 0)
// Price 2008's (the default), (0, 1) the velocity-based one (SchemeOptions::vsig_u); weights, not
// a choice tested per pair.
template <int D>
struct ArtificialConduction {
  static constexpr bool own_h_kernels = true;
  static constexpr Writes writes{.dudt = true};
  double alpha_u = 1.0;
  double by_pressure = 1.0, by_velocity = 0.0;
  void pair(const Particles<D>& p, PairSums<D>& s, const OwnHPair<D>& q) const {
    const double rho = 0.5 * (p.rho[q.i] + p.rho[q.j]);
    const double r = q.r > 0.0 ? q.r : 1.0;  // coincident pairs: r_ij = 0
    const double vsig = by_pressure * std::sqrt(std::abs(p.p[q.i] - p.p[q.j]) / rho) +
                        by_velocity * std::abs((q.vi - q.vj).dot(q.rij)) / r;
    const double F = 0.5 * (q.gradWi + q.gradWj).dot(q.rij) / r;
    s.dudt += p.m[q.j] * alpha_u * vsig * (p.u[q.i] - p.u[q.j]) * F / rho;
  }
};

}  // namespace sph
