#!/usr/bin/env bash
# Sanitizer job: sphv and its tests built with AddressSanitizer + UndefinedBehaviorSanitizer
# (-O1, line tables, no MPI) in build-asan; the first finding fails the run. Runs the unit
# tests, the quick gates and the fuzz tests (every Catch2 test) and the command-line tests.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DSPHV_SANITIZE=ON \
      -DSPHV_WERROR="${SPHV_WERROR:-ON}" -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON >/dev/null
cmake --build build-asan -j "$(nproc)" --target sphv sphv_tests
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
ctest --test-dir build-asan --output-on-failure -j "$(nproc)" --output-junit junit-asan.xml
