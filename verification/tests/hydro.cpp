// Hydrodynamics of 9.2-9.4.2: equations of state, conservation by the symmetric forms over many
// steps, the verdict check, bad input, the extreme Riemann presets, and the shock-tube gates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "sph/core/isa.hpp"
#include "sph/core/lattice.hpp"
#include "sph/core/verdict.hpp"
#include "sph/density/fixed_neighbours.hpp"
#include "sph/density/terms.hpp"
#include "sph/density/variable_h.hpp"
#include "sph/hydro/energy.hpp"
#include "sph/hydro/eos.hpp"
#include "sph/hydro/euler.hpp"
#include "sph/hydro/evolve.hpp"
#include "verification/harness/sweep.hpp"
#include "verification/tests/isa_path.hpp"

namespace {

// A disordered, moving 2D gas in a periodic box: jittered lattice, random velocities of about
// half the sound speed, internal energy varying by +-50 %; every interaction is active.
sph::Particles<2> stirred_gas(std::uint64_t seed) {
  auto p = sph::lattice<2>(24, sph::unit_box<2>(true), 1.0, 2.4, 0.15, seed);
  std::mt19937_64 rng(seed + 7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.v[i] = sph::Vec<2>(0.5 * U(rng), 0.5 * U(rng));
    p.u[i] = 1.0 + 0.5 * U(rng);
  }
  return p;
}

struct Drift {
  double momentum = 0.0, energy = 0.0, rate = 0.0, mass = 0.0;
  long steps = 0;
  std::string verdict;
};

template <class Euler, class Energy>
Drift conservation_run(double t_end, double C) {
  auto p = stirred_gas(3);
  const auto box = sph::unit_box<2>(true);
  sph::density_summation(p, sph::grid_search<2>(p.x, p.h, box), box);
  sph::smoothing_length_from_density(p, 2.4);
  sph::Scene<2, sph::SummationDensity<2>, sph::EquationOfState<2, sph::IdealGas>, Euler, Energy,
             sph::ArtificialViscosity<2>, sph::SmoothingLengthRate<2>>
      scene;
  std::get<1>(scene.terms).eos.gamma = 5.0 / 3.0;
  sph::HydroControls c;
  c.t_end = t_end;
  c.step.C = C;
  sph::Derivatives<2> none;
  none.reset(p.size());
  const auto first = sph::totals(p, none, 0, p.size());
  Drift d;
  double pscale = first.momentum_scale;
  sph::HydroHooks<2> hooks;
  hooks.evaluated = [&](const sph::Particles<2>& q, const sph::Derivatives<2>& dd) {
    const auto t = sph::totals(q, dd, 0, q.size());
    d.rate = std::max(d.rate, std::abs(t.energy_rate) / t.rate_scale);
  };
  hooks.stepped = [&](const sph::Particles<2>& q, const sph::Derivatives<2>& dd, long, double) {
    const auto t = sph::totals(q, dd, 0, q.size());
    pscale = std::max(pscale, t.momentum_scale);
    d.momentum = std::max(d.momentum, (t.momentum - first.momentum).norm() / pscale);
    d.mass = std::max(d.mass, std::abs(t.mass - first.mass) / first.mass);
    d.energy = std::abs(t.energy - first.energy) / first.energy;
  };
  const auto out = sph::evolve(scene, p, box, c, hooks);
  d.steps = out.steps;
  d.verdict = out.verdict;
  return d;
}

}  // namespace

TEST_CASE("equations of state: pressure and sound speed", "[hydro]") {
  const sph::IdealGas gas{1.4};
  CHECK(gas.pressure(0.125, 2.0) == Approx(0.4 * 0.125 * 2.0).epsilon(1e-15));
  CHECK(gas.sound_speed(0.125, 2.0) == Approx(std::sqrt(1.4 * gas.pressure(0.125, 2.0) / 0.125)).epsilon(1e-14));
  // (47) c^2 = dp/drho of (35), against a central difference (step 1e-5: error ~1e-10).
  const sph::Polytropic poly{0.7, 5.0 / 3.0};
  const double rho = 1.3, d = 1e-5;
  const double dpdrho = (poly.pressure(rho + d, 0) - poly.pressure(rho - d, 0)) / (2 * d);
  CHECK(poly.sound_speed(rho, 0) * poly.sound_speed(rho, 0) == Approx(dpdrho).epsilon(1e-8));
}

