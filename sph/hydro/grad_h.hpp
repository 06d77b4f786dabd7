#pragma once
// The grad-h formulation (Springel & Hernquist 2002, MNRAS 333, 649; Price & Monaghan 2007, MNRAS
// 374, 1347; Price 2012, JCP 231, 759, Sec. 2.5-2.7): the equations of motion and energy that
// follow from a Lagrangian whose density is rho_i = sum_j m_j W(r_ij, h_i), each particle's sum at
// its own h, with h_i tied to rho_i by (50). Each pair weighs the kernel of each end at that
// end's h (OwnHPair, hydro/scene.hpp), and each end's share is divided by its
//   Omega_i = 1 - (dh_i/drho_i) sum_j m_j dW(r_ij, h_i)/dh_i = 1 + h_i / (D rho_i) sum_j m_j dW(r_ij, h_i)/dh_i
// (dh_i/drho_i = -h_i / (D rho_i) by (50); the sum includes the self term), which the scheme's
// density phase sets (grad_h_omega). With these, momentum and total energy are conserved exactly by
// the semi-discrete equations however h varies, which (23) with h_ij misses (conservation_gradh).
#include <cstddef>
#include <vector>

#include "sph/hydro/scene.hpp"

namespace sph {

// Omega_i from d rho_i / d h_i = sum_j m_j dW(r_ij, h_i)/dh_i (density/fixed_neighbours_newton.hpp,
// own_h), at the particles' h and rho.
template <int D>
void grad_h_omega(const Particles<D>& p, const std::vector<double>& drho_dh, std::vector<double>& omega) {
  const std::size_t n = p.size();
  omega.resize(n);
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) omega[i] = 1.0 + p.h[i] / (D * p.rho[i]) * drho_dh[i];
}

// The grad-h momentum equation:
//   dv_i/dt = -sum_j m_j [P_i / (Omega_i rho_i^2) grad_i W_ij(h_i) + P_j / (Omega_j rho_j^2) grad_i W_ij(h_j)].
// omega: the scheme's Omega_i (grad_h_omega), read in the pair loop.
template <int D>
struct GradhEuler {
  static constexpr bool own_h_kernels = true;
  static constexpr Writes writes{.dvdt = true};
  const std::vector<double>* omega = nullptr;
  void pair(const Particles<D>& p, PairSums<D>& s, const OwnHPair<D>& q) const {
    const double* om = omega->data();
    const double fi = p.p[q.i] / (om[q.i] * p.rho[q.i] * p.rho[q.i]);
    const double fj = p.p[q.j] / (om[q.j] * p.rho[q.j] * p.rho[q.j]);
    s.dvdt -= p.m[q.j] * (fi * q.gradWi + fj * q.gradWj);
  }
};

// The energy equation that matches it (the first law with drho_i/dt of the h_i-sum):
//   du_i/dt = P_i / (Omega_i rho_i^2) sum_j m_j v_ij . grad_i W_ij(h_i),
// (38) with the kernel at h_i and the factor 1/Omega_i. With GradhEuler, sum_i m_i (v_i . dv_i/dt +
// du_i/dt) = 0 pair by pair.
template <int D>
struct GradhEnergy {
  static constexpr bool own_h_kernels = true;
  static constexpr Writes writes{.dudt = true};
  const std::vector<double>* omega = nullptr;
  void pair(const Particles<D>& p, PairSums<D>& s, const OwnHPair<D>& q) const {
    const double fi = p.p[q.i] / ((*omega)[q.i] * p.rho[q.i] * p.rho[q.i]);
    s.dudt += p.m[q.j] * fi * (q.vi - q.vj).dot(q.gradWi);
  }
};

}  // namespace sph
