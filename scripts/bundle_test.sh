#!/usr/bin/env bash
# Tests of scripts/bundle.sh (ctest bundle_*).
#   bundle_test.sh compiles RESULTS WORK   bundles RESULTS, compiles both .tex files with pdflatex
#                                         (one case lengthened past a page: its tables must break across
#                                         pages), checks no float is too large, no line overfull and the
#                                         section at most 4 pages; exit 77 (ctest:
#                                         skipped) with a message when pdflatex is absent
#   bundle_test.sh dirty RESULTS WORK      a copy of the scripts in a scratch git repository: a tracked
#                                         change or an untracked file under verification/ is refused
#                                         (exit 2), --allow-dirty and a clean tree are not
#   bundle_test.sh reproduce RESULTS WORK  a bundle of RESULTS relabelled as produced at the commit of a
#                                         scratch repository (bundle.sh there a stub), by its full and its
#                                         12-character hash: reproduce.sh runs in a clone at that commit
#                                         and refuses one at another
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=$1 results=$(cd "$2" && pwd) work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

if [ "$mode" = compiles ]; then
  command -v pdflatex >/dev/null || { echo "SKIP: pdflatex not found (bash scripts/install-deps.sh --tex installs it); the bundle is not compiled"; exit 77; }
  # A case with more rows and checks, each with a long reason, than a page holds: its tables must
  # break across pages, not become floats too large to place (whose rows LaTeX drops).
  cp -r "$results" "$work/results" && results=$work/results
  py=$(bash "$root/scripts/find-python.sh") || exit 1
  "$py" - "$results/kernel/sweep.json" <<'EOF_PY' || fail "lengthening the kernel sweep"
import json, sys
f = sys.argv[1]
s = json.load(open(f))
why = "a reason long enough to wrap over several lines of the table's narrow reason column, " * 3
for k in range(90):
    s["rows"].append({"error": f"long_error_{k}", "fine_value": 1e-3, "observed": None, "se": None, "expected": None,
                      "band": 0, "outcome": "fail", "why": f"failed: bound_long_error_{k}: {why}"})
    s["checks"].append({"name": f"bound_long_error_{k}", "value": 1e-3, "lo": 0, "hi": 1e-4, "why": why, "pass": False,
                        "kind": "verification", "error": f"long_error_{k}"})
json.dump(s, open(f, "w"))
EOF_PY
  bash "$root/scripts/bundle.sh" --results "$results" --out "$work/bundle" --allow-dirty >"$work/out.txt" 2>&1 ||
    { cat "$work/out.txt"; fail "bundle.sh exit $?"; }
  cat "$work/out.txt"
  for f in verification.tex verification-supplement.tex provenance.json reproduce.sh example.pdf example-supplement.pdf; do
    [ -s "$work/bundle/$f" ] || fail "no $f"
  done
  ! grep -q "^!" "$work/bundle/example.log" "$work/bundle/example-supplement.log" || fail "LaTeX errors in the logs"
  ! grep -q "undefined references" "$work/bundle/example.log" || fail "undefined references in example.log"
  for log in "$work/bundle/example.log" "$work/bundle/example-supplement.log"; do
    ! grep -q "Float too large" "$log" || fail "$(grep -m1 "Float too large" "$log") ($log)"
    ! grep -qF 'Overfull \hbox' "$log" || fail "$(grep -m1 -F 'Overfull \hbox' "$log") ($log)"
  done
  pages=$(grep -o '([0-9]* pages\?' "$work/bundle/example.log" | tr -dc 0-9)
  [ -n "$pages" ] && [ "$pages" -le 4 ] || fail "verification.tex compiles to ${pages:-?} pages (at most 4)"
  for pdf in $(grep -o 'figures/[^}]*' "$work/bundle/verification.tex" "$work/bundle/verification-supplement.tex" | cut -d: -f2); do
    [ -s "$work/bundle/$pdf" ] || fail "included figure $pdf missing"
  done
  echo "PASS: verification.tex $pages pages; supplement $(grep -o '([0-9]* pages\?' "$work/bundle/example-supplement.log" | tr -d '(')"
  exit 0
