#pragma once
// Artificial viscosity in the signal-velocity form (Monaghan 1997, JCP 136, 298; Price 2008, JCP
// 227, 10040; Price 2012, JCP 231, 759, Sec. 4), with a viscosity parameter per particle (the
// switch's, hydro/viscosity_switch.hpp):
//   Pi_ij = -1/2 alpha_ij v_sig,ij w_ij / rho_ij   where w_ij = v_ij . r_ij / |r_ij| < 0 (else 0),
//   v_sig,ij = c_i + c_j - beta w_ij,  alpha_ij = (alpha_i + alpha_j) / 2,  rho_ij = (rho_i + rho_j) / 2,
//   dv_i/dt = -sum_j m_j Pi_ij gbar_ij,   du_i/dt = 1/2 sum_j m_j Pi_ij v_ij . gbar_ij,
// with the mean of the two ends' kernel gradients gbar_ij = (grad_i W_ij(h_i) + grad_i W_ij(h_j)) / 2,
// which is antisymmetric in i, j: the pair's force is equal and opposite and the work it does
// reappears as heat, so momentum and total energy stay conserved with variable h.
#include <algorithm>
#include <vector>

#include "sph/hydro/scene.hpp"

namespace sph {

// beta: the signal velocity's coefficient of the approach speed (2: the scheme's default, the
// options' beta). Writes max_j v_sig,ij (interacting pairs, receding ones at c_i + c_j) into the
// pair sums' mu_max: the signal speed of the scheme's Courant condition (time/timestep.hpp,
// signal_time_step). Branch-free: a receding pair has w_ij clipped to 0, so Pi_ij = 0.
template <int D>
struct SignalVelocityViscosity {
  static constexpr bool own_h_kernels = true;
  static constexpr Writes writes{.dvdt = true, .dudt = true, .mu_max = true};
  const std::vector<double>* alpha = nullptr;  // alpha_i
  double beta = 2.0;
  void pair(const Particles<D>& p, PairSums<D>& s, const OwnHPair<D>& q) const {
    const Vec<D> vij = q.vi - q.vj;
    const double w = std::min(vij.dot(q.rij), 0.0) / (q.r > 0.0 ? q.r : 1.0);  // coincident pairs: v_ij . r_ij = 0
    const double vsig = p.c[q.i] + p.c[q.j] - beta * w;
    const double a = 0.5 * ((*alpha)[q.i] + (*alpha)[q.j]);
    const double Pi = -0.5 * a * vsig * w / (0.5 * (p.rho[q.i] + p.rho[q.j]));
    const Vec<D> g = 0.5 * (q.gradWi + q.gradWj);
    s.dvdt -= (p.m[q.j] * Pi) * g;
    s.dudt += 0.5 * p.m[q.j] * Pi * vij.dot(g);
    s.mu_max = std::max(s.mu_max, vsig);
  }
};

}  // namespace sph
