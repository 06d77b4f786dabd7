#!/usr/bin/env bash
# The main job: install what is missing, build, run the standard tier of the catalogue
# (sphv verify --tier standard; JUnit XML in runs/verify/junit.xml),
# write the report to reports/verify/index.html. Exits non-zero when a gate fails; the
# report is written either way. Arguments go to sphv verify (e.g. --tier quick for the CI-sized
# catalogue and its report).
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh sphv || exit 1
python=$(bash scripts/find-python.sh) || exit 1
rm -rf runs/verify.new
tier=(--tier standard)
for a in "$@"; do case $a in --tier|--tier=*) tier=() ;; esac; done
./build/sphv verify "${tier[@]}" --out runs/verify.new "$@"
status=$?
[ -d runs/verify.new ] && rm -rf runs/verify && mv runs/verify.new runs/verify
"$python" scripts/report.py runs/verify --name verify || exit 1
echo "report: $(pwd)/reports/verify/index.html"
exit $status
