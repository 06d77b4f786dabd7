#!/usr/bin/env bash
# The catalogue survives a point killed mid-run (SIGKILL) and a point that hangs past --timeout:
# each becomes that point's verdict, every other point and case finishes, the JUnit XML names the
# failed checks, and verify exits 1. A second run without the faults reruns only those points.
# `sphv sweep --timeout` kills a hung point the same way. Uses the test-only hook SPHV_TEST_FAULT
# of `sphv run` (verification/main.cpp).
# usage: test-faults.sh SPHV WORKDIR
set -uo pipefail
sphv=$1; dir=$2
fail() { echo "FAIL: $*"; cat "$dir/out.txt" "$dir/err.txt" 2>/dev/null; exit 1; }
rm -rf "$dir"; mkdir -p "$dir"
# Two cheap cases of one variant each, so one point hangs (a case's every variant would hang at n).
cases=kepler,heat_stiff
t0=$(date +%s)
SPHV_TEST_FAULT=crash:heat_stiff@128,hang:kepler@256 "$sphv" verify --tier quick --cases $cases --timeout 8 \
  --out "$dir/v" > "$dir/out.txt" 2> "$dir/err.txt"
status=$?
[ "$status" -eq 1 ] || fail "verify exited $status, expected 1"
grep -q '"verdict": "timeout after 8 s"' "$dir/v/kepler/n256/result.json" || fail "no timeout verdict for kepler n=256"
grep -q '"verdict": "crashed: signal 9' "$dir/v/heat_stiff/n128/result.json" || fail "no crash verdict for heat_stiff n=128"
grep -q '"verdict": "ok"' "$dir/v/kepler/n512/result.json" || fail "kepler n=512 did not finish after the hang"
grep -q '"verdict": "ok"' "$dir/v/heat_stiff/n256/result.json" || fail "heat_stiff n=256 did not finish after the crash"
[ -s "$dir/v/summary.json" ] || fail "no summary.json"
grep -q 'classname="kepler.default" name="expected_verdict_n256"' "$dir/v/junit.xml" || fail "JUnit lacks the timed-out point's check"
grep -q '<failure message="expected_verdict_n128 = ' "$dir/v/junit.xml" || fail "JUnit lacks the crashed point's failure"
grep -q "FAIL: .* of [0-9]* sweeps failing" "$dir/out.txt" || fail "no final summary line"
pgrep -f "$dir/v/kepler/.*/n256" > /dev/null && fail "the hung point still runs"
took=$(( $(date +%s) - t0 ))
# Without the faults: only the crashed and timed-out points run again (the gates' own outcome is
# the cases' business here, not this test's).
"$sphv" verify --tier quick --cases $cases --out "$dir/v" > "$dir/out2.txt" 2> "$dir/err2.txt"
[ $? -le 1 ] || fail "rerun failed: $(cat "$dir/err2.txt")"
grep -rqE '"verdict": "(crashed|timeout)' "$dir/v" --include=result.json && fail "a crash or timeout verdict survived the rerun"
total=$(find "$dir/v" -name result.json | wc -l)
faulty=$(( $(find "$dir/v/kepler" -path '*/n256/result.json' | wc -l) + $(find "$dir/v/heat_stiff" -path '*/n128/result.json' | wc -l) ))
grep -q "reusing $(( total - faulty )) finished point(s) of $total" "$dir/err2.txt" || fail "rerun did not reuse the $(( total - faulty )) good points: $(cat "$dir/err2.txt")"
# `sphv sweep --timeout` the same way: the hung point's verdict, the other levels finish, exit 1.
SPHV_TEST_FAULT=hang:kepler@256 "$sphv" sweep kepler --tier quick --timeout 3 --jobs 1 --out "$dir/s" \
  > "$dir/out3.txt" 2> "$dir/err3.txt"
status=$?
[ "$status" -eq 1 ] || fail "sweep exited $status, expected 1: $(cat "$dir/err3.txt")"
grep -q '"verdict": "timeout after 3 s"' "$dir/s/n256/result.json" || fail "no timeout verdict from sweep for kepler n=256"
grep -q '"verdict": "ok"' "$dir/s/n512/result.json" || fail "sweep: kepler n=512 did not finish after the hang"
echo "PASS: timeout and SIGKILL became verdicts, $total points in ${took} s, exit 1; the rerun reran $faulty point(s); sweep --timeout too"
