#pragma once
// The n = 1 polytrope's initial state, shared by `sphv run` and `sphv ic`: a cubic lattice cut to
// the unit ball (uniform, mass fraction |x|^3 within |x|) stretched radially by the inverse of the
// polytrope's cumulative mass, |x| -> r(q = |x|^3) (reference::Polytrope1), so that equal masses
// M / N follow rho(r) = rho_c sin(pi r / R) / (pi r / R); at rest, h from (50) with the target
// density. u = K rho / (gamma - 1) with gamma = 2 makes p = (gamma - 1) rho u = K rho^2: the
// adiabatic gas keeps p = K rho^2 while the flow stays adiabatic (a run sets u from its summation
// density (27), the ic from the target density).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/polytrope.hpp"
#include "sph/core/lattice.hpp"
#include "verification/harness/params.hpp"

namespace sphv::polytrope {

// The star of the parameters M = 1, K and G (R = sqrt(pi K / (2 G)); the defaults K = 2 / pi,
// G = 1 give R = 1).
inline reference::Polytrope1 star(const Params& p) { return reference::Polytrope1(1.0, p.real("K"), p.real("G")); }

// Cells per diameter of the cube around the ball: pi side^3 / 6 ~ n.
inline int lattice_side(long n) {
  return std::max(2, static_cast<int>(std::lround(std::cbrt(6.0 * n / std::numbers::pi))));
}

inline sph::Particles<3> sphere(long n, const reference::Polytrope1& star, double gamma, double hfact) {
  const int side = lattice_side(n);
  sph::Box<3> cube = sph::unit_box<3>(false);
  cube.lo = sph::Vec<3>::Constant(-1.0);
  const sph::Particles<3> grid = sph::lattice<3>(side, cube, 1.0, hfact);
  std::vector<sph::Vec<3>> x;
  for (const auto& xi : grid.x) {
    const double s = xi.norm();
    if (s < 1.0) x.push_back(s > 0.0 ? (xi * (star.radius_of_mass_fraction(s * s * s) / s)).eval() : xi);
  }
  sph::Particles<3> p;
  p.resize(x.size());
  p.x = x;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.m[i] = star.mass() / p.size();
    p.rho[i] = star.density(p.x[i].norm());
    p.u[i] = star.K() * p.rho[i] / (gamma - 1.0);
    p.h[i] = hfact * std::cbrt(p.m[i] / p.rho[i]);  // (50) with the target density
  }
  return p;
}

}  // namespace sphv::polytrope
