// sound_wave and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/sound_wave/snapshots.hpp"

#include "reference/sound_wave.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/sound_wave/errors.hpp"
#include "verification/cases/sound_wave/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/problem_check.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::sound_wave_snapshots_case {
namespace {

using namespace snapshot_columns;

// The wave's mean state, which no linear wave changes: the mean density (the particles' mass over
// the box's volume) rho0 within 1e-3 relative (a code conserves mass; the file's float32 masses
// sum within 1e-7), the mass-weighted mean pressure rho0 c_s^2 / gamma within 5 % (the density
// sum's error on a lattice, and the wave's second-order mean of order A^2) and the mean v_x 0
// within 5 % of c_s (momentum is conserved; the wave's amplitude is A c_s). A gas of another gamma
// or sound speed is off in p by tens of %.
void check_mean_state(Result& r, const Params& prm, const Snapshot& s, double lo, double L) {
  const std::string who = "sound_wave";
  const double rho0 = prm.real("rho0"), c_s = prm.real("c_s"), gamma = prm.real("gamma"), p0 = rho0 * c_s * c_s / gamma;
  double volume = L;
  for (int d = 1; d < s.dim; ++d) {
    const auto box = s.stated.find("box");
    volume *= box != s.stated.end() && box->second.value.size() >= static_cast<std::size_t>(2 * d + 2)
                  ? box->second.value[2 * d + 1] - box->second.value[2 * d]
                  : 1.0;
  }
  const auto &m = s.at("m", who), &vx = s.at("vx", who), &rho = s.at("rho", who);
  const auto p = pressure(s, gamma, who);
  double mass = 0.0, momentum = 0.0, mp = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) mass += m[i], momentum += m[i] * vx[i], mp += m[i] * p[i];
  const std::string where = "the mean state (" + std::to_string(s.size()) + " particles in the box of volume " +
                            problem_check::number(volume) + ", x from " + problem_check::number(lo) + ")";
  const std::vector<StateCheck> checks = {{where, "mean rho", mass / volume, rho0, rho0, 1e-3},
                                          {where, "mean v_x", momentum / mass, 0.0, c_s, 0.05},
                                          {where, "mean p", mp / mass, p0, p0, 0.05}};
  std::string cause;
  if (!checks[0].pass())
    cause = "rho0 or the box: the particles' mass over the box's volume is " + problem_check::number(mass / volume) +
            " (--set rho0=RHO, or a file that states its box)";
  else if (!checks[2].pass()) {
    double mu = 0.0;
    if (s.has("u"))
      for (std::size_t i = 0; i < s.size(); ++i) mu += m[i] * rho[i] * s.columns.at("u")[i];
    cause = "gamma or c_s: the mean pressure is " + problem_check::number(mp / mass) + ", rho0 c_s^2 / gamma = " +
            problem_check::number(p0) +
            (s.has("u") ? " (the particles' u gives it at gamma " + problem_check::number(1.0 + p0 * mass / mu) + ")" : "") +
            " (--set gamma=G or c_s=C; SWIFT's gamma is fixed when it is built: --with-adiabatic-index)";
  } else if (!checks[1].pass()) {
    cause = "the velocity: the gas moves as a whole at " + problem_check::number(momentum / mass) + " (another frame?)";
  }
  apply_problem_check(r, checks, cause);
}

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
  check_mean_state(r, prm, s, lo, L);
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
