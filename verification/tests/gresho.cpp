// The Gresho-Chan vortex's exact solution (reference/gresho): the closed-form pressure against
// radial equilibrium dp/dr = rho v_phi^2 / r, integrated by quadrature and checked by a finite
// difference, and the published values of the standard set-up.
#include <catch2/catch.hpp>

#include <cmath>

#include "reference/gresho.hpp"

TEST_CASE("gresho: the pressure balances the vortex's rotation (dp/dr = rho v_phi^2 / r)", "[gresho]") {
  for (double rho0 : {1.0, 2.5}) {
    const reference::GreshoVortex g(rho0, 5.0, 5.0 / 3.0);
    for (int k = 1; k <= 120; ++k) {
      const double r = 0.005 * k;  // across both kinks and into the gas at rest
      INFO("rho0 " << rho0 << ", r = " << r);
      // The quadrature's tolerance is 1e-13 relative; the closed form's round-off ~1e-15 of p ~ 6.
      CHECK(std::abs(g.pressure(r) - g.pressure_by_quadrature(r)) < 1e-12);
      // Central difference away from the kinks (0.2, 0.4): truncation (dr^2 / 6) |p'''| with
      // |p'''| <= 8 rho0 / r^3 <= 1000 rho0 (the ring's, at r = 0.2; 0 elsewhere): 1.7e-8 rho0 for
      // dr = 1e-5, plus round-off ~eps p / dr ~ 1e-10.
      if (std::abs(r - 0.2) > 1e-3 && std::abs(r - 0.4) > 1e-3) {
        const double dr = 1e-5, v = g.v_phi(r);
        CHECK(std::abs((g.pressure(r + dr) - g.pressure(r - dr)) / (2.0 * dr) - rho0 * v * v / r) < 2e-8 * rho0 + 1e-9);
      }
    }
  }
}

TEST_CASE("gresho: the standard set-up's profile (Gresho & Chan 1990, Liska & Wendroff 2003)", "[gresho]") {
  const reference::GreshoVortex g(1.0, 5.0, 5.0 / 3.0);
  CHECK(g.v_phi(0.1) == Approx(0.5).epsilon(1e-15));
  CHECK(g.v_phi(0.2) == Approx(1.0).epsilon(1e-15));
  CHECK(g.v_phi(0.3) == Approx(0.5).epsilon(1e-14));
  CHECK(g.v_phi(0.45) == 0.0);
  CHECK(g.pressure(0.0) == 5.0);
  // Continuous at the kinks: 5.5 at r = 0.2, 3 + 4 ln 2 at r = 0.4 and beyond.
  CHECK(g.pressure(0.2 - 1e-12) == Approx(5.5).epsilon(1e-11));
  CHECK(g.pressure(0.2) == Approx(5.5).epsilon(1e-14));
  CHECK(g.pressure(0.4 - 1e-12) == Approx(3.0 + 4.0 * std::log(2.0)).epsilon(1e-11));
  CHECK(g.pressure(0.6) == Approx(3.0 + 4.0 * std::log(2.0)).epsilon(1e-15));
  CHECK(g.pressure(0.3) == Approx(9.0 + 12.5 * 0.09 - 6.0 + 4.0 * std::log(1.5)).epsilon(1e-14));
  CHECK(g.internal_energy(0.0) == Approx(7.5).epsilon(1e-15));  // p / ((gamma - 1) rho) = 5 / (2/3)
}
