// evolve's storage of the particles in the search's cell order (sph/hydro/storage_order.hpp): the
// same results as a run that keeps the caller's order, the particles returned in that order, the
// verdict naming the caller's particle, and no reordering where hooks or a scene's arrays need the
// caller's order.
#include <catch2/catch.hpp>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "sph/core/lattice.hpp"
#include "sph/density/terms.hpp"
#include "sph/hydro/energy.hpp"
#include "sph/hydro/eos.hpp"
#include "sph/hydro/euler.hpp"
#include "sph/hydro/evolve.hpp"

namespace {

using Gas = sph::Scene<3, sph::SummationDensity<3>, sph::EquationOfState<3, sph::IdealGas>,
                       sph::EulerSymmetric<3, sph::Lambda2>, sph::EnergySymmetric<3, sph::Lambda2>,
                       sph::ArtificialViscosity<3>>;

// A jittered 12^3 lattice in a periodic box with random velocities, stored in a random order (as a
// snapshot of another code may be), so that the search's cell order is far from the storage order.
sph::Particles<3> shuffled_gas() {
  const auto q = sph::lattice<3>(12, sph::unit_box<3>(true), 1.0, 2.4, 0.1, 3);
  std::vector<std::size_t> at(q.size());
  std::iota(at.begin(), at.end(), 0);
  std::shuffle(at.begin(), at.end(), std::mt19937_64(11));
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 0.3);
  sph::Particles<3> p;
  p.resize(q.size());
  for (std::size_t k = 0; k < q.size(); ++k) {
    p.x[k] = q.x[at[k]], p.m[k] = q.m[at[k]], p.h[k] = q.h[at[k]], p.rho[k] = 1.0;
    p.u[k] = 1.0;
    p.v[k] = sph::Vec<3>(g(rng), g(rng), g(rng));
  }
  return p;
}

struct Run {
  sph::Particles<3> p;
  sph::HydroOutcome out;
};
sph::HydroControls controls(long steps, long reorder_every) {
  sph::HydroControls c;
  c.t_end = 1e30;  // ended by the step budget
  c.max_steps = steps;
  c.reorder_every = reorder_every;
  return c;
}
Run run(sph::Particles<3> p, const sph::HydroControls& c, const sph::HydroHooks<3>& hooks = {}) {
  Gas scene;
  std::get<1>(scene.terms).eos.gamma = 5.0 / 3.0;
  const auto out = sph::evolve(scene, p, sph::unit_box<3>(true), c, hooks);
  return {std::move(p), out};
}

double largest_difference(const sph::Particles<3>& a, const sph::Particles<3>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    d = std::max({d, (a.x[i] - b.x[i]).norm(), (a.v[i] - b.v[i]).norm(), std::abs(a.u[i] - b.u[i]),
                  std::abs(a.rho[i] - b.rho[i]), std::abs(a.p[i] - b.p[i])});
  return d;
}

}  // namespace

