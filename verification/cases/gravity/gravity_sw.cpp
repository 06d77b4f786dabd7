// Case `gravity_sw`: a Salmon & Warren (1994) configuration where the plain opening criterion
// d / r < theta (89) fails above theta = 1/sqrt(3), and the robust criterion bounds the error.
// A heavy clump sits in one corner of the root cell, a light close pair in the opposite corner:
// seen from the pair, the root's centre of mass is about sqrt(3) d away, so at theta = 0.8 the
// plain criterion accepts the whole root as one monopole/quadrupole and misses the partner's
// pull, which grows as 1 / separation^2 (unbounded). The robust criterion (cell containing the
// particle always opened, r > d / theta + delta) opens it.
#include <cmath>
#include <numbers>

#include "sph/gravity/tree_gravity.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/gravity/compare.hpp"
#include "verification/cases/gravity/models.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::gravity_sw_case {
namespace {

using namespace gravity;

// Clump of n particles (Plummer, a = 0.02, mass 1) at the origin; a pair of mass 1e-3 each near
// (1, 1, 1) with separation s along x.
ParticleSet configuration(long n, double s) {
  ParticleSet set = plummer_sphere(n, 4242, 0.02, 0.1);
  for (const auto& x : {sph::Vec<3>(1.0, 1.0, 1.0), sph::Vec<3>(1.0 + s, 1.0, 1.0)}) {
    set.x.push_back(x);
    set.m.push_back(1e-3);
  }
  return set;
}

double max_error(const ParticleSet& set, const sph::Tree<3>& tree, const reference::DirectField& ref, double theta,
                 sph::Opening o) {
  const auto f = sph::tree_gravity(tree, set.x, set.m, {.theta = theta, .eps = 0.0, .opening = o});
  return percentiles(relative_force_error(f, ref)).max;
}

// Largest |a_tree - a_direct| on the light pair (the last two particles), in units of the
// clump's pull on it, G M / 3 (distance sqrt 3).
// The relative error saturates at 1 once the partner's pull dominates; this one shows the growth.
double max_abs_error(const ParticleSet& set, const sph::Tree<3>& tree, const reference::DirectField& ref,
                     double theta, sph::Opening o) {
  const auto f = sph::tree_gravity(tree, set.x, set.m, {.theta = theta, .eps = 0.0, .opening = o});
  double worst = 0.0;
  for (std::size_t i = set.x.size() - 2; i < set.x.size(); ++i)
    worst = std::max(worst, (f.a[i] - sph::Vec<3>(ref.ax[i], ref.ay[i], ref.az[i])).norm());
  return worst * 3.0;
}

Result run(const Params& p) {
  const long n = p.integer("n");
  const double theta = p.real("theta");
  Result r;
  // Error against theta at separation 0.01.
  const auto set = configuration(n, 0.01);
  r.n_particles = set.x.size();
  const auto tree = sph::build_tree<3>(set.x, set.m);
  const auto ref = direct(set.x, set.m, 0.0);
  Figure ft{"sw_theta", "Salmon-Warren configuration: worst force error against theta (quadrupole)",
            "opening angle theta", "max relative force error", "linear", "log", {}};
  Series plain{"plain d/r < theta (89)", {}, {}, "line"}, robust{"robust: r > d/theta + delta, own cell opened", {}, {}, "line"};
  for (double th = 0.3; th <= 1.0 + 1e-9; th += 0.05) {
    plain.x.push_back(th), plain.y.push_back(max_error(set, tree, ref, th, sph::Opening::plain));
    robust.x.push_back(th), robust.y.push_back(max_error(set, tree, ref, th, sph::Opening::robust));
  }
  Series limit{"theta = 1/sqrt(3)", {1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)}, {1e-6, 1e3}, "dashed"};
  ft.series = {plain, robust, limit};

