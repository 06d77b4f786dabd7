// The schemes of sph/schemes/: the chapter's scheme, phase by phase, is the scene of the chapter's
// terms (summation density (27), ideal gas, (23), (38), (44)-(48)) and a run by its phases is that
// scene's run with (50) iterated after every step, bit for bit; the registry resolves names and
// forms and refuses an unknown name.
#include <catch2/catch.hpp>

#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "sph/core/lattice.hpp"
#include "sph/density/terms.hpp"
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
