// The schemes of sph/schemes/: the chapter's scheme, phase by phase, is the scene of the chapter's
// terms (summation density (27), ideal gas, (23), (38), (44)-(48)) and a run by its phases is that
// scene's run with (50) iterated after every step, bit for bit; the registry resolves names and
// forms and refuses an unknown name.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "sph/core/lattice.hpp"
#include "sph/density/terms.hpp"
#include "sph/kernel/wendland_c4.hpp"
#include "sph/schemes/schemes.hpp"
#include "sph/search/grid_search.hpp"

namespace {

// A moving 2D gas in a periodic box, u varying by +-50 %.
sph::Particles<2> moving_gas() {
  auto p = sph::lattice<2>(16, sph::unit_box<2>(true), 1.0, 2.4, 0.15, 5);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.v[i] = sph::Vec<2>(0.5 * U(rng), 0.5 * U(rng));
    p.u[i] = 1.0 + 0.5 * U(rng);
  }
  return p;
}

using Terms = sph::Scene<2, sph::SummationDensity<2>, sph::EquationOfState<2, sph::IdealGas>,
                         sph::EulerSymmetric<2, sph::Lambda1>, sph::EnergyAsymmetric<2, sph::EnergyForm::difference38>,
                         sph::ArtificialViscosity<2>>;

Terms terms_of(const sph::SchemeOptions& o) { return Terms{{{}, {{o.gamma}}, {}, {}, {o.alpha, o.beta, 0.01, 0.5}}}; }

}  // namespace

TEST_CASE("the chapter's scheme: density then force are the chapter's scene, bit for bit", "[schemes]") {
  sph::SchemeOptions o;
  o.alpha = 0.8, o.beta = 1.6;
  const auto box = sph::unit_box<2>(true);
  auto p = moving_gas(), q = p;
  const sph::NeighbourList nl = sph::grid_search<2>(p.x, p.h, box);
  const sph::Neighbourhood<2> nb{nl, box};
  sph::Chapter<2> scheme(o);
  sph::Derivatives<2> ds, dt;
  scheme.density(p, nb);
  scheme.force(p, nb, ds);
  Terms scene = terms_of(o);
  scene.derivatives(q, nb, dt);
  CHECK(p.rho == q.rho);
  CHECK(p.p == q.p);
  for (std::size_t i = 0; i < p.size(); ++i) {
    REQUIRE(ds.dvdt[i] == dt.dvdt[i]);
    REQUIRE(ds.dudt[i] == dt.dudt[i]);
    REQUIRE(ds.mu_max[i] == dt.mu_max[i]);
  }
  CHECK(ds.mu_max != std::vector<double>(p.size(), 0.0));  // the viscosity acts: some pairs approach
  const sph::TimeStepControl c;
  CHECK(scheme.time_step(p, ds, c) == sph::courant_time_step(p, ds, o.alpha, o.beta, c));
}

TEST_CASE("the chapter's scheme: a run by its phases is the scene's run with (50) after every step", "[schemes]") {
  sph::SchemeOptions o;
  const auto box = sph::unit_box<2>(true);
  sph::HydroControls c;
  c.t_end = 0.02;
  auto p = moving_gas(), q = p;
  sph::Chapter<2> scheme(o);
  const sph::HydroOutcome a = sph::evolve(scheme, p, box, c);
  // The same method assembled by hand: h from (50) iterated with (27) before the run and after
  // every step, on lists kept between steps.
  const sph::SmoothingLengthControl hc{o.hfact, o.h_max};
  sph::smoothing_length_iterate(q, box, hc);
  sph::HydroHooks<2> hooks;
  hooks.index_free = true;
  auto lists = std::make_shared<sph::VerletList<2>>(hc.skin);
  hooks.constrain = [&](sph::Particles<2>& s, double) { sph::smoothing_length_iterate(s, box, hc, *lists); };
  Terms scene = terms_of(o);
  const sph::HydroOutcome b = sph::evolve(scene, q, box, c, hooks);
  REQUIRE(a.verdict == "ok");
  CHECK(a.steps == b.steps);
  CHECK(a.steps > 5);
  CHECK(p.x == q.x);
  CHECK(p.u == q.u);
  CHECK(p.h == q.h);
}

