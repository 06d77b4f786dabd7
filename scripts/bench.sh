#!/usr/bin/env bash
# Benchmarks: builds (Release), runs `sphv bench` (3D uniform gas, N = 1e4 to 1e6, 1 thread
# and all cores) and writes reports/bench/index.html. Extra arguments go to `sphv bench`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh sphv
python=$(bash scripts/find-python.sh)
./build/sphv bench --out runs/bench "$@"
"$python" scripts/report.py runs/bench --name bench
