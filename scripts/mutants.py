#!/usr/bin/env python3
"""Mutation testing: do the gates catch realistic faults? (issue 13, section 7)

Each verification/mutants/NN-name.patch is one fault in sph/ or reference/. For every mutant:
apply it to a scratch copy of the tree (kept between mutants, so builds are incremental and
ccache serves the unmutated files), build (Release), run the Catch2 unit tests that are not
catalogue gates, then `sphv verify --tier quick` one case at a time, the cases the mutant's
header names first. A mutant is killed when a check or unit test fails that passes on the
unmutated tree (checked against saved unmutated binaries, so a gate already failing on main
does not count as a kill). Unless --all-gates, a mutant stops at its first verification kill.
Writes DIR/kill_matrix.json after every mutant and a table on stdout; exit 0 only if every
mutant is killed by a verification gate. Usage: bash scripts/mutants.sh --help.
"""
import argparse
import filecmp
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MUTANTS = ROOT / "verification" / "mutants"
# The quick subset: one fault per family of gates, four of them in headers few translation units
# include (a rebuild is most of a mutant's cost): the density sum (every hydro case), the
# tree's opening criterion (gravity against the direct sum), Heun's second stage (the
# conduction order gates), pairs the tree search misses at the support edge with variable h,
# and the exact Riemann reference's right fan (only a tube with a right rarefaction samples it).
QUICK = ["03-density-no-self", "22-opening-no-delta", "28-heun-k1-twice", "33-tree-search-prune",
         "37-riemann-right-fan-branch"]
# Unit tests (Catch2, not catalogue gates) whose failure is a verification: they compare against
# an independent reference (published table, analytic value, direct sum, brute force, exact
# conservation law, theoretical order, a formula evaluated by hand, a known answer, an invariance
# of the equations). Any other failing unit test kills, but not "by verification".
VERIFYING_TESTS = re.compile(
    r"riemann solver reproduces|Sod wave speeds|sedov reference|noh reference|direct sum|brute force|"
    r"moments add up|point-mass term|cvode driver|equations of state|conserve momentum and energy|"
    r"second order in dt|evrard reference: energy conservation|tree search returns the grid search|"
    r"sedov density L1 converges|reduces to|evolve ends at t_end|reused neighbour lists hold every pair|"
    r"known answer|by hand|simple-wave relations|Galilean invariance|scores zero error|"
    # The KH linear reference against the vortex-sheet dispersion relation (L -> 0, c_s -> inf)
    # and against the other, independent solution of the same linear problem (eigenvalue by
    # shooting vs initial-value evolution on a grid).
    r"reaches the incompressible growth|tends to the sheet's|grows at the eigenvalue's rate|"
    # The 1D references against published values and the similarity solution; the references a
    # sweep's levels share against the 1D solvers' own output for the same inputs (as "tree search
    # returns the grid search": the same answer by another path).
    r"published 1D PPM profile|blast reference: against the similarity solution|keyed by every input", re.I)


def log(msg):
    print(msg, flush=True)


def fail(msg, code):
    print(f"mutants.sh: error: {msg}", file=sys.stderr)
    sys.exit(code)


def run(cmd, cwd=None, log_path=None, timeout=None):
    """Runs cmd under nice -n 10; returns (exit code, seconds)."""
    t0 = time.time()
    out = open(log_path, "a") if log_path else subprocess.DEVNULL
    try:
        rc = subprocess.run(["nice", "-n", "10"] + cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT,
                            timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        rc = 124
    finally:
        if log_path:
            out.close()
    return rc, time.time() - t0


def read_mutants():
    out = []
    for f in sorted(MUTANTS.glob("*.patch")):
        head = {}
        for line in f.read_text().splitlines():
            if not line.startswith("# "):
                break
            k, _, v = line[2:].partition(": ")
            head[k] = v
        out.append({"id": f.stem, "file": f, "area": head.get("area", ""), "description": head.get("description", ""),
                    "cases": [c for c in head.get("cases", "").split(",") if c]})
    return out


class Scratch:
    """A copy of the tracked (and untracked, not ignored) files, synced by content."""

    def __init__(self, path):
        self.src = path / "src"
        self.build = self.src / "build"

    def sync(self):
        files = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], cwd=ROOT,
                               capture_output=True, check=True).stdout.decode().split("\0")
        files = [f for f in files if f and (ROOT / f).is_file()]
        manifest = self.src / ".mutants-manifest"
        old = set(manifest.read_text().split("\n")) if manifest.exists() else set()
        for f in old - set(files):
            (self.src / f).unlink(missing_ok=True)
        for f in files:
            dst = self.src / f
            if not dst.exists() or not filecmp.cmp(ROOT / f, dst, shallow=False):
                dst.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(ROOT / f, dst)  # a fresh mtime: make rebuilds what depends on it
                shutil.copymode(ROOT / f, dst)
        manifest.write_text("\n".join(files))
        h = hashlib.sha256()
        for f in files:
            h.update(f.encode() + b"\0" + (self.src / f).read_bytes())
        self.digest = h.hexdigest()  # of the unmutated tree: keys the baseline cache

    def patch(self, patch_file, reverse=False):
        # GNU patch, not git apply: inside the worktree (build-mutants/) git apply would skip the
        # paths silently, as outside its current directory.
        cmd = ["patch", "-p1", "--batch", "--silent", "--no-backup-if-mismatch", "-i", str(patch_file)]
        return subprocess.run(cmd + (["-R"] if reverse else []), cwd=self.src, capture_output=True, text=True)

    def configure(self, logf):
        # The flags of the test command's build (scripts/test.sh): a fifth less compile time than
        # -O3, the same results (no fast-math, and no FMA at the default instruction set).
        return run(["cmake", "-S", str(self.src), "-B", str(self.build), "-DCMAKE_BUILD_TYPE=Release",
                    "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -fvect-cost-model=cheap -DNDEBUG"], log_path=logf)[0]

    def make(self, jobs, logf):
        return run(["cmake", "--build", str(self.build), "-j", str(jobs), "--target", "sphv", "sphv_tests"],
                   log_path=logf)