TEST_CASE("the scheme registry: names, forms, unknown names", "[schemes]") {
  CHECK(sph::default_scheme() == "chapter");
  sph::SchemeOptions o;
  o.energy = "41";
  o.hmode = "rate53";
  bool symmetric = false;
  sph::with_scheme<2, sph::CubicSpline<2>>("chapter", o, [&](auto& s) {
    using S = std::remove_cvref_t<decltype(s)>;
    symmetric = std::is_same_v<S, sph::Chapter<2, sph::CubicSpline<2>, sph::EnergySymmetric<2, sph::Lambda1>, true>>;
  });
  CHECK(symmetric);  // (41) and (53) in the type
  auto by_name = [&](const std::string& name) { sph::with_scheme<2, sph::CubicSpline<2>>(name, o, [](auto&) {}); };
  auto by_default = [&](const std::string& name) {
    sph::with_default_scheme<2, sph::CubicSpline<2>>(name, o, [](auto&) {});
  };
  CHECK_THROWS_WITH(by_name("nope"), Catch::Contains("unknown scheme 'nope'") && Catch::Contains("chapter"));
  CHECK_THROWS_WITH(by_default("nope"), Catch::Contains("unknown scheme 'nope'"));
  CHECK_THROWS_AS(sph::Chapter<2>(o), std::invalid_argument);  // the type's h rule is (50)
}

namespace {

// A gas whose masses vary by +-50 % along x (so h varies), h set 30 % short of (50).
sph::Particles<2> uneven_gas() {
  auto p = moving_gas();
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.m[i] *= 1.0 + 0.5 * std::sin(2.0 * std::numbers::pi * p.x[i][0]);
    p.h[i] *= 0.7;
  }
  return p;
}

// The largest relative difference between rho_i and (27) summed by brute force over every pair at
// the nearest image (L = 1 typed here) with the kernel K, h_ij = (h_i + h_j) / 2, and the self
// term m_i W(0, h_i); and the largest relative residual of (50), |h_i - hfact (m_i/rho_i)^(1/2)| / h_i.
template <class K>
std::pair<double, double> density_and_h_residuals(const sph::Particles<2>& p, double hfact) {
  double e_rho = 0.0, e_h = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    double rho = p.m[i] * K::W(0.0, p.h[i]);
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      double r2 = 0.0;
      for (int d = 0; d < 2; ++d) {
        const double dx = p.x[i][d] - p.x[j][d];
        r2 += std::pow(dx - std::round(dx), 2);
      }
      rho += p.m[j] * K::W(std::sqrt(r2), 0.5 * (p.h[i] + p.h[j]));
    }
    e_rho = std::max(e_rho, std::abs(p.rho[i] / rho - 1.0));
    e_h = std::max(e_h, std::abs(p.h[i] - hfact * std::sqrt(p.m[i] / p.rho[i])) / p.h[i]);
  }
  return {e_rho, e_h};
}

}  // namespace

// (50) and (27) hold together after the scheme's start in every hmode (9.4.4: h is iterated before
// the first step whatever the mode) and after each step with iterate50, with the run's kernel,
// not the default cubic spline: rho_i equals the brute-force sum of the returned h to round-off
// (1e-12; the iteration ends with a density summation at its h), and (50) holds to the
// iteration's tolerance (relative change of h below tol = 1e-3 when it stops; bound 1e-2). h set
// 30 % short before the start puts (50) 30 % off; the cubic spline's sum differs from Wendland
// C4's by far more than round-off.
TEST_CASE("the chapter's scheme: start and after_step set h by (50) with the run's kernel, against brute force",
          "[schemes]") {
  const auto box = sph::unit_box<2>(true);
  using E = sph::EnergyAsymmetric<2, sph::EnergyForm::difference38>;
  auto check_start = [&](auto& scheme, const sph::SchemeOptions& o, auto kernel) {
    using K = decltype(kernel);
    auto p = uneven_gas();
    REQUIRE(density_and_h_residuals<K>(p, o.hfact).second > 0.2);  // (50) off before the start
    scheme.start(p, box);
    const auto [e_rho, e_h] = density_and_h_residuals<K>(p, o.hfact);
    CHECK(e_rho < 1e-12);
    CHECK(e_h < 1e-2);
    return p;
  };
  for (const std::string hmode : {"iterate50", "fixed", "rate53"}) {
    INFO("hmode " << hmode);
    sph::SchemeOptions o;
    o.hmode = hmode;
    if (hmode == "rate53") {
      sph::Chapter<2, sph::CubicSpline<2>, E, true> cubic(o);
      check_start(cubic, o, sph::CubicSpline<2>{});
      sph::Chapter<2, sph::WendlandC4<2>, E, true> wendland(o);
      check_start(wendland, o, sph::WendlandC4<2>{});
    } else {
      sph::Chapter<2, sph::CubicSpline<2>, E, false> cubic(o);
      check_start(cubic, o, sph::CubicSpline<2>{});
      sph::Chapter<2, sph::WendlandC4<2>, E, false> wendland(o);
      auto p = check_start(wendland, o, sph::WendlandC4<2>{});
      if (hmode == "iterate50") {
        for (std::size_t i = 0; i < p.size(); ++i) p.x[i] += 0.02 * p.v[i];  // a step's drift
        wendland.after_step(p, box);
        const auto [e_rho, e_h] = density_and_h_residuals<sph::WendlandC4<2>>(p, o.hfact);
        CHECK(e_rho < 1e-12);
        CHECK(e_h < 1e-2);
      }
    }
  }
}
