#pragma once
// The velocity's divergence and curl at the particles, from the SPH estimate of its gradient with
// each particle's own kernel (the grad-h density's, Price 2012, JCP 231, 759, Sec. 2.8):
//   (d v^a / d x^b)_i = 1 / (Omega_i rho_i) sum_j m_j (v_j - v_i)^a d_b W_ij(h_i),
// div v_i its trace, |curl v_i| the norm of its antisymmetric part (sum over a < b of the
// squared differences of the transposed entries, in any dimension: 0 in 1D). The viscosity switch
// reads them (hydro/viscosity_switch.hpp).
#include <cmath>
#include <cstddef>
#include <vector>

#include "sph/core/box.hpp"
#include "sph/core/particles.hpp"
#include "sph/core/threads.hpp"
#include "sph/search/neighbour_list.hpp"

namespace sph {

template <int D, class K>
void velocity_divergence_curl(const Particles<D>& p, const NeighbourList& nl, const Box<D>& box,
                              const std::vector<double>& omega, std::vector<double>& div, std::vector<double>& curl) {
  const std::size_t n = p.size();
  const Vec<D> L = box.length(), wrap = box.wrap_factor();
  div.resize(n);
  curl.resize(n);
#pragma omp parallel for schedule(dynamic, 256) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Matrix<double, D, D> G = Eigen::Matrix<double, D, D>::Zero();
    for (int j : nl.of(i)) {
      const Vec<D> rij = min_image<D>(p.x[i] - p.x[j], L, wrap);
      const double r = rij.norm();
      const double g = r > 0.0 ? K::dWdr(r, p.h[i]) / r : 0.0;  // 0 beyond h_i
      G += p.m[j] * (p.v[j] - p.v[i]) * (g * rij).transpose();
    }
    G /= omega[i] * p.rho[i];
    double c2 = 0.0;
    for (int a = 0; a < D; ++a)
      for (int b = a + 1; b < D; ++b) c2 += (G(a, b) - G(b, a)) * (G(a, b) - G(b, a));
    div[i] = G.trace();
    curl[i] = std::sqrt(c2);
  }
}

}  // namespace sph
