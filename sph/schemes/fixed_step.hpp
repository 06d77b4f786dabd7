#pragma once
// A scheme run at a fixed time step: the phases of scheme S (scheme.hpp) with its time-step rule
// replaced by dt, so that an error of the time integration can be measured against dt (the
// conservation cases, the tests of a scheme's conservation).
#include "sph/schemes/scheme.hpp"

namespace sph {

template <HydroScheme S>
struct FixedStep {
  static constexpr int dim = S::dim;
  static constexpr bool reorderable = S::reorderable;
  S& scheme;
  double dt;

  void start(Particles<dim>& p, const Box<dim>& box) { scheme.start(p, box); }
  void density(Particles<dim>& p, const Neighbourhood<dim>& nb) { scheme.density(p, nb); }
  void force(Particles<dim>& p, const Neighbourhood<dim>& nb, Derivatives<dim>& d) { scheme.force(p, nb, d); }
  double time_step(const Particles<dim>&, const Derivatives<dim>&, const TimeStepControl&) const { return dt; }
  // S's own stepped phase, where it has one.
  void stepped(const Particles<dim>& p, double t) {
    if constexpr (requires { scheme.stepped(p, t); }) scheme.stepped(p, t);
  }
};

}  // namespace sph
