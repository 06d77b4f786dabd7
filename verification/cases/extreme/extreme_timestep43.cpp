// Case `extreme_timestep43`: the chapter's time step (43), dt = eta h / max|v| and dt = eta^2 for
// a gas at rest, on a gas at rest with a pressure jump (density 1, gamma 1.4, pressures
// p_ratio : 1). (43) ignores the sound speed, so its first step is eta^2 whatever the resolution
// and the sound speed; the safe criterion (Monaghan's signal-speed Courant condition with the
// acceleration criterion, errata) takes C (h/2) / (c (1 + 1.2 alpha)). Both runs are made; the
// independent reference is the exact Riemann solution.
#include <cmath>

#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::extreme_timestep43_case {
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
    nlohmann::json j = {{"verdict", run.outcome.verdict}, {"steps", run.outcome.steps}, {"t_reached", run.outcome.t},
                        {"first_dt", run.first_dt}};
    if (run.outcome.verdict == "ok") {
      const double l1 = extreme::tube_l1_rho(run, exact, pr.t_end, 0.0, 1.0);
      j["L1_rho"] = l1;
      r.errors["L1_rho_" + crit] = l1;
    }
    runs[crit] = j;
  }
  r.extra["runs"] = runs;
  // The first steps the integrator actually took (TubeRun::first_dt; (43)'s is eta^2 = 0.09 from
  // rest unless t_end is shorter, which clips it).
  r.extra["first_dt_ratio_43_over_courant"] =
      runs["chapter43"]["first_dt"].get<double>() / runs["courant"]["first_dt"].get<double>();
  const std::string v43 = runs["chapter43"]["verdict"], vc = runs["courant"]["verdict"];
  // The case's verdict: the safe criterion's, with (43)'s alongside.
  r.verdict = (vc == "ok" ? std::string("stable") : vc) + "; (43): " + (v43 == "ok" ? "stable" : v43);
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  const Params prm = find_case(s.case_name).parse(s.settings);
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const Result& r = s.runs[k];
    const auto& x = r.extra;
    const std::string level = "n" + std::to_string(s.levels[k]);
    c.push_back({level + "_courant_stable", double(x["runs"]["courant"]["verdict"] == "ok"), 1.0, 1.0,
                 "the signal-speed criterion runs to t_end"});
    // A step that moves sound over many support radii cannot stay bounded, so (43) must end with
    // an unstable verdict, not with a silent NaN.
    c.push_back({level + "_chapter43_unstable", double(x["runs"]["chapter43"]["verdict"].get<std::string>().rfind("unstable", 0) == 0),
                 1.0, 1.0, "(43) ignores the sound speed: dt = eta^2 from rest"});
    // The steps the integrator took (not the parameters): (43) from rest takes eta^2 (clipped at
    // t_end), exactly; the Courant step at most C (h/2) / (c (1 + 1.2 alpha)) with the left state's
    // sound speed and h = hfact / n (the acceleration criterion may take less at the jump).
    const double eta = prm.real("eta"), C = prm.real("C"), hfact = prm.real("hfact"), p_l = prm.real("p_ratio");
    const double n = static_cast<double>(s.levels[k]);
    const TubeProblem pr = extreme::pressure_jump(p_l);
    const double dt43 = std::min(eta * eta, pr.t_end), alpha = TubeMethod{}.alpha;
    const double dt_courant_max = C * 0.5 * hfact / n / (std::sqrt(pr.gamma * pr.left.p / pr.left.rho) * (1.0 + 1.2 * alpha));
    c.push_back({level + "_first_dt_43", x["runs"]["chapter43"]["first_dt"].get<double>() / dt43, 1.0 - 1e-12,
                 1.0 + 1e-12, "(43)'s first step from rest is eta^2 (or t_end if shorter): round-off"});
    // Upper end 1.01: the sound speed comes from the summation density, whose kernel-sum error at
    // 2.4 dx in 1D is ~2e-3 (c and dt move by half that).
    c.push_back({level + "_first_dt_courant", x["runs"]["courant"]["first_dt"].get<double>() / dt_courant_max, 0.1,
                 1.01, "the Courant step is at most C (h/2) / (c (1 + 1.2 alpha)) (theory), and not 10x below"});
    // Theory: a step a few times the Courant limit already diverges; (43)'s is > 10x it here.
    c.push_back({level + "_first_dt_ratio", x["first_dt_ratio_43_over_courant"], 10.0, 1e300,
                 "(43)'s first step, as taken, far above the Courant step taken"});
    const bool exact_sums = hfact == 2.0 || hfact == 4.0;
    if (k + 1 == s.runs.size() && k > 0 && exact_sums && r.errors.count("L1_rho_courant") &&
        s.runs[0].errors.count("L1_rho_courant"))
      // Where the 1D lattice sums are exact the error halves with each doubling of n (measured
      // ratios 0.50, 0.54, 0.49 on 100..800): the finest level over the coarsest below 0.6.
      c.push_back({"L1_rho_courant_falls", r.errors.at("L1_rho_courant") / s.runs[0].errors.at("L1_rho_courant"), 0.0,
                   0.6, "finest / coarsest level must fall (measured 0.50-0.54 a doubling at hfact 2)",
                   Check::Kind::verification, "L1_rho_courant"});
    if (r.errors.count("L1_rho_courant") && k + 1 == s.runs.size()) {
      // At hfact 2 the error falls: measured 0.005329 at n = 400, the finest quick level. At 2.4 it
      // levels off: the largest measured on 200..800 (p_ratio 10 0.01343, 1000 0.01776). Bound
      // + 20 %.
      const double measured = exact_sums ? 0.005329 : p_l > 100.0 ? 0.01776 : 0.01343;
      c.push_back({level + "_L1_rho_courant", r.errors.at("L1_rho_courant"), 0.0, 1.2 * measured,
                   "finest level: measured " + std::to_string(measured) +
                       (exact_sums ? " at n = 400 + 20 %" : ", the largest on n = 200..800, + 20 %"),
                   Check::Kind::verification, "L1_rho_courant"});
    }
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
    // The Courant-stepped tube at hfact 2.4 carries the 1D lattice-sum floor (noh.cpp): L1 falls
    // at first order to n = 200, then levels off; at hfact 2, where the sums are exact, it keeps
    // the first order (docs/cases/extreme.md). Quick from n = 200, where
    // the floor shows, with two levels so that CI gates the claim.
    .levels = {.quick = {200, 400}, .standard = {200, 400, 800}, .full = {200, 400, 800, 1600}},
    .orders = [](const Params& p) {
      const double hfact = p.real("hfact");
      if (hfact == 2.0 || hfact == 4.0)
        return OrderClaims{{"L1_rho_courant", {1.0, 0.25, "a jump smeared over a few h: first order in h ~ 1/n"}}};
      return OrderClaims{{"L1_rho_courant", known_failure(1.0, 0.25,
                                                          "fixed-h/dx lattice-sum floor: L1 {L1_rho_courant} at {levels} "
                                                          "levels off at this hfact",
                                                          "hfact=2")}};
    },
    .error_defs = {{"L1_rho_courant", "sum_i (m_i/rho_i) |rho_i - rho_exact(x_i)| / sum_i m_i/rho_i over the tube, "
                                      "Courant-stepped run against the exact Riemann solution"}},
    .variants = {{}, {"p_ratio=1000"}, {"hfact=2"}},
    .validate = {},
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::extreme_timestep43_case
