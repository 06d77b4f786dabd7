// evrard and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/evrard/snapshots.hpp"

#include <cmath>
#include <stdexcept>

#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/evrard/errors.hpp"
#include "verification/cases/evrard/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::evrard_snapshots_case {
namespace {

using namespace snapshot_columns;

Result score_evrard(const Params& prm, const Snapshot& s) {
  const std::string who = "evrard";
  positive(s, "rho", who);
  positive(s, "m", who);
  require_dim(s, 3, who);
  double mass = 0.0;
  for (double m : s.at("m", who)) mass += m;
  // The reference is in units G = M = R = 1: a units check, not an accuracy bound.
  if (!(std::abs(mass - 1.0) <= 1e-3))
    throw InputError(s.path.string() + ": the particles' total mass is " + std::to_string(mass) +
                     "; evrard scores the sphere in units G = M = R = 1 (rescale the snapshot)");
  const double gamma = prm.real("gamma");
  const int zones = static_cast<int>(prm.integer("zones"));
  const double t = prm.real("t_end"), u0 = prm.real("u0");
  auto reference = [&](int z) -> const reference::EvrardSolution& {
    try {
      return evrard::reference_solution(z, gamma, u0, t);
    } catch (const std::invalid_argument& e) {  // the 1D solver's step budget or a zone gone bad
      throw InputError(s.path.string() + ": no 1D reference at its time " + std::to_string(t) + ": " + e.what());
    }
  };
  const auto& ref = reference(zones);
  const auto& half = reference(zones / 2);
  Result r;
  evrard::measure_profiles(r, vectors<3>(s, "", who, radial::centre<3>(prm)), vectors<3>(s, "v", who), s.at("m", who),
                           s.at("rho", who), internal_energy(s, gamma, who), ref.at_end, half.at_end, t);
  return r;
}

}  // namespace
}  // namespace sphv::evrard_snapshots_case

namespace sphv::evrard {

Scorer scorer() { return {"t_end", evrard_snapshots_case::score_evrard, snapshot_columns::real_t_end, Resolution::count, snapshot_columns::real_gamma}; }

// The unit sphere around the origin, h before the run's iteration (evrard/setup.hpp); SWIFT's
// layout: the box of side 100 with the sphere at its centre (50, 50, 50), as its EvrardCollapse_3D.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  return ic_layout::placed(ic_layout::at_start(sphere(p.integer("n"), p.real("u0"), p.real("hfact")), p.real("gamma")),
                p.real("gamma"), layout, 50.0, 100.0);
}

}  // namespace sphv::evrard
