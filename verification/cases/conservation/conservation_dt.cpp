// Case `conservation_dt`: time-integration error of the total energy for the energy-conserving
// Euler/energy pairs. With (96) exact in the semi-discrete system, all that is left of
// |E(t) - E(0)| is the error of the leapfrog (9.3.2), second order in dt for both the
// chapter's form and kick-drift-kick. The reference is the exact invariance of E.
// With `scheme` a scheme of the registry (sph/schemes/) runs instead of the bare pairing: its own
// forms and dissipation, h by (50) at every evaluation, so h varies in space and time (the blobs'
// free surfaces, their collision). The variant scheme=gradh_switches: grad-h with its Omega terms,
// the switch and conduction conserve E exactly in the semi-discrete system, and the error is again
// the leapfrog's.
#include <cmath>
#include <map>

#include "verification/harness/case.hpp"
#include "verification/cases/common/measured_bound.hpp"
#include "verification/cases/common/scheme_param.hpp"
#include "verification/cases/conservation/catalogue.hpp"
#include "verification/cases/conservation/scheme_run.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::conservation_dt_case {
namespace {

conservation::EulerChoice euler_of(const Params& p) { return {p.text("euler"), p.real("lambda")}; }

Result run(const Params& p) {
  const double t_end = p.real("t_end"), dt = 1.0 / p.integer("n");
  const long steps = std::lround(t_end / dt);
  const auto e = euler_of(p);
  const auto integrator = p.text("integrator") == "kdk" ? sph::IntegratorKind::kdk : sph::IntegratorKind::chapter;
  const auto initial = conservation::colliding_blobs<2>(p.integer("res"), 2.4);
  const std::string scheme = p.text("scheme");
  const auto d = scheme == "forms" ? conservation::run_pairing<2>(initial, e, sph::partner_energy(e.form),
                                                                  p.integer("visc") != 0, integrator, dt, steps)
                                   : conservation::run_scheme<2>(initial, scheme, integrator, dt, steps);
  Result r;
  r.n_particles = initial.size();
  r.verdict = d.verdict;
  r.errors = {{"energy", d.max_of(d.energy)}};  // largest |E(t) - E(0)| / E(0) over the run
  r.extra = {{"dt", dt}, {"steps", steps}, {"energy_rate_residual", d.energy_rate},
             {"momentum", d.max_of(d.momentum)}, {"angular", d.max_of(d.angular)},
             {"pairing", scheme == "forms" ? "(" + e.label() + ")+(" + sph::partner_energy(e.form) + ")" : "scheme " + scheme}};
  Series s{"|E(t) - E(0)| / E(0)", {}, {}, "line"};
  for (std::size_t k = 1; k < d.t.size(); ++k) s.x.push_back(d.t[k]), s.y.push_back(std::max(d.energy[k], 1e-18));
  r.figures = {{"energy_time", "Energy error against time, dt = 1/" + std::to_string(p.integer("n")), "time t",
                "|E(t) - E(0)| / E(0)", "linear", "log", {s}}};
  return r;
}

// The energy error at dt = 1/1600 per catalogued variant (deterministic set-up, seed 11).
const std::map<std::string, double> measured_1600 = {
    {"default", 8.348e-07},  {"integrator=chapter", 8.568e-07}, {"euler=26", 8.602e-07},
    {"euler=26,integrator=chapter", 8.827e-07}, {"euler=25", 8.055e-07}, {"euler=22", 2.428e-07},
    {"visc=1", 7.848e-07}, {"scheme=gradh_switches", 1.303e-06}};

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  for (const auto& r : s.runs)
    c.push_back({"verdict_n" + std::to_string(r.params.value("n", 0L)), r.verdict == "ok" ? 1.0 : 0.0, 1.0, 1.0,
                 r.verdict});
  // Bound: the measured error times 1.5, carried to the finest level as dt^2. Over dt = 1/200 ..
  // 1/1600 the errors lie at most 1.34x above that line (viscosity at 1/200, pre-asymptotic);
  // without viscosity they lie below it. A variant not measured here has no bound, so its row
  // fails: measure it.
  if (const auto m = measured_1600.find(s.variant()); m != measured_1600.end())
    c.push_back(measured_bound(s, "energy", m->second, 1600, 1.5));
  return c;
}

const Registration reg{Case{
    .name = "conservation_dt",
    .summary = "total-energy error against time step for the energy-conserving pairings, both leapfrogs",
    .n_counts = "time steps per unit time (dt = 1/n)",
    .tags = {"gate", "sweep"},
    .params = {integer_param("n", 400, "time steps per unit time"),
               choice_param("euler", "23", "Euler form, with its matched energy form", {"22", "23", "25", "26"}),
               real_param("lambda", 1.5, "lambda of (25)"),
               choice_param("integrator", "kdk", "leapfrog: kick-drift-kick or the chapter's", {"kdk", "chapter"}),
               integer_param("res", 12, "particles per blob diameter"),
               choice_param("visc", "0", "artificial viscosity on (1) or off (0)", {"0", "1"}),
               real_param("t_end", 0.4, "end time (the blobs meet at about 0.15)", 0.0),
               forms_or_scheme_param("forms: the Euler form and its energy form as a bare scene, fixed h; or a scheme "
                                     "(sph/schemes/) with its own forms and viscosity, h by (50)")},
    // dt = 1/100 is pre-asymptotic with viscosity (measured slope 3.5 there). Full adds
    // dt = 1/3200 (the error there, ~2e-7, is still 1e8 above round-off; CPU times:
    // docs/cases/conservation.md).
    .levels = {.quick = {400, 800, 1600}, .standard = {200, 400, 800, 1600}, .full = {200, 400, 800, 1600, 3200}},
    // Leapfrog is second order (9.3.2, errata); the fit over dt = 1/400 .. 1/1600 measured
    // 1.91-1.97 (KDK and chapter, with and without viscosity), over 1/200 .. 1/1600 1.87-1.95 and
    // 2.12 +- 0.10 with viscosity, whose switch (45) has a kink at v_ij . r_ij = 0. Band +-0.3
    // around 2: a first-order slip fails it. scheme=gradh_switches (h by (50), the viscosity switch
    // and conduction acting): 6.04e-5, 1.69e-5, 4.88e-6, 1.30e-6 at dt = 1/200 .. 1/1600, local
    // orders 1.84, 1.79, 1.90, fit 1.84 +- 0.02 (the switch's max(.) and instant rise are kinks in
    // time, as (45)'s is).
    .orders = [](const Params&) {
      return OrderClaims{{"energy", {2.0, 0.3, "E is exactly conserved by the semi-discrete system; the leapfrog's error is O(dt^2)"}}};
    },
    .error_defs = {{"energy", "largest |E(t) - E(0)| / E(0) over the run (E kinetic + internal)"}},
    .variants = {{},
                 {"integrator=chapter"},
                 {"euler=26"},
                 {"euler=26", "integrator=chapter"},
                 {"euler=25"},
                 {"euler=22"},
                 {"visc=1"},
                 {"scheme=gradh_switches"}},
    .validate = [](const Params& p) {
      if (p.text("scheme") != "forms" && (p.text("euler") != "23" || p.integer("visc") != 0))
        throw InputError("conservation_dt: scheme=" + p.text("scheme") + " has its own forms and viscosity (euler, visc do not apply)");
      if (p.integer("n") * p.real("t_end") < 1.0) throw InputError("conservation_dt: t_end * n must be at least one step");
      if (p.integer("res") < 4) throw InputError("conservation_dt: res must be at least 4 particles per diameter");
    },
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::conservation_dt_case
