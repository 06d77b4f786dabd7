#pragma once
#include <cmath>

#include "sph/hydro/scene.hpp"

namespace sph {

// Variable smoothing length of 9.4.4. Start from (50), h_i = hfact (m_i / rho_i)^(1/D) (a fixed
// number of neighbours), then evolve h with (53):
//   dh_i/dt = (1/D) (h_i / rho_i) sum_j m_j (v_j - v_i) . grad_i W_ij.
// Setting h from the summation density at every step instead is a fixed-point iteration that
// diverges where a particle has few neighbours (a free surface: rho ~ m W(0, h) ~ 1/h makes h
// grow by hfact sigma_1D each step), so h is integrated. Pairs use h_ij = (h_i + h_j)/2; the
// grad-h terms are neglected (9.4.4).
template <int D>
void smoothing_length_from_density(Particles<D>& p, double hfact) {
  const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) p.h[i] = hfact * std::pow(p.m[i] / p.rho[i], 1.0 / D);
}

template <int D>
struct SmoothingLengthRate {
  static constexpr Writes writes{.dhdt = true};
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& q) const {
    s.dhdt += p.h[q.i] / (D * p.rho[q.i]) * p.m[q.j] * (q.vj - q.vi).dot(q.gradW);  // (53)
  }
};

}  // namespace sph
