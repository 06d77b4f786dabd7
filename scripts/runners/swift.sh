#!/usr/bin/env bash
# A runner for `sphv sweep CASE --runner`: SWIFT (github.com/SWIFTSIM/SWIFT) started from sphv's
# initial conditions in SWIFT's layout, its last snapshot handed back for scoring.
#
#   sphv sweep sod --set gamma=5/3 --ic-format swift \
#     --runner 'bash scripts/runners/swift.sh {ic} {out} {t_end} {threads}'
#
# It writes SWIFT's parameter file next to {out} (folder swift/): the time to run to ({t_end}),
# snapshots at t = 0 and t = {t_end} (SWIFT writes its parameters into them, so sphv reads the
# box, the periodicity and the time from the file), the periodic box of `sphv ic --format
# swift`'s layout, cgs units of 1 (sphv's quantities are dimensionless); then it runs SWIFT in
# that folder and copies the last snapshot to {out}.
#
# SWIFT's dimension, hydro scheme, kernel and adiabatic index are fixed when it is built
# (./configure --with-hydro-dimension=1 --with-adiabatic-index=5/3 ...): build one SWIFT per
# dimension and gamma the sweep needs. `sphv ic --format swift` writes the state for gamma 5/3
# unless gamma is set, and says which --with-adiabatic-index another gamma needs.
#
# Environment:
#   SWIFT             the swift executable (default: swift on PATH)
#   SWIFT_FLAGS       its run flags (default: --hydro)
#   SWIFT_ETA         SPH:resolution_eta (default 1.2348: about 48 neighbours in 3D with the cubic spline)
#   SWIFT_CFL         SPH:CFL_condition (default 0.1)
#   SWIFT_PERIODIC    InitialConditions:periodic (default 1: sphv's SWIFT layout is a periodic box)
#   SWIFT_EXTRA_YAML  a file appended to the parameter file (the scheme's own parameters, e.g.
#                     SPH:viscosity_alpha; a section named twice is refused by SWIFT: put the
#                     SPH keys there only if SWIFT_ETA and SWIFT_CFL are not enough)
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: swift.sh IC OUT T_END [THREADS]" >&2
  exit 2
fi
ic=$1 out=$2 t_end=$3 threads=${4:-1}
swift=${SWIFT:-swift}
if ! command -v "$swift" > /dev/null; then
  echo "swift.sh: no SWIFT executable '$swift' (set SWIFT=/path/to/swift)" >&2
  exit 2
fi
if ! awk -v t="$t_end" 'BEGIN { exit !(t + 0 > 0) }'; then
  echo "swift.sh: t_end must be > 0, got '$t_end'" >&2
  exit 2
fi
work=$(dirname "$out")/swift
rm -rf "$work"
mkdir -p "$work"
ic=$(realpath "$ic")
# The largest step SWIFT may take: a hundredth of the run (its own criteria take smaller ones).
dt_max=$(awk -v t="$t_end" 'BEGIN { printf "%.17g", t / 100 }')
cat > "$work/params.yml" <<YAML
InternalUnitSystem:
  UnitMass_in_cgs: 1
  UnitLength_in_cgs: 1
  UnitVelocity_in_cgs: 1
  UnitCurrent_in_cgs: 1
  UnitTemp_in_cgs: 1
TimeIntegration:
  time_begin: 0
  time_end: $t_end
  dt_min: 1e-12
  dt_max: $dt_max
Snapshots:
  basename: snap
  time_first: 0
  delta_time: $t_end
Statistics:
  delta_time: $t_end
SPH:
  resolution_eta: ${SWIFT_ETA:-1.2348}
  CFL_condition: ${SWIFT_CFL:-0.1}
InitialConditions:
  file_name: $ic
  periodic: ${SWIFT_PERIODIC:-1}
YAML
if [ -n "${SWIFT_EXTRA_YAML:-}" ]; then cat "$SWIFT_EXTRA_YAML" >> "$work/params.yml"; fi
# shellcheck disable=SC2086  # SWIFT_FLAGS is a list of flags
(cd "$work" && "$swift" ${SWIFT_FLAGS:---hydro} --threads="$threads" params.yml)
last=$(ls "$work"/snap_[0-9]*.hdf5 2> /dev/null | sort | tail -n 1)
if [ -z "$last" ]; then
  echo "swift.sh: SWIFT wrote no snapshot in $work" >&2
  exit 3
fi
cp "$last" "$out"
echo "swift.sh: $last -> $out"
