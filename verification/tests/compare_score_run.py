#!/usr/bin/env python3
"""Checks a `sphv score` result against the `sphv run` whose particles it scored: every error the
score reports is the run's, exactly (same function, same doubles).
usage: compare_score_run.py SCORE_RESULT_JSON RUN_RESULT_JSON [EXPECTED_ERROR ...]"""
import json
import sys

score = json.load(open(sys.argv[1]))["errors"]
run = json.load(open(sys.argv[2]))["errors"]
problems = [f"{e}: score {v!r}, run {run.get(e)!r}" for e, v in score.items() if run.get(e) != v]
problems += [f"{e}: not scored" for e in sys.argv[3:] if e not in score]
if not score:
    problems.append("no errors scored")
print("\n".join(problems) if problems else f"PASS: {len(score)} errors equal ({', '.join(sorted(score))})")
sys.exit(1 if problems else 0)
