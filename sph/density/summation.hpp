#pragma once
#include "sph/core/particles.hpp"
#include "sph/hydro/pairs.hpp"
#include "sph/kernel/cubic_spline.hpp"

namespace sph {

// Density by summation, eq (27): rho_i = sum_j m_j W_ij, including the self term m_i W_ii
// (the self-density (49) is its floor).
// xs: a buffer for the positions' columns that a caller summing at every step keeps (see
// Scene::xs, hydro/scene.hpp). K: the kernel (sph/kernel/kernels.hpp).
template <int D, class K = CubicSpline<D>>
void density_summation(Particles<D>& p, const NeighbourList& nl, const Box<D>& box, Components<D>& xs) {
  sum_weights_over_pairs<D>(
      p.x, p.h, nl, box, xs, [&](int j, double r, double h) { return p.m[j] * K::W(r, h); },
      [&](std::size_t i, double rho) { p.rho[i] = p.m[i] * K::W(0.0, p.h[i]) + rho; });
}
template <int D, class K = CubicSpline<D>>
void density_summation(Particles<D>& p, const NeighbourList& nl, const Box<D>& box) {
  Components<D> xs;
  density_summation<D, K>(p, nl, box, xs);
}

// Compiled once, in sph/density/summation.cpp, instead of in each of the ~11 files whose scenes
// sum the density: its pair loop in two instruction-set copies. Another kernel's is compiled where
// a scene selects it.
extern template void density_summation<1>(Particles<1>&, const NeighbourList&, const Box<1>&, Components<1>&);
extern template void density_summation<2>(Particles<2>&, const NeighbourList&, const Box<2>&, Components<2>&);
extern template void density_summation<3>(Particles<3>&, const NeighbourList&, const Box<3>&, Components<3>&);

}  // namespace sph
