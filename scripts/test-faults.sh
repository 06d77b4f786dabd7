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
cases=kernel,interpolation
t0=$(date +%s)
SPHV_TEST_FAULT=crash:interpolation@32,hang:kernel@64 "$sphv" verify --tier quick --cases $cases --timeout 8 \
  --out "$dir/v" > "$dir/out.txt" 2> "$dir/err.txt"
status=$?
[ "$status" -eq 1 ] || fail "verify exited $status, expected 1"
grep -q '"verdict": "timeout after 8 s"' "$dir/v/kernel/default/n64/result.json" || fail "no timeout verdict for kernel n=64"
grep -q '"verdict": "crashed: signal 9' "$dir/v/interpolation/default/n32/result.json" || fail "no crash verdict for interpolation n=32"
grep -q '"verdict": "ok"' "$dir/v/kernel/default/n128/result.json" || fail "kernel n=128 did not finish after the hang"
grep -q '"verdict": "ok"' "$dir/v/interpolation/default/n64/result.json" || fail "interpolation n=64 did not finish after the crash"
[ -s "$dir/v/summary.json" ] || fail "no summary.json"
grep -q 'classname="kernel.default" name="expected_verdict_n64"' "$dir/v/junit.xml" || fail "JUnit lacks the timed-out point's check"
grep -q '<failure message="expected_verdict_n32 = ' "$dir/v/junit.xml" || fail "JUnit lacks the crashed point's failure"
grep -q "FAIL: .* of [0-9]* sweeps failing" "$dir/out.txt" || fail "no final summary line"
pgrep -f "$dir/v/kernel/.*/n64" > /dev/null && fail "the hung point still runs"
took=$(( $(date +%s) - t0 ))
# Without the faults: only the crashed and timed-out points run again (the gates' own outcome is
# the cases' business here, not this test's).
"$sphv" verify --tier quick --cases $cases --out "$dir/v" > "$dir/out2.txt" 2> "$dir/err2.txt"
[ $? -le 1 ] || fail "rerun failed: $(cat "$dir/err2.txt")"
grep -rqE '"verdict": "(crashed|timeout)' "$dir/v" --include=result.json && fail "a crash or timeout verdict survived the rerun"
total=$(find "$dir/v" -name result.json | wc -l)
faulty=$(( $(find "$dir/v/kernel" -path '*/n64/result.json' | wc -l) + $(find "$dir/v/interpolation" -path '*/n32/result.json' | wc -l) ))
grep -q "reusing $(( total - faulty )) finished point(s) of $total" "$dir/err2.txt" || fail "rerun did not reuse the $(( total - faulty )) good points: $(cat "$dir/err2.txt")"
# `sphv sweep --timeout` the same way: the hung point's verdict, the other levels finish, exit 1.
SPHV_TEST_FAULT=hang:kernel@64 "$sphv" sweep kernel --tier quick --timeout 3 --jobs 1 --out "$dir/s" \
  > "$dir/out3.txt" 2> "$dir/err3.txt"
status=$?
[ "$status" -eq 1 ] || fail "sweep exited $status, expected 1: $(cat "$dir/err3.txt")"
grep -q '"verdict": "timeout after 3 s"' "$dir/s/n64/result.json" || fail "no timeout verdict from sweep for kernel n=64"
grep -q '"verdict": "ok"' "$dir/s/n128/result.json" || fail "sweep: kernel n=128 did not finish after the hang"
echo "PASS: timeout and SIGKILL became verdicts, $total points in ${took} s, exit 1; the rerun reran $faulty point(s); sweep --timeout too"