// The chapter's (25) reduces to (23) at lambda = 1 and to (26) at lambda = 2, and its lambda = 0
// is p_j / rho_i^2 + p_i / rho_j^2 (the weights swap sides). The general form is the pair loop's,
// with the powers prepare() takes by pow(); the special ones take none: a swapped exponent or side
// shows at lambda = 0 and 2. Tolerance 1e-14 relative: a few roundings of pow() and two divisions.
TEST_CASE("(25) reduces to (23) at lambda 1 and (26) at lambda 2", "[hydro]") {
  std::mt19937 rng(25);
  std::uniform_real_distribution<double> u(0.1, 10.0);
  auto general = [](double lambda, const sph::Particles<1>& p) {
    sph::LambdaGeneral g{lambda};
    g.prepare(p);
    return g.factor(p, 0, 1);
  };
  for (int k = 0; k < 100; ++k) {
    sph::Particles<1> p;
    p.resize(2);
    p.p = {u(rng), u(rng)}, p.rho = {u(rng), u(rng)};
    const double pi = p.p[0], pj = p.p[1], ri = p.rho[0], rj = p.rho[1];
    CHECK(general(1.0, p) == Approx(sph::Lambda1{}.factor(p, 0, 1)).epsilon(1e-14));
    CHECK(general(2.0, p) == Approx(sph::Lambda2{}.factor(p, 0, 1)).epsilon(1e-14));
    CHECK(general(0.0, p) == Approx(pj / (ri * ri) + pi / (rj * rj)).epsilon(1e-14));
  }
}

// Every hydro term against a direct sum of the chapter's formula over all pairs, on a gas whose
// density, smoothing length, pressure and velocity all vary (masses rising threefold along x, a
// jittered lattice in an open box, h from (50), random velocities): forms that agree on uniform
// density (rho_j^2 for rho_i rho_j, p_i for p_j, h_i for h_ij) differ here at first order. The
// sums are written out from (22)-(48), (27) and (53) with the errata (kernel gradient at h_ij = (h_i + h_j) / 2,
// Monaghan's h = h_ij / 2 in mu_ij, |r_ij|^2 + eps h^2); p and c from the ideal gas. Tolerance 1e-12
// of each particle's sum of |terms| (round-off of a few dozen terms).
namespace {
struct PairRates {
  sph::Vec<2> dv = sph::Vec<2>::Zero();
  double du = 0.0, drho = 0.0, dh = 0.0;
};
}  // namespace

