// sedov and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/sedov/snapshots.hpp"

#include "reference/sedov.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/sedov/errors.hpp"
#include "verification/cases/sedov/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::sedov_snapshots_case {
namespace {

using namespace snapshot_columns;

Result score_sedov(const Params& prm, const Snapshot& s) {
  const std::string who = "sedov";
  positive(s, "rho", who);
  positive(s, "m", who);
  const reference::Sedov exact(static_cast<int>(prm.integer("dim")), prm.real("gamma"));
  if (!(prm.real("t") > 0.0)) throw InputError(s.path.string() + ": sedov needs a time t > 0");
  Result r;
  by_dimension(prm, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    if constexpr (D == 1) throw InputError("sedov: dim must be 2 or 3");
    else {
      const auto c = radial::centre<D>(prm);
      const auto v = s.has("vx") ? vectors<D>(s, "v", who) : std::vector<sph::Vec<D>>{};
      sedov::measure<D>(r, vectors<D>(s, "", who, c), v, s.at("m", who), s.at("rho", who),
                        s.has("h") ? s.at("h", who) : std::vector<double>{}, prm.real("h_support"),
                        static_cast<int>(prm.integer("n")), prm.real("E"), prm.real("rho0"), prm.real("t"), exact);
    }
    return r;
  });
  if (r.extra["ball_particles"].get<double>() == 0.0)
    r.verdict = "no particle within 1.2 R of the centre: L1_rho is not a measurement (is the centre right?)";
  else if (!r.extra["front_found"].get<bool>())
    r.verdict = "no shock front: the binned density never falls through (rho0 + peak) / 2 beyond its peak";
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
