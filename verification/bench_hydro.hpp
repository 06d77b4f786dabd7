#pragma once
// The hydro part of `sphv bench`: the force loop of the Sod scene's matched pair (26)/(42)
// with artificial viscosity, and a full kick-drift-kick step: as `evolve` takes it (Courant step,
// neighbour lists reused while they cover, sph/hydro.hpp), and with a fresh search every step.
#include <functional>
#include <random>

#include "sph/energy.hpp"
#include "sph/eos.hpp"
#include "sph/euler.hpp"
#include "sph/grid_search.hpp"
#include "sph/hydro_density.hpp"
#include "sph/hydro.hpp"
#include "sph/integrator.hpp"
#include "sph/viscosity.hpp"

namespace sphv {

// Floating-point operations of one force pair of the bench's scene, counted from the source (a
// division or square root counts as one, min/max and compares as none): the pair geometry (r_ij,
// nearest image, |r_ij|, h_ij; pairs.hpp, box.hpp) 26, grad W (kernel.hpp) 17, Euler (26) 12,
// energy (42) 12, viscosity (44)-(48) 32. That is 99 once the repeated subexpressions are computed
// once (the energy's P_ij is the Euler's; v_ij, v_ij . grad W and m_j / 2 are shared by the energy
// and the viscosity); 113 as written. The lower count keeps the share of peak from overstating.
constexpr double force_pair_flops = 99.0;

struct HydroTimes {
  double forces, step, step_fresh_search, pairs, bytes_per_particle, searches_per_step;
};

inline HydroTimes time_hydro_step(sph::Particles<3>& p, const sph::Box<3>& box,
                                  const std::function<double(const std::function<void()>&)>& timer) {
  using namespace sph;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 0.1);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.u[i] = 1.0;
    p.v[i] = Vec<3>(g(rng), g(rng), g(rng));  // random motion: about half the pairs approach (viscosity on)
  }
  using Forces = Scene<3, EquationOfState<3, IdealGas>, EulerSymmetric<3, Lambda2>, EnergySymmetric<3, Lambda2>,
                       ArtificialViscosity<3>>;
  using Step = Scene<3, SummationDensity<3>, EquationOfState<3, IdealGas>, EulerSymmetric<3, Lambda2>,
                     EnergySymmetric<3, Lambda2>, ArtificialViscosity<3>>;
  NeighbourList nl = grid_search<3>(p.x, p.h, box);
  density_summation<3>(p, nl, box);
  Derivatives<3> d;
  Forces forces;
  HydroTimes t{};
  t.pairs = static_cast<double>(nl.pairs());
  t.forces = timer([&] { forces.derivatives(p, Neighbourhood<3>{nl, box}, d); });
  Step step;
  auto derivs = [&](Particles<3>& q, Derivatives<3>& dd) {
    nl = grid_search<3>(q.x, q.h, box);
    step.derivatives(q, Neighbourhood<3>{nl, box}, dd);
  };
  derivs(p, d);
  t.step_fresh_search = timer([&] { kdk_leapfrog_step(p, d, 1e-4, derivs); });
  // As evolve steps: the Courant step of 9.3 and lists kept while they cover. Averaged over
  // `steps` steps so the searches are shared out as in a run.
  VerletList<3> lists(HydroControls{}.skin);
  auto reused = [&](Particles<3>& q, Derivatives<3>& dd) {
    step.derivatives(q, Neighbourhood<3>{lists.update(q.x, q.h, box), box}, dd);
  };
  reused(p, d);
  const auto& visc = step.term<ArtificialViscosity<3>>();
  constexpr int steps = 8;
  long taken = 0;
  auto run_steps = [&] {
    for (int k = 0; k < steps; ++k, ++taken)
      kdk_leapfrog_step(p, d, courant_time_step(p, d, visc.alpha, visc.beta, TimeStepControl{}), reused);
  };
  // Once untimed: above ~1e5 particles the timer runs the 8 steps once, and the first pass pays
  // one-time costs a run pays once (each thread's first touch of its list buffers): at N = 125,000
  // on 2 threads that made a step as evolve takes it slower than one with a search every step.
  run_steps();
  const long searches_before = lists.searches();
  taken = 0;
  t.step = timer(run_steps) / steps;
  t.searches_per_step = static_cast<double>(lists.searches() - searches_before) / static_cast<double>(taken);
  // Particle state (x, v: 6 doubles; m, rho, p, c, u, h: 6), derivatives (dv/dt: 3; du/dt,
  // drho/dt, dh/dt, mu_max: 4) and the KDK step's copy of them, neighbour list (one int per pair,
  // an offset and a place in the visiting order per particle).
  t.bytes_per_particle = (12 + 7 + 7) * 8.0 + 12.0 + 4.0 * t.pairs / p.size();
  return t;
}

}  // namespace sphv
