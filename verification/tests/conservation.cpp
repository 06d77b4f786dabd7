// Gates of the conservation catalogue (9.5): conservation, conservation_dt, conservation_gradh.
#include <catch2/catch.hpp>

#include "verification/sweep.hpp"

namespace {

void require_gates(const std::string& name) {
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
