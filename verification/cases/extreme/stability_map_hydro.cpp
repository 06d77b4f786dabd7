// Case `stability_map_hydro`: a stability map of the hydro scheme on a gas at rest with a pressure
// jump (common/extreme_hydro.hpp): for a grid of (pressure ratio, Courant number C) each point runs the
// tube to t_end and is classed by its verdict: "stable", "stable, inaccurate" (L1(rho) against the
// exact Riemann solution more than twice the C = 0.1 run's), or "unstable" (the first step and
// particle where the state went bad, or the step budget).
#include <cmath>

#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::stability_map_hydro_case {
namespace {

const std::vector<double> ratios = {10.0, 1e2, 1e3, 1e4, 1e5};
const std::vector<double> courants = {0.1, 0.3, 0.6, 1.0, 1.5, 2.0, 3.0};

Result run(const Params& p) {
  const long n = p.integer("n");
  Result r;
  Series stable{"stable", {}, {}, "points"}, inaccurate{"stable, inaccurate (L1 > 2x the C = 0.1 run)", {}, {}, "points"},
      unstable{"unstable", {}, {}, "points"};
  nlohmann::json rows = nlohmann::json::array();
  long counts[3] = {0, 0, 0};
  for (double ratio : ratios) {
    const TubeProblem pr = extreme::pressure_jump(ratio);
    const reference::RiemannSolution exact(pr.left, pr.right, pr.gamma, pr.x0);
    double l1_ref = 0.0;
    double largest_stable = 0.0;
    for (double C : courants) {
      TubeMethod m;
      m.energy = p.text("energy");
      m.hfact = p.real("hfact");
      m.controls.step.C = C;
      m.controls.max_steps = p.integer("max_steps");
      const TubeRun run = simulate_tube<1>(pr, m, n);
      r.n_particles = run.x.size();
      int cls = 2;
      double l1 = -1.0;
      if (run.outcome.verdict == "ok") {
        l1 = extreme::tube_l1_rho(run, exact, pr.t_end, 0.0, 1.0);
        if (C == courants.front()) l1_ref = l1;
        cls = l1 <= 2.0 * l1_ref ? 0 : 1;
        largest_stable = C;
      }
      ++counts[cls];
      Series& s = cls == 0 ? stable : cls == 1 ? inaccurate : unstable;
      s.x.push_back(ratio), s.y.push_back(C);
      rows.push_back({{"p_ratio", ratio}, {"C", C}, {"class", s.label}, {"verdict", run.outcome.verdict},
                      {"steps", run.outcome.steps}, {"L1_rho", l1}});
    }
    r.extra["largest_stable_C_ratio_" + std::to_string(static_cast<long>(ratio))] = largest_stable;
  }
  r.extra["points"] = rows;
  r.verdict = "ok: " + std::to_string(counts[0]) + " stable, " + std::to_string(counts[1]) + " stable but inaccurate, " +
              std::to_string(counts[2]) + " unstable points";
  r.figures.push_back({"stability_map", "Stability map: gas at rest with a pressure jump, n = " + std::to_string(n),
                       "pressure ratio p_L / p_R", "Courant number C", "log", "log", {stable, inaccurate, unstable}});
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const std::string level = "n" + std::to_string(s.levels[k]);
    // Theory (Monaghan 1992): C ~ 0.3 is a safe Courant number at any pressure ratio. With
    // energy (38) every point at C <= 0.3 must be stable. With (41) (auto) u goes negative in the
    // first step at ratio 1e5 for every C (measured): that is the energy form, not the step, so
    // the gate there covers ratios up to 1e4.
    const bool form41 = s.runs[k].params["energy"] == "auto";
    double bad = 0.0;
    for (const auto& row : s.runs[k].extra["points"])
      if (row["C"].get<double>() <= 0.3 && row["verdict"] != "ok" && !(form41 && row["p_ratio"].get<double>() > 1e4)) ++bad;
    c.push_back({level + "_unstable_at_safe_C", bad, 0.0, 0.0, "C <= 0.3 is the safe Courant number"});
  }
  return c;
}

const Registration reg{Case{
    .name = "stability_map_hydro",
    .summary = "stability map of SPH hydro: verdict over (pressure ratio, Courant number) for a gas at rest with a pressure jump",
    .n_counts = "particles per unit length",
    .tags = {"gate", "extreme"},
    .params = {integer_param("n", 100, "particles per unit length"),
               choice_param("energy", "38", "energy form with Euler (23): (38), or auto = (41)", {"38", "auto"}),
               real_param("hfact", 2.4, "support radius / spacing", 0.0),
               integer_param("max_steps", 20000, "step budget per point (ends with a verdict)")},
    .levels = {.quick = {100}, .standard = {100, 200}, .full = {100, 200}},
    .orders = [](const Params&) { return OrderClaims{}; },  // no convergence: a map of verdicts per resolution: no errors, only verdicts and bounds
    .variants = {{}, {"energy=auto"}},
    .validate = {},
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::stability_map_hydro_case