TEST_CASE("evolve reorders the particles' storage and returns them in the caller's order", "[hydro][reorder]") {
  const auto p = shuffled_gas();
  SECTION("until the next search, bit for bit the run in the caller's order") {
    // The renumbered lists are those of a search of the reordered particles: the same pairs in the
    // same order, so every sum is the same.
    const Run kept = run(p, controls(4, 0)), reordered = run(p, controls(4, 64));
    REQUIRE(kept.out.verdict == "unstable: step 4 (t = " + std::to_string(kept.out.t) +
                                    "): step budget of 4 steps exhausted before t_end");
    REQUIRE(reordered.out.verdict == kept.out.verdict);
    REQUIRE(reordered.out.searches == 1);  // no search after the first: a later one may order pairs anew
    CHECK(kept.out.reorders == 0);
    CHECK(reordered.out.reorders == 1);
    CHECK(largest_difference(kept.p, reordered.p) == 0.0);
    CHECK(reordered.out.t == kept.out.t);
  }
  SECTION("over many searches, the same run to round-off") {
    // Reordered at every search. A later search of the reordered particles lists a particle's
    // neighbours in another order, so sums differ at round-off: 1e-13 bounds what round-off grows
    // to over these steps (measured: 1.1e-15, 100x margin; a wrong pair or particle moves things by far more).
    const Run kept = run(p, controls(40, 0)), reordered = run(p, controls(40, 1));
    REQUIRE(reordered.out.searches >= 3);
    CHECK(reordered.out.reorders == reordered.out.searches);
    INFO("searches " << reordered.out.searches << ", t " << reordered.out.t);
    CHECK(largest_difference(kept.p, reordered.p) <= 1e-13);
    CHECK(std::abs(reordered.out.t - kept.out.t) <= 1e-13 * kept.out.t);
  }
  SECTION("the same on one thread and on three, every loop forked") {
    // Three threads split the renumbered rows into ranges none of which is a contiguous run of
    // rows: each range's filter buffer must hold its own rows' candidates.
    const std::size_t threshold = sph::parallel_threshold;
    const int threads = omp_get_max_threads();
    sph::parallel_threshold = 0;
    omp_set_num_threads(1);
    const Run one = run(p, controls(40, 1));
    omp_set_num_threads(3);
    const Run three = run(p, controls(40, 1));
    omp_set_num_threads(threads);
    sph::parallel_threshold = threshold;
    CHECK(three.out.reorders == one.out.reorders);
    CHECK(largest_difference(one.p, three.p) == 0.0);
  }
  SECTION("not with hooks, which may address particles by their index") {
    sph::HydroHooks<3> hooks;
    std::vector<sph::Vec<3>> seen;
    hooks.stepped = [&](const sph::Particles<3>& q, const sph::Derivatives<3>&, long, double) { seen.push_back(q.x[7]); };
    const Run hooked = run(p, controls(4, 64), hooks), kept = run(p, controls(4, 0));
    CHECK(hooked.out.reorders == 0);
    CHECK(seen.back() == kept.p.x[7]);
  }
  SECTION("with hooks that treat every particle alike, which then see them in storage order") {
    sph::HydroHooks<3> hooks;
    hooks.index_free = true;
    double mass = 0.0;
    hooks.stepped = [&](const sph::Particles<3>& q, const sph::Derivatives<3>&, long, double) {
      mass = std::accumulate(q.m.begin(), q.m.end(), 0.0);
    };
    const Run hooked = run(p, controls(4, 64), hooks), kept = run(p, controls(4, 0));
    CHECK(hooked.out.reorders == 1);
    CHECK(largest_difference(kept.p, hooked.p) == 0.0);
    CHECK(std::abs(mass - std::accumulate(p.m.begin(), p.m.end(), 0.0)) <= 1e-12 * mass);
  }
}

TEST_CASE("a run gone bad after a reordering names the caller's particle", "[hydro][reorder]") {
  // Particle `cold` has almost no internal energy and its neighbours move away from it: without the
  // cooling criterion of the time step, the expansion drives its u below zero in the first step,
  // after the particles were reordered, and the state goes bad around it.
  auto p = shuffled_gas();
  const std::size_t cold = 100;
  p.u[cold] = 1e-10;
  const sph::Box<3> box = sph::unit_box<3>(true);
  for (std::size_t i = 0; i < p.size(); ++i)
    p.v[i] = 3.0 * sph::min_image<3>(p.x[i] - p.x[cold], box.length(), box.wrap_factor());
  auto c = controls(10, 0);
  c.step.C_energy = 0.0;
  const Run kept = run(p, c);
  c.reorder_every = 64;
  const Run reordered = run(p, c);
  INFO(reordered.out.verdict);
  CHECK(reordered.out.reorders == 1);
  CHECK(reordered.out.verdict == kept.out.verdict);
  // The particle named is the caller's first bad one in the particles returned.
  const auto at = reordered.out.verdict.find("particle ");
  REQUIRE(at != std::string::npos);
  const std::size_t named = std::stoul(reordered.out.verdict.substr(at + 9));
  REQUIRE(named < p.size());
  CHECK(sph::what_is_bad(reordered.p, named) != nullptr);
  for (std::size_t i = 0; i < named; ++i) CHECK_FALSE(sph::what_is_bad(reordered.p, i));
  CHECK(largest_difference(kept.p, reordered.p) == 0.0);
}
