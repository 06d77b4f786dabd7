#pragma once
// The hydro part of `sphv bench`, for the scheme named (sph/schemes/; the chapter's by default, the
// one the blast cases verify), with its default forms: its force loop, and a full kick-drift-kick
// step: `evolve`'s own (the scheme's phases and time step, neighbour lists reused while they cover,
// sph/hydro/evolve.hpp) with its phases, and with a fresh search every step; and evolve's step from
// the particles stored in a random order, with and without its reordering of them
// (sph/hydro/storage_order.hpp).
#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <omp.h>

#include "sph/core/verdict.hpp"
#include "sph/density/summation.hpp"
#include "sph/hydro/evolve.hpp"
#include "sph/schemes/schemes.hpp"
#include "sph/search/grid_search.hpp"
#include "sph/time/leapfrog.hpp"

namespace sphv {

// Floating-point operations of one force pair of the chapter's scheme (sph/schemes/chapter.hpp),
// counted from the source (a division or square root counts as one, min/max and compares as none):
// the pair geometry (r_ij, nearest image, |r_ij|, h_ij; sph/hydro/pairs.hpp, sph/core/box.hpp) 26,
// grad W (sph/kernel/cubic_spline.hpp) 17, Euler (23) 10, energy (38) 12, viscosity (44)-(48) 33.
// That is 98 once the repeated subexpressions are computed once (rho_i rho_j is the Euler's and the
// energy's; v_ij and v_ij . grad W are shared by the energy and the viscosity); 107 as written. The
// lower count keeps the share of peak from overstating. Another scheme's share is not shown.
constexpr double force_pair_flops = 98.0;
constexpr const char* force_pair_flops_scheme = "chapter";

// The steps over which the full step is timed (time_hydro_step).
constexpr long full_step_window = 32;

// A run's time in parts, measured by the run itself (evolve's steps; one part: the run whole). A
// stage's time on each of the thread counts benchmarked, in their order: each part's least over a
// few runs, summed (verification/commands/bench.cpp: the thread counts take turns run by run).
using Parts = std::vector<double>;
using Times = std::vector<double>;
using Timer = std::function<Times(const std::function<Parts()>&)>;

// f's run as one part.
inline std::function<Parts()> whole(std::function<void()> f) {
  return [f = std::move(f)] {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return Parts{std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
  };
}

// The full step's phases (sph::StepPhases) on each thread count timed, by count: each phase of each
// step at its least over the runs, summed over the window and divided by it, as the step is.
using PhaseTimes = std::map<int, sph::StepPhases>;

struct HydroTimes {
  Times forces, step, step_fresh_search;
  PhaseTimes phases;
  double pairs, bytes_per_particle, searches_per_step;
};

// f(scheme) for the bench's gas (gamma 1.4; the lattice's h = 2.4 dx is (50)'s hfact): the scheme
// named, with the cubic spline and its default forms.
template <class F>
void with_bench_scheme(const std::string& scheme, F&& f) {
  sph::SchemeOptions o;
  o.gamma = 1.4;
  sph::with_default_scheme<3, sph::CubicSpline<3>>(scheme, o, std::forward<F>(f));
}

// A step as evolve takes it (sph/schemes/scheme.hpp: the scheme's phases and time step, lists reused
// while they cover, the particles stored in the search's cell order, the verdict's check), from the
// state p: evolve itself, run for 1 + full_step_window steps, each step after the first timed by
// its `stepped` hook (which only reads the clock, so evolve still reorders). The first step, with
// the start (first evaluation, search and reordering), is left out. The window spans several reuses
// of a list: with 8 steps it held 3 searches at the skin of 0.1 (0.38 a step, against 0.28 over 40
// steps) and the step came out 8 % too slow (N = 125,000, one thread). Each step's least over the
// runs: the runs repeat the same steps bit for bit, and the host's slow spells (seconds long, one
// core or both, up to 1.5x) only add time, so a step slowed in one run counts at its time in
// another. The least of whole runs (12-22 s each at N = 1e6) kept a spell that fell somewhere in
// every one: two threads' speed-up of the step at N = 1e6 came out 1.63-1.84x over six benches;
// with each step's least 1.81x, 1.90x and 1.81x, and 1.73x and 1.71x in two benches while the host
// was slow throughout (two cores' FMA peak 1.83x one's; a canary 10-40 % slow after); 1.80-1.97x in
// a driver's quiet minutes.
// The runs are timed after an untimed one that pays the process's first touch of the buffers (a
// cold first run took 1.03 s against 0.52 s warm at N = 125,000 on one thread). Each step's phases
// are timed by evolve's `timed` hook and taken likewise, each at its least over the runs (so their
// sum may fall a little short of the step's). Returns the step's time and the searches a step, and
// the phases if asked for.
struct EvolveStepTimes {
  Times step;
  double searches_per_step;
  PhaseTimes phases;
};
inline EvolveStepTimes time_evolve_step(const std::string& scheme, const sph::Particles<3>& p, const sph::Box<3>& box,
                                        const Timer& timer, long reorder_every = sph::HydroControls{}.reorder_every) {
  using namespace sph;
  using Clock = std::chrono::steady_clock;
  HydroControls run;
  run.t_end = 1e30;  // ended by the step budget
  run.reorder_every = reorder_every;
  auto evolve_for = [&](long steps, const HydroHooks<3>& hooks) {  // returns the searches made
    run.max_steps = steps;
    Particles<3> q = p;
    HydroOutcome out;
    with_bench_scheme(scheme, [&](auto& s) { out = evolve(s, q, box, run, hooks); });
    // The budget ends the run with its verdict; a state gone bad on the last step also has
    // steps == budget, so the particles are checked as well.
    if (out.steps != steps || first_bad(q)) throw std::runtime_error("bench: the uniform gas went bad: " + out.verdict);
    return out.searches;
  };
  const long at_start = evolve_for(1, {});  // untimed; the searches of the first step
  long searches = 0;  // the same in every run
  std::map<int, std::vector<StepPhases>> least;  // by thread count: each step's phases at their least
  const Times t = timer([&] {
    std::vector<Clock::time_point> stepped;
    std::vector<StepPhases> phases;
    stepped.reserve(1 + full_step_window);
    phases.reserve(1 + full_step_window);
    HydroHooks<3> clock;
    clock.stepped = [&](const Particles<3>&, const Derivatives<3>&, long, double) { stepped.push_back(Clock::now()); };
    clock.timed = [&](const StepPhases& ph) { phases.push_back(ph); };
    clock.index_free = true;
    searches = evolve_for(1 + full_step_window, clock);
    Parts steps(full_step_window);
    for (long k = 0; k < full_step_window; ++k)
      steps[k] = std::chrono::duration<double>(stepped[k + 1] - stepped[k]).count();
    // Step k + 1's phases are those of the time between stepped[k] and stepped[k + 1].
    auto [at, fresh] = least.try_emplace(omp_get_max_threads(), phases.begin() + 1, phases.end());
    if (!fresh)
      for (long k = 0; k < full_step_window; ++k) {
        StepPhases& a = at->second[k];
        const StepPhases& b = phases[k + 1];
        a = {std::min(a.search, b.search),         std::min(a.density, b.density), std::min(a.forces, b.forces),
             std::min(a.time_step, b.time_step),   std::min(a.reorder, b.reorder), std::min(a.kick_drift, b.kick_drift),
             std::min(a.check, b.check)};
      }
    return steps;
  });
  EvolveStepTimes out{Times(t.size()), static_cast<double>(searches - at_start) / full_step_window, {}};
  for (std::size_t k = 0; k < t.size(); ++k) out.step[k] = t[k] / full_step_window;
  for (const auto& [threads, steps] : least) {
    StepPhases& sum = out.phases[threads];
    for (const StepPhases& ph : steps) {
      sum.search += ph.search / full_step_window, sum.density += ph.density / full_step_window;
      sum.forces += ph.forces / full_step_window, sum.time_step += ph.time_step / full_step_window;
      sum.reorder += ph.reorder / full_step_window, sum.kick_drift += ph.kick_drift / full_step_window;
      sum.check += ph.check / full_step_window;
    }
  }
  return out;
}

// The particles of p stored in a random order, as a snapshot of another code may hold them.
inline sph::Particles<3> shuffled(const sph::Particles<3>& p) {
  std::vector<std::size_t> at(p.size());
  std::iota(at.begin(), at.end(), 0);
  std::shuffle(at.begin(), at.end(), std::mt19937_64(11));
  sph::Particles<3> q = p;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const std::size_t i = at[k];
    q.x[k] = p.x[i], q.v[k] = p.v[i], q.m[k] = p.m[i], q.rho[k] = p.rho[i];
    q.p[k] = p.p[i], q.c[k] = p.c[i], q.u[k] = p.u[i], q.h[k] = p.h[i];
  }
  return q;
}

inline HydroTimes time_hydro_step(const std::string& scheme, sph::Particles<3>& p, const sph::Box<3>& box,
                                  const Timer& timer) {
  using namespace sph;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 0.1);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.u[i] = 1.0;
    p.v[i] = Vec<3>(g(rng), g(rng), g(rng));  // random motion: about half the pairs approach (viscosity on)
  }
  NeighbourList nl = grid_search<3>(p.x, p.h, box);
  density_summation<3>(p, nl, box);
  Derivatives<3> d, at_t;
  HydroTimes t{};
  t.pairs = static_cast<double>(nl.pairs());
  with_bench_scheme(scheme, [&](auto& s) {
    // The force loop alone, at a state the scheme's start and density phase have set (the force
    // loop reads what they set: h and rho, and the grad-h scheme's Omega and alpha), on the pairs
    // that phase selected.
    s.start(p, box);
    VerletList<3> lists(HydroControls{}.skin);
    const NeighbourList& pairs = lists.update(p.x, p.h, box);
    s.density(p, Neighbourhood<3>{pairs, box, &lists});
    t.forces = timer(whole([&] { s.force(p, Neighbourhood<3>{pairs, box}, d); }));
    // The scheme's step, its rates on lists searched afresh at every evaluation (with evolve's skin,
    // within which a density phase may set h), their buffers kept as evolve's are: fresh ones fault
    // pages in every step.
    VerletList<3> fresh(HydroControls{}.skin);
    auto derivs = [&](Particles<3>& q, Derivatives<3>& dd) {
      fresh.expire();
      const Neighbourhood<3> nb{fresh.update(q.x, q.h, box), box, &fresh};
      s.density(q, nb);
      s.force(q, nb, dd);
    };
    derivs(p, d);
    t.step_fresh_search = timer(whole([&] { kdk_leapfrog_step(p, d, at_t, 1e-4, derivs); }));
  });
  EvolveStepTimes e = time_evolve_step(scheme, p, box, timer);
  t.step = e.step, t.searches_per_step = e.searches_per_step, t.phases = std::move(e.phases);
  // Particle state (x, v: 6 doubles; m, rho, p, c, u, h: 6), derivatives (dv/dt: 3; du/dt,
  // drho/dt, dh/dt, mu_max: 4) and the KDK step's scratch of them, the rates' neighbour list (one
  // int per pair, an offset and a place in the visiting order per particle).
  t.bytes_per_particle = (12 + 7 + 7) * 8.0 + 12.0 + 4.0 * t.pairs / p.size();
  return t;
}

}  // namespace sphv
