#pragma once
// The Sedov blast's initial state, shared by `sphv run` and `sphv ic`: a lattice of n^d particles
// of density rho0 in the periodic box [-0.5, 0.5]^d with the blast centre at the origin; every
// particle has u_ambient, and the energy E is shared by kernel weight W(r, r_b) among those
// within r_b = r_blast R_target of the centre (see sedov.cpp for why r_b is a fraction of R).
#include "sph/core/lattice.hpp"
#include "sph/kernel/cubic_spline.hpp"
#include "verification/cases/sedov/errors.hpp"

namespace sphv::sedov {

template <int D>
sph::Box<D> box() {
  sph::Box<D> b = sph::unit_box<D>(true);
  b.lo = sph::Vec<D>::Constant(-0.5);
  b.hi = sph::Vec<D>::Constant(0.5);
  return b;
}

template <int D>
sph::Particles<D> initial_particles(const Params& prm, double hfact) {
  const double E = prm.real("E");
  sph::Particles<D> p = sph::lattice<D>(static_cast<int>(prm.integer("n")), box<D>(), prm.real("rho0"), hfact);
  const double r_b = prm.real("r_blast") * R_target;
  double wsum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) wsum += p.m[i] * sph::CubicSpline<D>::W(p.x[i].norm(), r_b);
  for (std::size_t i = 0; i < p.size(); ++i)
    p.u[i] = prm.real("u_ambient") + E * sph::CubicSpline<D>::W(p.x[i].norm(), r_b) / wsum;
  return p;
}

}  // namespace sphv::sedov
