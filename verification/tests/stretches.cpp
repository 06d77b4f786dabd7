// The stretches the pair loops share among threads (sph/core/stretches.hpp): every index handed
// out once, in chunks numbered in index order, the chunks of a stretch in order from its front,
// and a slow thread's stretch finished by the others.
#include <catch2/catch.hpp>
#include <omp.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "sph/core/stretches.hpp"

TEST_CASE("stretches hand out every index once, and a slow thread's work to the others", "[threads]") {
  const int threads = 3;
  const std::vector<std::size_t> from = {0, 10000, 10007, 25000};  // uneven; one nearly empty
  std::vector<std::atomic<int>> visits(from.back());
  std::vector<int> by(from.back(), -1);
  std::vector<char> in_order(threads, 1);  // checked after the team: Catch's checks are not thread-safe
  int team = 0;
  sph::Stretches stretches;
  stretches.reset(from);
  std::vector<std::atomic<int>> taken(stretches.chunks());
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
#pragma omp single
    team = omp_get_num_threads();
    // Thread 0 starts late: the others finish their own and take the back of its stretch.
    if (t == 0) std::this_thread::sleep_for(std::chrono::milliseconds(200));
    std::size_t next = from[t];  // where thread t's next chunk of its own stretch starts
    stretches.work(t, [&](std::size_t c, std::size_t k0, std::size_t k1) {
      if (stretches.owns(t, c)) in_order[t] = in_order[t] && k0 == next, next = k1;
      taken[c]++;
      for (std::size_t k = k0; k < k1; ++k) visits[k]++, by[k] = t;
    });
  }
  // The chunks tile the range in their numbers' order, each taken once, and range(c) names them.
  std::size_t end = 0;
  for (std::size_t c = 0; c < stretches.chunks(); ++c) {
    const auto [k0, k1] = stretches.range(c);
    CHECK(k0 == end);
    CHECK(k1 > k0);
    CHECK(taken[c] == 1);
    end = k1;
  }
  CHECK(end == from.back());
  int twice = 0, never = 0;
  for (const auto& v : visits) twice += v > 1, never += v == 0;
  CHECK(twice == 0);
  CHECK(never == 0);
  for (int t = 0; t < team; ++t) CHECK(in_order[t]);
  // 200 ms is far longer than the others' 15,000 empty visits take: they took its back.
  if (team == threads) CHECK(by[from[1] - 1] != 0);
}