// Run on each instruction-set path of the pair loops (sph/core/isa.hpp) this CPU supports: each
// must equal the direct sums, whichever the harness picks.
TEST_CASE("hydro terms equal a direct sum of the chapter's (22)-(53) on a non-uniform gas", "[hydro]") {
  const sph::IsaPath path = GENERATE(sph::IsaPath::portable, sph::IsaPath::avx2);
  const OnIsaPath on(path);
  if (!on.supported()) return;
  INFO("instruction-set path " << sph::isa_name(path));
  constexpr int D = 2;
  const double gamma = 1.4;
  const sph::Box<D> box = sph::unit_box<D>(false);
  auto p = sph::lattice<D>(14, box, 1.0, 2.4, 0.2, 17);
  const std::size_t n = p.size();
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    p.m[i] *= 1.0 + 2.0 * p.x[i][0] * p.x[i][0];
    p.v[i] = sph::Vec<D>(U(rng), U(rng));
    p.u[i] = 1.0 + 0.5 * U(rng);
  }
  sph::density_summation(p, sph::grid_search<D>(p.x, p.h, box), box);
  sph::smoothing_length_from_density(p, 2.4);
  const auto nl = sph::grid_search<D>(p.x, p.h, box);
  sph::density_summation(p, nl, box);
  std::vector<double> P(n), c(n);
  for (std::size_t i = 0; i < n; ++i) P[i] = (gamma - 1.0) * p.rho[i] * p.u[i], c[i] = std::sqrt(gamma * P[i] / p.rho[i]);

  // Compares the scene {ideal gas, term} with sum_j formula(i, j, r_ij, h_ij, grad_i W_ij).
  auto compare = [&](const char* name, auto term, auto formula) {
    sph::Scene<D, sph::EquationOfState<D, sph::IdealGas>, decltype(term)> scene{{{{gamma}}, term}};
    sph::Particles<D> q = p;
    sph::Derivatives<D> d;
    scene.derivatives(q, sph::Neighbourhood<D>{nl, box}, d);
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      PairRates sum, scale;
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        const sph::Vec<D> rij = p.x[i] - p.x[j];
        const double hij = 0.5 * (p.h[i] + p.h[j]);
        const PairRates t = formula(i, j, rij, hij, sph::CubicSpline<D>::gradW(rij, rij.norm(), hij));
        sum.dv += t.dv, sum.du += t.du, sum.drho += t.drho, sum.dh += t.dh;
        scale.dv += t.dv.cwiseAbs(), scale.du += std::abs(t.du), scale.drho += std::abs(t.drho), scale.dh += std::abs(t.dh);
      }
      worst = std::max({worst, (d.dvdt[i] - sum.dv).norm() / std::max(scale.dv.norm(), 1e-300),
                        std::abs(d.dudt[i] - sum.du) / std::max(scale.du, 1e-300),
                        std::abs(d.drhodt[i] - sum.drho) / std::max(scale.drho, 1e-300),
                        std::abs(d.dhdt[i] - sum.dh) / std::max(scale.dh, 1e-300)});
    }
    INFO(name << ": largest relative difference " << worst);
    CHECK(worst <= 1e-12);
  };
  const auto& m = p.m;
  const auto& rho = p.rho;
  const auto& v = p.v;
  using V = sph::Vec<D>;
  auto sym = [&](std::size_t i, std::size_t j, double lambda) {  // the bracket of (25)
    return P[j] / (std::pow(rho[i], 2.0 - lambda) * std::pow(rho[j], lambda)) +
           P[i] / (std::pow(rho[i], lambda) * std::pow(rho[j], 2.0 - lambda));
  };
  using sph::EnergyForm;
  using sph::ContinuityForm;
  compare("(22)", sph::EulerDirect<D>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{-(1.0 / rho[i]) * m[j] / rho[j] * P[j] * g};
  });
  compare("(23)", sph::EulerSymmetric<D, sph::Lambda1>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{-m[j] * (P[j] + P[i]) / (rho[i] * rho[j]) * g};
  });
  compare("(25), lambda 1.5", sph::EulerSymmetric<D, sph::LambdaGeneral>{{1.5}},
          [&](auto i, auto j, const V&, double, const V& g) { return PairRates{-m[j] * sym(i, j, 1.5) * g}; });
  compare("(26)", sph::EulerSymmetric<D, sph::Lambda2>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{-m[j] * (P[j] / (rho[j] * rho[j]) + P[i] / (rho[i] * rho[i])) * g};
  });
  compare("(29)", sph::ContinuityDensity<D, ContinuityForm::direct29>{}, [&](auto, auto j, const V&, double, const V& g) {
    return PairRates{V::Zero(), 0.0, -m[j] * v[j].dot(g)};
  });
  compare("(33)", sph::ContinuityDensity<D, ContinuityForm::difference33>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{V::Zero(), 0.0, -m[j] * (v[j] - v[i]).dot(g)};
  });
  compare("(37)", sph::EnergyAsymmetric<D, EnergyForm::direct37>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{V::Zero(), -m[j] * P[i] / (rho[i] * rho[j]) * v[j].dot(g)};
  });
  compare("(38)", sph::EnergyAsymmetric<D, EnergyForm::difference38>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{V::Zero(), m[j] * P[i] / (rho[i] * rho[j]) * (v[i] - v[j]).dot(g)};
  });
  compare("(40)", sph::EnergyAsymmetric<D, EnergyForm::swapped40>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{V::Zero(), m[j] * P[j] / (rho[i] * rho[j]) * (v[i] - v[j]).dot(g)};
  });
  compare("(41)", sph::EnergySymmetric<D, sph::Lambda1>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{V::Zero(), 0.5 * m[j] * (P[i] + P[j]) / (rho[i] * rho[j]) * (v[i] - v[j]).dot(g)};
  });
  compare("(42)", sph::EnergySymmetric<D, sph::Lambda2>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{V::Zero(), 0.5 * m[j] * (P[i] / (rho[i] * rho[i]) + P[j] / (rho[j] * rho[j])) * (v[i] - v[j]).dot(g)};
  });
  compare("(25)'s energy form, lambda 1.5", sph::EnergySymmetric<D, sph::LambdaGeneral>{{1.5}},
          [&](auto i, auto j, const V&, double, const V& g) {
            return PairRates{V::Zero(), 0.5 * m[j] * sym(i, j, 1.5) * (v[i] - v[j]).dot(g)};
          });
  compare("(53)", sph::SmoothingLengthRate<D>{}, [&](auto i, auto j, const V&, double, const V& g) {
    return PairRates{V::Zero(), 0.0, 0.0, (1.0 / D) * p.h[i] / rho[i] * m[j] * (v[j] - v[i]).dot(g)};
  });
  // (27) with its self term j = i (h_ii = h_i).
  double worst27 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0.0;
    for (std::size_t j = 0; j < n; ++j) sum += m[j] * sph::CubicSpline<D>::W((p.x[i] - p.x[j]).norm(), 0.5 * (p.h[i] + p.h[j]));
    worst27 = std::max(worst27, std::abs(rho[i] - sum) / sum);
  }
  INFO("(27): largest relative difference " << worst27);
  CHECK(worst27 <= 1e-12);
  const double alpha = 1.0, beta = 2.0, eps = 0.01;
  compare("viscosity (44)-(48)", sph::ArtificialViscosity<D>{alpha, beta, eps, 0.5},
          [&](auto i, auto j, const V& rij, double hij, const V& g) {
            const V vij = v[i] - v[j];
            if (vij.dot(rij) >= 0.0) return PairRates{};  // (45): receding pairs
            const double h = 0.5 * hij;                   // Monaghan's h (errata)
            const double mu = h * vij.dot(rij) / (rij.squaredNorm() + eps * h * h);
            const double Pi = (-alpha * 0.5 * (c[i] + c[j]) * mu + beta * mu * mu) / (0.5 * (rho[i] + rho[j]));
            return PairRates{-m[j] * Pi * g, 0.5 * m[j] * Pi * vij.dot(g)};
          });
}

