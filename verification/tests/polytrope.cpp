// The n = 1 polytrope (reference/polytrope) against its defining equations, checked numerically:
// the Lane-Emden equation of index 1, hydrostatic equilibrium with the mass from a quadrature of
// the density, the total mass 4 rho_c R^3 / pi and the inverse of the cumulative mass; and the
// case's set-up (verification/cases/polytrope/setup.hpp) built on it.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "reference/polytrope.hpp"
#include "verification/cases/polytrope/setup.hpp"

namespace {

// Composite Simpson's rule with n (even) intervals: error O((b - a) h^4 f'''').
double simpson(const std::function<double(double)>& f, double a, double b, int n = 2000) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
  return s * h / 3.0;
}

constexpr double pi = std::numbers::pi;

}  // namespace

TEST_CASE("polytrope n = 1: theta = rho / rho_c solves the Lane-Emden equation of index 1", "[polytrope]") {
  const reference::Polytrope1 star(1.0, 2.0 / pi);
  REQUIRE(star.radius() == Approx(1.0).epsilon(1e-14));
  const double R = star.radius();
  auto theta = [&](double xi) { return star.density(xi * R / pi) / star.central_density(); };
  // (1 / xi^2) (xi^2 theta')' + theta = theta'' + 2 theta' / xi + theta, by central differences
  // of step d: truncation O(d^2 theta'''') ~ 1e-8, round-off ~ 1e-16 / d^2 ~ 1e-10.
  const double d = 1e-3;
  for (double xi : {0.1, 0.5, 1.0, 2.0, 2.5, 3.0, 3.1}) {
    const double t1 = (theta(xi + d) - theta(xi - d)) / (2.0 * d);
    const double t2 = (theta(xi + d) - 2.0 * theta(xi) + theta(xi - d)) / (d * d);
    CHECK(std::abs(t2 + 2.0 * t1 / xi + theta(xi)) < 1e-6);
  }
  // Regular at the centre (theta = 1, theta' = 0) and zero at the surface, nothing beyond.
  CHECK(theta(0.0) == 1.0);
  CHECK(std::abs(theta(1e-6) - 1.0) < 1e-12);
  CHECK(std::abs(theta(pi - 1e-9)) < 1e-9);
  CHECK(star.density(1.2 * R) == 0.0);
}

TEST_CASE("polytrope n = 1: hydrostatic equilibrium, mass and energy by quadrature", "[polytrope]") {
  // A star off the unit system, so that R = sqrt(pi K / (2 G)) and rho_c = pi M / (4 R^3) are tested.
  const double M = 2.5, K = 0.3, G = 1.7;
  const reference::Polytrope1 star(M, K, G);
  const double R = star.radius();
  CHECK(R == Approx(std::sqrt(pi * K / (2.0 * G))).epsilon(1e-14));
  auto shell = [&](double r) { return 4.0 * pi * r * r * star.density(r); };
  // Total mass 4 rho_c R^3 / pi = M, by quadrature of the density.
  const double total = simpson(shell, 0.0, R);
  CHECK(total == Approx(M).epsilon(1e-10));
  CHECK(4.0 * star.central_density() * R * R * R / pi == Approx(M).epsilon(1e-14));
  for (double f : {0.05, 0.2, 0.5, 0.8, 0.97}) {
    const double r = f * R;
    const double m_r = simpson(shell, 0.0, r);
    CHECK(star.mass_within(r) == Approx(m_r).epsilon(1e-10));
    // dp/dr = -G M(<r) rho / r^2 with p = K rho^2 (central differences, relative step 1e-5).
    const double d = 1e-5 * R;
    const double dpdr = (star.pressure(r + d) - star.pressure(r - d)) / (2.0 * d);
    const double g = -G * m_r * star.density(r) / (r * r);
    CHECK(dpdr == Approx(g).epsilon(1e-7));
    CHECK(star.pressure(r) == Approx(K * star.density(r) * star.density(r)).epsilon(1e-15));
  }
  // The inverse of the cumulative mass, to round-off, including the series near the centre.
  for (double q : {1e-9, 1e-4, 0.01, 0.1, 0.5, 0.9, 0.999999})
    CHECK(star.mass_within(star.radius_of_mass_fraction(q)) / M == Approx(q).epsilon(1e-12));
  CHECK(star.radius_of_mass_fraction(0.0) == 0.0);
  CHECK(star.radius_of_mass_fraction(1.0) == R);
  // The inner shell's mass-weighted mean density, int rho dM / (q M).
  for (double q : {0.001, 0.1, 1.0}) {
    const double rq = star.radius_of_mass_fraction(q);
    const double mean = simpson([&](double r) { return shell(r) * star.density(r); }, 0.0, rq) / (q * M);
    CHECK(star.mean_density_within_mass_fraction(q) == Approx(mean).epsilon(1e-9));
  }
  // W = -G int M(<r) dM / r = -3 G M^2 / (4 R).
  const double W = -G * simpson([&](double r) { return r > 0.0 ? star.mass_within(r) * shell(r) / r : 0.0; }, 0.0, R);
  CHECK(star.potential_energy() == Approx(W).epsilon(1e-9));
}

TEST_CASE("polytrope n = 1: refuses a non-positive or non-finite M, K, G and a mass fraction outside [0, 1]",
          "[polytrope]") {
  CHECK_THROWS_AS(reference::Polytrope1(0.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(reference::Polytrope1(1.0, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(reference::Polytrope1(1.0, 1.0, NAN), std::invalid_argument);
  const reference::Polytrope1 star(1.0, 1.0);
  CHECK_THROWS_AS(star.radius_of_mass_fraction(1.5), std::invalid_argument);
  CHECK_THROWS_AS(star.radius_of_mass_fraction(NAN), std::invalid_argument);
}

TEST_CASE("polytrope set-up: the stretched lattice follows the profile's cumulative mass, p = K rho^2", "[polytrope]") {
  const reference::Polytrope1 star(1.0, 2.0 / pi);
  for (long n : {552L, 1189L}) {  // an even and an odd lattice (the odd one has a particle at the centre)
    const sph::Particles<3> p = sphv::polytrope::sphere(n, star, 2.0, 2.4);
    REQUIRE(static_cast<long>(p.size()) == n);
    double mass = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      mass += p.m[i];
      const double r = p.x[i].norm();
      REQUIRE(std::isfinite(r));
      CHECK(r < star.radius());
      CHECK(p.rho[i] == star.density(r));
      CHECK((2.0 - 1.0) * p.rho[i] * p.u[i] == Approx(star.K() * p.rho[i] * p.rho[i]).epsilon(1e-14));
    }
    CHECK(mass == Approx(1.0).epsilon(1e-12));
    // Each particle is a lattice point x0 of the unit ball moved along its direction to the radius
    // enclosing the mass fraction |x0|^3: undoing the stretch, cbrt(M(<r) / M) x / r, gives back a
    // lattice point (cell centres -1 + (k + 1/2) 2 / side).
    const int side = sphv::polytrope::lattice_side(n);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double r = p.x[i].norm();
      const sph::Vec<3> x0 = r > 0.0 ? (p.x[i] * (std::cbrt(star.mass_within(r)) / r)).eval() : p.x[i];
      for (int d = 0; d < 3; ++d) {
        const double k = (x0[d] + 1.0) * side / 2.0 - 0.5;
        CHECK(std::abs(k - std::round(k)) < 1e-8);
      }
    }
  }
}
