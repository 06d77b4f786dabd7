// Catch2 gates: every case tagged "gate" runs its CI-sized sweep and must pass its checks.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include "verification/sweep.hpp"

TEST_CASE("the catalogue has gated cases", "[catalogue]") {
  int gated = 0;
  for (const auto& c : sphv::catalogue()) gated += c.has_tag("gate");
  REQUIRE(gated >= 2);
}