def gated_cases(sphv):
    out = subprocess.run([str(sphv), "list"], capture_output=True, text=True, check=True).stdout
    cases = []
    for line in out.splitlines():
        m = re.match(r"^(\S+)\s.*\[([^\]]*)\]\s*$", line)
        if m and "gate" in m.group(2).split(","):
            cases.append(m.group(1))
    return cases


def unit_tests(tests_bin, cases):
    """Catch2 tests that are not a re-run of a catalogue case (those are `sphv verify`'s job)."""
    names = subprocess.run([str(tests_bin), "--list-test-names-only"], capture_output=True, text=True).stdout
    names = [n.strip() for n in names.splitlines() if n.strip()]
    return [n for n in names if not (n.startswith("gate: ") and n[len("gate: "):] in cases)]


def ctest_regex(names):
    return "^(" + "|".join(re.sub(r"([][.*+?^$()|\\])", r"\\\1", n) for n in names) + ")$"


def run_unit_tests(build, names, work, logf):
    """Runs the tests under ctest (one process each); returns the failing names."""
    junit = work / "junit.xml"
    junit.unlink(missing_ok=True)
    run(["ctest", "--test-dir", str(build), "-j", "2", "-R", ctest_regex(names), "--output-junit", str(junit),
         "--timeout", "900"], log_path=logf)
    if not junit.exists():
        return list(names)  # ctest itself failed: every test counts as failed
    failed = []
    for tc in ET.parse(junit).getroot().iter("testcase"):
        if tc.get("status") not in (None, "run") or tc.find("failure") is not None or tc.find("error") is not None:
            failed.append(tc.get("name"))
    return failed


def failed_checks(case_dir, case, rc):
    """Failing checks of every sweep.json under case_dir; a crash or a verdict failure without a
    failing check is listed with kind "exit"."""
    out = []
    for sj in sorted(Path(case_dir).rglob("sweep.json")):
        s = json.loads(sj.read_text())
        for ch in s.get("checks", []):
            if not ch.get("pass", True):
                kind = ch.get("kind") or ("drift" if ch["name"].startswith("drift_") else "verification")
                out.append({"case": case, "variant": s.get("variant", ""), "check": ch["name"], "kind": kind})
    if rc != 0 and not out:
        out.append({"case": case, "variant": "", "check": f"sphv verify exit {rc} (verdict or crash)", "kind": "exit"})
    return out


def has_tiers(sphv):
    """Whether `sphv verify` has --tier (the core harness API); before it, the Catch2 gate
    test of a case ran its quick levels, and is run instead."""
    return "--tier" in subprocess.run([str(sphv), "verify", "--help"], capture_output=True, text=True).stdout


def verify_case(build, case, out_dir, args, log_path):
    """The gates of one case at the quick tier; returns its failing checks."""
    if args.tiers:
        rc, _ = run([str(build / "sphv"), "verify", "--tier", args.tier, "--cases", case, "--force", "--out",
                     str(out_dir)], log_path=log_path, timeout=args.case_timeout)
        return failed_checks(out_dir, case, rc)
    out_dir.mkdir(parents=True, exist_ok=True)
    xml = out_dir / "catch.xml"
    rc, _ = run([str(build / "sphv_tests"), f"gate: {case}", "-r", "xml", "-o", str(xml)], timeout=args.case_timeout)
    out = []
    try:  # the XML reporter writes the INFO of each failed CHECK: "[case ][[variant] |variant: ]name = v in [lo, hi]"
        infos = [i.text.strip() for i in ET.parse(xml).getroot().iter("Info") if i.text]
    except (ET.ParseError, FileNotFoundError):
        infos = []
    for info in infos:
        m = re.match(r"^(?:([^ :\[]+): |(?:\S+ )?\[([^\]]*)\] )?(\S+) = \S+ in \[", info)
        if m:
            name = m.group(3)
            out.append({"case": case, "variant": m.group(1) or m.group(2) or "", "check": name,
                        "kind": "drift" if name.startswith("drift_") else "verification"})
    if rc != 0 and not out:
        out.append({"case": case, "variant": "", "check": f"gate test exit {rc}", "kind": "exit"})
    return out


