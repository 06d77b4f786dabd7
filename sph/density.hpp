#pragma once
#include "sph/kernel.hpp"
#include "sph/pairs.hpp"
#include "sph/particles.hpp"

namespace sph {

// Density by summation, eq (27): rho_i = sum_j m_j W_ij, including the self term m_i W_ii
// (the self-density (49) is its floor).
template <int D>
void density_summation(Particles<D>& p, const NeighbourList& nl, const Box<D>& box) {
  using K = CubicSpline<D>;
  for (std::size_t i = 0; i < p.size(); ++i) p.rho[i] = p.m[i] * K::W(0.0, p.h[i]);
  for_each_pair<D>(p.x, p.h, nl, box, [&](std::size_t i, int j, const Vec<D>&, double r, double h) {
    p.rho[i] += p.m[j] * K::W(r, h);
  });
}

}  // namespace sph
