// gravity and other codes' files: the scorer of `sphv score` (the code's accelerations against the direct sum).
#include "verification/cases/gravity/snapshots.hpp"

#include "sph/gravity/tree_gravity.hpp"
#include "verification/cases/gravity/compare.hpp"
#include "verification/io/gravity_input.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::gravity_snapshots_case {
namespace {

using namespace snapshot_columns;

Result score_gravity(const Params& prm, const Snapshot& s) {
  const std::string who = "gravity (the code's accelerations ax, ay, az)";
  const gravity::ParticleSet set = gravity_particles(s, prm.real("eps"));
  sph::GravityField code;
  code.a = vectors<3>(s, "a", who);
  if (s.has("phi")) code.phi = s.at("phi", who);
  const auto d = gravity::direct(set.x, set.m, prm.real("eps"));
  const auto p = gravity::percentiles(finite_values(gravity::relative_force_error(code, d)));
  Result r;
  r.errors = {{"force_p50", p.p50}, {"force_p90", p.p90}, {"force_p99", p.p99}, {"force_max", p.max}};
  if (s.has("phi")) {
    const double wd = gravity::potential_energy(set.m, d.phi), wc = gravity::potential_energy(set.m, code.phi);
    r.errors["energy"] = std::abs(wc - wd) / std::abs(wd);
  }
  return r;
}

}  // namespace
}  // namespace sphv::gravity_snapshots_case

namespace sphv::gravity {

Scorer scorer() { return {"", gravity_snapshots_case::score_gravity, {}}; }

}  // namespace sphv::gravity
