"""Reading a results folder of sphv (`sphv verify --out DIR` or `sphv sweep`) for the report.

A sweep is the parsed sweep.json (keys as verification/harness/sweep.cpp writes them) plus "_dir", the
folder that holds it, relative to the results root. The report only renders what the harness
decided (rows and their outcomes, checks and their kinds); it never re-judges a number."""
import json
import math
import re
import sys
from pathlib import Path

# "known failure": a claimed order the error does not reach, for a reason the row states ("why"),
# with the variant or setting that does converge ("experiment"); it does not fail the gate.
# "provisional": inside the former window (expected ± (band + 2 s.e.)) but not the acceptance
# rule's; never counted as verified, listed with the parts of the rule it fails.
OUTCOMES = ("verified", "known failure", "provisional", "no order claimed", "fail")


def fail(msg, code=2):
    print(f"report.py: error: {msg}", file=sys.stderr)
    sys.exit(code)


def read_json(path):
    try:
        return json.loads(Path(path).read_text())
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror}", 3)
    except json.JSONDecodeError as e:
        fail(f"{path} is not JSON: {e}")


def load(root):
    """Returns (sweeps by case, summary.json entries that have no sweep.json, tier)."""
    root = Path(root)
    files = sorted(root.glob("**/sweep.json"))
    if not files:
        fail(f"no sweep.json under {root}")
    sweeps = {}
    for f in files:
        s = read_json(f)
        for key in ("case", "variant", "levels", "runs", "rows", "checks"):
            if key not in s:
                fail(f"{f} has no '{key}' (written by an sphv older than the outcome rows?)")
        s["_dir"] = f.parent.relative_to(root)
        sweeps.setdefault(s["case"], []).append(s)
    for ss in sweeps.values():  # the default variant first
        ss.sort(key=lambda s: (s["variant"] != "default", s["variant"]))
    missing = []
    if (root / "summary.json").exists():
        have = {(s["case"], s["variant"]) for ss in sweeps.values() for s in ss}
        missing = [e for e in read_json(root / "summary.json") if (e["case"], e["variant"]) not in have]
    tiers = sorted({str(s.get("tier", "")) for ss in sweeps.values() for s in ss} - {""})
    return sweeps, missing, ", ".join(tiers) or "not recorded"


def num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def fmt(v, spec=".3g", none="–"):
    return format(v, spec) if num(v) else none


def f2(v):
    """Two decimals, without a negative zero."""
    return f"{v:.2f}".replace("-0.00", "0.00")


def order_text(row):
    """Observed order as 'p ± se' (the standard error of the least-squares fit)."""
    if not num(row.get("observed")):
        return "–"
    se = row.get("se")
    local = local_text(row)
    text = f"{f2(row['observed'])} ± {f2(se)}" if num(se) else f"{f2(row['observed'])} (no s.e.: 2 levels)"
    return f"{text} ({local})" if local else text


def window_edges(row):
    """The lower and upper edge of a row's window (None where it has none)."""
    lo, hi = (list(row.get("window") or []) + [None, None])[:2]
    return lo, hi


def expected_text(row):
    """The claim and its window: "1 ± 0.25 [0.75, 1.25]", or "at least 0.74"."""
    if not num(row.get("expected")):
        return "none"
    lo, hi = window_edges(row)
    if num(lo) and not num(hi):
        return f"at least {lo:.3g}"
    text = f"{row['expected']:.3g} ± {row.get('band', 0):.3g}"
    return text + f" [{lo:.3g}, {hi:.3g}]" if num(lo) and num(hi) else text


def one_sided(row):
    """A one-sided claim ("at least p"): its window has a lower edge and no upper one."""
    lo, hi = window_edges(row)
    return num(lo) and not num(hi)


def claim_tex(row, missing):
    """The claim in LaTeX: "$1 \\pm 0.3$", or "$\\geq 0.74$" for a one-sided claim (its window has no
    upper edge); `missing` where no order is claimed."""
    if not num(row.get("expected")):
        return missing
    if one_sided(row):
        return f"$\\geq {row['window'][0]:.3g}$"
    return f"${row['expected']:.3g} \\pm {row.get('band', 0):.3g}$"