// smoothing_length_iterate's contract on a gas whose mass per particle varies threefold, in an
// open box (edge particles have few neighbours) and a periodic one: it converges, the returned rho
// is the summation density (27) of the returned h, as a direct sum over all pairs gives it
// (tolerance 1e-12: round-off of a few dozen terms), and h satisfies (50) for that rho to 0.1 %.
// That bound is fixed, not the iteration's own tol: ten times the tolerance Phantom iterates h to
// by default (tolh = 1e-4; Price et al. 2018, PASA 35, e031), a density that (50) and (27) agree
// on to D x 0.1 % (rho ~ h^-D). Measured 1.4e-4 (open box) and 2.7e-4 (periodic) at the default
// tol = 1e-3; a tol 30 times looser leaves 3.5e-3.
// The 3D pair loops have a copy of their own for each path (AVX-512 too, sph/core/isa.hpp); the
// test above checks the 2D copies against direct sums. Here the density (27) and the rates of the
// bench's scene (ideal gas, (26), (42), viscosity) on a disordered 3D gas, on every path this CPU
// has, against the portable path: equal to round-off (1e-13 of the largest value: the copies
// contract multiply-adds into FMAs where the portable one does not; measured 7.6e-16 here on the
// avx2 and avx512 paths).
TEST_CASE("3D pair loops give the portable path's density and rates on every instruction-set path", "[hydro]") {
  constexpr int D = 3;
  const sph::Box<D> box = sph::unit_box<D>(true);
  auto gas = sph::lattice<D>(12, box, 1.0, 2.4, 0.2, 5);
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (std::size_t i = 0; i < gas.size(); ++i) {
    gas.m[i] *= 1.0 + 0.5 * U(rng);
    gas.v[i] = sph::Vec<D>(U(rng), U(rng), U(rng));
    gas.u[i] = 1.0 + 0.5 * U(rng);
  }
  const auto nl = sph::grid_search<D>(gas.x, gas.h, box);
  using Scene = sph::Scene<D, sph::EquationOfState<D, sph::IdealGas>, sph::EulerSymmetric<D, sph::Lambda2>,
                           sph::EnergySymmetric<D, sph::Lambda2>, sph::ArtificialViscosity<D>>;
  auto rates = [&](sph::IsaPath path, sph::Particles<D>& q, sph::Derivatives<D>& d) {
    const OnIsaPath on(path);
    if (!on.supported()) return false;
    q = gas;
    sph::density_summation(q, nl, box);
    Scene scene;
    scene.derivatives(q, sph::Neighbourhood<D>{nl, box}, d);
    return true;
  };
  sph::Particles<D> p0, q;
  sph::Derivatives<D> d0, d;
  REQUIRE(rates(sph::IsaPath::portable, p0, d0));
  double rho_max = 0.0, a_max = 0.0, du_max = 0.0;
  for (std::size_t i = 0; i < p0.size(); ++i)
    rho_max = std::max(rho_max, p0.rho[i]), a_max = std::max(a_max, d0.dvdt[i].norm()),
    du_max = std::max(du_max, std::abs(d0.dudt[i]));
  REQUIRE(a_max > 0.0);
  for (sph::IsaPath path : {sph::IsaPath::avx2, sph::IsaPath::avx512}) {
    if (!rates(path, q, d)) continue;
    INFO("instruction-set path " << sph::isa_name(path));
    double worst = 0.0;
    for (std::size_t i = 0; i < q.size(); ++i)
      worst = std::max({worst, std::abs(q.rho[i] - p0.rho[i]) / rho_max, (d.dvdt[i] - d0.dvdt[i]).norm() / a_max,
                        std::abs(d.dudt[i] - d0.dudt[i]) / du_max});
    INFO("largest difference from the portable path, relative to the largest value: " << worst);
    CHECK(worst <= 1e-13);
  }
}

