#!/usr/bin/env bash
# The tests: install what is missing, build, run every Catch2 gate and CLI test under ctest.
# JUnit XML for CI dashboards: build/junit.xml.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" --output-junit junit.xml "$@"
