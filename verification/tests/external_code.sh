#!/usr/bin/env bash
# A stand-in "external SPH code" for the tests of `sphv sweep --runner` and `sphv score`: runs
# `sphv run` and hands back its particles in another code's format, with the run's end time.
# With --ic FILE it first reads its initial conditions, as SWIFT reads the file its parameter
# file names (any format sphv reads: `sphv ic`'s csv, swift or h5part), and refuses a file
# without the gas state a code starts from (x, vx, m, rho, u, h at time 0).
# EXTERNAL_CODE_FAULT=half_order makes it a code with a fault a gate must catch: it runs at the
# resolution 10 sqrt(N) when asked for N, so its errors fall at half their order.
# usage: external_code.sh SPHV CASE N OUT FORMAT [--ic FILE] [key=value ...]   (FORMAT: csv, swift, h5part)
set -euo pipefail
sphv=$1 case=$2 n=$3 out=$4 format=$5
shift 5
if [ "${EXTERNAL_CODE_FAULT:-}" = half_order ]; then
  n=$(python3 -c 'import math, sys; print(round(10 * math.sqrt(int(sys.argv[1]))))' "$n")
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ "${1:-}" = "--ic" ]; then
  "$sphv" convert --input "$2" --out "$work/ic.csv" --format csv > /dev/null
  shift 2
  python3 - "$work/ic.csv" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
header = [l for l in lines if l.startswith("#")]
rows = [l for l in lines if not l.startswith("#")]
names = rows[0].split(",")
missing = [c for c in ("x", "vx", "m", "rho", "u", "h") if c not in names]
if missing or not any(l.replace(" ", "") == "#time=0" for l in header) or len(rows) < 2:
    sys.exit("external code: the initial conditions lack %s" % (", ".join(missing) or "time 0 or particles"))
print("external code: read %d particles at t = 0 (%s)" % (len(rows) - 1, ", ".join(names)))
PY
fi
"$sphv" --threads 1 run "$case" --set "n=$n" "$@" --out "$work"
t=$(python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); print(repr(r["extra"].get("t_reached", r["params"].get("t_end"))))' "$work/result.json")
"$sphv" convert --input "$work/particles.csv" --out "$out" --format "$format" --time "$t"
