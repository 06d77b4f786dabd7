// Catch2's main, compiled once and linked into both test executables (sphv_tests and the
// sanitizer tests).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
