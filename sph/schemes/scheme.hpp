#pragma once
// What a scheme is, and evolve for one. A scheme (one header each under sph/schemes/, listed by
// name in schemes.hpp) is the whole method of a hydro run: its kernel (a template parameter), the
// fields its loops write and the rates it returns (Derivatives), and its phases by the moment they
// run, each a member function of that name:
//   start(p, box)           once, before the first step (e.g. the initial smoothing lengths)
//   density(p, nb)          the density loop, at every evaluation of the rates (it may set h, and
//                           then selects nb.list anew from nb.lists for the force loop)
//   force(p, nb, d)         then the force loop: the rates d
//   time_step(p, d, c)      the scheme's time-step rule at a state with its rates
//   stepped(p, t)           optional: after every step, at its end time t (a state the scheme
//                           advances once a step, outside the integrator: a viscosity switch)
// and `static constexpr bool reorderable`: false when it keeps arrays over the particles
// (HydroControls::reorder_every). A reader counts the neighbour loops of a step from the phases.
#include <concepts>
#include <stdexcept>
#include <string>

#include "sph/hydro/evolve.hpp"

namespace sph {

// The options every scheme reads; a scheme rejects (std::invalid_argument) a choice it lacks.
// hmode: how h is set (9.4.4): "iterate50", (50) solved with the density in every density phase;
// "rate53", h integrated by (53); "fixed", the initial h kept. energy: the energy form's equation.
struct SchemeOptions {
  double gamma = 5.0 / 3.0;
  double alpha = 1.0, beta = 2.0;  // artificial viscosity (45)
  double alpha_u = 1.0;            // artificial conduction (Price 2008), in the schemes that have it
  std::string vsig_u = "pressure";  // its signal velocity: "pressure" (Price 2008) or "velocity"
  double hfact = 2.4;              // (50)
  double h_max = 1e300;            // (50)'s cap (density/fixed_neighbours.hpp)
  std::string hmode = "iterate50";
  std::string energy = "38";
};

template <class S>
concept HydroScheme = requires(S& s, Particles<S::dim>& p, const Box<S::dim>& box, const Neighbourhood<S::dim>& nb,
                               Derivatives<S::dim>& d, const TimeStepControl& c) {
  s.start(p, box);
  s.density(p, nb);
  s.force(p, nb, d);
  { s.time_step(p, d, c) } -> std::convertible_to<double>;
  { S::reorderable } -> std::convertible_to<bool>;
};

// Advances the particles by the scheme s to c.t_end: start, then for every evaluation of the rates
// the density and the force phase, after every step the caller's constrain hook, and s's time
// step. Ends with "ok", or with the first step and particle where the state went bad, or with the
// step budget exhausted; never throws on a blow-up (a start that fails ends the run with its
// verdict).
template <HydroScheme S, int D = S::dim>
HydroOutcome evolve(S& s, Particles<D>& p, const Box<D>& box, const HydroControls& c, const HydroHooks<D>& hooks = {}) {
  try {
    s.start(p, box);
  } catch (const std::invalid_argument& e) {
    return {0, 0.0, std::string("unstable: ") + e.what()};
  }
  auto density = [&](Particles<D>& q, const Neighbourhood<D>& nb) { s.density(q, nb); };
  auto force = [&](Particles<D>& q, const Neighbourhood<D>& nb, Derivatives<D>& d) { s.force(q, nb, d); };
  auto time_step = [&](const Particles<D>& q, const Derivatives<D>& d) { return s.time_step(q, d, c.step); };
  if constexpr (requires(const Particles<D>& q) { s.stepped(q, 0.0); }) {
    HydroHooks<D> with_stepped = hooks;
    with_stepped.stepped = [&s, &hooks](const Particles<D>& q, const Derivatives<D>& d, long step, double t) {
      s.stepped(q, t);
      if (hooks.stepped) hooks.stepped(q, d, step, t);
    };
    return evolve_rates<D>(density, force, time_step, p, box, c, with_stepped, S::reorderable);
  }
  return evolve_rates<D>(density, force, time_step, p, box, c, hooks, S::reorderable);
}

}  // namespace sph
