// The artificial viscosity's defaults (sph/hydro/viscosity.hpp) against (44)-(46) evaluated by
// hand with the chapter's standard values alpha = 1, beta = 2 (after (45)), the errata's
// eps = 0.01 and Monaghan's h = half the support radius (errata, (46)), on pairs close enough
// that eps h^2 is most of mu_ij's denominator. (The direct-sum test of hydro.cpp passes its own
// alpha, beta and eps; this one checks the values a scene gets when it names none.)
#include <catch2/catch.hpp>

#include <cmath>

#include "sph/hydro/eos.hpp"
#include "sph/hydro/viscosity.hpp"
#include "sph/search/grid_search.hpp"

TEST_CASE("viscosity defaults: mu_ij and Pi_ij of close pairs equal (44)-(46) by hand", "[hydro]") {
  constexpr int D = 2;
  const double gamma = 1.4, h = 0.2;  // support radius; Monaghan's h is 0.1
  const sph::Box<D> box = sph::unit_box<D>(false);
  // Two particles approaching head on at r_ij = s h/2: for s = 0.05, 0.1, 0.3 the r^2 of (46)'s
  // denominator is 1/4, 1, 9 times eps (h/2)^2 = 1e-4.
  for (const double s : {0.05, 0.1, 0.3}) {
    sph::Particles<D> p;
    p.resize(2);
    const double r = s * 0.5 * h;
    p.x[0] = sph::Vec<D>(0.5 - 0.5 * r, 0.5), p.x[1] = sph::Vec<D>(0.5 + 0.5 * r, 0.5);
    p.v[0] = sph::Vec<D>(0.8, 0.1), p.v[1] = sph::Vec<D>(-0.6, 0.3);
    for (int i = 0; i < 2; ++i) p.m[i] = 0.01, p.h[i] = h, p.u[i] = 1.0 + 0.5 * i;
    p.rho[0] = 1.0, p.rho[1] = 1.3;
    const auto nl = sph::grid_search<D>(p.x, p.h, box);
    sph::Scene<D, sph::EquationOfState<D, sph::IdealGas>, sph::ArtificialViscosity<D>> scene{{{{gamma}}, {}}};
    sph::Derivatives<D> d;
    scene.derivatives(p, sph::Neighbourhood<D>{nl, box}, d);

    const double alpha = 1.0, beta = 2.0, eps = 0.01, hm = 0.5 * h;
    const sph::Vec<D> rij = p.x[0] - p.x[1], vij = p.v[0] - p.v[1];
    const double mu = hm * vij.dot(rij) / (rij.squaredNorm() + eps * hm * hm);  // (46)
    const double c0 = std::sqrt(gamma * (gamma - 1.0) * p.u[0]), c1 = std::sqrt(gamma * (gamma - 1.0) * p.u[1]);
    const double Pi = (-alpha * 0.5 * (c0 + c1) * mu + beta * mu * mu) / (0.5 * (p.rho[0] + p.rho[1]));  // (45)
    const sph::Vec<D> dvdt0 = -p.m[1] * Pi * sph::CubicSpline<D>::gradW(rij, rij.norm(), h);         // (44)
    INFO("r_ij = " << s << " h/2: mu_ij " << -d.mu_max[0] << " (by hand " << mu << "), dv_0/dt " << d.dvdt[0].transpose()
                   << " (by hand " << dvdt0.transpose() << ")");
    REQUIRE(vij.dot(rij) < 0.0);
    // Round-off of a few operations on each side: 1e-12 relative.
    CHECK(d.mu_max[0] == Approx(-mu).epsilon(1e-12));
    CHECK(d.mu_max[1] == Approx(-mu).epsilon(1e-12));
    CHECK((d.dvdt[0] - dvdt0).norm() <= 1e-12 * dvdt0.norm());
    CHECK((d.dvdt[1] + dvdt0 * (p.m[0] / p.m[1])).norm() <= 1e-12 * dvdt0.norm());  // (44) is antisymmetric
  }
}
