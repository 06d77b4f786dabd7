#!/usr/bin/env bash
# A sweep of 12 points killed halfway and restarted finishes without recomputing the points
# that were finished: their result.json files keep their contents and modification times.
# usage: test-resume.sh SPHV WORKDIR
set -euo pipefail
sphv=$1; dir=$2
rm -rf "$dir"; mkdir -p "$dir"
args=(sweep interpolation --set dim=3 --set jitter=0.1 --levels 40 --vary seed=1,2,3,4,5,6,7,8,9,10,11,12 --jobs 2 --out "$dir/sweep")
setsid "$sphv" "${args[@]}" > "$dir/first.log" 2>&1 &
pid=$!
for _ in $(seq 600); do
  [ "$(find "$dir/sweep" -name result.json 2>/dev/null | wc -l)" -ge 4 ] && break
  sleep 0.05
done
kill -9 -- -"$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
before=$(find "$dir/sweep" -name result.json | wc -l)
[ "$before" -ge 4 ] && [ "$before" -lt 12 ] || { echo "FAIL: killed with $before of 12 points finished"; exit 1; }
[ ! -e "$dir/sweep/seed=1/sweep.json" ] || { echo "FAIL: the first sweep finished before the kill"; exit 1; }
find "$dir/sweep" -name result.json -exec stat -c '%n %Y.%y' {} + | sort > "$dir/before.txt"
"$sphv" "${args[@]}" > "$dir/second.log" 2>&1
grep -q "reusing $before finished point(s) of 12" "$dir/second.log" || { echo "FAIL: restart did not reuse $before points"; cat "$dir/second.log"; exit 1; }
find "$dir/sweep" -name result.json -exec stat -c '%n %Y.%y' {} + | sort > "$dir/after.txt"
[ "$(wc -l < "$dir/after.txt")" -eq 12 ] || { echo "FAIL: not all 12 points finished"; exit 1; }
comm -23 "$dir/before.txt" "$dir/after.txt" | grep . && { echo "FAIL: finished points were recomputed"; exit 1; }
[ "$(find "$dir/sweep" -name sweep.json | wc -l)" -eq 12 ] || { echo "FAIL: sweep.json missing"; exit 1; }
echo "PASS: killed after $before of 12 points; restart reused them and ran the other $((12 - before))"
