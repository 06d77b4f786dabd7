// Case `conservation`: the conservation catalogue of 9.5. Every Euler form ((22), (23), (25) with
// lambda = 0, 0.5, 1.5, (26)) with every energy form ((37), (38), (40), (41), (42), and (25)'s own
// symmetric form) on two colliding, spinning gas blobs with free surfaces and unequal masses. The
// reference is the exact invariance of total momentum, angular momentum (9.5.1-2) and energy
// (9.5.3): the drifts must be round-off where the proof applies and clearly not where it does not.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "verification/harness/case.hpp"
#include "verification/cases/conservation/catalogue.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::conservation_case {
namespace {

using conservation::Catalogue;
using conservation::CatalogueRow;

// Drifts plotted on a log axis: an exact zero is drawn at this floor.
constexpr double log_floor = 1e-18;
double floored(double x) { return std::max(x, log_floor); }

bool symmetric(const CatalogueRow& r) { return r.euler.form != "22"; }
std::string row_label(const CatalogueRow& r) { return "(" + r.euler.label() + ")+(" + r.energy + ")"; }

Series over_time(const std::string& label, const std::vector<double>& t, const std::vector<double>& y) {
  Series s{label, {}, {}, "line"};
  for (std::size_t k = 1; k < t.size(); ++k) s.x.push_back(t[k]), s.y.push_back(floored(y[k]));
  return s;
}

Result run(const Params& p) {
  conservation::CatalogueSetup s;
  s.n = p.integer("n");
  s.hfact = p.real("hfact");
  s.viscosity = p.integer("visc") != 0;
  s.steps = p.integer("steps");
  s.t_end = p.real("t_end");
  s.integrator = p.text("integrator") == "kdk" ? sph::IntegratorKind::kdk : sph::IntegratorKind::chapter;
  const Catalogue c = p.integer("dim") == 2 ? conservation::catalogue<2>(s) : conservation::catalogue<3>(s);

  Result r;
  r.n_particles = c.particles;
  const double inf = std::numeric_limits<double>::infinity();
  double mom_sym = 0.0, ang_sym = 0.0, rate_cons = 0.0, drift_cons = 0.0;
  double mom_direct = inf, rate_noncons = inf;
  nlohmann::json table = nlohmann::json::array();
  Figure fig_table{"conservation_table", "Largest drift over the run per Euler/energy pairing",
                   "pairing index (extra.table)", "relative drift (0 drawn at 1e-18)", "linear", "log", {}};
  Series s_mom{"momentum |dP|/sum m|v|", {}, {}, "points"}, s_ang{"angular momentum |dL|/sum m|r x v|", {}, {}, "points"},
      s_en{"energy |dE|/E", {}, {}, "points"}, s_rate{"energy rate residual (96)", {}, {}, "points"};
  Figure fig_mom{"momentum_time", "Momentum drift per Euler form (matched energy form)", "time t",
                 "|P(t) - P(0)| / sum m|v(0)|", "linear", "log", {}};
  Figure fig_ang{"angular_time", "Angular momentum drift per Euler form (matched energy form)", "time t",
                 "|L(t) - L(0)| / sum m|r x v|(0)", "linear", "log", {}};
  Figure fig_en{"energy_time", "Energy drift: matched pairs, and (26) with the other energy forms", "time t",
                "|E(t) - E(0)| / E(0)", "linear", "log", {}};
  for (std::size_t k = 0; k < c.rows.size(); ++k) {
    const CatalogueRow& row = c.rows[k];
    const auto& d = row.drifts;
    const double mom = d.max_of(d.momentum), ang = d.max_of(d.angular), en = d.max_of(d.energy);
    if (d.verdict != "ok" && r.verdict == "ok") r.verdict = row_label(row) + ": " + d.verdict;
    if (symmetric(row)) mom_sym = std::max(mom_sym, mom), ang_sym = std::max(ang_sym, ang);
    else mom_direct = std::min(mom_direct, mom);
    if (row.conserves_energy) rate_cons = std::max(rate_cons, d.energy_rate), drift_cons = std::max(drift_cons, en);
    else rate_noncons = std::min(rate_noncons, d.energy_rate);
    table.push_back({{"index", k}, {"euler", row.euler.label()}, {"energy_form", row.energy},
                     {"conserves_energy_by_algebra", row.conserves_energy}, {"momentum", mom}, {"angular", ang},
                     {"energy_drift", en}, {"energy_rate", d.energy_rate}, {"verdict", d.verdict}});
    const double x = static_cast<double>(k);
    s_mom.x.push_back(x), s_mom.y.push_back(floored(mom));
    s_ang.x.push_back(x), s_ang.y.push_back(floored(ang));
    s_en.x.push_back(x), s_en.y.push_back(floored(en));
    s_rate.x.push_back(x), s_rate.y.push_back(floored(d.energy_rate));
    if (row.energy == sph::partner_energy(row.euler.form)) {
      fig_mom.series.push_back(over_time(row.euler.label(), d.t, d.momentum));
      fig_ang.series.push_back(over_time(row.euler.label(), d.t, d.angular));
    }
    if (row.energy == sph::partner_energy(row.euler.form) || row.euler.form == "26")
      fig_en.series.push_back(over_time(row_label(row), d.t, d.energy));
  }
  fig_table.series = {s_mom, s_ang, s_en, s_rate};
  r.figures = {fig_table, fig_mom, fig_ang, fig_en};
  r.errors = {{"momentum_symmetric", mom_sym}, {"angular_symmetric", ang_sym},
              {"energy_rate_conserving", rate_cons}, {"energy_drift_conserving", drift_cons}};
  r.extra = {{"table", table}, {"dt", s.t_end / s.steps}, {"steps", s.steps},
             {"momentum_direct22_min", mom_direct}, {"energy_rate_nonconserving_min", rate_noncons},
             {"drift_definitions", "momentum |P(t)-P(0)|/sum_i m_i|v_i(0)|; angular |L(t)-L(0)|/sum_i m_i|r_i x v_i|(0); "
                                   "energy |E(t)-E(0)|/E(0); each the largest over the run"}};
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  const auto v = Check::Kind::verification;
  for (const auto& r : s.runs) {
    const std::string n = "_n" + std::to_string(r.params.value("n", 0L));
    c.push_back({"verdict" + n, r.verdict == "ok" ? 1.0 : 0.0, 1.0, 1.0, r.verdict});
    // Bound 1e-12; the proof (92)-(95) makes the drift pure round-off (measured
    // <= 1.5e-15 over 150 steps in 2D and 3D, with and without viscosity).
    c.push_back({"momentum_symmetric" + n, r.errors.at("momentum_symmetric"), 0.0, 1e-12, "(92): pairwise forces", v,
                 "momentum_symmetric"});
    c.push_back({"angular_symmetric" + n, r.errors.at("angular_symmetric"), 0.0, 1e-12, "(94)-(95): central forces", v,
                 "angular_symmetric"});
    // The harness must see (22) break momentum conservation: measured >= 5e-3; 1e-6 leaves
    // a margin of 5000 and is still 1e6 above the round-off of the symmetric forms.
    c.push_back({"momentum_direct22_detected" + n, r.extra.at("momentum_direct22_min").get<double>(), 1e-6,
                 std::numeric_limits<double>::infinity(), "(22) is not antisymmetric in i, j"});
    // (96) holds identically for the conserving pairs: residual is round-off of sums of O(1)
    // terms (measured <= 2e-16); the others leave a discretisation residual (measured >= 4e-3).
    c.push_back({"energy_rate_conserving" + n, r.errors.at("energy_rate_conserving"), 0.0, 1e-12,
                 "(96)-(104): sum of m_i (v_i . a_i + du_i/dt) cancels pairwise", v, "energy_rate_conserving"});
    c.push_back({"energy_rate_nonconserving_detected" + n, r.extra.at("energy_rate_nonconserving_min").get<double>(),
                 1e-6, std::numeric_limits<double>::infinity(), "unmatched pairs leave an O(h^2) residual"});
  }
  // The leapfrog's energy error at the fixed dt = 2e-3 of the conserving pairings: no order in n
  // (it grows with n, as (dt c / h)^2 and faster with viscosity), bounded per variant and level
  // at 1.5x the value measured there (deterministic set-up, seed 11). Levels not measured here
  // have no bound; the row then rests on its round-off companions.
  static const std::map<std::string, std::map<long, double>> drift_measured = {
      {"default", {{16, 1.284e-05}, {24, 3.629e-05}, {32, 1.044e-04}}},
      {"visc=0", {{16, 1.096e-05}, {24, 1.672e-05}, {32, 4.135e-05}}},
      {"dim=3,hfact=2", {{8, 1.053e-05}, {12, 1.724e-05}}}};
  if (const auto m = drift_measured.find(s.variant()); m != drift_measured.end())
    for (const auto& r : s.runs)
      if (const auto at = m->second.find(r.params.value("n", 0L)); at != m->second.end()) {
        char why[96];
        std::snprintf(why, sizeof why, "measured %.4g at this level, margin 1.5", at->second);
        c.push_back({"bound_energy_drift_conserving_n" + std::to_string(at->first), r.errors.at("energy_drift_conserving"),
                     0.0, 1.5 * at->second, why, v, "energy_drift_conserving"});
      }
  return c;
}

// Each level runs the whole catalogue of 36 pairings. 3D costs ~10x more per level, so its
// standard tier is the quick level only and full carries 12 and 16 (2.4x the particles of 12 with
// more neighbours; CPU times: docs/cases/conservation.md).
const Levels levels = {.quick = {16}, .standard = {16, 24, 32}, .full = {16, 24, 32}};

const Registration reg{Case{
    .name = "conservation",
    .summary = "momentum, angular momentum and energy drift of every Euler/energy pairing (9.5)",
    .n_counts = "particles per blob diameter (two colliding blobs)",
    .tags = {"gate"},
    .params = {integer_param("n", 16, "particles per blob diameter"),
               choice_param("dim", "2", "dimension", {"2", "3"}),
               choice_param("visc", "1", "artificial viscosity (44)-(48) on (1) or off (0)", {"0", "1"}),
               integer_param("steps", 150, "fixed time steps (at least 100 for the gates)"),
               real_param("t_end", 0.3, "end time (blob crossing time 1.4)", 0.0),
               real_param("hfact", 2.4, "support radius / particle spacing (50)", 0.0),
               choice_param("integrator", "kdk", "leapfrog: kick-drift-kick or the chapter's", {"kdk", "chapter"})},
    .levels = levels,
    .orders = [](const Params&) {
      const std::string why = "no order: where section 9.5 applies the drift is round-off, independent of n";
      return OrderClaims{{"momentum_symmetric", no_order(why)}, {"angular_symmetric", no_order(why)},
                         {"energy_rate_conserving", no_order(why)},
                         {"energy_drift_conserving", no_order("no order in n: the leapfrog's O(dt^2) error at fixed steps")}};
    },
    .error_defs = {{"momentum_symmetric", "max over the run and the symmetric Euler forms of |P(t) - P(0)| / sum_i m_i |v_i(0)|"},
                   {"angular_symmetric", "max over the run and the symmetric forms of |L(t) - L(0)| / sum_i m_i |r_i x v_i|(0)"},
                   {"energy_rate_conserving", "max over the run and the conserving pairings of |dE/dt| / sum_i m_i (|v_i . a_i| + |du_i/dt|)"},
                   {"energy_drift_conserving", "max over the run and the conserving pairings of |E(t) - E(0)| / E(0)"}},
    .variants = {{}, {"visc=0"}, {"dim=3", "hfact=2"}},
    .levels_for = [](const Params& p) {
      if (p.text("dim") == "3") return Levels{.quick = {8}, .standard = {8}, .full = {8, 12, 16}};  // 3D: half the particles per diameter
      return levels;
    },
    .validate = [](const Params& p) {
      if (p.integer("n") < 4) throw InputError("conservation: n must be at least 4 particles per diameter");
      if (p.real("hfact") < 1.0) throw InputError("conservation: hfact must be at least 1 (no neighbours otherwise)");
    },
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::conservation_case
