#!/usr/bin/env bash
# A stand-in "external SPH code" for the tests of `sphv sweep --runner` and `sphv score`: runs
# `sphv run` and hands back its particles in another code's format, with the run's end time.
# usage: external_code.sh SPHV CASE N OUT FORMAT [key=value ...]   (FORMAT: csv, swift, h5part)
set -euo pipefail
sphv=$1 case=$2 n=$3 out=$4 format=$5
shift 5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$sphv" --threads 1 run "$case" --set "n=$n" "$@" --out "$work"
t=$(python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); print(repr(r["extra"].get("t_reached", r["params"].get("t_end"))))' "$work/result.json")
"$sphv" convert --input "$work/particles.csv" --out "$out" --format "$format" --time "$t"
