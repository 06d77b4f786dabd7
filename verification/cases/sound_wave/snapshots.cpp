// sound_wave and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/sound_wave/snapshots.hpp"

#include "reference/sound_wave.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/sound_wave/errors.hpp"
#include "verification/cases/sound_wave/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::sound_wave_snapshots_case {
namespace {

using namespace snapshot_columns;

// The wave along x with one wavelength across the box: the file's box along x where it states
// one ([lo, hi): wavelength hi - lo, phase from lo), else the unit box [0, 1) of sphv's layout.
Result score_sound_wave(const Params& prm, const Snapshot& s) {
  const std::string who = "sound_wave";
  positive(s, "rho", who);
  positive(s, "m", who);
  double lo = 0.0, L = 1.0;
  std::string from = "the unit box [0, 1): the file states no box";
  if (const auto box = s.stated.find("box"); box != s.stated.end() && box->second.value.size() >= 2) {
    lo = box->second.value[0], L = box->second.value[1] - box->second.value[0];
    from = "the file's box along x (" + box->second.from + ")";
  }
  if (!(L > 0.0)) throw InputError(s.path.string() + ": sound_wave needs a box of positive length along x");
  const reference::AcousticWave w(prm.real("rho0"), prm.real("c_s"), prm.real("gamma"), prm.real("A"), L);
  Result r;
  by_dimension(prm, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    auto x = vectors<D>(s, "", who);
    for (auto& xi : x) xi[0] -= lo;
    sound_wave::measure<D>(r, x, vectors<D>(s, "v", who), s.at("m", who), s.at("rho", who), prm.real("t_end"), w,
                           prm.real("A"), prm.integer("n"));
    return r;
  });
  r.extra["wavelength"] = L;
  r.extra["wavelength_from"] = from;
  return r;
}

}  // namespace
}  // namespace sphv::sound_wave_snapshots_case

namespace sphv::sound_wave {

Scorer scorer() { return {"t_end", sound_wave_snapshots_case::score_sound_wave, snapshot_columns::real_t_end, Resolution::per_length, snapshot_columns::real_gamma}; }

// The displaced lattice in the periodic unit box [0, 1)^d (sound_wave/setup.hpp), v_x and u of
// the wave, rho the wave's exact density (a run replaces it by the summation (27)); the unit box
// is SWIFT's layout too.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    return ic_layout::placed(ic_layout::at_start(initial_particles<D>(p), p.real("gamma")), p.real("gamma"), layout, 0.0, 1.0);
  });
}

}  // namespace sphv::sound_wave
