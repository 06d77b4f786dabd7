#!/usr/bin/env python3
"""Checks that two sweep folders hold the same points with the same numbers (errors,
functionals, verdicts, observed orders, outcomes), ignoring wall times and provenance. Where they
differ it names the sweeps and lists the largest relative changes of an error, so that a change
meant to move results at round-off (or to an iteration's tolerance) shows how far they moved.
usage: compare-sweeps.py DIR_A DIR_B [--largest K]"""
import json
import sys
from pathlib import Path


def load(root):
    # A sweep is named by its case and variant: several cases have a variant of the same name
    # ("default" above all), and keyed by the variant alone they would hide each other.
    out = {}
    for f in sorted(Path(root).glob("**/sweep.json")):
        s = json.loads(f.read_text())
        out[(s["case"], s["variant"])] = s
    return out


def key(s):
    runs = [(r["params"], r["errors"], r["functionals"], r["verdict"]) for r in s["runs"]]
    outcomes = [(r.get("error"), r.get("outcome")) for r in s.get("rows", [])]
    return runs, s["observed_order"], s["claims"], [c["pass"] for c in s["checks"]], outcomes


def changes(sa, sb):
    """(relative change, what) for every error of every level both sweeps ran."""
    out = []
    for ra, rb in zip(sa["runs"], sb["runs"]):
        for name, va in ra["errors"].items():
            vb = rb["errors"].get(name)
            if not isinstance(va, (int, float)) or not isinstance(vb, (int, float)) or va == vb:
                continue
            scale = max(abs(va), abs(vb))
            level = f"n = {ra['params']['n']}" if "n" in ra["params"] else str(ra["params"])
            out.append((abs(va - vb) / scale, f"{sa['case']} [{sa['variant']}] {name} at {level}: {va:.6g} -> {vb:.6g}"))
    return out


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    largest = 10
    if "--largest" in argv:
        largest = int(argv[argv.index("--largest") + 1])
        args.remove(argv[argv.index("--largest") + 1])
    if len(args) != 2:
        sys.exit(__doc__)
    a, b = load(args[0]), load(args[1])
    if not a or a.keys() != b.keys():
        sys.exit(f"compare-sweeps: sweeps differ: {sorted(a.keys() ^ b.keys())}")
    bad = [k for k in a if key(a[k]) != key(b[k])]
    points = sum(len(s["runs"]) for s in a.values())
    if not bad:
        print(f"{len(a)} sweep(s), {points} points identical")
        return 0
    moved = sorted((c for k in bad for c in changes(a[k], b[k])), reverse=True)
    outcome_changes = [
        f"{k[0]} [{k[1]}] {ea}: {oa} -> {ob}"
        for k in bad
        for (ea, oa), (eb, ob) in zip(key(a[k])[4], key(b[k])[4])
        if oa != ob
    ]
    parts = ("runs", "observed orders", "claims", "checks", "outcomes")
    print(f"compare-sweeps: {len(bad)} of {len(a)} sweeps differ ({points} points):")
    for k in bad:
        what = [name for name, x, y in zip(parts, key(a[k]), key(b[k])) if x != y]
        print(f"  {k[0]} [{k[1]}]: {', '.join(what)}")
    print(f"outcomes changed: {len(outcome_changes)}")
    for line in outcome_changes:
        print(f"  {line}")
    print(f"largest relative changes of an error ({len(moved)} errors changed):")
    for rel, what in moved[:largest]:
        print(f"  {rel:.3g}  {what}")
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
