#!/usr/bin/env bash
# The tests: install what is missing, build (warnings as errors), run every Catch2 gate and
# CLI test under ctest (JUnit XML for CI dashboards: build/junit.xml).
set -euo pipefail
cd "$(dirname "$0")/.."
# Warnings are errors here: a full build of main at 542cd4f and 33c4caf gave 0 warnings under
# -Wall -Wextra -Wpedantic (GCC 12.2).
export SPHV_WERROR=${SPHV_WERROR:-ON}
bash scripts/build.sh
# Tests run side by side with OpenMP inside: threads that wait should sleep, not spin.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
ctest --test-dir build --output-on-failure -j "$(nproc)" --output-junit junit.xml "$@"
