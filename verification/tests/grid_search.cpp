// The grid search returns exactly the pairs of a brute-force O(N^2) search at the nearest
// image, for periodic and open boxes, constant and variable h, a few particles far wider than the
// rest (cells follow the median h), few cells per axis, and on more threads in the same order.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include <omp.h>

#include "sph/grid_search.hpp"

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
  // The same lists in the same order on one thread and on two (n above the parallel threshold).
  const int threads = omp_get_max_threads();
  omp_set_num_threads(threads == 1 ? 2 : 1);
  const auto other = sph::grid_search<D>(x, h, box);
  omp_set_num_threads(threads);
  REQUIRE(other.offset == nl.offset);
  REQUIRE(other.j == nl.j);
}

}  // namespace

TEST_CASE("grid search equals brute force", "[neighbours]") {
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
