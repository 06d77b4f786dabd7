// Catch2's main, compiled once and linked into both test executables (sphv_tests and the
// sanitizer tests), with sphv's allocator setting (verification/allocator.hpp).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "verification/allocator.hpp"

int main(int argc, char* argv[]) {
  sphv::keep_freed_memory();
  return Catch::Session().run(argc, argv);
}
