#!/usr/bin/env bash
# Configures and builds sphv (Release) in build/. Used by both README commands.
# SPHV_BUILD_TYPE and SPHV_ARCH (a -march= value, e.g. x86-64-v3) override the defaults.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE="${SPHV_BUILD_TYPE:-Release}" -DSPHV_ARCH="${SPHV_ARCH:-}" >/dev/null
cmake --build build -j "$(nproc)"