class Baseline:
    """Saved unmutated binaries; runs a case or a test on them once, on demand, to tell a kill
    from a gate that fails without any mutant. The layout build/ + reference/ lets the binaries
    find the drift baselines next to them."""

    def __init__(self, dir_, scratch, args):
        self.dir, self.args = dir_, args
        self.build = dir_ / "build"
        self.build.mkdir(parents=True, exist_ok=True)
        for b in ("sphv", "sphv_tests"):
            shutil.copy2(scratch.build / b, self.build / b)
        ref = dir_ / "reference"
        if not ref.exists():
            ref.symlink_to(scratch.src / "reference")
        self.cache_file = dir_ / "baseline.json"
        self.cache = json.loads(self.cache_file.read_text()) if self.cache_file.exists() else {}
        if self.cache.get("tree") != scratch.digest or self.cache.get("tiers") != args.tiers:  # another code version
            self.cache = {"tree": scratch.digest, "tiers": args.tiers, "cases": {}, "tests": {}}

    def case_failures(self, case):
        if case not in self.cache["cases"]:
            d = self.dir / "cases" / case
            shutil.rmtree(d, ignore_errors=True)
            fails = verify_case(self.build, case, d, self.args, self.dir / "baseline.log")
            self.cache["cases"][case] = [f"{c['variant']}/{c['check']}" for c in fails]
            self.cache_file.write_text(json.dumps(self.cache, indent=1))
        return set(self.cache["cases"][case])

    def test_fails(self, name):
        if name not in self.cache["tests"]:
            rc, _ = run([str(self.build / "sphv_tests"), name.replace(",", "\\,")], log_path=self.dir / "baseline.log")
            self.cache["tests"][name] = rc != 0
            self.cache_file.write_text(json.dumps(self.cache, indent=1))
        return self.cache["tests"][name]


def source_commit():
    """The commit the mutants are applied to (with "+dirty" when the tree has changes)."""
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True)
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT, capture_output=True,
                           text=True)
    return (head.stdout.strip() or "unknown") + ("+dirty" if dirty.stdout.strip() else "")


def mutant_run(m, scratch, base, cases, tests, args, work):
    """Applies, builds and judges one mutant; returns its kill-matrix row."""
    t0 = time.time()
    row = {"id": m["id"], "commit": source_commit(), "area": m["area"], "description": m["description"], "killed": False,
           "by_verification": False, "failed_checks": [], "failed_tests": [], "wall_time_s": 0.0}
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    logf = work / "log.txt"
    applied = scratch.patch(m["file"])
    try:
        if applied.returncode != 0:
            row["error"] = "patch does not apply: " + (applied.stdout + applied.stderr).strip().replace("\n", " ")[:200]
            return row
        rc, build_s = scratch.make(args.jobs, logf)
        row["build_time_s"] = round(build_s, 1)
        if rc != 0:
            row["error"] = "does not compile (a catalogue error, not a kill); see " + str(logf)
            return row
        # Unit tests first (seconds), then the cases, the mutant's own first.
        for name in run_unit_tests(scratch.build, tests, work, logf):
            if not base.test_fails(name):
                row["failed_tests"].append(name)
        row["by_verification"] = any(VERIFYING_TESTS.search(n) for n in row["failed_tests"])
        order = [c for c in m["cases"] if c in cases] + [c for c in cases if c not in m["cases"]]
        for case in order:
            if row["by_verification"] and not args.all_gates:
                break
            d = work / "verify" / case
            fails = verify_case(scratch.build, case, d, args, logf)
            known = base.case_failures(case)
            fresh = [c for c in fails if f"{c['variant']}/{c['check']}" not in known]
            row["failed_checks"] += fresh
            row["by_verification"] |= any(c["kind"] == "verification" for c in fresh)
            if not args.keep_runs:
                shutil.rmtree(d, ignore_errors=True)
        row["killed"] = bool(row["failed_checks"] or row["failed_tests"])
        return row
    finally:
        if applied.returncode == 0:
            scratch.patch(m["file"], reverse=True)
        scratch.sync()  # restores anything the reverse patch left
        row["wall_time_s"] = round(time.time() - t0, 1)