def claim_window_tex(row, missing):
    """expected_text in LaTeX: the claim and, for a two-sided one, its window ("$1 \\pm 0.3$
    [0.7, 1.3]"); a one-sided claim is its window ("$\\geq 0.74$"); `missing` where no order is
    claimed."""
    lo, hi = window_edges(row)
    if not num(row.get("expected")) or not (num(lo) and num(hi)):  # no claim, or a one-sided one
        return claim_tex(row, missing)
    return f"{claim_tex(row, missing)} \\mbox{{$[{lo:.3g}, {hi:.3g}]$}}"


def local_text(row):
    """The local orders between neighbouring levels, coarse to fine (the asymptotic range)."""
    local = [f2(p) for p in row.get("local_orders") or [] if num(p)]
    return "local " + ", ".join(local) if len(local) >= 2 else ""


def checks_on(s, error):
    return [c for c in s["checks"] if c.get("error", "") == error]


def row_reason(s, row):
    """What the outcome rests on, in a few words."""
    e = row["error"]
    bad = [c["name"] for c in checks_on(s, e) if not c["pass"]]
    if row["outcome"] == "fail":
        if row.get("why"):  # the harness's own reason ("failed: ...", "no bound", ...)
            return row["why"]
        if bad:
            return "failed: " + ", ".join(bad)
        if e not in s.get("claims", {}):
            return "the case states no claim for this error"
        if num(row.get("expected")):
            return "order claimed without a bound check on the error"
        return row.get("why", "")
    if row["outcome"] in ("no order claimed", "provisional"):
        return row.get("why", "")
    if row["outcome"] == "known failure":
        return known_text(row)
    bounds = [c["name"] for c in checks_on(s, e) if c.get("kind", "verification") == "verification"
              and c["name"] not in (f"order_{e}", f"order_resolved_{e}", f"order_finest_{e}", f"window_{e}") and c["pass"]]
    drift = [c["name"] for c in checks_on(s, e) if c.get("kind") == "drift" and c["pass"]]
    rest = (["bounds: " + ", ".join(bounds)] if bounds else []) + (["drift baselines: " + ", ".join(drift)] if drift else [])
    return "; ".join(["order in its window, finest pair too"] + rest)


def known_text(row):
    """A known failure's reason and the experiment that converges instead."""
    return "; ".join(x for x in (row.get("why", ""), f"converges instead: {row['experiment']}" if row.get("experiment") else "") if x)


def claim_notes(ss):
    """Each claim's reason once over the variants of a case: (the errors with what is claimed of
    each, why) in the order met, the errors sharing a reason joined ("sum_1d, sum_2d (order 2 ±
    0.2); sum_3d (order 4 ± 0.3)"), for the claim list a case opens with (its rows then omit it)."""
    items = []
    for s in ss:
        for r in s["rows"]:
            c = s.get("claims", {}).get(r["error"], {})
            if r["outcome"] == "known failure":
                item = (r["error"], f"known failure of order {expected_text(r)}", known_text(r))
            elif num(c.get("expected")):
                item = (r["error"], claim_order_text(c), c.get("why", ""))
            else:
                item = (r["error"], "no order claimed", r.get("why", "") or c.get("why", ""))
            if item[2] and item not in items:
                items.append(item)
    joined = {}  # why -> what -> errors
    for err, what, why in items:
        joined.setdefault(why, {}).setdefault(what, []).append(err)
    return [("; ".join(f"{', '.join(errs)} ({what})" for what, errs in whats.items()), why) for why, whats in joined.items()]


def row_note(s, row):
    """The row's own reason: row_reason less what claim_notes states once for its claim."""
    reason = row_reason(s, row)
    shared = {s.get("claims", {}).get(row["error"], {}).get("why", ""), row.get("why", ""), known_text(row)}
    return "" if reason in shared and row["outcome"] != "fail" else reason


