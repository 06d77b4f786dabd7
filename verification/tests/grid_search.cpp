// The grid search returns exactly the pairs of a brute-force O(N^2) search at the nearest
// image, for periodic and open boxes, constant and variable h, a few particles far wider than the
// rest (cells follow the median h), few cells per axis, and in the same order on any number of
// threads; and lists reused across steps (sph/search/verlet_list.hpp) still hold every pair.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <random>
#include <utility>

#include <omp.h>

#include "sph/core/isa.hpp"
#include "sph/search/grid_search.hpp"
#include "sph/search/verlet_list.hpp"

namespace {

template <int D>
void compare(std::size_t n, bool periodic, double hmin, double hmax, unsigned seed, double wide = 0.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), uh(hmin, hmax);
  sph::Box<D> box = sph::unit_box<D>(periodic);
  std::vector<sph::Vec<D>> x(n);
  std::vector<double> h(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) x[i][d] = periodic ? u(rng) * 3.0 - 1.0 : u(rng);  // outside the box too
    h[i] = uh(rng);
    if (i % 97 == 0 && wide > 0.0) h[i] = wide;  // ~1 %: the hot, rarefied centre of a blast wave
  }
  const auto nl = sph::grid_search<D>(x, h, box);
  const sph::Vec<D> L = box.length(), wrap = box.wrap_factor();
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<int> brute;
    for (std::size_t j = 0; j < n; ++j) {
      const double rs = std::max(h[i], h[j]);
      if (j != i && sph::min_image<D>(x[i] - x[j], L, wrap).squaredNorm() < rs * rs) brute.push_back(int(j));
    }
    std::vector<int> grid(nl.of(i).begin(), nl.of(i).end());
    std::sort(grid.begin(), grid.end());
    REQUIRE(grid == brute);
    pairs += brute.size();
  }
  REQUIRE(pairs == nl.pairs());
  // The same lists in the same order, and the same visiting order, on one thread, two and three (n
  // above the parallel threshold; three split the counting sort's ranges unevenly).
  const int threads = omp_get_max_threads();
  for (int other_threads : {1, 2, 3}) {
    omp_set_num_threads(other_threads);
    const auto other = sph::grid_search<D>(x, h, box);
    omp_set_num_threads(threads);
    REQUIRE(other.offset == nl.offset);
    REQUIRE(other.j == nl.j);
    REQUIRE(other.order == nl.order);
  }
}

// A periodic box [lo, lo + L) that does not start at 0, particles anywhere in [lo - L, lo + 2L):
// the brute-force pairs at the nearest image with L typed here, dx - L round(dx / L), not from
// the box (every other test's box is [0, 1), where hi and the length agree).
template <int D>
void compare_offset_box(std::size_t n, double lo, double L, double hmin, double hmax, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), uh(hmin, hmax);
  sph::Box<D> box = sph::unit_box<D>(true);
  for (int d = 0; d < D; ++d) box.lo[d] = lo, box.hi[d] = lo + L;
  std::vector<sph::Vec<D>> x(n);
  std::vector<double> h(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) x[i][d] = lo + (u(rng) * 3.0 - 1.0) * L;
    h[i] = uh(rng);
  }
  const auto nl = sph::grid_search<D>(x, h, box);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<int> brute;
    for (std::size_t j = 0; j < n; ++j) {
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double dx = x[i][d] - x[j][d];
        r2 += std::pow(dx - L * std::round(dx / L), 2);
      }
      const double rs = std::max(h[i], h[j]);
      if (j != i && r2 < rs * rs) brute.push_back(int(j));
    }
    std::vector<int> grid(nl.of(i).begin(), nl.of(i).end());
    std::sort(grid.begin(), grid.end());
    INFO("particle " << i);
    REQUIRE(grid == brute);
    pairs += brute.size();
  }
  REQUIRE(pairs == nl.pairs());
}

}  // namespace

TEST_CASE("grid search equals brute force in periodic boxes that do not start at 0", "[neighbours]") {
  compare_offset_box<1>(300, -0.5, 1.0, 0.01, 0.05, 11);  // [-0.5, 0.5): hi 0.5, length 1
  compare_offset_box<2>(800, -0.5, 1.0, 0.03, 0.08, 12);
  compare_offset_box<3>(1500, -0.5, 1.0, 0.05, 0.15, 13);
  compare_offset_box<2>(800, -0.25, 1.25, 0.03, 0.08, 14);  // [-0.25, 1): hi 1, length 1.25
  compare_offset_box<3>(1500, 0.3, 0.9, 0.05, 0.12, 15);    // [0.3, 1.2): lo > 0
}

// On every instruction-set path this CPU has (the 3D candidate loop has AVX2 and AVX-512 copies).
TEST_CASE("grid search equals brute force", "[neighbours]") {
  const sph::IsaPath chosen = sph::isa_path();
  for (sph::IsaPath path : {sph::IsaPath::portable, sph::IsaPath::avx2, sph::IsaPath::avx512}) {
    if (!sph::isa_supported(path)) continue;
    sph::set_isa_path(path);
    for (bool periodic : {true, false}) {
      compare<1>(300, periodic, 0.01, 0.05, 1);
      compare<2>(800, periodic, 0.03, 0.08, 2);
      compare<3>(1500, periodic, 0.05, 0.15, 3);
      compare<3>(400, periodic, 0.2, 0.45, 4);  // only 2-4 cells per axis: stencils wrap onto themselves
      compare<2>(500, periodic, 0.1, 0.1, 5);   // constant h
      compare<2>(5000, periodic, 0.01, 0.03, 6, 0.2);  // a few wide particles; above parallel_threshold
      compare<3>(5000, periodic, 0.04, 0.08, 7, 0.45);
      compare<3>(5000, periodic, 0.05, 0.07, 8);  // nearly uniform h: cells of h_max / 2
    }
  }
  sph::set_isa_path(chosen);
}

