#pragma once
// Shock tubes (case sod and its 2D/3D versions): the problem, the SPH method chosen at run
// time, and the simulation, instantiated once per dimension (shock_tubes/tube_scenes_1d.cpp, ...).
#include <string>
#include <vector>

#include "reference/riemann.hpp"
#include "sph/hydro/evolve.hpp"

namespace sphv {

// A Riemann problem at x0 on the tube [x_lo, x_hi] (sphv run: Toro's [0, 1]), ideal gas. The
// ends (sphv score): "open" (the domain is a window of an unbounded tube: sphv run's layout, codes
// with boundary layers held at the end states), "periodic" (a periodic box: a second interface at
// its wrap x_lo = x_hi, the states the other way round, as SWIFT's Sod tube) or "closed" (walls or
// free ends).
struct TubeProblem {
  reference::GasState left, right;
  double gamma, x0, t_end;
  double x_lo = 0.0, x_hi = 1.0;
  std::string ends = "open";
};

// The method: every runtime choice of 9.2-9.4.2, dispatched once to a scene type.
struct TubeMethod {
  std::string density = "summation";  // summation (27) | continuity29 | continuity33
  std::string euler = "23";           // 22 | 23 | 25 | 26
  std::string energy = "auto";        // auto (the Euler form's partner) | 37 | 38 | 40 | 41 | 42
  double lambda = 1.5;                // for (25)
  double hfact = 2.4;                 // initial support radius / particle spacing, (50)
  std::string kernel = "cubic_spline";  // sph/kernel/kernels.hpp; others: 1D, the default forms only
  // forms: the scene of the forms above, h by (53); or a scheme of the registry by name
  // (sph/schemes/), its default forms and h rule, with hfact, alpha, beta.
  std::string scheme = "forms";
  double alpha = 1.0, beta = 2.0, eps = 0.01, h_scale = 0.5;  // artificial viscosity (45), (46)
  sph::HydroControls controls;
};

// Final particle state reduced to the tube's axis, plus the run's diagnostics. Particles
// [0, active) are evolved; the rest are the boundary layers held at the initial state.
struct TubeRun {
  std::vector<double> x, v, rho, p, u, m, h;
  std::vector<std::vector<double>> position;  // all coordinates, for particles.csv
  std::size_t active = 0;
  sph::HydroOutcome outcome;
  double box_lo = 0.0, box_hi = 1.0, width = 0.0;  // x extent of the active particles at t = 0, periodic width
  double momentum_drift = 0.0;     // max_t |P(t) - P(0)| / max_t sum m |v|
  double energy_drift = 0.0;       // |E(t_end) - E(0)| / E(0)
  double energy_rate = 0.0;        // max_t |dE/dt| / rate scale (96)
  double mass_drift = 0.0;         // |M(t) - M(0)| / M(0)
  double first_dt = 0.0;           // the first step the integrator took (0: none)
};

template <int D>
TubeRun simulate_tube(const TubeProblem& pr, const TubeMethod& m, long n);

// The 1D tube with a kernel other than the cubic spline (shock_tubes/tube_scenes_kernels_1d.cpp: their scenes
// compile in a unit of their own).
TubeRun simulate_tube_other_kernel(const TubeProblem& pr, const TubeMethod& m, long n);

extern template TubeRun simulate_tube<1>(const TubeProblem&, const TubeMethod&, long);
extern template TubeRun simulate_tube<2>(const TubeProblem&, const TubeMethod&, long);
extern template TubeRun simulate_tube<3>(const TubeProblem&, const TubeMethod&, long);

}  // namespace sphv