TEST_CASE("(50) iterated: rho is the direct sum (27) of the returned h, and h fits (50)", "[hydro]") {
  constexpr int D = 2;
  for (bool periodic : {false, true}) {
    const sph::Box<D> box = sph::unit_box<D>(periodic);
    auto p = sph::lattice<D>(16, box, 1.0, 1.5, 0.2, 23);  // h far from (50)'s: many iterations
    for (std::size_t i = 0; i < p.size(); ++i) p.m[i] *= 1.0 + 2.0 * p.x[i][0] * p.x[i][0];
    const sph::SmoothingLengthControl c{.hfact = 2.4};
    const auto out = sph::smoothing_length_iterate(p, box, c);
    REQUIRE(out.converged);
    CHECK(out.iterations > 2);
    const sph::Vec<D> L = box.length(), wrap = box.wrap_factor();
    double worst_rho = 0.0, worst_h = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      double rho = p.m[i] * sph::CubicSpline<D>::W(0.0, p.h[i]);
      for (std::size_t j = 0; j < p.size(); ++j)
        if (j != i)
          rho += p.m[j] * sph::CubicSpline<D>::W(sph::min_image<D>(p.x[i] - p.x[j], L, wrap).norm(),
                                                 0.5 * (p.h[i] + p.h[j]));
      worst_rho = std::max(worst_rho, std::abs(p.rho[i] - rho) / rho);
      worst_h = std::max(worst_h, std::abs(p.h[i] - c.hfact * std::sqrt(p.m[i] / rho)) / p.h[i]);  // (50), D = 2
    }
    INFO((periodic ? "periodic" : "open") << " box: rho differs by " << worst_rho << ", h from (50) by " << worst_h);
    CHECK(worst_rho < 1e-12);
    CHECK(worst_h < 1e-3);
  }
}

TEST_CASE("verdict names the first bad particle and quantity", "[hydro]") {
  sph::Particles<1> p;
  p.resize(4);
  for (std::size_t i = 0; i < 4; ++i) p.rho[i] = 1.0, p.u[i] = 1.0, p.p[i] = 0.4, p.h[i] = 0.1;
  CHECK(!sph::first_bad(p));
  p.u[2] = -1e-3;
  p.rho[3] = 0.0;
  const auto b = sph::first_bad(p);
  REQUIRE(b);
  CHECK(b->particle == 2);
  CHECK(b->what == "u < 0");
  p.u[2] = 1.0;
  p.p[1] = NAN;
  CHECK(sph::first_bad(p)->particle == 1);
  CHECK(sph::first_bad(p)->what == "p not finite");
  CHECK(sph::unstable_verdict(12, 0.5, *sph::first_bad(p)) == "unstable: step 12 (t = 0.500000), particle 1: p not finite");
}

