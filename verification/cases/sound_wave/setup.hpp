#pragma once
// The sound wave's initial state, shared by `sphv run` and `sphv ic`: a cubic lattice of n^d
// particles in the periodic unit box [0, 1)^d (also SWIFT's layout), all of mass rho0 / n^d,
// displaced along x so that the mass left of every particle is that of the wave's density
// rho0 (1 + A sin(k x)): particle i of lattice coordinate x0 = (i + 1/2) / n sits at the root of
// x + (A / k) (1 - cos(k x)) = x0 (Newton, to round-off), so the density is realised exactly in
// the continuum limit (not only to first order in A). v_x and u from the reference at t = 0,
// h = hfact / n (the run iterates (50) from it).
#include <cmath>

#include "reference/sound_wave.hpp"
#include "sph/core/lattice.hpp"
#include "verification/harness/params.hpp"

namespace sphv::sound_wave {

inline reference::AcousticWave wave(const Params& p) {
  return {p.real("rho0"), p.real("c_s"), p.real("gamma"), p.real("A"), 1.0};
}

// Root of x + (A/k)(1 - cos(k x)) = x0: the mapping is monotonic for |A| < 1 (its derivative
// 1 + A sin(k x) > 0), and Newton from x0 converges in a few steps for the small A allowed.
inline double displaced(double x0, double A, double k) {
  double x = x0;
  for (int it = 0; it < 50; ++it) {
    const double f = x + (A / k) * (1.0 - std::cos(k * x)) - x0, df = 1.0 + A * std::sin(k * x);
    const double dx = f / df;
    x -= dx;
    if (std::abs(dx) < 1e-16) break;
  }
  return x;
}

template <int D>
sph::Particles<D> initial_particles(const Params& prm) {
  const reference::AcousticWave w = wave(prm);
  const int n = static_cast<int>(prm.integer("n"));
  sph::Particles<D> p = sph::lattice<D>(n, sph::unit_box<D>(true), prm.real("rho0"), prm.real("hfact"));
  const double A = prm.real("A"), k = w.wave_number();
  for (std::size_t i = 0; i < p.size(); ++i) {
    double& x = p.x[i][0];
    x = displaced(x, A, k);
    x -= std::floor(x);  // [0, 1)
    const reference::AcousticState s = w.at(x, 0.0);
    p.v[i][0] = s.v;
    p.rho[i] = s.rho;
    p.u[i] = s.u;
  }
  return p;
}

}  // namespace sphv::sound_wave
