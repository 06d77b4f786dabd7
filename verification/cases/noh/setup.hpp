#pragma once
// Noh's implosion's initial state, shared by `sphv run` and `sphv ic`: a lattice of spacing 1/n
// cut to the ball r < R0 around the origin, rho = 1, unit inflow v = -x / |x|, u = u_cold, h = hfact / n.
#include <cmath>
#include <string>

#include "sph/core/lattice.hpp"
#include "verification/cases/noh/errors.hpp"
#include "verification/harness/params.hpp"

namespace sphv::noh {

// Gas out to R0. The gas that meets the shock by t_end started within R_s + t_end = 4 t_end / 3;
// the shock runs ahead of R_s by up to ~5% in 1D/2D (measured), so a margin of 10% of that, plus
// one initial support radius for the neighbourhood of the last gas that matters. (A bare 3 h0 is
// 0.7 of the radius at the 3D gate size, n = 10, and tripled its particles.)
inline double gas_radius(double t_end, double h0) { return 1.1 * 4.0 / 3.0 * t_end + h0; }

// Refuses a run of more than max_particles (n counts per unit length in every dimension: the 1D
// default means ~1e5 particles in 2D and ~2e7 in 3D). Not in the case's validate: a variant's
// settings are validated with the default n before its levels.
inline void check_size(const Params& p) {
  const long dim = p.integer("dim"), n = p.integer("n");
  const double N = radial::ball_volume(static_cast<int>(dim), gas_radius(p.real("t_end"), p.real("hfact") / n)) * std::pow(double(n), dim);
  const double cap = p.real("max_particles");
  if (N > cap)
    throw InputError("noh: n = " + std::to_string(n) + " in " + std::to_string(dim) + "D means ~" +
                     std::to_string(static_cast<long>(N)) + " particles (max_particles " +
                     std::to_string(static_cast<long>(cap)) +
                     "); n counts per unit length: use n ~ 50 in 2D, 10-20 in 3D, or raise max_particles");
}

template <int D>
struct Setup {
  sph::Box<D> box;       // open, one spacing beyond the lattice
  sph::Particles<D> p;
  double R0 = 0.0;
};

template <int D>
Setup<D> initial(const Params& prm, double hfact) {
  const int n = static_cast<int>(prm.integer("n"));
  const double dx = 1.0 / n, h0 = hfact * dx;
  Setup<D> s;
  s.R0 = gas_radius(prm.real("t_end"), h0);
  const int k = static_cast<int>(std::ceil(s.R0 / dx));
  s.box = sph::unit_box<D>(false);
  s.box.lo = sph::Vec<D>::Constant(-(k + 1) * dx);
  s.box.hi = sph::Vec<D>::Constant((k + 1) * dx);
  const sph::Particles<D> all = sph::lattice<D>(
      2 * k, sph::Box<D>{s.box.lo + sph::Vec<D>::Constant(dx), s.box.hi - sph::Vec<D>::Constant(dx), s.box.periodic}, 1.0, hfact);
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all.x[i].norm() < s.R0) {
      const double r = all.x[i].norm();
      s.p.x.push_back(all.x[i]);
      s.p.v.push_back(-all.x[i] / r);  // unit inflow
      s.p.m.push_back(all.m[i]);
      s.p.rho.push_back(1.0);
      s.p.p.push_back(0.0);
      s.p.c.push_back(0.0);
      s.p.u.push_back(prm.real("u_cold"));
      s.p.h.push_back(h0);
    }
  return s;
}

}  // namespace sphv::noh
