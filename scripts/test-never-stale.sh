#!/usr/bin/env bash
# A finished point is reused only by the very build that produced it. The same sweep run twice
# reuses its point; run by a binary whose bytes differ (here: the same binary with one byte
# appended, as any edit of a source or a build flag changes the binary) it is run again.
# usage: test-never-stale.sh SPHV WORKDIR
set -euo pipefail
sphv=$1; dir=$2
rm -rf "$dir"; mkdir -p "$dir"
args=(sweep kernel --levels 16 --jobs 1 --out "$dir/sweep")
# One level: the sweep's order checks fail (exit 1), which is not what this test is about.
"$sphv" "${args[@]}" > "$dir/first.log" 2>&1 || true
"$sphv" "${args[@]}" > "$dir/second.log" 2>&1 || true
grep -q "reusing 1 finished point(s) of 1" "$dir/second.log" || { echo "FAIL: the same build did not reuse its point"; cat "$dir/second.log"; exit 1; }
cp "$sphv" "$dir/sphv-other"
printf '\0' >> "$dir/sphv-other"
"$dir/sphv-other" "${args[@]}" > "$dir/third.log" 2>&1 || true
grep -q "reusing" "$dir/third.log" && { echo "FAIL: another build reused a point"; cat "$dir/third.log"; exit 1; }
# Provenance names the new binary; a result that another binary wrote is never in its place.
want=$(sha256sum "$dir/sphv-other" | cut -d' ' -f1)
grep -q "\"executable_sha256\": \"$want\"" "$dir/sweep/n16/result.json" || { echo "FAIL: provenance does not name the binary that ran"; exit 1; }
grep -q '"source_tree"' "$dir/sweep/n16/result.json" || { echo "FAIL: provenance lacks the source tree state"; exit 1; }
echo "PASS: reused by the same build, rerun by a different one"