TEST_CASE("symmetric forms conserve momentum and energy over many steps", "[hydro][conservation]") {
  using L1 = sph::Lambda1;
  using L2 = sph::Lambda2;
  // Over a thousand steps of 576 particles with viscosity active.
  const Drift a = conservation_run<sph::EulerSymmetric<2, L1>, sph::EnergySymmetric<2, L1>>(5.0, 0.3);
  INFO("(23)+(41): steps " << a.steps << ", momentum " << a.momentum << ", dE/dt " << a.rate << ", energy " << a.energy);
  REQUIRE(a.verdict == "ok");
  CHECK(a.steps > 1000);
  CHECK(a.mass == 0.0);  // equal masses, none created or lost
  // Round-off: pairwise antisymmetric forces; measured ~1e-16, bound 1e-13 (a thousand steps of
  // accumulation at 1e-16).
  CHECK(a.momentum <= 1e-13);
  // (96)-(104): the semi-discrete energy rate vanishes; measured ~1e-16 of its scale.
  CHECK(a.rate <= 1e-13);
  const Drift b = conservation_run<sph::EulerSymmetric<2, L2>, sph::EnergySymmetric<2, L2>>(1.0, 0.3);
  INFO("(26)+(42): momentum " << b.momentum << ", dE/dt " << b.rate << ", energy " << b.energy);
  CHECK(b.momentum <= 1e-13);
  CHECK(b.rate <= 1e-13);
  // Controls. (22) is not antisymmetric: momentum must visibly drift. Paired with (37) it still
  // conserves energy exactly (swapping i, j in (37) gives minus the work of (22)).
  const Drift c = conservation_run<sph::EulerDirect<2>, sph::EnergyAsymmetric<2, sph::EnergyForm::direct37>>(0.2, 0.3);
  INFO("(22)+(37): momentum " << c.momentum << ", dE/dt " << c.rate);
  CHECK(c.momentum > 1e-6);
  CHECK(c.rate <= 1e-13);
  // (38), (40) and (41) give the same total (v_ij . grad_i W_ij is symmetric in i, j), so any of
  // them conserves energy with (23); the mismatched pair (23)+(42) leaves
  // 1/2 sum m_i m_j [P(23) - P(26)]_ij v_ij . grad W and must not.
  const Drift e = conservation_run<sph::EulerSymmetric<2, L1>, sph::EnergySymmetric<2, L2>>(0.2, 0.3);
  INFO("(23)+(42): momentum " << e.momentum << ", dE/dt " << e.rate);
  CHECK(e.momentum <= 1e-13);
  CHECK(e.rate > 1e-6);
}

// The last step is clipped so that the run ends exactly at t_end. Analytic check: with
// antisymmetric forces the centre of mass moves at the constant velocity P / M, so it must have
// moved by exactly P / M t_end (an unclipped last step overshoots by up to one dt, here about 1 %
// of t_end). Tolerance 1e-12 relative: momentum is conserved to 1e-13 (the test above).
TEST_CASE("evolve ends at t_end: the centre of mass moves by P / M t_end", "[hydro][conservation]") {
  auto p = stirred_gas(5);
  for (auto& v : p.v) v += sph::Vec<2>(0.7, 0.2);
  const auto box = sph::unit_box<2>(true);
  sph::density_summation(p, sph::grid_search<2>(p.x, p.h, box), box);
  sph::Scene<2, sph::SummationDensity<2>, sph::EquationOfState<2, sph::IdealGas>, sph::EulerSymmetric<2, sph::Lambda1>,
             sph::EnergySymmetric<2, sph::Lambda1>, sph::ArtificialViscosity<2>>
      scene;
  std::get<1>(scene.terms).eos.gamma = 5.0 / 3.0;
  sph::HydroControls c;
  c.t_end = 0.1234;
  auto centre = [&](const std::vector<sph::Vec<2>>& w) {
    sph::Vec<2> s = sph::Vec<2>::Zero();
    double m = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) s += p.m[i] * w[i], m += p.m[i];
    return sph::Vec<2>(s / m);
  };
  const sph::Vec<2> x0 = centre(p.x), V = centre(p.v);
  const auto out = sph::evolve(scene, p, box, c);
  REQUIRE(out.verdict == "ok");
  CHECK(out.steps > 5);
  const sph::Vec<2> moved = centre(p.x) - x0;
  INFO("moved " << moved.transpose() << ", V t_end " << (V * c.t_end).transpose() << " in " << out.steps << " steps");
  CHECK((moved - V * c.t_end).norm() <= 1e-12 * (V * c.t_end).norm());
}

