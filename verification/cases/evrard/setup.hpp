#pragma once
// The Evrard sphere's initial state, shared by `sphv run` and `sphv ic`: the unit sphere with
// rho = 1 / (2 pi r) (M(<r) = r^2), at rest, u = u0: a cubic lattice cut to the unit ball (uniform,
// M(<r) = r^3) stretched radially r -> r^(3/2), which makes M(<r) = r^2. Equal masses; h from (50)
// with the target density (the run iterates it with the summation density).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sph/core/lattice.hpp"

namespace sphv::evrard {

inline sph::Particles<3> sphere(long n, double u0, double hfact) {
  const int side = std::max(2, static_cast<int>(std::lround(std::cbrt(6.0 * n / std::numbers::pi))));  // pi side^3 / 6 ~ n
  sph::Box<3> cube = sph::unit_box<3>(false);
  cube.lo = sph::Vec<3>::Constant(-1.0);
  const sph::Particles<3> grid = sph::lattice<3>(side, cube, 1.0, hfact);
  sph::Particles<3> p;
  std::vector<sph::Vec<3>> x;
  for (const auto& xi : grid.x)
    if (xi.norm() < 1.0) x.push_back(xi * std::sqrt(xi.norm()));  // |x| -> |x|^(3/2)
  p.resize(x.size());
  p.x = x;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = std::max(p.x[i].norm(), 1e-3);
    p.m[i] = 1.0 / p.size();
    p.u[i] = u0;
    p.rho[i] = 1.0 / (2.0 * std::numbers::pi * r);
    p.h[i] = hfact * std::cbrt(p.m[i] / p.rho[i]);  // (50) with the target density
  }
  return p;
}

}  // namespace sphv::evrard
