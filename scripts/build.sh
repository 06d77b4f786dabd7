#!/usr/bin/env bash
# Configures and builds sphv (Release) in build/ (SPHV_BUILD_DIR overrides). Used by both README
# commands; the tests build in build-tests/ (scripts/test.sh). Arguments name the targets to
# build (default: all; the main job builds only sphv).
# SPHV_BUILD_TYPE and SPHV_ARCH (a -march= value, e.g. x86-64-v3) override the defaults;
# SPHV_WERROR=ON (set by scripts/test.sh, i.e. CI) turns compiler warnings into errors;
# SPHV_SANITIZER_TESTS=ON (also set by scripts/test.sh) adds the sanitizer tests (CMakeLists.txt);
# SPHV_PCH=ON (also set by scripts/test.sh) precompiles the common headers (CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
dir=${SPHV_BUILD_DIR:-build}
# Ninja for a new build folder (it keeps both cores busy across targets); an existing folder
# keeps the generator it was configured with.
generator=()
if [ ! -f "$dir/CMakeCache.txt" ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake "${generator[@]}" -S . -B "$dir" -DCMAKE_BUILD_TYPE="${SPHV_BUILD_TYPE:-Release}" -DSPHV_ARCH="${SPHV_ARCH:-}" ${SPHV_WERROR:+-DSPHV_WERROR="$SPHV_WERROR"} \
      ${SPHV_RELEASE_FLAGS:+-DCMAKE_CXX_FLAGS_RELEASE="$SPHV_RELEASE_FLAGS"} -DSPHV_SANITIZER_TESTS="${SPHV_SANITIZER_TESTS:-OFF}" \
      -DSPHV_PCH="${SPHV_PCH:-OFF}" >/dev/null
cmake --build "$dir" -j "$(nproc)" ${1:+--target "$@"}
