// noh and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/noh/snapshots.hpp"

#include <cmath>

#include "verification/harness/case.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/noh/errors.hpp"
#include "verification/cases/noh/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::noh_snapshots_case {
namespace {

using namespace snapshot_columns;

Result score_noh(const Params& prm, const Snapshot& s) {
  const std::string who = "noh";
  positive(s, "rho", who);
  positive(s, "m", who);
  Result r;
  by_dimension(prm, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    const auto c = radial::centre<D>(prm);
    noh::measure<D>(r, vectors<D>(s, "", who, c), vectors<D>(s, "v", who), s.at("m", who), s.at("rho", who),
                    internal_energy(s, prm.real("gamma"), who), prm.real("t_end"), prm.real("gamma"), prm.integer("n"));
    return r;
  });
  if (!r.extra["shock_front_found"].get<bool>())
    r.verdict = "no shock front: the binned density never rises through the post-/pre-shock midpoint (rho_post and "
                "shock_speed not computed; is the centre right?)";
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
