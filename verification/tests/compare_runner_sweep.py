#!/usr/bin/env python3
"""Checks a `sphv sweep --runner` folder against a plain `sphv sweep` of the same levels: every
level's errors identical (same norms, same numbers), an observed order per error, and each run's
wall time (the external command's) recorded for the error-against-cost figure.
usage: compare_runner_sweep.py RUNNER_DIR SPHV_DIR"""
import json
import math
import sys
from pathlib import Path

runner = json.loads((Path(sys.argv[1]) / "sweep.json").read_text())
plain = json.loads((Path(sys.argv[2]) / "sweep.json").read_text())
problems = []
if "runner" not in runner:
    problems.append("sweep.json does not name the runner command")
by_n = {r["params"]["n"]: r for r in plain["runs"]}
for r in runner["runs"]:
    n = r["params"]["n"]
    if r["verdict"] not in ("ok", "stable"):
        problems.append(f"n={n}: verdict {r['verdict']}")
    if not r["errors"] or r["errors"] != by_n[n]["errors"]:
        problems.append(f"n={n}: errors {r['errors']} differ from sphv run's {by_n[n]['errors']}")
    if not r["wall_time_s"] > 0:
        problems.append(f"n={n}: no wall time")
    level = json.loads((Path(sys.argv[1]) / f"n{n}" / "result.json").read_text())
    if "sha256" not in level["provenance"].get("snapshot", {}):
        problems.append(f"n={n}: provenance has no snapshot SHA-256")
for e in runner["runs"][0]["errors"]:
    p = runner["observed_order"].get(e)
    if p is None or not math.isfinite(p):
        problems.append(f"no observed order for {e}")
if problems:
    sys.exit("compare_runner_sweep: " + "; ".join(problems))
print(f"PASS: {len(runner['runs'])} levels, errors identical to sphv run, orders "
      + ", ".join(f"{k}={v:.2f}" for k, v in runner["observed_order"].items()))
