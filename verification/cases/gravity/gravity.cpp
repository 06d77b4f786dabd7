// Case `gravity`: Barnes-Hut tree forces (9.4.7, monopole and quadrupole (79)-(89)) against the
// O(N^2) direct sum, as a function of the opening angle theta; cost against N.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <string>

#include "sph/gravity/tree_gravity.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/gravity/compare.hpp"
#include "verification/cases/gravity/models.hpp"
#include "verification/cases/gravity/snapshots.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::gravity_case {
namespace {

using namespace gravity;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Best of up to 5 repetitions (fewer once 0.5 s are spent): short runs on a shared machine are
// dominated by thread start-up and by other processes.
template <class F>
double best_time(F&& f) {
  double best = INFINITY, total = 0.0;
  for (int k = 0; k < 5 && total < 0.5; ++k) {
    const auto t0 = Clock::now();
    f();
    const double dt = seconds_since(t0);
    best = std::min(best, dt), total += dt;
  }
  return best;
}

const std::vector<double> thetas = {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};

std::string key(const char* what, sph::Multipole m, double theta) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s_%s_%.1f", what, m == sph::Multipole::monopole ? "mono" : "quad", theta);
  return buf;
}

// Least-squares slope of log y on log x.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> nx, ny;
  for (std::size_t k = 0; k < x.size(); ++k) nx.push_back(1.0 / x[k]), ny.push_back(y[k]);
  return observed_order(nx, ny).p;  // fits y ~ n^-p with n = 1/theta: p is the slope in theta
}

