#!/usr/bin/env bash
# Mutation testing (issue 13, section 7): applies each fault of verification/mutants/ to a scratch
# copy of the tree, builds it (Release) and runs the gates; writes DIR/kill_matrix.json (default
# runs/mutants) and a table. Exit 0 only if every mutant is killed by a verification gate.
#   bash scripts/mutants.sh [--quick] [--only ID,...] [--out DIR] [--all-gates] [--help]
set -euo pipefail
cd "$(dirname "$0")/.."
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
exec python3 scripts/mutants.py "$@"
