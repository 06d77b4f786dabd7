// Catch2 gates: every case tagged "gate" is a test "gate: NAME" (registered from the catalogue, so
// a new case needs no line here) that runs its quick tier (the CI-sized levels `sphv verify
// --tier quick` runs, from the case's one declaration) for each variant, and every check and
// every error's outcome must hold; its smallest level must give the same bits on two threads. Areas with their own test files add finer unit tests.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstring>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "sph/core/threads.hpp"
#include "verification/harness/sweep.hpp"
#include "verification/tests/deferred.hpp"

namespace {

// A fixed number of OpenMP threads for one scope.
struct Threads {
  int before = omp_get_max_threads();
  explicit Threads(int n) { omp_set_num_threads(n); }
  ~Threads() { omp_set_num_threads(before); }
};

// One thread: the gate scenes are small (at most a few thousand particles) and run many short
// pair loops, where a fork-join per loop costs more than it gains, above all when ctest runs
// tests side by side (measured: conservation 24 s on one thread against 105 s on two, loaded).
// Results do not depend on the thread count (sph/hydro/pairs.hpp).
struct OneThread : Threads {
  OneThread() : Threads(1) {}
};

// The names whose values differ bit for bit between two runs (or are in one only).
std::string differences(const std::map<std::string, double>& a, const std::map<std::string, double>& b) {
  std::ostringstream o;
  o.precision(17);
  for (const auto& [k, v] : a)
    if (!b.count(k)) o << k << " in one run only; ";
    else if (std::memcmp(&v, &b.at(k), sizeof v) != 0) o << k << ": " << v << " vs " << b.at(k) << "; ";
  for (const auto& [k, v] : b)
    if (!a.count(k)) o << k << " in one run only; ";
  return o.str();
}

// Thread-count independence (sph/hydro/pairs.hpp: each particle's sums in a fixed order, whatever
// thread computes them): the sweep's smallest level, run on one thread, again on two threads
// gives the same verdict, errors and functionals bit for bit. Gate scenes are mostly smaller than
// sph::parallel_threshold, so the second run lowers it to 0 and every threaded loop forks. Not for
// the cases below: their smallest levels take thousands of steps of a few hundred particles, and
// forking every loop of every step costs half the run again or more, most of it sleeping and
// waking the second thread (OMP_WAIT_POLICY=passive). Their rerun keeps the threshold and checks
// the loops above it only; the loops they share (pair loop, EOS, integrators, Courant step,
// verdict, (50) iteration, neighbour lists) fork in sedov, evrard (with the gravity tree), sod,
// heat_stability and the other gates. extreme_tubes runs sod's 1D tube scenes (forked in sod's
// eleven variants) and the chapter scheme (forked in sedov).
const std::set<std::string> fork_bound = {"noh", "conservation", "stability_map_hydro", "extreme_degenerate",
                                          "stability_map_heat", "extreme_tubes"};
void require_thread_independent(const sphv::Case& c, const std::vector<std::string>& settings, const sphv::Sweep& s) {
  auto at_smallest = settings;
  at_smallest.push_back("n=" + std::to_string(s.levels.front()));
  const sphv::Result& one = s.runs.front();
  const sphv::Result two = [&] {
    const Threads t(2);
    struct AllThreaded {
      std::size_t before = sph::parallel_threshold;
      explicit AllThreaded(bool on) {
        if (on) sph::parallel_threshold = 0;
      }
      ~AllThreaded() { sph::parallel_threshold = before; }
    } all(!fork_bound.count(c.name));
    return sphv::run_case(c, c.parse(at_smallest));
  }();
  INFO("n = " << s.levels.front() << " on one thread and on two");
  CHECK(one.verdict == two.verdict);
  CHECK(differences(one.errors, two.errors) == "");
  CHECK(differences(one.functionals, two.functionals) == "");
}

// Everything a failure message needs: verdicts, orders, every check with its bounds and kind.
std::string describe(const sphv::Sweep& s) {
  std::ostringstream o;
  o << s.case_name << " [" << s.variant() << "], tier " << s.tier << "\n";
  for (const auto& r : s.runs) o << "  n=" << r.params["n"] << " verdict " << r.verdict << "\n";
  for (const auto& r : s.rows)
    o << "  " << r.error << ": finest " << r.fine_value << ", observed " << r.observed << " +- " << r.se
      << ", expected " << r.expected << ": " << r.outcome << " (" << r.why << ")\n";
  for (const auto& ch : s.checks)
    o << "  " << (ch.pass() ? "pass " : "FAIL ") << (ch.kind == sphv::Check::Kind::drift ? "[drift] " : "")
      << ch.name << " = " << ch.value << " in [" << ch.lo << ", " << ch.hi << "]: " << ch.why << "\n";
  return o.str();
}

// The gate of the case the running test names ("gate: NAME").
void gate() {
  const OneThread one;
  const std::string test = Catch::getResultCapture().getCurrentTestName();
  const sphv::Case& c = sphv::find_case(test.substr(test.find(": ") + 2));
  std::vector<sphv::Sweep> sweeps;
  for (const auto& settings : c.variants) sweeps.push_back(sphv::run_tier(c, sphv::Tier::quick, settings));
  sphv::check_experiments(sweeps);  // every known failure beside an experiment that verifies it
  for (std::size_t k = 0; k < sweeps.size(); ++k) {
    INFO(describe(sweeps[k]));
    CHECK(sweeps[k].passed());
    require_thread_independent(c, c.variants[k], sweeps[k]);
  }
}

// A test "gate: NAME" for every case tagged "gate", tagged [gate][NAME] and with the case's tags:
// declared by the case's registration alone.
void register_gates() {
  for (const auto& c : sphv::catalogue()) {
    if (!c.has_tag("gate")) continue;
    std::string tags = "[gate][" + c.name + "]";
    for (const auto& t : c.tags)
      if (t != "gate") tags += "[" + t + "]";
    Catch::getMutableRegistryHub().registerTest(Catch::makeTestCase(
        Catch::makeTestInvoker(&gate), "", Catch::NameAndTags{"gate: " + c.name, tags}, CATCH_INTERNAL_LINEINFO));
  }
}
const sphv::tests::Deferred gates{register_gates};

}  // namespace

