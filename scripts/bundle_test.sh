#!/usr/bin/env bash
# Tests of scripts/bundle.sh (ctest bundle_*).
#   bundle_test.sh compiles RESULTS WORK   bundles RESULTS, compiles both .tex files with pdflatex
#                                         and checks the section is at most 4 pages; exit 77 (ctest:
#                                         skipped) with a message when pdflatex is absent
#   bundle_test.sh dirty RESULTS WORK      a copy of the scripts in a scratch git repository: a tracked
#                                         change or an untracked file under verification/ is refused
#                                         (exit 2), --allow-dirty and a clean tree are not
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=$1 results=$(cd "$2" && pwd) work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

if [ "$mode" = compiles ]; then
  command -v pdflatex >/dev/null || { echo "SKIP: pdflatex not found (Debian texlive-latex-base); the bundle is not compiled"; exit 77; }
  bash "$root/scripts/bundle.sh" --results "$results" --out "$work/bundle" --allow-dirty >"$work/out.txt" 2>&1 ||
    { cat "$work/out.txt"; fail "bundle.sh exit $?"; }
  cat "$work/out.txt"
  for f in verification.tex verification-supplement.tex provenance.json reproduce.sh example.pdf example-supplement.pdf; do
    [ -s "$work/bundle/$f" ] || fail "no $f"
  done
  ! grep -q "^!" "$work/bundle/example.log" "$work/bundle/example-supplement.log" || fail "LaTeX errors in the logs"
  ! grep -q "undefined references" "$work/bundle/example.log" || fail "undefined references in example.log"
  pages=$(grep -o '([0-9]* pages\?' "$work/bundle/example.log" | tr -dc 0-9)
  [ -n "$pages" ] && [ "$pages" -le 4 ] || fail "verification.tex compiles to ${pages:-?} pages (at most 4)"
  for pdf in $(grep -o 'figures/[^}]*' "$work/bundle/verification.tex" "$work/bundle/verification-supplement.tex" | cut -d: -f2); do
    [ -s "$work/bundle/$pdf" ] || fail "included figure $pdf missing"
  done
  echo "PASS: verification.tex $pages pages; supplement $(grep -o '([0-9]* pages\?' "$work/bundle/example-supplement.log" | tr -d '(')"
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
