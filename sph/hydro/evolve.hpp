#pragma once
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "sph/core/verdict.hpp"
#include "sph/hydro/storage_order.hpp"
#include "sph/hydro/viscosity.hpp"
#include "sph/search/verlet_list.hpp"
#include "sph/time/leapfrog.hpp"
#include "sph/time/timestep.hpp"

namespace sph {

// Time evolution of a hydrodynamic scene (9.3): neighbour lists for the particles' current
// support radii (a scene term may evolve them, see density/variable_h.hpp), reused across
// steps while they cover them (search/verlet_list.hpp); the scene's derivatives, an integrator of
// 9.3.2 and a time-step criterion, with a verdict.

enum class IntegratorKind { kdk, chapter };

struct HydroControls {
  IntegratorKind integrator = IntegratorKind::kdk;
  TimeStepControl step;
  double t_end = 0.2;
  long max_steps = 1000000;
  // Neighbour lists padded by this fraction of h, reused while they cover (search/verlet_list.hpp).
  // A wider skin searches less often but lists and filters more pairs at every step; the step is
  // about as fast at 0.2 as at 0.3, and 0.2 keeps the lists shorter.
  double skin = 0.2;
  // The particles stored in the search's cell order (hydro/storage_order.hpp) at the first search,
  // then at the first search this many steps after the last reordering (0: never). As particles
  // move, neighbours' storage drifts apart and the pair loops' gathers slow down. A reordering
  // costs a fraction of a step (mostly renumbering the lists): 8 reorders at every search of a gas
  // that searches every ten steps or so, and costs little in a run that searches at every step.
  // Only in a run without hooks, or with hooks that are index_free (others may address particles
  // by index), of a scene that keeps no arrays over the particles. The particles are returned in
  // the caller's order; the renumbered lists hold the same pairs in the same order, so the results
  // are the same until the next search, whose lists may order a particle's neighbours otherwise
  // (a change at round-off).
  long reorder_every = 8;
};

struct HydroOutcome {
  long steps = 0;
  double t = 0.0;
  std::string verdict = "ok";
  long searches = 0;  // neighbour searches made (the lists serve while they cover, search/verlet_list.hpp)
  long reorders = 0;  // times the particles were stored anew in the search's cell order (HydroControls)
};

// Total mass, momentum and energy sum_i m_i (v_i^2 / 2 + u_i) of particles [first, last), and
// the rate (96) dE/dt = sum_i m_i (v_i . dv_i/dt + du_i/dt) with the scale
// sum_i m_i (|v_i . dv_i/dt| + |du_i/dt|) that its round-off is measured against.
template <int D>
struct Totals {
  double mass = 0.0, energy = 0.0, energy_rate = 0.0, rate_scale = 0.0, momentum_scale = 0.0;
  Vec<D> momentum = Vec<D>::Zero();
};
template <int D>
Totals<D> totals(const Particles<D>& p, const Derivatives<D>& d, std::size_t first, std::size_t last) {
  Totals<D> t;
  for (std::size_t i = first; i < last; ++i) {
    t.mass += p.m[i];
    t.momentum += p.m[i] * p.v[i];
    t.momentum_scale += p.m[i] * p.v[i].norm();
    t.energy += p.m[i] * (0.5 * p.v[i].squaredNorm() + p.u[i]);
    const double kin = p.v[i].dot(d.dvdt[i]);
    t.energy_rate += p.m[i] * (kin + d.dudt[i]);
    t.rate_scale += p.m[i] * (std::abs(kin) + std::abs(d.dudt[i]));
  }
  return t;
}

// The wall time of a step by phase, in seconds (`sphv bench` shows it): the neighbour lists
// (the covers test, a search when they no longer cover, the pairs selected, search/verlet_list.hpp),
// the density phase without its lists (a scheme's density loop with its h iteration), the force
// loop (a bare scene's derivatives whole), the time step, the particles' reordering, the
// integrator's kicks and drifts (the step less its evaluations), and the state's check for the
// verdict with the caller's hooks. Together they are the step.
struct StepPhases {
  double search = 0.0, density = 0.0, forces = 0.0, time_step = 0.0, reorder = 0.0, kick_drift = 0.0, check = 0.0;
  double total() const { return search + density + forces + time_step + reorder + kick_drift + check; }
};

// Optional hooks of a run: `constrain` imposes prescribed particles (e.g. boundary layers
// held at a known state) after every step; `evaluated` sees every derivative evaluation with
// the state it belongs to; `stepped` sees the state after every step (step count, time); `timed`
// sees each step's StepPhases, after `stepped` (whose time it counts in the step's check).
// index_free: the hooks treat every particle alike, whatever its index (sums over all of them),
// so evolve may store the particles in its own order (HydroControls::reorder_every), in which the
// hooks then see them. `timed` reads no particle and leaves the order free.
template <int D>
struct HydroHooks {
  std::function<void(Particles<D>&, double)> constrain;
  std::function<void(const Particles<D>&, const Derivatives<D>&)> evaluated;
  std::function<void(const Particles<D>&, const Derivatives<D>&, long, double)> stepped;
  std::function<void(const StepPhases&)> timed;
  bool index_free = false;
  bool none() const { return !constrain && !evaluated && !stepped; }
};

// A scheme's density phase at a state with its neighbourhood (empty for a bare scene); the rates
// of a scene at a state with its neighbourhood, and its time-step rule at a state with its rates:
// all that evolve needs of a scene or a scheme.
template <int D>
using DensityPhase = std::function<void(Particles<D>&, const Neighbourhood<D>&)>;
template <int D>
using SceneRates = std::function<void(Particles<D>&, const Neighbourhood<D>&, Derivatives<D>&)>;
template <int D>
using TimeStepRule = std::function<double(const Particles<D>&, const Derivatives<D>&)>;

// The time step of TimeStepControl's criterion: the Courant condition with the viscosity's alpha and
// beta in its signal speed (0 without viscosity), or (43).
template <int D>
double hydro_time_step(const Particles<D>& p, const Derivatives<D>& d, double alpha, double beta,
                       const TimeStepControl& c) {
  return c.criterion == TimeStepCriterion::courant ? courant_time_step(p, d, alpha, beta, c) : chapter_time_step(p, c);
}

// evolve's loop, behind DensityPhase, SceneRates and TimeStepRule: compiled once per dimension, not
// once per scene type (a case choosing among 72 scenes would otherwise compile 72 copies of the
// integrators and this loop). An evaluation: the lists for the particles' h, the density phase (which
// may set h and select the pairs anew, Neighbourhood::lists), the rates. reorderable: the scene keeps
// no arrays over the particles (HydroControls::reorder_every).
template <int D>
HydroOutcome evolve_rates(const DensityPhase<D>& density, const SceneRates<D>& rates, const TimeStepRule<D>& time_step,
                          Particles<D>& p, const Box<D>& box, const HydroControls& c, const HydroHooks<D>& hooks,
                          bool reorderable) {
  using Clock = std::chrono::steady_clock;
  Derivatives<D> d, at_t;  // at_t: the KDK step's scratch
  HydroOutcome out;
  VerletList<D> lists(c.skin);
  StorageOrder<D> storage;
  const bool reorder = c.reorder_every > 0 && reorderable && (hooks.index_free || hooks.none());
  long reordered_at = 0, searched = 0;  // the step of the last reordering, and the searches made by then
  // The clock is read only for a `timed` hook; the lists keep their own time.
  const bool timing = static_cast<bool>(hooks.timed);
  StepPhases phase;
  double evaluating = 0.0;  // the step's time in derivs
  auto now = [&] { return timing ? Clock::now() : Clock::time_point{}; };
  auto since = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  auto derivs = [&](Particles<D>& q, Derivatives<D>& dd) {
    const auto t0 = now();
    const double listed = lists.seconds();
    const Neighbourhood<D> nb{lists.update(q.x, q.h, box), box, &lists};
    const double updated = lists.seconds();
    const auto t1 = now();
    if (density) density(q, nb);
    const auto t2 = now();
    rates(q, nb, dd);
    if (timing) {
      const double in_density = lists.seconds() - updated;
      phase.search += lists.seconds() - listed;
      phase.density += std::chrono::duration<double>(t2 - t1).count() - in_density;
      phase.forces += since(t2);
      evaluating += since(t0);
    }
    if (hooks.evaluated) hooks.evaluated(q, dd);
  };
  auto ended = [&] {
    out.searches = lists.searches();
    storage.restore(p);
    return out;
  };
  auto unstable = [&] {  // named by the caller's index: the lowest bad one
    storage.restore(p);
    out.verdict = unstable_verdict(out.steps, out.t, *first_bad(p));
    return ended();
  };
  auto bad_state = [&](const std::string& what) {
    out.verdict = "unstable: step " + std::to_string(out.steps) + " (t = " + std::to_string(out.t) + "): " + what;
    return ended();
  };
  try {
    if (auto b = first_bad(p)) return bad_state("initial state, particle " + std::to_string(b->particle) + ": " + b->what);
    derivs(p, d);
    while (out.t < c.t_end) {
      if (out.steps >= c.max_steps)
        return bad_state("step budget of " + std::to_string(c.max_steps) + " steps exhausted before t_end");
      phase = {}, evaluating = 0.0;
      const auto t0 = now();
      if (reorder && lists.searches() > searched && (searched == 0 || out.steps - reordered_at >= c.reorder_every)) {
        storage.apply(lists.renumber_in_visiting_order(), p, d);
        reordered_at = out.steps, searched = lists.searches(), ++out.reorders;
      }
      const auto t1 = now();
      double dt = time_step(p, d);
      if (!(dt > 0.0) || !std::isfinite(dt)) return bad_state("time step not positive and finite");
      dt = std::min(dt, c.t_end - out.t);
      const auto t2 = now();
      if (c.integrator == IntegratorKind::kdk) kdk_leapfrog_step(p, d, at_t, dt, derivs);
      else chapter_leapfrog_step(p, d, dt, derivs);
      const auto t3 = now();
      ++out.steps;
      out.t = (c.t_end - out.t <= dt) ? c.t_end : out.t + dt;
      if (hooks.constrain) hooks.constrain(p, out.t);
      if (first_bad(p)) return unstable();
      if (hooks.stepped) hooks.stepped(p, d, out.steps, out.t);
      if (timing) {
        phase.reorder = std::chrono::duration<double>(t1 - t0).count();
        phase.time_step = std::chrono::duration<double>(t2 - t1).count();
        phase.kick_drift = std::chrono::duration<double>(t3 - t2).count() - evaluating;
        phase.check = since(t3);
        hooks.timed(phase);
      }
    }
  } catch (const std::invalid_argument& e) {  // e.g. a support radius grown beyond a periodic box
    return bad_state(e.what());
  }
  return ended();
}

// Advances the particles of a bare scene (one that is not a scheme, sph/schemes/) to c.t_end: its
// rates are the scene's derivatives, its time step hydro_time_step's with the ArtificialViscosity
// the scene lists, if any. Ends with "ok", or with the first step and particle where the state went
// bad, or with the step budget exhausted; never throws on a blow-up.
template <int D, class... Terms>
HydroOutcome evolve(Scene<D, Terms...>& scene, Particles<D>& p, const Box<D>& box, const HydroControls& c,
                    const HydroHooks<D>& hooks = {}) {
  double alpha = 0.0, beta = 0.0;
  if constexpr ((std::is_same_v<Terms, ArtificialViscosity<D>> || ...)) {
    const auto& visc = scene.template term<ArtificialViscosity<D>>();
    alpha = visc.alpha, beta = visc.beta;
  }
  auto rates = [&](Particles<D>& q, const Neighbourhood<D>& nb, Derivatives<D>& d) { scene.derivatives(q, nb, d); };
  auto time_step = [&](const Particles<D>& q, const Derivatives<D>& d) {
    return hydro_time_step(q, d, alpha, beta, c.step);
  };
  return evolve_rates<D>({}, rates, time_step, p, box, c, hooks, !(keeps_particle_arrays<Terms> || ...));
}

}  // namespace sph