Result run(const Params& p) {
  const long n = p.integer("n");
  const double eps = p.real("eps");
  const auto opening = p.text("opening") == "plain" ? sph::Opening::plain : sph::Opening::robust;
  const auto set = make_model(p.text("model"), n, 12345);
  Result r;
  r.n_particles = set.x.size();

  auto t0 = Clock::now();
  const auto ref = direct(set.x, set.m, eps);
  const double direct_time = seconds_since(t0);
  const double w_direct = potential_energy(set.m, ref.phi);
  t0 = Clock::now();
  const auto tree = sph::build_tree<3>(set.x, set.m);
  const double build_time = seconds_since(t0);

  double quad_half_walk_time = NAN;  // quadrupole walk at theta = 0.5, reused in the cost scan
  nlohmann::json table = nlohmann::json::array();
  std::vector<Figure> figs(3);
  figs[0] = {"force_error_theta", "Tree force error against opening angle (" + p.text("model") + ", N = " +
                 std::to_string(n) + ")", "opening angle theta", "relative force error |a_tree - a_direct| / |a_direct|",
             "log", "log", {}};
  figs[1] = {"energy_error_theta", "Potential energy error against opening angle", "opening angle theta",
             "|W_tree - W_direct| / |W_direct|", "log", "log", {}};
  figs[2] = {"error_time", "Accuracy against cost (tree walk; build " + std::to_string(build_time) + " s, direct sum " +
                 std::to_string(direct_time) + " s)",
             "wall time of the force evaluation [s]", "99th percentile relative force error", "log", "log", {}};
  for (const auto m : {sph::Multipole::monopole, sph::Multipole::quadrupole}) {
    const std::string label = m == sph::Multipole::monopole ? "monopole" : "quadrupole";
    Series med{label + " median", {}, {}, "line"}, p90{label + " 90th pct", {}, {}, "dashed"},
        p99{label + " 99th pct", {}, {}, "line"}, mx{label + " max", {}, {}, "points"},
        en{label, {}, {}, "line"}, cost{label, {}, {}, "line"};
    for (double theta : thetas) {
      t0 = Clock::now();
      const auto f = sph::tree_gravity(tree, set.x, set.m, {.theta = theta, .eps = eps, .multipole = m, .opening = opening});
      const double walk_time = seconds_since(t0);
      const auto pc = percentiles(relative_force_error(f, ref));
      const double w_err = std::abs(potential_energy(set.m, f.phi) - w_direct) / std::abs(w_direct);
      double inter = 0.0;
      for (long c : f.interactions) inter += c;
      inter /= n;
      for (auto [s, v] : {std::pair{&med, pc.p50}, {&p90, pc.p90}, {&p99, pc.p99}, {&mx, pc.max}, {&en, w_err}})
        s->x.push_back(theta), s->y.push_back(v);
      cost.x.push_back(walk_time), cost.y.push_back(pc.p99);
      if (m == sph::Multipole::quadrupole && theta == 0.5) quad_half_walk_time = walk_time;
      table.push_back({{"multipole", label}, {"theta", theta}, {"p50", pc.p50}, {"p90", pc.p90}, {"p99", pc.p99},
                       {"max", pc.max}, {"energy", w_err}, {"interactions_per_particle", inter},
                       {"walk_time_s", walk_time}});
      if (theta == 0.2 || theta == 0.5 || theta == 0.8) {
        r.errors[key("p99", m, theta)] = pc.p99;
        r.errors[key("max", m, theta)] = pc.max;
        r.errors[key("energy", m, theta)] = w_err;
      }
    }
    r.extra["theta_slope_median_" + label] = loglog_slope(med.x, med.y);
    r.extra["theta_slope_p99_" + label] = loglog_slope(p99.x, p99.y);
    for (auto* s : {&med, &p90, &p99, &mx}) figs[0].series.push_back(*s);
    figs[1].series.push_back(en);
    figs[2].series.push_back(cost);
  }

  // Cost against N: the same model at N/64, N/16, N/4 and N; tree = build + quadrupole walk at
  // theta = 0.5.
  Figure inter{"interactions_N", "Interactions per particle against N (quadrupole, theta = 0.5)",
               "number of particles N", "interactions per particle", "log", "log", {}};
  Figure wall{"time_N", "Wall time against N (quadrupole, theta = 0.5; " + p.text("model") + ")",
              "number of particles N", "wall time [s]", "log", "log", {}};
  Series it{"tree", {}, {}, "line"}, id{"direct sum (N - 1)", {}, {}, "dashed"};
  Series tt{"tree (build + walk)", {}, {}, "line"}, td{"direct sum", {}, {}, "line"};
  nlohmann::json cost = nlohmann::json::array();
  double crossover = NAN;
  for (long nk : {n / 64, n / 16, n / 4, n}) {
    if (nk < 64) continue;
    const auto s = nk == n ? set : make_model(p.text("model"), nk, 777);
    sph::GravityField f;
    const sph::GravityOptions o{.theta = 0.5, .eps = eps, .opening = opening};
    // At N itself the timings above are reused (one direct sum at the largest N is enough).
    const double td_k = nk == n ? direct_time : best_time([&] { direct(s.x, s.m, eps); });
    const double tt_k = nk == n ? build_time + quad_half_walk_time : best_time([&] {
      f = sph::tree_gravity(sph::build_tree<3>(s.x, s.m), s.x, s.m, o);
    });
    if (nk == n) f = sph::tree_gravity(tree, s.x, s.m, o);
    double inter_k = 0.0;
    for (long c : f.interactions) inter_k += c;
    inter_k /= nk;
    it.x.push_back(nk), it.y.push_back(inter_k), id.x.push_back(nk), id.y.push_back(nk - 1.0);
    tt.x.push_back(nk), tt.y.push_back(tt_k), td.x.push_back(nk), td.y.push_back(td_k);
    if (std::isnan(crossover) && tt_k < td_k) crossover = nk;
    cost.push_back({{"N", nk}, {"tree_s", tt_k}, {"direct_s", td_k}, {"interactions_per_particle", inter_k}});
  }
  // Guides through the largest point: N log N and N^2.
  Series gl{"~ N log N", {}, {}, "dashed"}, g2{"~ N^2", {}, {}, "dashed"};
  for (double nk : tt.x) {
    gl.x.push_back(nk), gl.y.push_back(tt.y.back() * nk * std::log(nk) / (tt.x.back() * std::log(tt.x.back())));
    g2.x.push_back(nk), g2.y.push_back(td.y.back() * nk * nk / (td.x.back() * td.x.back()));
  }
  inter.series = {it, id};
  wall.series = {tt, td, gl, g2};
  figs.push_back(inter);
  figs.push_back(wall);
  r.figures = std::move(figs);
  r.extra["theta_table"] = table;
  r.extra["cost_against_N"] = cost;
  r.extra["tree_beats_direct_from_N"] = std::isnan(crossover) ? nlohmann::json() : nlohmann::json(crossover);
  r.extra["speedup_at_N"] = td.y.back() / tt.y.back();
  r.extra["direct_time_s"] = direct_time;
  r.extra["tree_build_time_s"] = build_time;
  r.extra["softening_eps"] = eps;
  return r;
}

