#!/usr/bin/env bash
# Configures and builds sphv (Release) in build/. Used by both README commands.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE="${SPHV_BUILD_TYPE:-Release}" >/dev/null
cmake --build build -j "$(nproc)"
