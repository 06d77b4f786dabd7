#!/usr/bin/env python3
"""Checks that a sweep.json carries each point's own provenance: every run's provenance equals the
one its point's n<level>/result.json recorded when the point ran (threads, date, host, ...), not
the provenance of the process that wrote sweep.json; and that the recorded commit is a full
40-character hash naming a commit of SOURCE_DIR (skipped, saying so, outside a git checkout).
usage: sweep_provenance.py SWEEP_DIR PARENT_THREADS SOURCE_DIR"""
import json
import re
import subprocess
import sys
from pathlib import Path

folder, parent_threads, source = Path(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
sweep = json.loads((folder / "sweep.json").read_text())
problems = []
threads = set()
for n, run in zip(sweep["levels"], sweep["runs"]):
    own = json.loads((folder / f"n{n}" / "result.json").read_text())["provenance"]
    if run.get("provenance") != own:
        diff = {k: (run.get("provenance", {}).get(k), own.get(k)) for k in own if run.get("provenance", {}).get(k) != own.get(k)}
        problems.append(f"n={n}: sweep.json's provenance differs from the point's result.json (sweep, point): {diff}")
    threads.add(own.get("threads"))
if parent_threads in threads:
    problems.append(f"a point ran on {parent_threads} threads, the parent's count: the test cannot tell them apart")
commit = sweep["runs"][0]["provenance"]["git_commit"]
in_git = subprocess.run(["git", "-C", source, "rev-parse", "--git-dir"], capture_output=True).returncode == 0
if in_git:
    if not re.fullmatch(r"[0-9a-f]{40}", commit):
        problems.append(f"git_commit '{commit}' is not a full 40-character hash")
    elif subprocess.run(["git", "-C", source, "cat-file", "-e", f"{commit}^{{commit}}"], capture_output=True).returncode:
        problems.append(f"git_commit {commit} names no commit of {source}")
for p in problems:
    print(f"FAIL: {p}")
if problems:
    sys.exit(1)
print(f"PASS: {len(sweep['runs'])} runs carry their points' provenance (threads {sorted(threads)}, parent {parent_threads}); "
      + (f"commit {commit}" if in_git else "commit not checked: not a git checkout"))