// Each reported error: p99, max of |a_tree - a_direct| / |a_direct| over the particles, and the
// relative potential-energy error, per multipole order and theta in {0.2, 0.5, 0.8}.
std::map<std::string, std::string> error_defs() {
  std::map<std::string, std::string> d;
  for (auto m : {sph::Multipole::monopole, sph::Multipole::quadrupole})
    for (double theta : {0.2, 0.5, 0.8}) {
      const std::string at = std::string(m == sph::Multipole::monopole ? "monopole" : "quadrupole") + " tree, theta " +
                             (theta == 0.2 ? "0.2" : theta == 0.5 ? "0.5" : "0.8");
      d[key("p99", m, theta)] = "99th percentile over particles of |a_tree - a_direct| / |a_direct|, " + at;
      d[key("max", m, theta)] = "max over particles of |a_tree - a_direct| / |a_direct|, " + at;
      d[key("energy", m, theta)] = "|W_tree - W_direct| / |W_direct|, W = 1/2 sum_i m_i phi_i, " + at;
    }
  d.insert(score_error_defs.begin(), score_error_defs.end());  // sphv score of a code's own accelerations
  return d;
}

// The largest error measured per model at N = 4096, 5000, 10000 and 20000 (the quick and
// standard levels; seeds fixed, so deterministic), per statistic and, in order, monopole theta
// 0.2, 0.5, 0.8, quadrupole theta 0.2, 0.5, 0.8. At fixed theta the error does not converge with
// N; from level to level it changes by up to 1.6x for p99 (another random sample), 4x for max
// (one particle) and 55x for the energy (a signed sum that can cancel; docs/cases/gravity.md).
using Row6 = std::array<double, 6>;
const std::map<std::string, std::array<Row6, 3>> largest_measured = {
    {"plummer",
     {{
       /* p99    */ {6.91e-04, 1.06e-02, 3.36e-02, 4.42e-05, 2.11e-03, 1.28e-02},
       /* max    */ {2.53e-03, 5.47e-02, 1.77e-01, 1.55e-04, 1.00e-02, 8.76e-02},
       /* energy */ {8.64e-06, 5.39e-05, 1.09e-04, 1.21e-07, 2.76e-06, 2.09e-05}}}},
    {"uniform",
     {{
       /* p99    */ {1.28e-03, 1.69e-02, 5.39e-02, 8.30e-05, 3.44e-03, 2.24e-02},
       /* max    */ {4.73e-03, 6.25e-02, 2.89e-01, 3.29e-04, 1.11e-02, 9.39e-02},
       /* energy */ {6.77e-05, 6.88e-04, 1.39e-03, 1.06e-06, 1.07e-05, 6.31e-05}}}},
    {"clustered",
     {{
       /* p99    */ {1.20e-03, 1.29e-02, 3.93e-02, 8.37e-05, 1.95e-03, 1.02e-02},
       /* max    */ {3.89e-03, 5.75e-02, 2.75e-01, 4.07e-04, 7.67e-03, 8.52e-02},
       /* energy */ {3.28e-05, 5.36e-04, 2.09e-03, 6.58e-07, 6.74e-06, 4.25e-05}}}},
};