fi

if [ "$mode" = reproduce ]; then
  repo=$work/repo
  mkdir -p "$repo/scripts" && cd "$repo" || exit 1
  printf '#!/usr/bin/env bash\necho "bundle.sh stub: $*"\n' > scripts/bundle.sh
  git init -q . && git add . && git -c user.name=t -c user.email=t@t commit -qm scratch || fail "git"
  commit=$(git rev-parse HEAD)
  py=$(bash "$root/scripts/find-python.sh") || exit 1
  git clone -q "$repo" "$work/clone" || fail "git clone"
  # sphv records the full hash; results from before it did hold 12 characters: both reproduce.
  for recorded in "$commit" "${commit:0:12}"; do
    # One sweep is enough for what reproduce.sh does (the dirty test's choice too): keep it quick.
    rm -rf "$work/results" && mkdir -p "$work/results" && cp -r "$results/kernel" "$work/results/"
    "$py" - "$work/results" "$recorded" <<'EOF_PY' || fail "relabelling the results"
import json, sys
from pathlib import Path
for f in Path(sys.argv[1]).glob("**/sweep.json"):
    s = json.loads(f.read_text())
    for r in s["runs"]:
        r["provenance"]["git_commit"] = sys.argv[2]
    f.write_text(json.dumps(s))
EOF_PY
    "$py" "$root/scripts/report.py" "$work/results" --reports "$work/reports" --bundle "$work/bundle" >/dev/null || fail "report.py --bundle"
    out=$(cd "$work/clone" && git checkout -q "$commit" && bash "$work/bundle/reproduce.sh" 2>&1) ||
      fail "reproduce.sh of results at $recorded, in a clone at that commit, refused: $out"
    [ "$out" = "bundle.sh stub: --tier quick --out bundle" ] || fail "reproduce.sh did not run bundle.sh as expected: $out"
  done
  cd "$work/clone" && git -c user.name=t -c user.email=t@t commit -q --allow-empty -m later || fail "git commit"
  out=$(bash "$work/bundle/reproduce.sh" 2>&1); rc=$?
  [ $rc -eq 2 ] && [[ "$out" == *"check out commit ${commit:0:12}"* ]] || fail "reproduce.sh at another commit: exit $rc: $out"
  echo "PASS: reproduce.sh runs in a clone at $commit and refuses a clone at another commit"
  exit 0
fi

[ "$mode" = dirty ] || fail "unknown mode $mode"
repo=$work/repo
mkdir -p "$repo/verification" "$work/results" && cp -r "$root/scripts" "$repo/" && cd "$repo" || exit 1
cp -r "$results/kernel" "$work/results/" && results=$work/results  # one sweep is enough here: keep it quick
echo "int x;" > verification/a.cpp
git init -q . && git add . && git -c user.name=t -c user.email=t@t commit -qm scratch || fail "git"
run() { bash scripts/bundle.sh --results "$results" --out "$work/b" "$@" >"$work/out.txt" 2>&1; }
echo "int y;" > verification/new.cpp
run; rc=$?
[ $rc -eq 2 ] && grep -q "^bundle: error: the tree has uncommitted changes" "$work/out.txt" || fail "untracked file under verification/ not refused (exit $rc): $(cat "$work/out.txt")"
run --allow-dirty || fail "--allow-dirty refused: $(cat "$work/out.txt")"
rm verification/new.cpp && echo "int z;" >> verification/a.cpp
run; rc=$?
[ $rc -eq 2 ] || fail "tracked change not refused (exit $rc)"
git checkout -q verification/a.cpp && touch notes.txt  # untracked outside sph/ reference/ verification/
run || fail "clean tree refused: $(cat "$work/out.txt")"
echo "PASS: a dirty tree is refused, a clean one and --allow-dirty are not"
