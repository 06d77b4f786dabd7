#!/usr/bin/env bash
# The tests: install what is missing (TeX included), build (warnings as errors), run every Catch2 gate, CLI
# test and sanitizer test under ctest (JUnit XML for CI dashboards: build-tests/junit.xml).
set -euo pipefail
cd "$(dirname "$0")/.."
# Warnings are errors here: the tree builds without a warning under -Wall -Wextra -Wpedantic
# (GCC 12), so a new one fails CI instead of hiding among others.
export SPHV_WERROR=${SPHV_WERROR:-ON}
# The sanitizer tests (ASan + UBSan on the input and file code, verification/tests/sanitizer_tests.cmake)
# are built and run with the others.
export SPHV_SANITIZER_TESTS=${SPHV_SANITIZER_TESTS:-ON}
# Their own folder at -O2: the whole command must stay under 8 minutes on a fresh 2-core machine.
# The main job's build/ compiles the scenes the same way but sph/ and reference/ at -O3
# (CMakeLists.txt: optimisation by part). -fvect-cost-model=cheap keeps -O3's packing of the
# 3-vector arithmetic in the pair loops, which plain -O2 leaves scalar (results bit-identical: no
# reassociation).
export SPHV_BUILD_DIR=${SPHV_BUILD_DIR:-build-tests} SPHV_RELEASE_FLAGS=${SPHV_RELEASE_FLAGS:--O2 -fvect-cost-model=cheap -DNDEBUG}
# Precompiled headers shorten the clean build (CMakeLists.txt says why they are off elsewhere).
export SPHV_PCH=${SPHV_PCH:-ON}
# TeX too (texlive-latex-base and -recommended, poppler-utils: once), so that bundle_compiles
# compiles the publication bundle on a fresh machine instead of skipping. It installs beside the
# build (apt waits on the network and the disk, the compiler on the cores), after the build's own
# packages, so the two never hold the package lock at once.
bash scripts/install-deps.sh
tex_log=$(mktemp)
bash scripts/install-deps.sh --tex >"$tex_log" 2>&1 &
tex=$!
bash scripts/build.sh
wait "$tex" || { cat "$tex_log" >&2; echo "sphv: error: installing TeX failed (bash scripts/install-deps.sh --tex)" >&2; exit 1; }
rm -f "$tex_log"
# Tests run side by side with OpenMP inside: threads that wait should sleep, not spin.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
# One test more than there are cores: some tests wait (on a hung point's timeout, on git, on
# pdflatex's files) and the extra one uses those waits.
ctest --test-dir "$SPHV_BUILD_DIR" --output-on-failure -j "$(( $(nproc) + 1 ))" --output-junit junit.xml "$@"
