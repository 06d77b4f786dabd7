// noh and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/noh/snapshots.hpp"

#include <algorithm>
#include <cmath>

#include "verification/harness/case.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/noh/errors.hpp"
#include "verification/cases/noh/setup.hpp"
#include "reference/noh.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/problem_check.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::noh_snapshots_case {
namespace {

using namespace snapshot_columns;

// The inflow ahead of the shock: the particles farther than 2 support radii beyond R_s(t) (the
// front smeared over about a support on either side, problem_check.hpp's supports) and 2 supports
// inside the ball's free edge (the outermost particle: the density sum falls there) stream in at
// v_r = -1 with rho = rho0 (1 + t / r)^(d - 1): medians within 5 % (relative in rho; v_r in units
// of the inflow speed, the problem's unit), at most a tenth of the particles off by more. sphv's
// own ball is cut to what meets the shock by t_end (noh/setup.hpp): at t_end it has no such part.
constexpr double reach = 2.0, tolerance = 0.05, max_off_share = 0.1;

struct Inflow {
  std::vector<double> r, v_r, rho, support;
  double edge = 0.0;  // the outermost particle's r
};

std::vector<std::size_t> ahead(const Inflow& in, const reference::Noh& exact, double t) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < in.r.size(); ++i)
    if (in.r[i] > exact.shock_radius(t) + reach * in.support[i] && in.r[i] + reach * in.support[i] < in.edge)
      at.push_back(i);
  return at;
}

std::vector<StateCheck> inflow_checks(const std::vector<std::size_t>& at, const Inflow& in, const reference::Noh& exact,
                                      double t) {
  if (at.empty()) return {};
  const std::string where = "the inflow ahead of the shock (" + std::to_string(at.size()) + " particles beyond R_s + " +
                            problem_check::number(reach) + " supports, R_s = " + problem_check::number(exact.shock_radius(t)) + ")";
  return {problem_check::part_check(where, "rho", at, [&](std::size_t i) { return in.rho[i]; },
                                  [&](std::size_t i) { return exact.at(in.r[i], t).rho; },
                                  [&](std::size_t i) { return exact.at(in.r[i], t).rho; }, tolerance, max_off_share),
          problem_check::part_check(where, "v_r", at, [&](std::size_t i) { return in.v_r[i]; }, [](std::size_t) { return -1.0; },
                                  [](std::size_t) { return 1.0; }, tolerance, max_off_share)};
}

// Why the inflow is not the problem's: its speed (units), or a compression (1 + t / r)^(d - 1)
// and a shock of another time, else the centre.
std::string inflow_cause(const std::vector<std::size_t>& at, const Inflow& in, const reference::Noh& exact, double t) {
  std::vector<double> v;
  for (std::size_t i : at) v.push_back(in.v_r[i]);
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  if (std::abs(v[v.size() / 2] + 1.0) > tolerance)
    return "the velocity unit: the inflow's median v_r is " + problem_check::number(v[v.size() / 2]) +
           ", the problem's is -1 (rescale the snapshot to an inflow speed of 1), or the centre (--set centre=X[,Y,Z])";
  for (double f : {0.5, 0.25, 0.1, 0.01, 2.0, 4.0, 10.0}) {
    const auto other = ahead(in, exact, t * f);
    if (other.size() >= 3 && problem_check::all_pass(inflow_checks(other, in, exact, t * f)))
      return "the time: the inflow is the problem's at t = " + problem_check::number(t * f) + ", not at the file's t = " +
             problem_check::number(t) + " (a time in other units?)";
  }
  return "the centre (--set centre=X[,Y,Z]) or the time";
}

Result score_noh(const Params& prm, const Snapshot& s) {
  const std::string who = "noh";
  positive(s, "rho", who);
  positive(s, "m", who);
  Result r;
  Inflow in{{}, {}, s.at("rho", who), problem_check::supports(s, who)};
  by_dimension(prm, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    const auto c = radial::centre<D>(prm);
    const auto x = vectors<D>(s, "", who, c), v = vectors<D>(s, "v", who);
    for (std::size_t i = 0; i < x.size(); ++i) {
      in.r.push_back(x[i].norm());
      in.v_r.push_back(x[i].norm() > 0.0 ? v[i].dot(x[i]) / x[i].norm() : 0.0);
    }
    in.edge = *std::max_element(in.r.begin(), in.r.end());
    noh::measure<D>(r, x, v, s.at("m", who), s.at("rho", who), internal_energy(s, prm.real("gamma"), who), prm.real("t_end"),
                    prm.real("gamma"), prm.integer("n"));
    return r;
  });
  if (!r.extra["shock_front_found"].get<bool>())
    r.verdict = "no shock front: the binned density never rises through the post-/pre-shock midpoint (rho_post and "
                "shock_speed not computed; is the centre right?)";
  const double t = prm.real("t_end");
  const reference::Noh exact(static_cast<int>(prm.integer("dim")), prm.real("gamma"));
  const auto at = ahead(in, exact, t);
  const auto checks = inflow_checks(at, in, exact, t);
  apply_problem_check(r, checks, problem_check::all_pass(checks) ? "" : inflow_cause(at, in, exact, t),
                      "no particle lies 2 supports ahead of the shock inside the inflowing ball");
  return r;
}

}  // namespace
}  // namespace sphv::noh_snapshots_case

namespace sphv::noh {

Scorer scorer() { return {"t_end", noh_snapshots_case::score_noh, snapshot_columns::real_t_end, Resolution::per_length, snapshot_columns::real_gamma}; }

// The inflowing ball around the origin (noh/setup.hpp); SWIFT's layout: centred in the periodic box
// of side 2 (as its Noh examples) or, for a ball that needs more, the next even side that leaves
// one initial support radius of empty space between the ball and its periodic images.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  check_size(p);
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    const Setup<D> s = initial<D>(p, p.real("hfact"));
    const double h0 = p.real("hfact") / p.integer("n"), side = 2.0 * std::ceil(s.R0 + 0.5 * h0);
    return ic_layout::placed(ic_layout::at_start(s.p, p.real("gamma")), p.real("gamma"), layout, side / 2.0, side);
  });
}

}  // namespace sphv::noh
