// kh and other codes' files: the scorer of `sphv score` (a time series of snapshots) and the
// initial conditions of `sphv ic`.
#include "verification/cases/kh/snapshots.hpp"

#include <algorithm>

#include "verification/cases/kh/errors.hpp"
#include "verification/cases/kh/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/problem_check.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::kh_snapshots_case {
namespace {

using namespace snapshot_columns;

// The layers the settings describe, which the instability mixes but does not change as a whole:
// the particles' mass over the box's area is the layers' mean density (rho1 + rho2) / 2 within
// 1e-3 (a code conserves mass) and their median pressure is p0 within 5 % (the flow is
// subsonic: pressure varies by a few % of p0 at most). Another gamma (u written for it), p0 or
// pair of densities is off by more.
void check_layers(Result& r, const Params& p, const Snapshot& s, const sph::Vec<2>& len) {
  const std::string who = "kh";
  const double rho_mean = 0.5 * (p.real("rho1") + p.real("rho2")), p0 = p.real("p0"), gamma = p.real("gamma");
  double mass = 0.0;
  for (double m : s.at("m", who)) mass += m;
  std::vector<double> pr = pressure(s, gamma, who);
  std::nth_element(pr.begin(), pr.begin() + pr.size() / 2, pr.end());
  const std::string where = "the layers (" + std::to_string(s.size()) + " particles)";
  const std::vector<StateCheck> checks = {{where, "mean rho", mass / (len[0] * len[1]), rho_mean, rho_mean, 1e-3},
                                          {where, "median p", pr[pr.size() / 2], p0, p0, 0.05}};
  apply_problem_check(r, checks,
                      !checks[0].pass() ? "rho1, rho2 or the box: the particles' mass over the box's area is " +
                                              problem_check::number(mass / (len[0] * len[1])) + " (--set rho1=R1 rho2=R2)"
                                        : "gamma or p0: the median pressure is " + problem_check::number(pr[pr.size() / 2]) +
                                              " (--set p0=P or gamma=G; SWIFT's gamma is fixed when it is built: "
                                              "--with-adiabatic-index)");
}

// One snapshot of the Kelvin-Helmholtz layer: its time (the file's; a series needs each one) and
// McNally et al.'s mode amplitude M over the file's box (the unit box where it states none).
Result score_kh(const Params& p, const Snapshot& s) {
  const std::string who = "kh";
  require_dim(s, 2, who);
  if (!s.time) throw InputError(s.path.string() + ": no time in the snapshot (kh fits a growth rate to the files' times)");
  positive(s, "rho", who);
  positive(s, "m", who);
  sph::Vec<2> lo{0.0, 0.0}, len{1.0, 1.0};
  std::string from = "the unit box [0, 1)^2: the file states no box";
  if (const auto box = s.stated.find("box"); box != s.stated.end() && box->second.value.size() >= 4) {
    lo = {box->second.value[0], box->second.value[2]};
    len = {box->second.value[1] - box->second.value[0], box->second.value[3] - box->second.value[2]};
    from = "the file's box (" + box->second.from + ")";
  }
  if (!(len[0] > 0.0 && len[1] > 0.0)) throw InputError(s.path.string() + ": kh needs a box of positive size");
  Result r;
  check_layers(r, p, s, len);
  r.extra["t"] = *s.time;
  r.extra["M"] = kh::mode_amplitude(vectors<2>(s, "", who), vectors<2>(s, "v", who), s.at("m", who), s.at("rho", who), lo, len);
  r.extra["box_from"] = from;
  return r;
}

Result score_kh_series(const Params& p, const std::vector<Result>& each) {
  std::vector<double> t, M;
  for (const Result& r : each) t.push_back(r.extra["t"].get<double>()), M.push_back(r.extra["M"].get<double>());
  const double lo = p.real("t_fit_lo"), hi = p.real("t_fit_hi");
  const kh::GrowthFit f = kh::fit_growth(t, M, lo, hi);
  if (f.samples < 3)
    throw InputError("kh: " + std::to_string(f.samples) + " of the " + std::to_string(each.size()) +
                     " snapshots lie in the fit window [t_fit_lo, t_fit_hi] = [" + shortest(lo) + ", " + shortest(hi) +
                     "]: give at least 3 (or --set the window)");
  Result r;
  kh::growth_result(r, p, f, t, M);
  r.extra["problem_check"] = each.front().extra["problem_check"];
  for (std::size_t k = 0; k < each.size(); ++k)  // a snapshot of another problem makes the series one
    if (each[k].verdict == "mismatch") {
      r.verdict = "mismatch";
      r.extra["mismatch"] = "snapshot " + std::to_string(k + 1) + " of " + std::to_string(each.size()) + ": " +
                            each[k].extra["mismatch"].get<std::string>();
      break;
    }
  r.extra["series_t"] = t;
  r.extra["series_M"] = M;
  r.extra["series_note"] = "growth rate " + shortest(f.rate) + " +- " + shortest(f.stderr_rate) + " from " +
                           std::to_string(f.samples) + " snapshots in [" + shortest(lo) + ", " + shortest(hi) +
                           "] against the linear eigenmode's " + shortest(r.extra["growth_rate_ref"].get<double>()) +
                           "; box: " + each.front().extra["box_from"].get<std::string>();
  return r;
}

}  // namespace
}  // namespace sphv::kh_snapshots_case

namespace sphv::kh {

Scorer scorer() {
  return {"", kh_snapshots_case::score_kh, {}, Resolution::none, snapshot_columns::real_gamma, {},
          kh_snapshots_case::score_kh_series};
}

// The lattice in the periodic unit box [0, 1)^2 with masses rho(y) dx^2, the shear layer's v_x, the
// seed's v_y and u = p0 / ((gamma - 1) rho) (kh/setup.hpp); rho the profile's (a run replaces it
// by the summation (27)). The unit box is SWIFT's layout too.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  return ic_layout::placed(ic_layout::at_start(initial_particles(p), p.real("gamma")), p.real("gamma"), layout, 0.0, 1.0);
}

}  // namespace sphv::kh
