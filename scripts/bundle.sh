#!/usr/bin/env bash
# Publication bundle (scripts/report_tex.py): verification.tex (the main part of a paper, at most
# four two-column pages), verification-supplement.tex (every variant, check and figure; contents,
# provenance, references), the figures as PDF at print size, verification.bib, provenance.json,
# source.tar.gz (`git archive` of the results' commit), results.tar.gz (summary.json and every
# sweep.json) and reproduce.sh (rebuilds all of it from the folder alone); with --with-runs also
# runs.tar.xz (every point's files) and the HTML report (report/index.html). Where pdflatex exists,
# both parts are compiled (through example.tex, example-supplement.tex), their page counts printed
# and the PDFs' fonts checked: no Type 3 font.
#
#   bash scripts/bundle.sh [--tier quick|standard|full] [--out DIR] [--results DIR] [--allow-dirty]
#                          [--with-runs] [--source-archive FILE] [DIR]
#
# Without --results it builds and runs `sphv verify --tier T` (default full: publication
# resolutions; finished points of this code version are reused) into runs/bundle-T. With
# --results it bundles an existing results folder. --with-runs adds every point's files (particles,
# logs) as runs.tar.xz. It refuses (exit 2) a tree with uncommitted changes to tracked files or
# untracked files under sph/ reference/ verification/, and results whose provenance records such a
# tree, unless --allow-dirty. An unpacked source.tar.gz is no checkout: reproduce.sh, which checked
# the archive against the results' commit, passes it as --source-archive instead.
set -uo pipefail
cd "$(dirname "$0")/.."
tier=full out=bundle results="" allow_dirty="" with_runs="" source_archive=""
die() { echo "bundle: error: $*" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --tier) [ $# -ge 2 ] || die "--tier needs a value"; tier=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || die "--out needs a value"; out=$2; shift 2 ;;
    --results) [ $# -ge 2 ] || die "--results needs a value"; results=$2; shift 2 ;;
    --allow-dirty) allow_dirty=--allow-dirty; shift ;;
    --with-runs) with_runs=--with-runs; shift ;;
    --source-archive) [ $# -ge 2 ] || die "--source-archive needs a file"; source_archive=$(cd "$(dirname "$2")" && pwd)/$(basename "$2"); shift 2 ;;
    -*) die "unknown option '$1' (--tier, --out, --results, --allow-dirty, --with-runs, --source-archive)" ;;
    *) out=$1; shift ;;
  esac
done
case "$tier" in quick|standard|full) ;; *) die "unknown tier '$tier' (quick, standard or full)" ;; esac
[ -z "$source_archive" ] || [ -f "$source_archive" ] || die "no source archive $source_archive"

if [ -z "$allow_dirty" ] && [ -z "$source_archive" ]; then
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
mkdir -p "$out" || exit 3
"$python" scripts/report.py "$results" --reports "$out" --name report --bundle "$out" $allow_dirty $with_runs \
  ${source_archive:+--source-archive "$source_archive"} || exit $?
# The HTML report (its figures as PNG and PDF) would double the bundle: only --with-runs keeps it.
[ -n "$with_runs" ] || rm -rf "$out/report"

if command -v pdflatex >/dev/null; then
  for doc in example example-supplement; do
    # three runs: the contents and the cross-references settle by the third
    (cd "$out" && for pass in 1 2 3; do pdflatex -interaction=nonstopmode -halt-on-error "$doc.tex" >/dev/null || exit 1; done) ||
      { echo "bundle: error: $out/$doc.tex does not compile; see $out/$doc.log" >&2; exit 1; }
    echo "bundle: $out/$doc.pdf: $(grep -o '([0-9]* pages\?' "$out/$doc.log" | tr -d '(')"
    if command -v pdffonts >/dev/null; then
      type3=$(pdffonts "$out/$doc.pdf" | grep -c "Type 3")
      [ "$type3" -eq 0 ] || { echo "bundle: error: $out/$doc.pdf embeds $type3 Type 3 font(s) (pdffonts): journals reject them" >&2; exit 1; }
    fi
  done
  rm -f "$out"/*.aux "$out"/*.toc "$out"/*.out
else
  echo "bundle: pdflatex not found (bash scripts/install-deps.sh --tex installs it): the .tex files are written but not compiled"
fi
echo "bundle: $out: $(du -sh "$out" | cut -f1)"