// The vectorised candidate loops round as the portable ones: the same lists in the same order, on a
// lattice where many pairs sit exactly at |r_ij| = h (ties decided alike) and on a jittered one;
// with one particle in 97 of three times the support radius, the wide-h search (own_reach).
TEST_CASE("grid search lists the same pairs on every instruction-set path", "[neighbours]") {
  if (!sph::isa_supported(sph::IsaPath::avx2)) return;
  const sph::IsaPath chosen = sph::isa_path();
  for (auto [jitter, wide] : std::initializer_list<std::pair<double, bool>>{{0.0, false}, {0.3, false}, {0.3, true}}) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    const int side = 20;
    const double dx = 1.0 / side;
    std::vector<sph::Vec<3>> x;
    for (int a = 0; a < side; ++a)
      for (int b = 0; b < side; ++b)
        for (int c = 0; c < side; ++c)
          x.push_back(dx * sph::Vec<3>(a + jitter * u(rng), b + jitter * u(rng), c + jitter * u(rng)));
    std::vector<double> h(x.size(), 2.0 * dx);
    if (wide)
      for (std::size_t i = 0; i < h.size(); i += 97) h[i] = 6.0 * dx;
    for (bool periodic : {true, false}) {
      const sph::Box<3> box = sph::unit_box<3>(periodic);
      sph::set_isa_path(sph::IsaPath::portable);
      const auto portable = sph::grid_search<3>(x, h, box);
      for (sph::IsaPath path : {sph::IsaPath::avx2, sph::IsaPath::avx512}) {
        if (!sph::isa_supported(path)) continue;
        sph::set_isa_path(path);
        const auto other = sph::grid_search<3>(x, h, box);
        REQUIRE(other.offset == portable.offset);
        REQUIRE(other.j == portable.j);
        REQUIRE(other.order == portable.order);
      }
    }
  }
  sph::set_isa_path(chosen);
}

namespace {

// Particles in two streams that cross along x (pairs of opposite streams approach at twice the
// speed, the worst case the skin must cover) while every h grows by the same factor per step.
// The reused list must hold every pair a brute-force search finds at every step, and must be
// searched again far less often than every step. The box's sides are 1, 1.25 and 1.5: a nearest
// image that mixed up a side and its inverse would show.
template <int D>
void verlet_steps(std::size_t n, bool periodic, double h0, double speed, double growth, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), uh(0.7 * h0, 1.3 * h0);
  sph::Box<D> box = sph::unit_box<D>(periodic);
  for (int d = 0; d < D; ++d) box.hi[d] = 1.0 + 0.25 * d;
  std::vector<sph::Vec<D>> x(n), v(n, sph::Vec<D>::Zero());
  std::vector<double> h(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) x[i][d] = box.hi[d] * u(rng);
    v[i][0] = (i % 2 ? speed : -speed) * h0;
    h[i] = uh(rng);
  }
  const sph::Vec<D> L = box.length(), wrap = box.wrap_factor();
  sph::VerletList<D> lists(0.1);
  const int steps = 40;
  long missing = 0, extra = 0;
  for (int s = 0; s < steps; ++s) {
    const sph::NeighbourList& nl = lists.update(x, h, box);
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<int> listed(nl.of(i).begin(), nl.of(i).end());
      std::sort(listed.begin(), listed.end());
      long found = 0;
      for (std::size_t j = 0; j < n; ++j) {
        const double rs = std::max(h[i], h[j]);
        if (j != i && sph::min_image<D>(x[i] - x[j], L, wrap).squaredNorm() < rs * rs) {
          const bool in = std::binary_search(listed.begin(), listed.end(), int(j));
          missing += !in, found += in;
        }
      }
      extra += static_cast<long>(listed.size()) - found;
    }
    for (std::size_t i = 0; i < n; ++i) x[i] += v[i], h[i] *= 1.0 + growth;
  }
  CHECK(missing == 0);
  CHECK(extra == 0);                    // and no pair beyond max(h_i, h_j)
  CHECK(lists.searches() > 1);          // the lists were renewed as the particles moved
  CHECK(lists.searches() < steps / 3);  // and reused in between
}

}  // namespace

// sph/search/verlet_list.hpp's reuse conditions (a) (each particle within half its skin) and
// (b) (2 d_max and h's growth within the skin) against a brute-force search at every step, on
// every instruction-set path this CPU has (the pair filter and the search's candidate test have a
// portable, an AVX2 and an AVX-512 copy).
TEST_CASE("reused neighbour lists hold every pair of a brute-force search", "[neighbours]") {
  const sph::IsaPath chosen = sph::isa_path();
  for (sph::IsaPath path : {sph::IsaPath::portable, sph::IsaPath::avx2, sph::IsaPath::avx512}) {
    if (!sph::isa_supported(path)) continue;
    sph::set_isa_path(path);
    for (bool periodic : {true, false}) {
      verlet_steps<2>(1200, periodic, 0.04, 0.008, 0.0, 11);    // streams at constant h: (a)
      verlet_steps<3>(1200, periodic, 0.15, 0.008, 0.0, 12);
      verlet_steps<3>(1200, periodic, 0.15, 0.0, 0.008, 15);
      verlet_steps<2>(1200, periodic, 0.04, 0.0, 0.008, 13);    // at rest, h growing: (b)
      verlet_steps<2>(1200, periodic, 0.04, 0.004, 0.004, 14);  // both: (b) outlasts (a)
    }
  }
  sph::set_isa_path(chosen);
}
