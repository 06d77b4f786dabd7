// Catch2's main, compiled once and linked into both test executables (sphv_tests and the
// sanitizer tests), with sphv's allocator setting (verification/support/allocator.hpp). Tests queued by
// sphv::tests::Deferred (deferred.hpp) register here, before Catch2 lists or runs any.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "verification/support/allocator.hpp"
#include "verification/tests/deferred.hpp"

namespace sphv::tests {
std::vector<Registrar>& deferred_registrars() {
  static std::vector<Registrar> r;
  return r;
}
}  // namespace sphv::tests

int main(int argc, char* argv[]) {
  sphv::keep_freed_memory();
  for (const auto r : sphv::tests::deferred_registrars()) r();
  return Catch::Session().run(argc, argv);
}
