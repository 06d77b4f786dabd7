// Catch2 gates: every case tagged "gate" runs its CI-sized sweep for each variant and must
// pass its checks. Areas with their own test files may add finer unit tests.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include "verification/sweep.hpp"

namespace {
void gate(const std::string& name) {
  const sphv::Case& c = sphv::find_case(name);
  for (const auto& settings : c.variants) {
    const sphv::Sweep s = sphv::run_sweep(c, c.sweep_levels(settings, true), settings);
    INFO("variant " << s.variant());
    for (const auto& r : s.runs) INFO("n=" << r.params["n"] << " verdict " << r.verdict);
    for (const auto& [k, v] : s.observed_order) INFO("observed order " << k << " = " << v);
    for (const auto& ch : s.checks) {
      INFO(ch.name << " = " << ch.value << " in [" << ch.lo << ", " << ch.hi << "]: " << ch.why);
      CHECK(ch.pass());
    }
  }
}
}  // namespace

TEST_CASE("the catalogue has gated cases with checks", "[catalogue]") {
  int gated = 0;
  for (const auto& c : sphv::catalogue()) {
    gated += c.has_tag("gate");
    if (c.has_tag("gate")) CHECK(static_cast<bool>(c.gates));
  }
  REQUIRE(gated >= 2);
}

TEST_CASE("gate: kernel", "[gate][kernel]") { gate("kernel"); }
TEST_CASE("gate: interpolation", "[gate][interpolation]") { gate("interpolation"); }

TEST_CASE("drift baselines catch an error that grows", "[baseline]") {
  const sphv::Case& c = sphv::find_case("kernel");
  const sphv::Sweep s = sphv::run_sweep(c, c.gate_levels, {});
  int drift = 0;
  for (const auto& ch : s.checks) drift += ch.name.rfind("drift_", 0) == 0 && ch.pass();
  REQUIRE(drift > 0);  // reference/baselines/kernel.json exists and today's errors match it
  std::vector<sphv::Result> grown = s.runs;
  grown.back().errors.begin()->second *= 1.2;  // beyond the 1.1 factor
  const sphv::Sweep g = sphv::summarise(c, {}, s.levels, grown);
  int failed = 0;
  for (const auto& ch : g.checks) failed += !ch.pass();
  REQUIRE(failed == 1);
}
