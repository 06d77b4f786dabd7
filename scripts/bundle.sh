#!/usr/bin/env bash
# Publication bundle: verification.tex (a section of a few pages: one summary table and a few
# chosen figures), verification-supplement.tex (every variant, check and figure), the figures
# as PDF, provenance.json, reproduce.sh and the HTML report (report/index.html); where pdflatex
# exists, both .tex files are compiled (through example.tex, example-supplement.tex) and their
# page counts printed.
#
#   bash scripts/bundle.sh [--tier quick|standard|full] [--out DIR] [--results DIR] [--allow-dirty] [DIR]
#
# Without --results it builds and runs `sphv verify --tier T` (default full: publication
# resolutions; finished points of this code version are reused) into runs/bundle-T. With
# --results it bundles an existing results folder. It refuses (exit 2) a tree with uncommitted
# changes to tracked files or untracked files under sph/ reference/ verification/, and results
# whose provenance records such a tree, unless --allow-dirty.
set -uo pipefail
cd "$(dirname "$0")/.."
tier=full out=bundle results="" allow_dirty=""
die() { echo "bundle: error: $*" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --tier) [ $# -ge 2 ] || die "--tier needs a value"; tier=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || die "--out needs a value"; out=$2; shift 2 ;;
    --results) [ $# -ge 2 ] || die "--results needs a value"; results=$2; shift 2 ;;
    --allow-dirty) allow_dirty=--allow-dirty; shift ;;
    -*) die "unknown option '$1' (--tier, --out, --results, --allow-dirty)" ;;
    *) out=$1; shift ;;
  esac
done
case "$tier" in quick|standard|full) ;; *) die "unknown tier '$tier' (quick, standard or full)" ;; esac

if [ -z "$allow_dirty" ]; then
  git rev-parse --git-dir >/dev/null 2>&1 || die "not a git checkout: cannot show the tree is clean (or pass --allow-dirty)"
  changed=$(git status --porcelain --untracked-files=no | head -5)
  untracked=$(git ls-files --others --exclude-standard -- sph reference verification | head -5)
  if [ -n "$changed$untracked" ]; then
    die "the tree has uncommitted changes; commit them (or pass --allow-dirty): $(echo $changed $untracked)"
  fi
fi

python=$(bash scripts/find-python.sh) || exit 1
if [ -z "$results" ]; then
  bash scripts/build.sh sphv || exit 1
  results=runs/bundle-$tier
  ./build/sphv verify --tier "$tier" --out "$results"  # exit 1 on a failed gate: the bundle shows it
  [ -f "$results/summary.json" ] || die "sphv verify wrote no $results/summary.json"
fi
"$python" scripts/report.py "$results" --reports "$out" --name report --bundle "$out" $allow_dirty || exit $?

if command -v pdflatex >/dev/null; then
  for doc in example example-supplement; do
    # twice: the second run resolves the cross-references
    (cd "$out" && pdflatex -interaction=nonstopmode -halt-on-error "$doc.tex" >/dev/null &&
      pdflatex -interaction=nonstopmode -halt-on-error "$doc.tex" >/dev/null) ||
      { echo "bundle: error: $out/$doc.tex does not compile; see $out/$doc.log" >&2; exit 1; }
    echo "bundle: $out/$doc.pdf: $(grep -o '([0-9]* pages\?' "$out/$doc.log" | tr -d '(')"
  done
else
  echo "bundle: pdflatex not found (bash scripts/install-deps.sh --tex installs it): the .tex files are written but not compiled"
fi
