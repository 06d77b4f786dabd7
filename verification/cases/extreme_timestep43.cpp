// Case `extreme_timestep43`: the chapter's time step (43), dt = eta h / max|v| and dt = eta^2 for
// a gas at rest, on a gas at rest with a pressure jump (density 1, gamma 1.4, pressures
// p_ratio : 1). (43) ignores the sound speed, so its first step is eta^2 whatever the resolution
// and the sound speed; the safe criterion (Monaghan's signal-speed Courant condition with the
// acceleration criterion, errata) takes C (h/2) / (c (1 + 1.2 alpha)). Both runs are made; the
// independent reference is the exact Riemann solution.
#include <cmath>

#include "verification/case.hpp"
#include "verification/cases/extreme_hydro.hpp"
#include "verification/sweep.hpp"

namespace sphv {
namespace {

Result run(const Params& p) {
  const TubeProblem pr = extreme::pressure_jump(p.real("p_ratio"));
  const reference::RiemannSolution exact(pr.left, pr.right, pr.gamma, pr.x0);
  const long n = p.integer("n");
  Result r;
  r.extra["t_end"] = pr.t_end;
  nlohmann::json runs = nlohmann::json::object();
  for (const std::string crit : {"chapter43", "courant"}) {
    TubeMethod m;
    m.hfact = p.real("hfact");
    m.controls.step.criterion = crit == "courant" ? sph::TimeStepCriterion::courant : sph::TimeStepCriterion::chapter43;
    m.controls.step.eta = p.real("eta");
    m.controls.step.C = p.real("C");
    m.controls.max_steps = p.integer("max_steps");
    const TubeRun run = simulate_tube<1>(pr, m, n);
    r.n_particles = run.x.size();
    // First step of each criterion from the initial state (at rest: mu = 0, a = 0 away from the jump).
    const double h = m.hfact / n, c_max = std::sqrt(pr.gamma * pr.left.p / pr.left.rho);
    const double dt0 = crit == "courant" ? m.controls.step.C * 0.5 * h / (c_max * (1.0 + 1.2 * m.alpha))
                                         : m.controls.step.eta * m.controls.step.eta;
    nlohmann::json j = {{"verdict", run.outcome.verdict}, {"steps", run.outcome.steps}, {"t_reached", run.outcome.t},
                        {"first_dt_bound", dt0}};
    if (run.outcome.verdict == "ok") {
      const double l1 = extreme::tube_l1_rho(run, exact, pr.t_end, 0.0, 1.0);
      j["L1_rho"] = l1;
      r.errors["L1_rho_" + crit] = l1;
    }
    runs[crit] = j;
  }
  r.extra["runs"] = runs;
  r.extra["first_dt_ratio_43_over_courant"] =
      runs["chapter43"]["first_dt_bound"].get<double>() / runs["courant"]["first_dt_bound"].get<double>();
  const std::string v43 = runs["chapter43"]["verdict"], vc = runs["courant"]["verdict"];
  // The case's verdict: the safe criterion's, with (43)'s alongside.
  r.verdict = (vc == "ok" ? std::string("stable") : vc) + "; (43): " + (v43 == "ok" ? "stable" : v43);
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const auto& x = s.runs[k].extra;
    const std::string level = "n" + std::to_string(s.levels[k]);
    c.push_back({level + "_courant_stable", double(x["runs"]["courant"]["verdict"] == "ok"), 1.0, 1.0,
                 "the signal-speed criterion runs to t_end"});
    // Theory: the first (43) step exceeds the Courant step by the ratio below (> 100 here); a
    // step that moves sound over many support radii cannot stay bounded, so (43) must end with
    // an unstable verdict, not with a silent NaN.
    c.push_back({level + "_chapter43_unstable", double(x["runs"]["chapter43"]["verdict"].get<std::string>().rfind("unstable", 0) == 0),
                 1.0, 1.0, "(43) ignores the sound speed: dt = eta^2 from rest"});
    c.push_back({level + "_first_dt_ratio", x["first_dt_ratio_43_over_courant"], 10.0, 1e300,
                 "(43)'s first step is eta^2, far above C h / (2 c)"});
  }
  return c;
}

const Registration reg{Case{
    .name = "extreme_timestep43",
    .summary = "the chapter's time step (43) on a gas at rest with a pressure jump, against the signal-speed Courant step",
    .n_counts = "particles per unit length",
    .tags = {"gate", "extreme"},
    .params = {integer_param("n", 100, "particles per unit length"),
               real_param("p_ratio", 10.0, "pressure ratio left : right", 0.0),
               real_param("eta", 0.3, "eta of (43)", 0.0),
               real_param("C", 0.3, "Courant number", 0.0),
               real_param("hfact", 2.4, "support radius / spacing", 0.0),
               integer_param("max_steps", 100000, "step budget (ends with a verdict)")},
    .levels = {.quick = {100}, .standard = {100, 200, 400}, .full = {100, 200, 400}},
    .orders = [](const Params&) {
      return OrderClaims{{"L1_rho_courant", {1.0, 0.5, "discontinuities: first order in L1 for the stable run"}}};
    },
    .error_defs = {{"L1_rho_courant", "sum_i (m_i/rho_i) |rho_i - rho_exact(x_i)| / sum_i m_i/rho_i over the tube, "
                                      "Courant-stepped run against the exact Riemann solution"}},
    .variants = {{}, {"p_ratio=1000"}},
    .validate = {},
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv
