#!/usr/bin/env bash
# Configures and builds sphv (Release) in build/. Used by both README commands.
# SPHV_BUILD_TYPE and SPHV_ARCH (a -march= value, e.g. x86-64-v3) override the defaults;
# SPHV_WERROR=ON (set by scripts/test.sh, i.e. CI) turns compiler warnings into errors;
# SPHV_SANITIZER_TESTS=ON (also set by scripts/test.sh) adds the sanitizer tests (CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE="${SPHV_BUILD_TYPE:-Release}" -DSPHV_ARCH="${SPHV_ARCH:-}" ${SPHV_WERROR:+-DSPHV_WERROR="$SPHV_WERROR"} \
      -DSPHV_SANITIZER_TESTS="${SPHV_SANITIZER_TESTS:-OFF}" >/dev/null
cmake --build build -j "$(nproc)"
