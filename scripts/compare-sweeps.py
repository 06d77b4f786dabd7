#!/usr/bin/env python3
"""Checks that two sweep folders hold the same points with the same numbers (errors,
functionals, verdicts, observed orders), ignoring wall times and provenance.
usage: compare-sweeps.py DIR_A DIR_B"""
import json
import sys
from pathlib import Path


def load(root):
    out = {}
    for f in sorted(Path(root).glob("**/sweep.json")):
        s = json.loads(f.read_text())
        out[s["variant"]] = s
    return out


def key(s):
    runs = [(r["params"], r["errors"], r["functionals"], r["verdict"]) for r in s["runs"]]
    return runs, s["observed_order"], s["claims"], [c["pass"] for c in s["checks"]]


a, b = load(sys.argv[1]), load(sys.argv[2])
if not a or a.keys() != b.keys():
    sys.exit(f"compare-sweeps: variants differ: {sorted(a)} vs {sorted(b)}")
bad = [v for v in a if key(a[v]) != key(b[v])]
if bad:
    sys.exit(f"compare-sweeps: numbers differ in {bad}")
print(f"{len(a)} variant(s), {sum(len(s['runs']) for s in a.values())} points identical")