TEST_CASE("total energy drift of KDK is the time-integration error, second order in dt", "[hydro][conservation]") {
  using L1 = sph::Lambda1;
  const Drift a = conservation_run<sph::EulerSymmetric<2, L1>, sph::EnergySymmetric<2, L1>>(0.5, 0.3);
  const Drift b = conservation_run<sph::EulerSymmetric<2, L1>, sph::EnergySymmetric<2, L1>>(0.5, 0.15);
  INFO("C = 0.3: " << a.energy << " (" << a.steps << " steps); C = 0.15: " << b.energy << " (" << b.steps << " steps)");
  // Halving dt divides an O(dt^2) drift by 4, an O(dt) drift by 2. Measured 3.3 (the switch of
  // (45) at v_ij . r_ij = 0 is not smooth); KDK without the velocity prediction measured 2.02.
  CHECK(a.energy / b.energy >= 2.8);
  CHECK(a.energy / b.energy <= 5.5);
}

TEST_CASE("bad shock-tube input is refused with InputError", "[hydro][input]") {
  const auto& c = sphv::find_case("sod");
  for (const char* bad : {"gamma=1", "gamma=0.5", "rho_l=-1", "rho_r=0", "p_l=-0.1", "p_r=0", "x0=0", "x0=1.5",
                          "t_end=-1", "n=0", "rho_l=abc", "v_l=-10", "preset=toro9"}) {
    INFO(bad);
    CHECK_THROWS_AS(c.parse({bad, bad[0] == 'v' ? "v_r=10" : "n=10"}), sphv::InputError);
  }
  CHECK_NOTHROW(c.parse({"rho_l=2", "p_r=0.5", "gamma=1.6667", "t_end=0.1", "x0=0.3"}));
  // t_end = 0 scores initial conditions (the tube's two states); a run needs t_end > 0.
  CHECK_THROWS_AS(c.run(c.parse({"t_end=0", "n=10"})), sphv::InputError);
}

TEST_CASE("extreme Riemann presets: the outcome each must have, and the method that survives it", "[hydro][extreme]") {
  // Measured at n = 100 (one thread): Toro 2 and 5 run stable with every form of the catalogue;
  // Toro 3 and 4 (pressure ratios 1e5, 1e4 from rest) end "unstable: step 1 ... u < 0" with
  // (23)+(41), (26)+(42), (23)+(40) and continuity (33), while (23)+(38) survives them: (38)
  // changes u_i in proportion to p_i (u_i stays positive for a small step), (41) feeds the hot
  // neighbour's p_j into the cold particle's du/dt. Bounds on L1(rho): measured + 20 %.
  struct Expect {
    const char* preset;
    const char* energy;
    bool stable;
    double l1_rho_measured;
  };
  const auto& c = sphv::find_case("sod");
  for (const Expect e : {Expect{"toro2", "auto", true, 0.0166}, Expect{"toro3", "auto", false, 0.0},
                         Expect{"toro3", "38", true, 0.0525}, Expect{"toro4", "auto", false, 0.0},
                         Expect{"toro4", "38", true, 0.0440}, Expect{"toro5", "auto", true, 0.370}}) {
    const auto p = c.parse({std::string("preset=") + e.preset, std::string("energy=") + e.energy, "n=100"});
    const auto r = sphv::run_case(c, p);
    INFO(e.preset << " energy " << e.energy << ": " << r.verdict);
    if (e.stable) {
      CHECK(r.verdict == "stable");
      // The four L1 errors, and the contact's where its window holds particles enough (not in
      // Toro 2's near vacuum).
      for (const char* k : {"L1_rho", "L1_v", "L1_p", "L1_u"}) REQUIRE(r.errors.count(k) == 1);
      REQUIRE(r.errors.size() - r.errors.count("L1_p_contact") == 4);
      for (const auto& [k, v] : r.errors) CHECK(std::isfinite(v));
      CHECK(r.errors.at("L1_rho") <= 1.2 * e.l1_rho_measured);
    } else {
      CHECK(r.verdict.rfind("unstable: step 1 ", 0) == 0);
      CHECK(r.verdict.find("u < 0") != std::string::npos);
      CHECK(r.errors.empty());
      CHECK(!c.verdict_expected(p, r.verdict));  // `sphv run` exits 1 on it: stability was expected
    }
  }
}
