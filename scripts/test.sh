#!/usr/bin/env bash
# The tests: install what is missing, build (warnings on), run every Catch2 gate and
# CLI test under ctest (JUnit XML for CI dashboards: build/junit.xml).
set -euo pipefail
cd "$(dirname "$0")/.."
export SPHV_WERROR=${SPHV_WERROR:-OFF}  # ON once main is confirmed clean under -Werror
bash scripts/build.sh
# Tests run side by side with OpenMP inside: threads that wait should sleep, not spin.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
ctest --test-dir build --output-on-failure -j "$(nproc)" --output-junit junit.xml "$@"