  // Error against the pair's separation at the given theta: unbounded for plain.
  Figure fs{"sw_separation", "Worst force error against the pair separation, theta = " + std::to_string(theta),
            "separation of the light pair", "max |a_tree - a_direct| on the pair / (G M_clump / 3)", "log", "log", {}};
  Series ps{"plain", {}, {}, "line"}, rs{"robust", {}, {}, "line"};
  double worst_plain = 0.0, worst_robust = 0.0;
  for (double s : {0.1, 0.03, 0.01, 0.003, 0.001, 0.0003}) {
    const auto cs = configuration(n, s);
    const auto tc = sph::build_tree<3>(cs.x, cs.m);
    const auto rc = direct(cs.x, cs.m, 0.0);
    const double ep = max_abs_error(cs, tc, rc, theta, sph::Opening::plain);
    const double er = max_abs_error(cs, tc, rc, theta, sph::Opening::robust);
    ps.x.push_back(s), ps.y.push_back(ep), rs.x.push_back(s), rs.y.push_back(er);
    worst_plain = std::max(worst_plain, ep), worst_robust = std::max(worst_robust, er);
  }
  fs.series = {ps, rs};
  r.figures = {ft, fs};
  r.errors = {{"max_plain", max_error(set, tree, ref, theta, sph::Opening::plain)},
              {"max_robust", max_error(set, tree, ref, theta, sph::Opening::robust)}};
  r.extra = {{"worst_over_separations_plain", worst_plain},
             {"worst_over_separations_robust", worst_robust},
             {"separation_slope_plain", -observed_order(ps.x, ps.y).p}};
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  const auto& r = s.runs.back();
  return {
      // Failure shown: the plain criterion misses the partner's pull entirely (error ~ 1 or more).
      {"plain_fails", r.errors.at("max_plain"), 0.5, INFINITY, "Salmon & Warren: plain d/r unbounded above 0.577",
       Check::Kind::verification, "max_plain"},
      // Unbounded: the plain absolute error grows as 1/s^2 with the separation s (slope -2 in s;
      // the least-squares fit includes s = 0.1 where the clump's error still adds: band -2.3..-1.7).
      {"plain_separation_slope", r.extra.at("separation_slope_plain"), -2.3, -1.7,
       "partner's pull G m / s^2 missed"},
      // Robust criterion: the pair's error stays at the ordinary tree error at this theta (99th
      // percentile ~1e-2 at theta 0.8 in the `gravity` case), whatever the separation.
      {"robust_bounded", r.extra.at("worst_over_separations_robust"), 0.0, 1e-2,
       "robust criterion: ordinary tree error at theta 0.8 (gravity case p99 ~1e-2)"},
      // Worst particle of the whole set (clump included): measured 4.58e-2 (n = 1000) and 2.16e-2
      // (n = 2000), bound 1.5x the larger. The `gravity` case's max at theta 0.8, 0.1, would be too
      // loose: a tree without the quadrupole term meets it (7.5e-2).
      {"robust_relative", r.errors.at("max_robust"), 0.0, 1.5 * 4.58e-2, "measured 4.58e-2 at n = 1000, margin 1.5",
       Check::Kind::drift, "max_robust"},
  };
}

const Registration reg{Case{
    .name = "gravity_sw",
    .summary = "Salmon-Warren configuration: plain opening criterion fails, robust one bounded",
    .n_counts = "particles in the heavy clump (plus a light pair)",
    .tags = {"gate"},
    .params = {integer_param("n", 2000, "particles in the clump"),
               real_param("theta", 0.8, "opening angle for the separation scan", 0.0)},
    .levels = {.quick = {1000}, .standard = {2000}, .full = {2000}},
    .orders = [](const Params&) {
      const std::string why = "no convergence in n: the failure is geometric (centre of mass near the cell's edge)";
      return OrderClaims{{"max_plain", no_order(why)}, {"max_robust", no_order(why)}};
    },
    .error_defs = {{"max_plain", "max over particles of |a_tree - a_direct| / |a_direct|, plain d/r opening (89), theta 0.8"},
                   {"max_robust", "max over particles of |a_tree - a_direct| / |a_direct|, robust opening, theta 0.8"}},
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::gravity_sw_case
