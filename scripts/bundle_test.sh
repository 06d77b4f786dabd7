#!/usr/bin/env bash
# Tests of scripts/bundle.sh (ctest bundle_*).
#   bundle_test.sh compiles RESULTS WORK   bundles RESULTS, compiles both .tex files with pdflatex
#                                         (one case lengthened past a page: its tables must break across
#                                         pages), checks no float is too large, no line overfull, the
#                                         section at most 4 pages, no Type 3 font (pdffonts), the bundle at
#                                         most 50 MB and reproduce.sh executable; exit 77 (ctest:
#                                         skipped) with a message when pdflatex is absent
#   bundle_test.sh dirty RESULTS WORK      a copy of the scripts in a scratch git repository: a tracked
#                                         change or an untracked file under verification/ is refused
#                                         (exit 2), --allow-dirty and a clean tree are not
#   bundle_test.sh reproduce RESULTS WORK  a bundle of one sweep of RESULTS made by a scratch repository
#                                         (sphv's scripts, a stub build whose sphv writes that sweep): copied
#                                         into an empty folder outside any checkout, its reproduce.sh unpacks
#                                         source.tar.gz, "builds", reruns and rebuilds the bundle there; a
#                                         changed archive and results of two commits are refused
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
  command -v pdffonts >/dev/null || fail "pdffonts not found (poppler-utils: bash scripts/install-deps.sh --tex installs it)"
  for pdf in example.pdf example-supplement.pdf; do
    type3=$(pdffonts "$work/bundle/$pdf" | grep -c "Type 3")
    [ "$type3" -eq 0 ] || fail "$pdf embeds $type3 Type 3 font(s): $(pdffonts "$work/bundle/$pdf" | grep "Type 3")"
  done
  [ -x "$work/bundle/reproduce.sh" ] || fail "reproduce.sh is not executable"
  size=$(du -sm "$work/bundle" | cut -f1)
  [ "$size" -le 50 ] || fail "the bundle is $size MB (at most 50)"
  pages=$(grep -o '([0-9]* pages\?' "$work/bundle/example.log" | tr -dc 0-9)
  [ -n "$pages" ] && [ "$pages" -le 4 ] || fail "verification.tex compiles to ${pages:-?} pages (at most 4)"
  for pdf in $(grep -o 'figures/[^}]*' "$work/bundle/verification.tex" "$work/bundle/verification-supplement.tex" | cut -d: -f2); do
    [ -s "$work/bundle/$pdf" ] || fail "included figure $pdf missing"
  done
  echo "PASS: verification.tex $pages pages; supplement $(grep -o '([0-9]* pages\?' "$work/bundle/example-supplement.log" | tr -d '('); no Type 3 font; $size MB"
  exit 0
fi

if [ "$mode" = reproduce ]; then
  # A scratch repository holding sphv's scripts, with a stub build: its "sphv verify" writes the
  # fixture's kernel sweep, labelled with the commit the build records (SPHV_ARCHIVE_COMMIT, set
  # by reproduce.sh as verification/build_state.cmake reads it). Everything else is real:
  # source.tar.gz is `git archive` of that commit, reproduce.sh unpacks and runs it.
  repo=$work/repo
  mkdir -p "$repo/fixture" && cp -r "$root/scripts" "$repo/" && cp -r "$results/kernel" "$repo/fixture/" || fail "scratch repository"
  cat > "$repo/scripts/build.sh" <<'EOF_BUILD'