TEST_CASE("every gated case has a gate test, checks and claims for its errors", "[catalogue]") {
  std::set<std::string> tests;
  for (const auto& t : Catch::getRegistryHub().getTestCaseRegistry().getAllTests()) tests.insert(t.name);
  int gated = 0;
  for (const auto& c : sphv::catalogue()) {
    if (!c.has_tag("gate")) continue;
    ++gated;
    INFO(c.name);
    CHECK(tests.count("gate: " + c.name) == 1);
    CHECK(static_cast<bool>(c.gates));
    CHECK(static_cast<bool>(c.orders));
    CHECK(!c.levels.quick.empty());
    CHECK(!c.levels.standard.empty());
    CHECK(!c.levels.full.empty());
    // What a case writes for another code (sphv ic) it can score back (sphv score).
    if (c.ic) CHECK(static_cast<bool>(c.scorer.score));
    // Every error a case claims (or declines to claim) an order for is defined, and vice versa.
    if (c.orders)
      for (const auto& v : c.variants)
        for (const auto& [e, claim] : c.orders(c.parse(v))) {
          INFO(c.name << " error " << e);
          CHECK(c.error_defs.count(e) == 1);
          CHECK(!claim.why.empty());
        }
  }
  REQUIRE(gated >= 24);
  // Every case is gated, so the gates check every case's thread-count independence too.
  CHECK(gated == static_cast<int>(sphv::catalogue().size()));
}

TEST_CASE("drift baselines catch an error that grows and one that went stale", "[baseline]") {
  const sphv::Case& c = sphv::find_case("kernel");
  const sphv::Sweep s = sphv::run_tier(c, sphv::Tier::quick, {});
  int drift = 0;
  for (const auto& ch : s.checks) drift += ch.kind == sphv::Check::Kind::drift && ch.pass();
  REQUIRE(drift > 0);  // reference/baselines/kernel.json exists and today's errors match it
  for (double factor : {1.2, 0.8}) {  // beyond the 1.1 and 0.9 factors
    std::vector<sphv::Result> changed = s.runs;
    changed.back().errors.begin()->second *= factor;
    const sphv::Sweep g = sphv::summarise(c, {}, s.levels, changed, "quick");
    int failed = 0;
    for (const auto& ch : g.checks) failed += !ch.pass() && ch.kind == sphv::Check::Kind::drift;
    CHECK(failed == 1);
    CHECK(!g.passed());
  }
}

// The catalogue's layout (verification/cases/README.md): every listed case has a folder of its own
// (cases/NAME/case.cpp) or its file in a family folder (cases/FAMILY/NAME.cpp); a case registered
// per dimension (sod2d, sod3d) lives in the file of its 1D name.
TEST_CASE("every case has its folder or its file in a family folder", "[catalogue]") {
  namespace fs = std::filesystem;
  const fs::path cases = fs::path(SPHV_SOURCE_DIR) / "verification" / "cases";
  for (const auto& c : sphv::catalogue()) {
    INFO(c.name);
    const std::string file = std::regex_replace(c.name, std::regex("[23]d$"), "") + ".cpp";
    bool found = fs::is_regular_file(cases / c.name / "case.cpp");
    for (const auto& family : fs::directory_iterator(cases))
      found = found || (family.is_directory() && fs::is_regular_file(family.path() / file));
    CHECK(found);
  }
  // Only the catalogue's README sits directly in cases/: helpers go to cases/common/.
  for (const auto& entry : fs::directory_iterator(cases)) {
    INFO(entry.path());
    CHECK((entry.is_directory() || entry.path().filename() == "README.md"));
  }
}
