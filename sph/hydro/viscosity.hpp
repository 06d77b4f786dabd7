#pragma once
#include <algorithm>
#include <cmath>

#include "sph/hydro/scene.hpp"

namespace sph {

// Artificial viscosity of 9.4.2, eqs (44)-(48). The h inside mu_ij (46) is Monaghan's smoothing
// length, half of this chapter's support radius (errata): h_mu = h_scale * h_ij with
// h_scale = 1/2 by default; h_scale = 1 is the chapter's literal reading (doubles mu, so alpha
// acts as 2 alpha and beta as 4 beta).
template <int D>
struct ArtificialViscosity {
  static constexpr Writes writes{.dvdt = true, .dudt = true, .mu_max = true};
  double alpha = 1.0, beta = 2.0, eps = 0.01, h_scale = 0.5;

  // Branch-free: a receding pair has v_ij . r_ij clipped to 0, so mu_ij = Pi_ij = 0 (45) without
  // a jump that half the pairs would mispredict.
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& q) const {
    const Vec<D> vij = q.vi - q.vj;
    const double vr = std::min(vij.dot(q.rij), 0.0);  // (45): only approaching pairs
    const double h = h_scale * q.h;
    const double mu = h * vr / (q.r * q.r + eps * h * h);  // (46), errata: |r_i - r_j|^2
    const double c = 0.5 * (p.c[q.i] + p.c[q.j]), rho = 0.5 * (p.rho[q.i] + p.rho[q.j]);
    const double Pi = (-alpha * c * mu + beta * mu * mu) / rho;  // (45)
    s.dvdt -= (p.m[q.j] * Pi) * q.gradW;                         // (44)
    s.dudt += 0.5 * p.m[q.j] * Pi * vij.dot(q.gradW);            // (48)
    s.mu_max = std::max(s.mu_max, -mu);
  }
};

}  // namespace sph
