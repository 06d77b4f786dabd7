// heat and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/heat/snapshots.hpp"

#include "verification/harness/case.hpp"
#include "verification/cases/heat/errors.hpp"
#include "verification/cases/heat/lattice.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/problem_check.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::heat_snapshots_case {
namespace {

using namespace snapshot_columns;

Result score_heat(const Params& prm, const Snapshot& s) {
  const std::string who = "heat";
  positive(s, "rho", who);
  const int D = static_cast<int>(prm.integer("dim"));
  std::vector<std::vector<double>> coords(s.size(), std::vector<double>(D));
  for (int a = 0; a < D; ++a) {
    const auto& c = s.at(std::string(1, "xyz"[a]), who);
    for (std::size_t i = 0; i < c.size(); ++i) coords[i][a] = c[i];
  }
  const double cv = prm.real("c_v");
  const double chi = heat::diffusivity(s.at("rho", who), prm.real("K"), cv);
  const auto& [error, exact] = heat::setups.at(prm.text("setup"));
  Result r;
  const auto& u = s.at("u", who);
  const auto expected = exact(coords, prm.real("t_end"), chi, cv);
  r.errors[error] = heat::rms_error(u, expected);
  // Conduction moves heat and keeps its total: the particles' mean u is the exact field's mean at
  // the same points within 5 % of the amplitude c_v A (the SPH conduction is pairwise symmetric:
  // it conserves the total to round-off). Another c_v, T0 or unit of energy is off by more.
  double mean = 0.0, mean_exact = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) mean += u[i] / u.size(), mean_exact += expected[i] / u.size();
  apply_problem_check(r, {{"the gas (" + std::to_string(u.size()) + " particles)", "mean u", mean, mean_exact, cv * heat::A, 0.05}},
                      "c_v or the energy unit: the mean u is " + problem_check::number(mean) + ", c_v T0 = " +
                          problem_check::number(mean_exact) + " for c_v = " + problem_check::number(cv) + " (--set c_v=C)");
  r.extra["chi"] = chi;
  r.extra["setup"] = prm.text("setup");
  return r;
}

}  // namespace
}  // namespace sphv::heat_snapshots_case

namespace sphv::heat {

Scorer scorer() { return {"t_end", heat_snapshots_case::score_heat, snapshot_columns::real_t_end}; }

// The lattice in the periodic unit box with the summation density, u = c_v T(x, 0) of the chosen
// set-up (setup=gauss or sine; heat/errors.hpp); no pressure (conduction only). The unit box is
// SWIFT's layout too.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    const ParticleSet<D> set(static_cast<int>(p.integer("n")), p.real("hfact"), p.real("jitter"));
    sph::Particles<D> q = set.p;
    std::vector<std::vector<double>> coords(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) coords[i] = set.coords(i);
    const double cv = p.real("c_v");
    q.u = setups.at(p.text("setup")).second(coords, 0.0, diffusivity(q.rho, p.real("K"), cv), cv);
    return ic_layout::placed(ic_layout::at_start(q, std::nullopt), std::nullopt, layout, 0.0, 1.0);
  });
}

}  // namespace sphv::heat
