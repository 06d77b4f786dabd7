#pragma once
// The isobaric square's initial state, shared by `sphv run` and `sphv ic`, in the periodic unit
// box [0, 1)^d (d = 2, 3).
//
// lattice=two (the default, a sharp step): equal-mass particles on two cubic lattices, the light
// gas on the lattice of spacing 1/n outside the square [1/4, 3/4)^d (n a multiple of 4, so the
// lattice's cells tile the outside exactly) and the dense gas on a lattice of n_in = round(n/2
// contrast^(1/d)) per side of the square (2D, contrast 4: n_in = n, spacing 1/(2n)), of mass
// rho_in (1/2)^d / n_in^d (equal to the light particles' rho_out / n^d where n_in is exact; in 3D
// at contrast 4 the two differ by the rounding of n_in, below 12 % at n >= 16). Each phase then
// has the same neighbour number at the same hfact, and the density jump is carried by the
// particles' spacing, not by their masses: the set-up of Saitoh & Makino 2013 and Hopkins 2015. With
// unequal masses on one lattice a kernel sum across the jump mixes masses four-fold apart and the
// density estimate's error at the interface is larger (lattice=one shows it).
//
// lattice=one: one lattice of spacing 1/n, mass rho(x_i) / n^d from the reference's density (the
// step, or the smooth profile at width > 0, which needs this lattice: no two lattices realise it).
//
// Every particle at rest in the frame of v_adv (v = v_adv along every axis), u from the exact
// density at the uniform pressure, h = hfact times the local spacing (the run iterates (50) from it).
#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/square.hpp"
#include "sph/core/particles.hpp"
#include "verification/harness/params.hpp"

namespace sphv::square {

inline reference::IsobaricSquare problem(const Params& p) {
  return {static_cast<int>(p.integer("dim")), p.real("contrast"), p.real("rho_out"), p.real("p0"),
          p.real("gamma"),                    p.real("v_adv"),    p.real("width")};
}

// Particles per side of the dense lattice (lattice=two).
inline long dense_per_side(long n, long dim, double contrast) {
  return std::lround(0.5 * n * std::pow(contrast, 1.0 / double(dim)));
}

// Adds the sites of a cubic lattice of `side` per side over [lo, lo + len)^D, skipping those
// inside [1/4, 3/4)^D when `outside_only`.
template <int D>
void add_lattice(sph::Particles<D>& p, long side, double lo, double len, bool outside_only, double mass,
                 double hfact) {
  const double dx = len / side;
  long total = 1;
  for (int d = 0; d < D; ++d) total *= side;
  for (long k = 0; k < total; ++k) {
    sph::Vec<D> x;
    long rest = k;
    bool in = true;
    for (int d = 0; d < D; ++d) {
      x[d] = lo + (static_cast<double>(rest % side) + 0.5) * dx;
      rest /= side;
      in = in && x[d] >= 0.25 && x[d] < 0.75;
    }
    if (outside_only && in) continue;
    p.x.push_back(x);
    p.v.push_back(sph::Vec<D>::Zero());
    p.m.push_back(mass);
    p.h.push_back(hfact * dx);
  }
}

template <int D>
sph::Particles<D> initial_particles(const Params& prm) {
  const reference::IsobaricSquare sq = problem(prm);
  const long n = prm.integer("n");
  const double hfact = prm.real("hfact"), cell = std::pow(1.0 / n, D);
  sph::Particles<D> p;
  if (prm.text("lattice") == "two") {
    const long n_in = dense_per_side(n, D, prm.real("contrast"));
    add_lattice<D>(p, n, 0.0, 1.0, true, sq.rho_out() * cell, hfact);
    add_lattice<D>(p, n_in, 0.25, 0.5, false, sq.rho_in() * std::pow(0.5 / n_in, D), hfact);
  } else {
    add_lattice<D>(p, n, 0.0, 1.0, false, 0.0, hfact);
    for (std::size_t i = 0; i < p.x.size(); ++i) p.m[i] = sq.density(p.x[i].data(), 0.0) * cell;
  }
  const std::size_t N = p.x.size();
  p.rho.assign(N, 0.0), p.p.assign(N, 0.0), p.c.assign(N, 0.0), p.u.assign(N, 0.0);
  for (std::size_t i = 0; i < N; ++i) {
    p.v[i].setConstant(sq.advection_speed());
    p.rho[i] = sq.density(p.x[i].data(), 0.0);
    p.u[i] = sq.internal_energy(p.x[i].data(), 0.0);
  }
  return p;
}

}  // namespace sphv::square
