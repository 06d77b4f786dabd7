#pragma once
// The Kelvin-Helmholtz layer's initial state, shared by `sphv run` and `sphv ic`: McNally, Lyra &
// Passy (2012, ApJS 201, 18, section 2) in the periodic unit box [0, 1)^2: density and v_x from
// reference::KhProfile (rho 1 outside, 2 inside y in (1/4, 3/4), v_x +-U, piecewise exponentials of
// width L at the interfaces), uniform pressure p0 (u = p0 / ((gamma - 1) rho)), and the seed
// v_y = A sin(4 pi x).
//
// One square lattice of n^2 particles with masses m_i = rho(y_i) dx^2, not equal masses on two
// lattices: the profile is smooth (L = 0.025 spans 1.6 to 6.4 spacings at n = 64 to 256), so a
// single lattice holds it without the seam a change of spacing puts at the interface, and every
// particle sees the same neighbour geometry (the same h / dx, the lattice sums of sound_wave).
// The mass ratio across the layer is rho2 / rho1 = 2, far from the large ratios at which unequal
// masses harm SPH.
#include <cmath>
#include <numbers>

#include "reference/kh_linear.hpp"
#include "sph/core/lattice.hpp"
#include "sph/density/fixed_neighbours.hpp"
#include "sph/kernel/kernels.hpp"
#include "verification/harness/params.hpp"

namespace sphv::kh {

// McNally et al.'s seeded mode: two wavelengths across the unit box.
constexpr double wave_number = 4.0 * std::numbers::pi;

inline reference::KhProfile profile(const Params& p) {
  reference::KhProfile pr;
  pr.rho1 = p.real("rho1");
  pr.rho2 = p.real("rho2");
  pr.U1 = p.real("U");
  pr.U2 = -p.real("U");
  pr.L = p.real("L");
  pr.p0 = p.real("p0");
  pr.gamma = p.real("gamma");
  return pr;
}

inline sph::Particles<2> initial_particles(const Params& prm) {
  const reference::KhProfile pr = profile(prm);
  const int n = static_cast<int>(prm.integer("n"));
  sph::Particles<2> p = sph::lattice<2>(n, sph::unit_box<2>(true), 1.0, prm.real("hfact"));
  const double A = prm.real("A"), cell = 1.0 / (double(n) * n);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.x[i][0], y = p.x[i][1], rho = pr.density(y);
    p.m[i] = rho * cell;
    p.rho[i] = rho;
    p.u[i] = pr.p0 / ((pr.gamma - 1.0) * rho);
    p.v[i][0] = pr.velocity(y);
    p.v[i][1] = A * std::sin(wave_number * x);
  }
  return p;
}

// u_i = p0 / ((gamma - 1) rho_i) with rho_i the summation density (27) at h from (50) with the run's
// kernel, the values the first step starts from: the layer in pressure equilibrium as the scheme measures it. The
// profile's own rho(y_i) differs from the summation by the kernel's smoothing, ~rho'' h^2, which
// at the interfaces (rho'' = 400 at L = 0.025) puts pressure blips of several per cent of p0, far
// above the seed's pressure perturbation (~rho sigma A / k, 2e-3 of p0), into the initial state.
inline void pressure_equilibrium(sph::Particles<2>& p, const Params& prm, double h_max) {
  sph::with_kernel<2>(prm.text("kernel"), [&](auto k) {
    sph::smoothing_length_iterate<2, decltype(k)>(p, sph::unit_box<2>(true),
                                                  sph::SmoothingLengthControl{prm.real("hfact"), h_max});
  });
  const double gamma = prm.real("gamma"), p0 = prm.real("p0");
  for (std::size_t i = 0; i < p.size(); ++i) p.u[i] = p0 / ((gamma - 1.0) * p.rho[i]);
}

}  // namespace sphv::kh
