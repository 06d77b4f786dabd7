#pragma once
#include "sph/density/summation.hpp"
#include "sph/hydro/scene.hpp"

namespace sph {

// Density methods of 9.2 as scene terms. List the density term first: the equation of state
// and the force terms read rho.

// Summation (27), recomputed from the positions before every pair loop.
template <int D>
struct SummationDensity {
  Components<D> xs;  // the positions' columns, kept (Scene::xs)
  void prepare(Particles<D>& p, const Neighbourhood<D>& nb) { density_summation<D>(p, nb.list, nb.box, xs); }
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