def first_gates(row, k=3):
    names = [f"{c['case']}[{c['variant']}]:{c['check']}({c['kind']})" for c in row["failed_checks"]]
    names += [f"test:{t}" for t in row["failed_tests"]]
    return ", ".join(names[:k]) + (f" (+{len(names) - k})" if len(names) > k else "")


def main():
    ap = argparse.ArgumentParser(prog="bash scripts/mutants.sh", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="only the fixed subset " + ",".join(QUICK))
    ap.add_argument("--only", help="comma-separated mutant ids or their numbers (e.g. 03,31), run in that order")
    ap.add_argument("--out", default="runs/mutants", help="output directory (default runs/mutants)")
    ap.add_argument("--scratch", default="build-mutants", help="scratch copy of the tree (default build-mutants)")
    ap.add_argument("--tier", default="quick", help="sphv verify tier (default quick)")
    ap.add_argument("--jobs", type=int, default=2, help="build jobs (default 2)")
    ap.add_argument("--all-gates", action="store_true", help="run every gate even after a verification kill")
    ap.add_argument("--keep-runs", action="store_true", help="keep each mutant's sweep outputs")
    ap.add_argument("--case-timeout", type=float, default=3600, help="seconds per case before it counts as a hang")
    ap.add_argument("--merge", action="store_true", help="keep rows of mutants not run now from an existing kill_matrix.json")
    args = ap.parse_args()

    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    mutants = read_mutants()
    if args.quick:
        mutants = [m for m in mutants if m["id"] in QUICK]
    if args.only:
        sel = []  # in the order given
        for w in args.only.split(","):
            hit = [m for m in mutants if m["id"] == w or m["id"].startswith(w + "-")]
            if len(hit) != 1:
                fail(f"--only: '{w}' matches {len(hit)} mutants", 2)
            sel += hit
        mutants = sel
    scratch = Scratch((ROOT / args.scratch).resolve() if not Path(args.scratch).is_absolute() else Path(args.scratch))
    scratch.src.mkdir(parents=True, exist_ok=True)
    scratch.sync()
    logf = out / "build.log"
    log(f"mutants: {len(mutants)}; scratch tree {scratch.src}; building the unmutated tree")
    if scratch.configure(logf) != 0 or scratch.make(args.jobs, logf)[0] != 0:
        fail(f"the unmutated tree does not build (see {logf})", 1)
    args.tiers = has_tiers(scratch.build / "sphv")
    if not args.tiers:
        log("sphv verify has no --tier yet: each case's Catch2 gate test runs its quick levels instead")
    base = Baseline(out / "baseline", scratch, args)
    cases = gated_cases(scratch.build / "sphv")
    tests = unit_tests(scratch.build / "sphv_tests", cases)

    matrix_file = out / "kill_matrix.json"
    rows = {}
    if args.merge and matrix_file.exists():
        rows = {r["id"]: r for r in json.loads(matrix_file.read_text())["mutants"]}
    t_start = time.time()
    for m in mutants:
        log(f"[{time.strftime('%H:%M:%S')}] {m['id']}: {m['description']}")
        r = mutant_run(m, scratch, base, cases, tests, args, out / "work" / m["id"])
        rows[m["id"]] = r
        state = r.get("error") or ("killed" if r["killed"] else "SURVIVED") + (" by verification" if r["by_verification"] else "")
        log(f"    {state} in {r['wall_time_s']:.0f} s (build {r.get('build_time_s', 0):.0f} s): {first_gates(r)}")
        ordered = [rows[k] for k in sorted(rows)]
        tmp = matrix_file.with_suffix(".tmp")
        tmp.write_text(json.dumps({"quick": args.quick, "total_wall_time_s": round(time.time() - t_start, 1),
                                   "mutants": ordered}, indent=1) + "\n")
        tmp.replace(matrix_file)

    ordered = [rows[k] for k in sorted(rows)]
    print(f"\n{'mutant':30} {'area':18} {'killed':7} {'by verif.':9} {'time s':>7}  first failing gates")
    for r in ordered:
        k = "ERROR" if r.get("error") else ("yes" if r["killed"] else "NO")
        print(f"{r['id']:30} {r['area']:18} {k:7} {'yes' if r['by_verification'] else 'no':9} {r['wall_time_s']:7.0f}  "
              f"{r.get('error') or first_gates(r)}")
    good = sum(1 for r in ordered if r["by_verification"] and not r.get("error"))
    print(f"{good}/{len(ordered)} mutants killed by a verification gate; wall time {time.time() - t_start:.0f} s; "
          f"matrix: {matrix_file}")
    return 0 if good == len(ordered) else 1


if __name__ == "__main__":
    sys.exit(main())