def sweep_wide_failures(s):
    return [c["name"] for c in checks_on(s, "") if not c["pass"]]


def counts(sweeps):
    out = {k: 0 for k in OUTCOMES}
    for ss in sweeps.values():
        for s in ss:
            for r in s["rows"]:
                out[r["outcome"]] = out.get(r["outcome"], 0) + 1
    return out


def errors_of(s):
    """Every error name the runs of a sweep report, claimed ones (rows) first."""
    names = [r["error"] for r in s["rows"]]
    for run in s["runs"]:
        names += [e for e in run.get("errors", {}) if e not in names]
    return names


def claim_order_text(c):
    """A claim as words: "order 1 ± 0.3", or "order at least 0.74" for a one-sided claim."""
    if c.get("at_least"):
        return f"order at least {c['expected']:g}"
    return f"order {c['expected']:g} ± {c.get('band', 0):g}"


def claim(s, error):
    c = s.get("claims", {}).get(error, {})
    return c if num(c.get("expected")) else None


def series(s, error, x="n"):
    """(x, error) of every run with a positive finite error: x is the level n or the wall time."""
    pts = []
    for n, run in zip(s["levels"], s["runs"]):
        y = run.get("errors", {}).get(error)
        xv = n if x == "n" else run.get("wall_time_s")
        if num(y) and y > 0 and num(xv) and xv > 0:
            pts.append((xv, y))
    return pts


def provenances(sweeps):
    return [run.get("provenance", {}) for ss in sweeps.values() for s in ss for run in s["runs"]]


def threads_text(runs):
    """The OpenMP threads the runs ran on, each run's own count: "1 thread", "1 to 2 threads"."""
    t = sorted({r["provenance"]["threads"] for r in runs if num(r.get("provenance", {}).get("threads"))})
    if not t:
        return "threads not recorded"
    return f"{t[0]} thread{'s' if t[-1] != 1 else ''}" if len(t) == 1 else f"{t[0]} to {t[-1]} threads"


def is_dirty(prov):
    """A result produced by a tree with uncommitted changes (any of the spellings provenance uses)."""
    tree = prov.get("source_tree")
    return (bool(tree.get("dirty")) if isinstance(tree, dict) else False) or bool(prov.get("dirty") or prov.get("git_dirty")) \
        or str(prov.get("git_commit", "")).endswith("-dirty")


def file_of(stem, ext):
    """A figure's file: its stem and the extension ext ("png", "pdf"). Stems hold dots (a variant
    "gamma=1.4" gives "gamma_1.4_..."), which Path.with_suffix would take for an extension to replace."""
    return stem.parent / f"{stem.name}.{ext}"


def slug(text):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", str(text)).strip("_") or "x"


def wrap(text, width):
    """Breaks text into lines of at most about width characters (axis labels)."""
    lines, line = [], ""
    for word in str(text).split():
        if line and len(line) + 1 + len(word) > width:
            lines.append(line)
            line = word
        else:
            line = f"{line} {word}".strip()
    return "\n".join(lines + [line])


def settings_set(name):
    """A variant's name ("kernel=wendland_c4,hfact=4.5") as its set of settings."""
    return frozenset(x.strip() for x in str(name).split(",") if x.strip() and x.strip() != "default")


def variant_named(ss, name, besides=None):
    """The sweep of ss that a known failure's experiment names: the same settings in any order,
    else the variant (other than besides) whose settings are the most of the named ones (a name may
    spell out a default, "preset=toro3,energy=38,hfact=2" for the variant "energy=38,hfact=2")."""
    want = settings_set(name)
    exact = next((s for s in ss if settings_set(s["variant"]) == want), None)
    if exact or not want:
        return exact
    subsets = [s for s in ss if s is not besides and settings_set(s["variant"]) < want]
    return max(subsets, key=lambda s: len(settings_set(s["variant"])), default=None)
