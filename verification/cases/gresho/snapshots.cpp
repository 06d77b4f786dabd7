// gresho and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/gresho/snapshots.hpp"

#include "verification/harness/case.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/gresho/errors.hpp"
#include "verification/cases/gresho/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::gresho_snapshots_case {
namespace {

using namespace snapshot_columns;

// The vortex at `centre` (by default the middle of the file's box, complete_centre in score.cpp),
// at the file's time (stationary: the exact profile is the same at every time).
Result score_gresho(const Params& prm, const Snapshot& s) {
  const std::string who = "gresho";
  positive(s, "m", who);
  require_dim(s, 2, who);
  Result r;
  gresho::measure(r, vectors<2>(s, "", who, radial::centre<2>(prm)), vectors<2>(s, "v", who), s.at("m", who),
                  prm.real("t_end"), gresho::vortex(prm), prm.integer("n"));
  return r;
}

}  // namespace
}  // namespace sphv::gresho_snapshots_case

namespace sphv::gresho {

Scorer scorer() {
  return {"t_end", gresho_snapshots_case::score_gresho, snapshot_columns::real_t_end, Resolution::per_length,
          snapshot_columns::real_gamma};
}

// The square lattice in the periodic unit box [0, 1)^2 with the vortex at its centre (1/2, 1/2)
// (gresho/setup.hpp): v and u of the exact vortex, rho = rho0 (a run replaces it by the summation
// (27)); the unit box is SWIFT's layout too.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  check_centre(p);
  return ic_layout::placed(ic_layout::at_start(initial_particles(p), p.real("gamma")), p.real("gamma"), layout, 0.0,
                           1.0);
}

}  // namespace sphv::gresho
