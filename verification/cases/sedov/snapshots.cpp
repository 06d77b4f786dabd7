// sedov and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/sedov/snapshots.hpp"

#include "reference/sedov.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/sedov/errors.hpp"
#include "verification/cases/sedov/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/problem_check.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::sedov_snapshots_case {
namespace {

using namespace snapshot_columns;

// The ambient gas ahead of the shock: the particles farther than 2 support radii beyond R(t)
// (the front smeared over about a support on either side, problem_check.hpp's supports) are at
// rest at rho0: median rho within 5 % of rho0 and median |v| within 5 % of the shock speed U, at
// most a tenth of them off by more (SWIFT's 32^3 blast, tests/data: the farthest particle 1.1 % off
// in rho and 6.5e-4 U in |v|; SPH-EXA's, 0.07 % and 7e-6 U; sphv's 2D n = 32: 0.02 %).
constexpr double reach = 2.0, tolerance = 0.05, max_off_share = 0.1;

std::vector<std::size_t> ambient(const std::vector<double>& r, const std::vector<double>& support, double R) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < r.size(); ++i)
    if (r[i] > R + reach * support[i]) at.push_back(i);
  return at;
}

std::vector<StateCheck> ambient_checks(const std::vector<std::size_t>& at, const std::vector<double>& rho,
                                       const std::vector<double>& speed, double R, double rho0, double U) {
  if (at.empty()) return {};
  const std::string where = "the ambient gas (" + std::to_string(at.size()) + " particles beyond R + " +
                            problem_check::number(reach) + " supports, R = " + problem_check::number(R) + ")";
  return {problem_check::part_check(where, "rho", at, [&](std::size_t i) { return rho[i]; }, [&](std::size_t) { return rho0; },
                                  [&](std::size_t) { return rho0; }, tolerance, max_off_share),
          problem_check::part_check(where, "|v|", at, [&](std::size_t i) { return speed[i]; }, [](std::size_t) { return 0.0; },
                                  [&](std::size_t) { return U; }, tolerance, max_off_share)};
}

// Why the ambient gas is not the problem's: its density (rho0), or a blast that has reached
// farther than E, rho0 and t put it (R grows as (E t^2 / rho0)^(1 / (D + 2))): another time unit
// or E, else the centre.
std::string ambient_cause(const std::vector<std::size_t>& at, const std::vector<double>& r, const std::vector<double>& rho,
                          const std::vector<double>& speed, const std::vector<double>& support,
                          const reference::Sedov& exact, double E, double rho0, double t) {
  std::vector<double> ratio;
  for (std::size_t i : at) ratio.push_back(rho[i] / rho0);
  std::nth_element(ratio.begin(), ratio.begin() + ratio.size() / 2, ratio.end());
  const double median = ratio[ratio.size() / 2];
  if (std::abs(median - 1.0) > tolerance)
    return "rho0: the ambient gas's median density is " + problem_check::number(median * rho0) + ", not rho0 = " +
           problem_check::number(rho0) + " (--set rho0=RHO)";
  for (double f = 1.02; f < 1e4; f *= 1.02) {
    const double R = exact.shock_radius(E, rho0, t * f);
    const auto beyond = ambient(r, support, R);
    if (beyond.size() < 3) break;
    if (problem_check::all_pass(ambient_checks(beyond, rho, speed, R, rho0, exact.shock_speed(E, rho0, t * f))))
      return "the time or E: the blast has reached about R = " + problem_check::number(R) + ", where E and rho0 put it at t = " +
             problem_check::number(t * f) + ", not at the file's t = " + problem_check::number(t) +
             " (a time in other units, or E = " + problem_check::number(E * f * f) + " at this t?)";
  }
  return "the centre (the blast lies elsewhere: --set centre=X,Y[,Z]) or the blast energy E";
}

Result score_sedov(const Params& prm, const Snapshot& s) {
  const std::string who = "sedov";
  positive(s, "rho", who);
  positive(s, "m", who);
  const reference::Sedov exact(static_cast<int>(prm.integer("dim")), prm.real("gamma"));
  if (!(prm.real("t") > 0.0)) throw InputError(s.path.string() + ": sedov needs a time t > 0");
  Result r;
  std::vector<double> radius(s.size()), speed(s.size());
  by_dimension(prm, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    if constexpr (D == 1) throw InputError("sedov: dim must be 2 or 3");
    else {
      const auto c = radial::centre<D>(prm);
      const auto v = s.has("vx") ? vectors<D>(s, "v", who) : std::vector<sph::Vec<D>>{};
      const auto x = vectors<D>(s, "", who, c);
      for (std::size_t i = 0; i < x.size(); ++i) radius[i] = x[i].norm(), speed[i] = v.empty() ? 0.0 : v[i].norm();
      sedov::measure<D>(r, x, v, s.at("m", who), s.at("rho", who),
                        s.has("h") ? s.at("h", who) : std::vector<double>{}, prm.real("h_support"),
                        static_cast<int>(prm.integer("n")), prm.real("E"), prm.real("rho0"), prm.real("t"), exact);
    }
    return r;
  });
  if (r.extra["ball_particles"].get<double>() == 0.0)
    r.verdict = "no particle within 1.2 R of the centre: L1_rho is not a measurement (is the centre right?)";
  else if (!r.extra["front_found"].get<bool>())
    r.verdict = "no shock front: the radial density profile never falls through (rho0 + peak) / 2 beyond its peak";
  const double E = prm.real("E"), rho0 = prm.real("rho0"), t = prm.real("t"), R = exact.shock_radius(E, rho0, t);
  const auto support = problem_check::supports(s, who);
  const auto& rho = s.at("rho", who);
  const auto at = ambient(radius, support, R);
  const auto checks = ambient_checks(at, rho, speed, R, rho0, exact.shock_speed(E, rho0, t));
  apply_problem_check(r, checks,
                      problem_check::all_pass(checks) ? "" : ambient_cause(at, radius, rho, speed, support, exact, E, rho0, t),
                      "no particle lies 2 supports beyond R = " + problem_check::number(R));
  return r;
}

}  // namespace
}  // namespace sphv::sedov_snapshots_case

namespace sphv::sedov {

Scorer scorer() { return {"t", sedov_snapshots_case::score_sedov, end_time, Resolution::per_length, snapshot_columns::real_gamma}; }

// The blast in the periodic box [-0.5, 0.5]^d, centre at the origin (sedov/setup.hpp); SWIFT's
// layout: the box [0, 1]^d, centre (0.5, ...) as in its SedovBlast examples.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    return ic_layout::placed(ic_layout::at_start(sedov::initial_particles<D>(p, p.real("hfact")), p.real("gamma")), p.real("gamma"), layout,
                  0.5, 1.0);
  });
}

}  // namespace sphv::sedov