// The same at N = 100000 (the full tier's finest level), measured. The max over particles samples
// the tail of the error distribution further as N grows: 1.9x to 11x the table above for the
// Plummer sphere (the particles far out, where |a| is small), so that level has bounds of its
// own; p99 and the energy stay within 2.2x.
const std::map<std::string, std::array<Row6, 3>> measured_n100000 = {
    {"plummer",
     {{
       /* p99    */ {4.24e-04, 4.72e-03, 1.52e-02, 3.74e-05, 1.19e-03, 6.93e-03},
       /* max    */ {1.28e-02, 1.90e-01, 3.32e-01, 1.66e-03, 5.27e-02, 2.69e-01},
       /* energy */ {2.87e-06, 1.43e-05, 7.65e-05, 4.94e-08, 6.49e-07, 5.80e-06}}}},
    {"uniform",
     {{
       /* p99    */ {7.23e-04, 9.47e-03, 4.34e-02, 5.28e-05, 1.69e-03, 1.54e-02},
       /* max    */ {9.36e-03, 6.45e-02, 3.94e-01, 6.77e-04, 1.68e-02, 5.16e-02},
       /* energy */ {7.21e-05, 7.18e-04, 1.42e-03, 1.12e-06, 1.07e-05, 5.06e-05}}}},
    {"clustered",
     {{
       /* p99    */ {2.02e-03, 1.62e-02, 4.09e-02, 3.40e-05, 9.42e-04, 4.86e-03},
       /* max    */ {7.11e-03, 3.95e-02, 1.41e-01, 3.66e-04, 5.70e-03, 3.79e-02},
       /* energy */ {7.08e-05, 8.85e-04, 2.45e-03, 1.03e-07, 7.47e-06, 1.28e-06}}}},
};

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  const auto& r = s.runs.back();
  const auto& e = r.errors;
  const std::string model = r.params.value("model", std::string("plummer"));
  const bool plummer = model == "plummer";
  const auto v = Check::Kind::verification;
  // Bounds per model, statistic, multipole order and theta at every measured level: 1.5x the
  // largest measured value at N <= 20000, and at N = 100000 over all five levels. The
  // quadrupole p99 bounds lie below the monopole's measured p99 at every theta and level (by 1.2x
  // at theta 0.8 up to 8x at 0.2), so a tree that drops the quadrupole term fails them. At other
  // N, with another opening criterion (opening=plain) or softening there is no measurement: no
  // bounds then, only the published numbers and the rates in theta below.
  const bool measured = r.params.value("opening", std::string("robust")) == "robust" &&
                        r.params.value("eps", 0.0) == 0.01 && largest_measured.count(model);
  if (measured)
    for (const auto& run : s.runs) {
      const long n = run.params.value("n", 0L);
      if (n > 20000 && n != 100000) continue;
      const std::string at = "_n" + std::to_string(n);
      const auto& m = largest_measured.at(model);
      const auto& m5 = measured_n100000.at(model);
      const std::string source = n <= 20000 ? "1.5x the largest measured at N = 4096..20000 (" + model + ")"
                                            : "1.5x the largest measured at N = 4096..100000 (" + model + ")";
      int k = 0;
      for (const auto mp : {sph::Multipole::monopole, sph::Multipole::quadrupole})
        for (double theta : {0.2, 0.5, 0.8}) {
          int w = 0;
          for (const char* what : {"p99", "max", "energy"}) {
            const std::string name = key(what, mp, theta);
            const double largest = n <= 20000 ? m[w][k] : std::max(m[w][k], m5[w][k]);
            c.push_back({"bound_" + name + at, run.errors.at(name), 0.0, 1.5 * largest, source, Check::Kind::drift, name});
            ++w;
          }
          ++k;
        }
    }
  // Published numbers, weaker than the bounds above but independent of this code:
  // SPH-EXA (ryoanji) test, reference-values.md: theta = 0.2 with quadrupoles: p99 < 3e-3,
  // max < 3e-2, potential energy < 1e-2.
  c.push_back({"p99_quad_0.2", e.at("p99_quad_0.2"), 0.0, 3e-3, "SPH-EXA: theta 0.2 quadrupole p99 < 3e-3", v, "p99_quad_0.2"});
  c.push_back({"max_quad_0.2", e.at("max_quad_0.2"), 0.0, 3e-2, "SPH-EXA: theta 0.2 quadrupole max < 3e-2", v, "max_quad_0.2"});
  c.push_back({"energy_quad_0.5", e.at("energy_quad_0.5"), 0.0, 1e-2, "SPH-EXA: potential energy < 1e-2", v, "energy_quad_0.5"});
  // The gate on the Plummer sphere: quadrupole theta = 0.5, p99 below Phantom's tolerance
  // for the maximum error at theta 0.5 (6e-3, measured there 2.8e-3; reference-values.md).
  if (plummer)
    c.push_back({"p99_quad_0.5", e.at("p99_quad_0.5"), 0.0, 6e-3, "Phantom: theta 0.5 max error tolerance 6e-3", v, "p99_quad_0.5"});
  // Rate in theta: each accepted node's relative error is O((d/r)^(p+1)) with p the order kept
  // ((81): monopole p = 1 since the dipole (86) vanishes, so ~theta^2; quadrupole ~theta^3-4,
  // reference-values.md). Lower bounds: that leading rate less 0.3 for the fit. At finite N the
  // curve is steeper: as theta falls, more of the force comes from exact leaf interactions
  // (clustered sets most: local slopes up to 3.5 and 5.8 at theta 0.2-0.3, N = 4096), so the upper
  // bounds are the measured slopes over theta 0.2-1.0 (2.9 and 4.3) plus 0.6.
  c.push_back({"theta_order_monopole", r.extra.at("theta_slope_median_monopole"), 1.7, 3.5,
               "monopole ~ theta^2 or steeper"});
  c.push_back({"theta_order_quadrupole", r.extra.at("theta_slope_median_quadrupole"), 2.7, 4.9,
               "quadrupole ~ theta^3-4 or steeper"});
  return c;
}

