// Hydrodynamics of 9.2-9.4.2: equations of state, conservation by the symmetric forms over many
// steps, the verdict check, bad input, the extreme Riemann presets, and the shock-tube gates.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "sph/energy.hpp"
#include "sph/eos.hpp"
#include "sph/euler.hpp"
#include "sph/hydro.hpp"
#include "sph/hydro_density.hpp"
#include "sph/hydro_smoothing_length.hpp"
#include "sph/lattice.hpp"
#include "sph/verdict.hpp"
#include "verification/sweep.hpp"

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
                          "t_end=0", "t_end=-1", "n=0", "rho_l=abc", "v_l=-10", "preset=toro9"}) {
    INFO(bad);
    CHECK_THROWS_AS(c.parse({bad, bad[0] == 'v' ? "v_r=10" : "n=10"}), sphv::InputError);
  }
  CHECK_NOTHROW(c.parse({"rho_l=2", "p_r=0.5", "gamma=1.6667", "t_end=0.1", "x0=0.3"}));
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
      REQUIRE(r.errors.size() == 4);
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
