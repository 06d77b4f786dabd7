#!/usr/bin/env bash
# Publication bundle: builds, runs the default catalogue (reusing finished points of this
# code version), and writes OUT (default bundle/) with figures as PDF, tables.tex,
# verification.tex for \input in a paper, provenance.json and reproduce.sh.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:-bundle}
bash scripts/build.sh || exit 1
python=$(bash scripts/find-python.sh) || exit 1
./build/sphv verify --out runs/verify
"$python" scripts/report.py runs/verify --name verify --bundle "$out"