#!/usr/bin/env bash
# Stub build (bundle_test.sh reproduce): build/sphv copies fixture/ labelled with the commit the build
# records, as verification/build_state.cmake does: an unpacked archive's from SPHV_ARCHIVE_COMMIT.
cd "$(dirname "$0")/.." && mkdir -p build
echo "${SPHV_ARCHIVE_COMMIT:-unknown}" > build/commit
cat > build/sphv <<'EOF_SPHV'
#!/usr/bin/env bash
[ "$1 $2" = "verify --tier" ] && [ "$4" = --out ] || { echo "sphv stub: unexpected arguments: $*" >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$5" && mkdir -p "$5" && cp -r "$here/fixture/kernel" "$5/" || exit 3
py=$(bash "$here/scripts/find-python.sh") || exit 1
"$py" - "$5" "$(cat "$here/build/commit")" <<'EOF_PY'
import json, sys
from pathlib import Path
for f in Path(sys.argv[1]).glob("**/sweep.json"):
    s = json.loads(f.read_text())
    for r in s["runs"]:
        r["provenance"]["git_commit"] = sys.argv[2]
    f.write_text(json.dumps(s))
EOF_PY
echo "sphv stub: verify --tier $3 -> $5"
EOF_SPHV
chmod +x build/sphv
EOF_BUILD
  cd "$repo" && git init -q . && git add . && git -c user.name=t -c user.email=t@t commit -qm scratch || fail "git"
  commit=$(git rev-parse HEAD)
  py=$(bash "$root/scripts/find-python.sh") || exit 1
  SPHV_ARCHIVE_COMMIT=$commit bash scripts/build.sh && ./build/sphv verify --tier quick --out "$work/results" >/dev/null || fail "stub run"
  "$py" "$root/scripts/report.py" "$work/results" --reports "$work/reports" --bundle "$work/bundle" --source-repo "$repo" >/dev/null ||
    fail "report.py --bundle"
  [ -x "$work/bundle/reproduce.sh" ] || fail "reproduce.sh is not executable"
  [ "$(gzip -dc "$work/bundle/source.tar.gz" | git get-tar-commit-id)" = "$commit" ] || fail "source.tar.gz is not git archive of $commit"
  # The bundle copied into an empty folder outside any checkout reruns and rebuilds itself there.
  copy=$(mktemp -d) && trap 'rm -rf "$copy"' EXIT
  cp -r "$work/bundle" "$copy/b" && cd / || fail "copy"
  out=$("$copy/b/reproduce.sh" 2>&1) || fail "reproduce.sh from a copy in $copy: $out"
  [[ "$out" == *"rebuilt from commit $commit"* ]] || fail "reproduce.sh did not finish: $out"
  [ -s "$copy/b/reproduced/verification.tex" ] && [ -s "$copy/b/reproduced/source.tar.gz" ] ||
    fail "reproduce.sh wrote no bundle into $copy/b/reproduced: $out"
  "$py" - "$copy/b/reproduced/provenance.json" "$commit" <<'EOF_PY' || fail "the rebuilt bundle's provenance: $(cat "$copy/b/reproduced/provenance.json")"
import json, sys
p = json.load(open(sys.argv[1]))
sys.exit(p["git_commits"] != [sys.argv[2]] or p["dirty_runs"] != 0)
EOF_PY
  # A changed archive, and results that name no single commit, are refused (exit 2), saying why.
  printf x >> "$copy/b/source.tar.gz"
  out=$("$copy/b/reproduce.sh" 2>&1); rc=$?
  [ $rc -eq 2 ] && [[ "$out" == *"SHA-256"* ]] || fail "reproduce.sh with a changed source.tar.gz: exit $rc: $out"
  "$py" - "$work/results" <<'EOF_PY' || fail "relabelling"
import json, sys
from pathlib import Path
for f in Path(sys.argv[1]).glob("**/sweep.json"):
    s = json.loads(f.read_text())
    s["runs"][0]["provenance"]["git_commit"] = "0" * 40
    f.write_text(json.dumps(s))
EOF_PY
  "$py" "$root/scripts/report.py" "$work/results" --reports "$work/reports" --bundle "$work/mixed" --source-repo "$repo" >/dev/null 2>&1 ||
    fail "report.py --bundle of mixed results"
  out=$(bash "$work/mixed/reproduce.sh" 2>&1); rc=$?
  [ $rc -eq 2 ] && [[ "$out" == *"not one"* ]] || fail "reproduce.sh of results from two commits: exit $rc: $out"
  echo "PASS: reproduce.sh rebuilds the bundle from a copy in an empty folder ($commit); a changed archive and mixed commits are refused"
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
