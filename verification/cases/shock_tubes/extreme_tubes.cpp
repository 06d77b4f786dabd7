// Case `extreme_tubes`: the strong and near-vacuum shock tubes with variable h ((53), the tube's
// default): Toro's test 2 (123, near vacuum, p* = 0.00189), test 3 (left blast, pressure ratio
// 1e5) and LeBlanc (density ratio 1e3, pressure ratio 1e9, gamma 5/3). Independent reference: the
// exact Riemann solver (reference/riemann, Toro ch. 4). Each run ends with its verdict.
#include <cmath>

#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/common/scheme_param.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::extreme_tubes_case {
namespace {

struct Problem {
  TubeProblem pr;
  double lo, hi;  // the interval errors are taken over
};

Problem problem(const std::string& name) {
  if (name == "toro2") return {{{1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, 1.4, 0.5, 0.15}, 0.0, 1.0};
  if (name == "toro3") return {{{1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, 1.4, 0.5, 0.012}, 0.0, 1.0};
  // LeBlanc (reference-values.md): x0 = 3 on [0, 9], t = 6.
  return {{{1.0, 0.0, 2.0 / 3.0 * 1e-1}, {1e-3, 0.0, 2.0 / 3.0 * 1e-10}, 5.0 / 3.0, 3.0, 6.0}, 0.0, 9.0};
}

Result run(const Params& p) {
  const Problem pb = problem(p.text("preset"));
  TubeMethod m;
  m.energy = p.text("energy");
  m.hfact = p.real("hfact");
  m.scheme = p.text("scheme");
  m.controls.step.C = p.real("C");
  m.controls.max_steps = p.integer("max_steps");
  const long n = p.integer("n");
  const TubeRun run = simulate_tube<1>(pb.pr, m, n);
  const reference::RiemannSolution exact(pb.pr.left, pb.pr.right, pb.pr.gamma, pb.pr.x0);
  Result r;
  r.n_particles = run.x.size();
  r.verdict = run.outcome.verdict == "ok" ? "stable" : run.outcome.verdict;
  r.extra = {{"steps", run.outcome.steps}, {"t_reached", run.outcome.t}, {"t_end", pb.pr.t_end},
             {"p_star", exact.p_star()}, {"energy_drift", run.energy_drift}};
  if (run.outcome.verdict != "ok") return r;
  r.errors["L1_rho"] = extreme::tube_l1_rho(run, exact, pb.pr.t_end, pb.lo, pb.hi);
  // Smallest density in the tube against the exact minimum (near vacuum: 0.02185 for toro2).
  double rho_min = 1e300, rho_min_exact = 1e300;
  for (std::size_t i = 0; i < run.active; ++i)
    if (run.x[i] >= pb.lo && run.x[i] <= pb.hi) rho_min = std::min(rho_min, run.rho[i]);
  for (int k = 0; k <= 4000; ++k)
    rho_min_exact = std::min(rho_min_exact, exact.sample(pb.lo + (pb.hi - pb.lo) * k / 4000.0, pb.pr.t_end).rho);
  // The star region right of the contact (Toro 3's shell between contact and shock): the
  // particles' mean density over its middle half, against the exact plateau, to tell a plateau
  // that is off at every n from errors confined to the waves.
  const double t = pb.pr.t_end, x_c = pb.pr.x0 + exact.u_star() * t, x_w = pb.pr.x0 + exact.right_tail() * t;
  const double a = x_c + 0.25 * (x_w - x_c), b = x_w - 0.25 * (x_w - x_c);
  double rho_sum = 0.0;
  long in_star = 0;
  for (std::size_t i = 0; i < run.active; ++i)
    if (run.x[i] >= a && run.x[i] <= b) rho_sum += run.rho[i], ++in_star;
  if (in_star > 0) r.extra["rho_star_right_mean"] = rho_sum / double(in_star);
  r.extra["rho_star_right"] = exact.rho_star_right();
  r.extra["rho_min"] = rho_min;
  r.extra["rho_min_exact"] = rho_min_exact;
  Series pts{"SPH particles", {}, {}, "points"}, line{"exact (Toro)", {}, {}, "line"};
  for (std::size_t i = 0; i < run.active; ++i)
    if (run.x[i] >= pb.lo && run.x[i] <= pb.hi) pts.x.push_back(run.x[i]), pts.y.push_back(run.rho[i]);
  for (int k = 0; k <= 2000; ++k) {
    const double x = pb.lo + (pb.hi - pb.lo) * k / 2000.0;
    line.x.push_back(x), line.y.push_back(exact.sample(x, pb.pr.t_end).rho);
  }
  r.figures.push_back({"profile_rho", p.text("preset") + ", n = " + std::to_string(n) + ": density", "x", "density rho",
                       "linear", p.text("preset") == "leblanc" ? "log" : "linear", {pts, line}});
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  const Params p = find_case(s.case_name).parse(s.settings);
  const std::string preset = p.text("preset");
  const bool lattice_exact = p.real("hfact") == 2.0 || p.real("hfact") == 4.0;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const auto& r = s.runs[k];
    const std::string level = "n" + std::to_string(s.levels[k]);
    c.push_back({level + "_stable", double(r.verdict == "stable"), 1.0, 1.0, "runs to t_end with a finite, positive state"});
    if (r.verdict != "stable") continue;
    // Bound at every level: the largest L1(rho) measured (one thread; toro2 0.00667, toro3 with
    // energy 38 at hfact 2.4 0.0252, at hfact 2 0.0189) + 20 %; the series: docs/cases/sod.md.
    const double tol = 1.2 * (preset == "toro2" ? 0.00667 : lattice_exact ? 0.0189 : 0.0252);
    c.push_back({level + "_L1_rho", r.errors.at("L1_rho"), 0.0, tol,
                 "L1(rho) against the exact Riemann solution (largest measured on 200..800 + 20 %)",
                 Check::Kind::drift, "L1_rho"});
  }
  return c;
}

const Registration reg{Case{
    .name = "extreme_tubes",
    .summary = "strong and near-vacuum shock tubes (Toro 2, 3, LeBlanc) with variable h: verdict and L1 against the exact solver",
    .n_counts = "particles per unit length on the left",
    .tags = {"gate", "extreme", "sweep"},
    .params = {integer_param("n", 200, "particles per unit length on the left"),
               choice_param("preset", "toro3", "toro2 (123, near vacuum), toro3 (left blast), leblanc", {"toro2", "toro3", "leblanc"}),
               choice_param("energy", "auto", "energy form (auto = (41) with Euler (23)) or (38)", {"auto", "38"}),
               real_param("hfact", 2.4, "initial support radius / spacing", 0.0),
               forms_or_scheme_param("forms: Euler (23) with the energy form above, h by (53); or a scheme "
                                     "(sph/schemes/) with its own forms and h by (50)"),
               real_param("C", 0.3, "Courant number", 0.0),
               integer_param("max_steps", 200000, "step budget (ends with a verdict)")},
    // Two levels in quick, so that CI gates every order claim; toro3 from n = 400, below which its
    // local orders are not yet first order at either hfact.
    .levels = {.quick = {200, 400}, .standard = {200, 400, 800}, .full = {200, 400, 800, 1600}},
    .orders = [](const Params& p) {
      // A tube's L1: at least 0.74 (sod.cpp, why_first_order), where the kernel's 1D lattice sums are
      // exact (hfact 2 or 4). At hfact 2.4 they are not (common/lattice_sums.hpp), and behind the
      // shock or in the near-vacuum of toro2 the lattice keeps h/dx = hfact: L1 levels off at a
      // floor set by hfact, not n; the same preset at hfact 2 is the experiment.
      const OrderClaim first = at_least(0.74, "shock, contact and rarefaction smeared over a few h ~ 1/n: L1 at least "
                                              "Athena++'s 0.74 (error ratio <= 0.6 per doubling)");
      const bool exact_sums = p.real("hfact") == 2.0 || p.real("hfact") == 4.0;
      if (p.text("preset") == "toro3") {
        // Behind the left blast the shell between contact and shock is compressed sixfold. h by
        // (53) (scheme forms) follows the continuity rate, not (50): the shell's h/dx leaves
        // hfact and its lattice sums are off whatever n; at hfact 2.4 even (50)'s h leaves them
        // off. h by (50) at hfact 2 (scheme chapter) is the experiment: its shell density meets
        // the exact one and L1 falls.
        if (p.text("scheme") == "forms" || !exact_sums)
          return OrderClaims{{"L1_rho", known_failure(first,
                                                      "the shell behind the blast sits on a lattice whose sums are off at "
                                                      "every n (h by (53) drifts from (50) through the sixfold "
                                                      "compression; at a hfact where the 1D sums are not exact they are off anyway): its density "
                                                      "{extra.rho_star_right_mean} against the exact "
                                                      "{extra.rho_star_right}; L1 {L1_rho} at {levels}",
                                                      "preset=toro3,energy=38,hfact=2,scheme=chapter")}};
        return OrderClaims{{"L1_rho", first}};
      }
      if (!exact_sums)
        return OrderClaims{{"L1_rho", known_failure(first,
                                                    "fixed-h/dx lattice-sum floor in the near-vacuum centre: L1 {L1_rho} "
                                                    "at {levels} levels off at this hfact",
                                                    "preset=toro2,hfact=2")}};
      return OrderClaims{{"L1_rho", first}};
    },
    .error_defs = {{"L1_rho", "sum_i (m_i/rho_i) |rho_i - rho_exact(x_i)| / sum_i m_i/rho_i over the tube at t_end "
                              "(exact Riemann solution)"}},
    // toro3 with (41) (energy=auto) goes to u < 0 in the first step (measured): not a gate variant.
    .variants = {{"preset=toro2"}, {"preset=toro2", "hfact=2"}, {"preset=toro3", "energy=38"},
                 {"preset=toro3", "energy=38", "hfact=2"}, {"preset=toro3", "energy=38", "hfact=2", "scheme=chapter"}},
    .levels_for = [](const Params& p) {
      // toro3 with h by (50): the shell's L1 falls at 0.98 from n = 800 to 1600 (levels to 3200:
      // 3.653e-3, 1.846e-3, 1.102e-3), at about 4 times the forms' cost a step.
      if (p.text("preset") == "toro3" && p.text("scheme") != "forms")
        return Levels{.quick = {400, 800}, .standard = {400, 800, 1600}, .full = {400, 800, 1600, 3200}};
      if (p.text("preset") == "toro3") return Levels{.quick = {400, 800}, .standard = {200, 400, 800}, .full = {200, 400, 800, 1600}};
      // toro2 levels off from n = 800 at hfact 2.4 (the floor): the known failure needs it in quick.
      if (p.real("hfact") != 2.0) return Levels{.quick = {400, 800, 1600}, .standard = {400, 800, 1600}, .full = {400, 800, 1600, 3200}};
      // toro2 at hfact 2: L1 5.512e-3, 3.025e-3, 1.486e-3, 1.073e-3, 5.135e-4 at n = 400..6400, local
      // orders 0.87, 1.03, 0.47, 1.06: the full tier ends at 6400, past the dip from 1600 to 3200.
      return Levels{.quick = {400, 800}, .standard = {400, 800, 1600}, .full = {400, 800, 1600, 3200, 6400}};
    },
    // A registered scheme brings its own energy form ((38) or its grad-h form): energy=auto, which
    // means (41) with the forms, would be silently ignored.
    .validate = [](const Params& p) {
      if (p.text("scheme") != "forms" && p.text("energy") != "38")
        throw InputError("extreme_tubes: scheme=" + p.text("scheme") + " has its own energy form ((38)'s); energy=" +
                         p.text("energy") + " applies to scheme=forms only: set energy=38");
    },
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::extreme_tubes_case
