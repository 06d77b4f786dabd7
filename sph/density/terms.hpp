#pragma once
#include "sph/density/summation.hpp"
#include "sph/hydro/scene.hpp"

namespace sph {

// Density methods of 9.2 as scene terms. List the density term first: the equation of state
// and the force terms read rho.

// Summation (27) with the kernel K, recomputed from the positions before every pair loop. The
// scene's pair loop takes its grad W from the same K (Scene::Kernel).
template <int D, class K = CubicSpline<D>>
struct SummationDensity {
  using kernel = K;
  Components<D> xs;  // the positions' columns, kept (Scene::xs)
  void prepare(Particles<D>& p, const Neighbourhood<D>& nb) { density_summation<D, K>(p, nb.list, nb.box, xs); }
};

// Continuity equation: rho is evolved by the integrator from drho/dt.
enum class ContinuityForm { direct29, difference33 };

template <int D, ContinuityForm F>
struct ContinuityDensity {
  static constexpr Writes writes{.drhodt = true};
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& q) const {
    if constexpr (F == ContinuityForm::direct29)
      s.drhodt -= p.m[q.j] * q.vj.dot(q.gradW);  // (29)
    else
      s.drhodt -= p.m[q.j] * (q.vj - q.vi).dot(q.gradW);  // (33)
  }
};

}  // namespace sph
