#pragma once
// The Gresho-Chan vortex's initial state, shared by `sphv run` and `sphv ic`: a square lattice of
// n x n particles in the periodic unit box [0, 1)^2 (sph::lattice: particle centres at
// ((i + 1/2) / n, (j + 1/2) / n), also SWIFT's layout), all of mass rho0 / n^2, the vortex centred
// at (1/2, 1/2); v = v_phi(r) e_phi and u = p(r) / ((gamma - 1) rho0) from the exact solution
// (reference/gresho), h = hfact / n (the run iterates (50) from it).
#include <algorithm>
#include <cmath>

#include "reference/gresho.hpp"
#include "sph/core/lattice.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/harness/params.hpp"

namespace sphv::gresho {

inline reference::GreshoVortex vortex(const Params& p) {
  return {p.real("rho0"), p.real("p0"), p.real("gamma")};
}

// The vortex's centre: sphv run and sphv ic put it at the middle of the unit box; sphv score reads
// it from the file (the middle of its box, score.cpp) or --set.
inline ParamSpec centre_param() {
  return {"centre", ParamSpec::Kind::Text, "0.5,0.5",
          "centre x,y of the vortex in a scored snapshot (sphv score: the middle of the file's box unless set; "
          "sphv run and ic: 0.5,0.5, the middle of the unit box)"};
}
inline void check_centre(const Params& p) {
  if (radial::centre<2>(p) != sph::Vec<2>(0.5, 0.5))
    throw InputError("gresho: centre is for scoring snapshots (sphv score); sphv run and ic put the vortex at 0.5,0.5");
}

// The set-up's pressure against radial equilibrium: the largest |p(r) - p_quad(r)| / p(r) on 200
// radii across the box (0 < r <= 0.7), p the closed form the particles' u comes from, p_quad the
// quadrature of dp/dr = rho0 v_phi^2 / r from the centre (reference::GreshoVortex).
inline double equilibrium_error(const reference::GreshoVortex& g) {
  double e = 0.0;
  for (int k = 1; k <= 200; ++k) {
    const double r = 0.7 * k / 200.0;
    e = std::max(e, std::abs(g.pressure(r) - g.pressure_by_quadrature(r)) / g.pressure(r));
  }
  return e;
}

inline sph::Particles<2> initial_particles(const Params& prm) {
  const reference::GreshoVortex g = vortex(prm);
  const int n = static_cast<int>(prm.integer("n"));
  sph::Particles<2> p = sph::lattice<2>(n, sph::unit_box<2>(true), g.density(), prm.real("hfact"));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double dx = p.x[i][0] - 0.5, dy = p.x[i][1] - 0.5, r = std::hypot(dx, dy);
    const double v = r > 0.0 ? g.v_phi(r) / r : 0.0;
    p.v[i] = sph::Vec<2>(-v * dy, v * dx);
    p.u[i] = g.internal_energy(r);
  }
  return p;
}

}  // namespace sphv::gresho
