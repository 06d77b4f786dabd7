#pragma once
// Artificial conduction of the internal energy (Price 2008, JCP 227, 10040, Sec. 3-4; Price 2012,
// JCP 231, 759, Sec. 4.2): the dissipation term of an SPH Riemann-solver analogue for u, which
// smooths the jump of u at a contact where the pressure is continuous, so that the pressure blip
// there and the surface tension that stops a Kelvin-Helmholtz roll-up go away:
//   du_i/dt = sum_j m_j alpha_u v_sig,ij^u (u_i - u_j) F_ij / rho_ij,
//   v_sig,ij^u = sqrt(|P_i - P_j| / rho_ij),   rho_ij = (rho_i + rho_j) / 2,
// with F_ij = r_ij . gbar_ij / |r_ij| <= 0 the kernels' mean radial derivative (gbar_ij as in
// hydro/signal_viscosity.hpp), so heat flows from the hotter particle to the colder. The pair term
// is antisymmetric in i, j (F_ij is symmetric): sum_i m_i du_i/dt = 0, total energy is conserved.
// The signal velocity vanishes where the pressure is uniform: conduction acts at a contact, and
// not in a gas in pressure equilibrium whose u varies (a hydrostatic contact stays put).
#include <cmath>

#include "sph/hydro/scene.hpp"

namespace sph {

// alpha_u = 1: Price 2008's value (his Kelvin-Helmholtz and shock-tube tests); the scheme's option.
template <int D>
struct ArtificialConduction {
  static constexpr bool own_h_kernels = true;
  static constexpr Writes writes{.dudt = true};
  double alpha_u = 1.0;
  void pair(const Particles<D>& p, PairSums<D>& s, const OwnHPair<D>& q) const {
    const double rho = 0.5 * (p.rho[q.i] + p.rho[q.j]);
    const double vsig = std::sqrt(std::abs(p.p[q.i] - p.p[q.j]) / rho);
    const double F = 0.5 * (q.gradWi + q.gradWj).dot(q.rij) / (q.r > 0.0 ? q.r : 1.0);  // coincident pairs: r_ij = 0
    s.dudt += p.m[q.j] * alpha_u * vsig * (p.u[q.i] - p.u[q.j]) * F / rho;
  }
};

}  // namespace sph
