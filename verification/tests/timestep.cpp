// The Courant condition (sph/time/timestep.hpp) against Monaghan's (1992) formula evaluated by
// hand (errata, "Places where the literal text is not enough"):
//   dt = C min_i (h_i/2) / (c_i + |v_i| + 1.2 (alpha c_i + beta max_j |mu_ij|)),
// with mu_ij of (46) summed directly over every pair, on a gas that converges on its centre, so
// that max_j |mu_ij| is not zero and the viscous term of the signal speed counts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/core/lattice.hpp"
#include "sph/density/summation.hpp"
#include "sph/hydro/eos.hpp"
#include "sph/hydro/viscosity.hpp"
#include "sph/search/grid_search.hpp"
#include "sph/time/timestep.hpp"

TEST_CASE("Courant step equals Monaghan's signal-speed formula by hand on a converging flow", "[timestep]") {
  constexpr int D = 2;
  const double gamma = 5.0 / 3.0, alpha = 1.0, beta = 2.0, eps = 0.01;
  const sph::Box<D> box = sph::unit_box<D>(false);
  auto p = sph::lattice<D>(12, box, 1.0, 2.4, 0.2, 41);  // one h for all: the pairs are r_ij < h
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const sph::Vec<D> r = p.x[i] - sph::Vec<D>(0.5, 0.5);
    p.v[i] = -3.0 * r;                      // converging: every pair approaches, |v| up to 2.1
    p.u[i] = 0.5 + r.squaredNorm();         // c from 0.75 to 1.05
  }
  const auto nl = sph::grid_search<D>(p.x, p.h, box);
  sph::density_summation(p, nl, box);
  sph::Scene<D, sph::EquationOfState<D, sph::IdealGas>, sph::ArtificialViscosity<D>> scene{
      {{{gamma}}, sph::ArtificialViscosity<D>{alpha, beta, eps, 0.5}}};
  sph::Derivatives<D> d;
  scene.derivatives(p, sph::Neighbourhood<D>{nl, box}, d);
  sph::TimeStepControl c;
  // The acceleration and cooling criteria off: the Courant condition alone sets dt.
  c.C_force = std::numeric_limits<double>::infinity();
  c.C_energy = 0.0;
  const double dt = sph::courant_time_step(p, d, alpha, beta, c);

  double by_hand = std::numeric_limits<double>::infinity(), without_viscosity = by_hand, largest_mu = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double ci = std::sqrt(gamma * (gamma - 1.0) * p.u[i]);  // c^2 = gamma p / rho, ideal gas
    double mu_max = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      const sph::Vec<D> rij = p.x[i] - p.x[j], vij = p.v[i] - p.v[j];
      if (j == i || !(rij.norm() < p.h[i]) || vij.dot(rij) >= 0.0) continue;
      const double h = 0.5 * p.h[i];  // Monaghan's h: half the support radius (errata, (46))
      mu_max = std::max(mu_max, std::abs(h * vij.dot(rij) / (rij.squaredNorm() + eps * h * h)));
    }
    largest_mu = std::max(largest_mu, mu_max);
    const double v = p.v[i].norm();
    by_hand = std::min(by_hand, c.C * 0.5 * p.h[i] / (ci + v + 1.2 * (alpha * ci + beta * mu_max)));
    without_viscosity = std::min(without_viscosity, c.C * 0.5 * p.h[i] / (ci + v));
  }
  INFO("dt " << dt << ", by hand " << by_hand << ", without the viscous term " << without_viscosity
             << ", largest max_j |mu_ij| " << largest_mu);
  // v_ij . r_ij = -3 r_ij^2 makes mu_ij about -3 h/2 = -0.3 on every close pair, and the viscous
  // term of the signal speed a third of it or more: leaving it out lengthens dt by half or more.
  REQUIRE(largest_mu > 0.2);
  REQUIRE(without_viscosity > 1.5 * by_hand);
  CHECK(dt == Approx(by_hand).epsilon(1e-12));  // round-off of a few operations
}
