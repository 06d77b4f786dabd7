#pragma once
// The velocity's divergence and curl at the particles, from the SPH estimate of its gradient with
// each particle's own kernel (the grad-h density's, Price 2012, JCP 231, 759, Sec. 2.8):
//   (d v^a / d x^b)_i = 1 / (Omega_i rho_i) sum_j m_j (v_j - v_i)^a d_b W_ij(h_i),
// div v_i its trace, |curl v_i| the norm of its antisymmetric part (sum over a < b of the
// squared differences of the transposed entries, in any dimension: 0 in 1D). The viscosity switch
// reads them (hydro/viscosity_switch.hpp).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "sph/core/box.hpp"
#include "sph/core/particles.hpp"
#include "sph/hydro/pairs.hpp"
#include "sph/search/neighbour_list.hpp"

namespace sph {

// Over the listed pairs of each particle (pairs beyond h_i add 0: dW/dr vanishes there), in the
// pair loops' copies (for_each_particle): each batch's shares computed without a branch in one
// vectorised loop, then summed in list order, so that the result does not depend on the vector
// width or the thread count. xs, vs: the caller's buffers for the positions' and velocities'
// columns, kept from one call to the next (see Scene::xs, hydro/scene.hpp).
template <int D, class K>
void velocity_divergence_curl(const Particles<D>& p, const NeighbourList& nl, const Box<D>& box,
                              const std::vector<double>& omega, std::vector<double>& div, std::vector<double>& curl,
                              Components<D>& xs, Components<D>& vs) {
  const std::size_t n = p.size();
  const Vec<D> L = box.length(), wrap = box.wrap_factor();
  div.resize(n);
  curl.resize(n);
  copy_components<D>(p.x, xs);
  copy_components<D>(p.v, vs);
  const double* m = p.m.data();
  constexpr int pairs_ab = D * (D - 1) / 2;  // the entries above the diagonal, a < b (at most 3)
  static_assert(D <= 3);
  // (a, b) of those entries, in the order of a then b: one flat loop over them, which GCC unrolls
  // at -O2; a nested loop over a and b leaves a branch in the 2D pair loop, which then stays scalar.
  static constexpr int above_diagonal[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for_each_particle<D>(n, nl, [&](std::size_t i) {
    constexpr int batch = 64;
    // Of the batch's pairs: the trace of m_j (v_j - v_i) (x) grad_i W_ij(h_i), and its entries
    // (a, b) less (b, a) above the diagonal: the only parts of the gradient the switch reads.
    double trace_share[batch], anti_share[pairs_ab > 0 ? pairs_ab : 1][batch];
    // The sums, one local each (an array of them is kept in memory, and each pair's add then
    // waits on the last one's store).
    double trace = 0.0, anti0 = 0.0, anti1 = 0.0, anti2 = 0.0;
    const int* js = nl.j.data() + nl.offset[i];
    const int count = static_cast<int>(nl.offset[i + 1] - nl.offset[i]);
    const double hi = p.h[i];
    for (int t0 = 0; t0 < count; t0 += batch) {
      const int nb = std::min(count - t0, batch);
#pragma omp simd
      for (int t = 0; t < nb; ++t) {
        const int j = js[t0 + t];
        double rij[D], dv[D];
        double r2 = 0.0;
#pragma GCC unroll 3
        for (int d = 0; d < D; ++d) {
          rij[d] = min_image(xs[d][i] - xs[d][j], L[d], wrap[d]);
          r2 += rij[d] * rij[d];
          dv[d] = m[j] * (vs[d][j] - vs[d][i]);
        }
        const double r = std::sqrt(r2);
        const double g = r > 0.0 ? K::dWdr(r, hi) / r : 0.0;  // 0 beyond h_i
        double tr = 0.0;
#pragma GCC unroll 3
        for (int d = 0; d < D; ++d) tr += dv[d] * (g * rij[d]);
        trace_share[t] = tr;
#pragma GCC unroll 3
        for (int k = 0; k < pairs_ab; ++k) {
          const int a = above_diagonal[k][0], b = above_diagonal[k][1];
          anti_share[k][t] = dv[a] * (g * rij[b]) - dv[b] * (g * rij[a]);
        }
      }
      for (int t = 0; t < nb; ++t) {
        trace += trace_share[t];
        if constexpr (pairs_ab > 0) anti0 += anti_share[0][t];
        if constexpr (pairs_ab > 1) anti1 += anti_share[1][t], anti2 += anti_share[2][t];
      }
    }
    const double s = omega[i] * p.rho[i];
    const double anti[3] = {anti0 / s, anti1 / s, anti2 / s};
    double c2 = 0.0;
    for (int k = 0; k < pairs_ab; ++k) c2 += anti[k] * anti[k];
    div[i] = trace / s;
    curl[i] = std::sqrt(c2);
  });
}

}  // namespace sph
