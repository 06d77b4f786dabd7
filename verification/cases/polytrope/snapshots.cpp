// polytrope and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/polytrope/snapshots.hpp"

#include <stdexcept>

#include "verification/harness/case.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/polytrope/errors.hpp"
#include "verification/cases/polytrope/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::polytrope_snapshots_case {
namespace {

using namespace snapshot_columns;

// The star's reference has the file's total mass and K, G of --set (defaults 2 / pi and 1: R = 1
// at M = 1); the centre is the file's box middle, --set centre or the origin (score.cpp records
// which), and the centre of mass's distance from it is reported beside the errors.
Result score_polytrope(const Params& prm, const Snapshot& s) {
  const std::string who = "polytrope";
  positive(s, "rho", who);
  positive(s, "m", who);
  require_dim(s, 3, who);
  const auto& m = s.at("m", who);
  double mass = 0.0;
  for (double mi : m) mass += mi;
  const std::vector<sph::Vec<3>> x = vectors<3>(s, "", who, radial::centre<3>(prm));
  sph::Vec<3> com = sph::Vec<3>::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) com += m[i] * x[i];
  Result r;
  try {
    polytrope::measure(r, polytrope::radii(x, sph::Vec<3>::Zero().eval()), m, s.at("rho", who), prm.real("K"),
                       prm.real("G"), prm.real("t_end"));
  } catch (const std::invalid_argument& e) {  // K or G not positive
    throw InputError(std::string("polytrope: ") + e.what());
  }
  r.extra["centre_of_mass_offset"] = (com / mass).norm();
  return r;
}

}  // namespace
}  // namespace sphv::polytrope_snapshots_case

namespace sphv::polytrope {

Scorer scorer() {
  return {"t_end", polytrope_snapshots_case::score_polytrope, snapshot_columns::real_t_end, Resolution::count,
          snapshot_columns::real_gamma, {"K", "G"}};
}

// The stretched lattice of the n = 1 polytrope around the origin, at rest, rho and u = K rho /
// (gamma - 1) of the profile, h from (50) with the profile's density (polytrope/setup.hpp; a run
// replaces rho by the summation (27) and u by K rho_i / (gamma - 1) with it). SWIFT's layout: the
// star at the centre (5, 5, 5) of a box of side 10, five radii across at K = 2 / pi, G = 1.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  const reference::Polytrope1 s = star(p);
  const double side = 10.0 * s.radius();
  return ic_layout::placed(ic_layout::at_start(sphere(p.integer("n"), s, p.real("gamma"), p.real("hfact")), p.real("gamma")),
                           p.real("gamma"), layout, side / 2.0, side);
}

}  // namespace sphv::polytrope
