// Gates of the conservation catalogue (9.5): conservation, conservation_dt, conservation_gradh.
#include <catch2/catch.hpp>

#include <omp.h>

#include "verification/sweep.hpp"

namespace {

// The gate scenes have a few hundred particles and thousands of short pair loops: one thread
// is faster than a fork-join per loop, above all when ctest runs tests side by side (measured:
// 24 s single-threaded against 105 s with two threads on a loaded machine). The results do
// not depend on the thread count (pairs.hpp).
struct OneThread {
  int before = omp_get_max_threads();
  OneThread() { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(before); }
};

void require_gates(const std::string& name) {
  const OneThread one;
  const auto& c = sphv::find_case(name);
  for (const auto& settings : c.variants) {
    const auto s = sphv::run_sweep(c, c.sweep_levels(settings, true), settings);
    for (const auto& ch : s.checks) {
      INFO(name << " [" << s.variant() << "] " << ch.name << " = " << ch.value << " in [" << ch.lo << ", " << ch.hi
                << "]: " << ch.why);
      CHECK(ch.pass());
    }
  }
}

}  // namespace

TEST_CASE("gate: conservation", "[gate][conservation]") { require_gates("conservation"); }
TEST_CASE("gate: conservation_dt", "[gate][conservation]") { require_gates("conservation_dt"); }
TEST_CASE("gate: conservation_gradh", "[gate][conservation]") { require_gates("conservation_gradh"); }