const Registration reg{Case{
    .name = "gravity",
    .summary = "Barnes-Hut tree gravity against direct summation: error vs theta, cost vs N",
    .n_counts = "number of particles N",
    .tags = {"gate", "sweep"},
    .params = {integer_param("n", 20000, "number of particles", 63.0),
               choice_param("model", "plummer", "particle set", {"uniform", "plummer", "clustered"}),
               real_param("eps", 0.01, "Plummer softening length (tree and direct sum)", std::nullopt),
               choice_param("opening", "robust", "opening criterion", {"robust", "plain"})},
    // The direct sum's N^2 sets the cost: quick one level, standard up to 20000, full 20000 and
    // SPH-EXA's 1e5 (CPU times: docs/cases/gravity.md).
    .levels = {.quick = {4096}, .standard = {4096, 10000, 20000}, .full = {20000, 100000}},
    .orders = [](const Params&) {
      OrderClaims o;
      for (const auto& [name, def] : error_defs())
        o[name] = no_order("the tree error at fixed theta does not converge with N (no order in n); the order in "
                           "theta is fitted inside each run (monopole ~theta^2, quadrupole ~theta^3-4)");
      return o;
    },
    .error_defs = error_defs(),
    .variants = {{}, {"model=uniform"}, {"model=clustered"}},
    .validate = [](const Params& p) {
      if (!(p.real("eps") >= 0.0)) throw InputError("parameter eps must be >= 0");
    },
    .run = run,
    .gates = gates,
    .scorer = gravity::scorer(),
}};

}  // namespace
}  // namespace sphv::gravity_case
