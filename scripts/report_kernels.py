"""The kernel comparison of a case: its variants that differ only in the parameter `kernel` (a
group), compared per error at a fixed resolution (the finest n every kernel ran), at a fixed cost
(each kernel's error interpolated, log-log, on its error-against-wall-time curve at one wall
time every kernel reached) and by observed order, with each kernel's wall time. Generic: any case
whose sweeps carry a `kernel` parameter (in their settings or their runs' params) gets one."""
import math

from report_data import num

KEY = "kernel"


def settings_of(s):
    """The sweep's settings as a dict (key=value items; a bare item continues the previous value)."""
    out, last = {}, None
    for item in s.get("settings", []):
        if "=" in item:
            last, value = item.split("=", 1)
            out[last] = value
        elif last:
            out[last] += "," + item
    return out


def kernel_of(s):
    """The kernel a sweep ran with: its setting, else its runs' recorded parameter; None when the
    sweep records neither (a case without the parameter)."""
    k = settings_of(s).get(KEY)
    if k:
        return k
    for run in s.get("runs", []):
        v = run.get("params", {}).get(KEY)
        if isinstance(v, str) and v:
            return v
    return None


def groups(ss):
    """[(label, [(kernel, sweep), ...])]: the sweeps of one case that differ only in the kernel,
    two kernels or more, in the order met (the default variant's group first); label names the
    settings they share ("default" for none)."""
    found = {}
    for s in ss:
        k = kernel_of(s)
        if k is None:
            continue
        rest = tuple(sorted((key, v) for key, v in settings_of(s).items() if key != KEY))
        members = found.setdefault(rest, [])
        if k not in [m[0] for m in members]:
            members.append((k, s))
    return [(",".join(f"{key}={v}" for key, v in rest) or "default", members)
            for rest, members in found.items() if len(members) >= 2]


def points(s, error):
    """[(n, wall time, error)] of the runs with a positive finite error and wall time."""
    out = []
    for n, run in zip(s["levels"], s["runs"]):
        y, t = run.get("errors", {}).get(error), run.get("wall_time_s")
        if num(y) and y > 0 and num(t) and t > 0:
            out.append((n, t, y))
    return out


def at_cost(pts, t):
    """The error at wall time t on the curve through pts, linear in log error against log time
    between the two runs that bracket t (pts in the order of n); None outside the curve."""
    for (_, t0, y0), (_, t1, y1) in zip(pts, pts[1:]):
        lo, hi = min(t0, t1), max(t0, t1)
        if lo <= t <= hi:
            if t1 == t0:
                return math.sqrt(y0 * y1)
            w = (math.log(t) - math.log(t0)) / (math.log(t1) - math.log(t0))
            return math.exp((1 - w) * math.log(y0) + w * math.log(y1))
    if len(pts) == 1 and pts[0][1] == t:
        return pts[0][2]
    return None


def errors(members):
    """The errors every member reports a row for, in the first member's order."""
    names = [r["error"] for r in members[0][1]["rows"]]
    return [e for e in names if all(any(r["error"] == e for r in s["rows"]) for _, s in members)]


def comparison(members, error):
    """The comparison of one error over a group: (n_fixed, t_fixed, rows), rows one per kernel:
    kernel, error at n_fixed, its wall time, error at cost t_fixed, order and s.e., expected, outcome.
    n_fixed: the finest level every kernel ran with a finite error; t_fixed: the largest wall time
    within every kernel's curve (the cheapest kernel's costliest run, where the others reach it),
    None when the curves share no wall time."""
    pts = {k: points(s, error) for k, s in members}
    common = set.intersection(*(set(p[0] for p in v) for v in pts.values())) if pts else set()
    n_fixed = max(common) if common else None
    spans = [(min(p[1] for p in v), max(p[1] for p in v)) for v in pts.values() if v]
    t_fixed = None
    if len(spans) == len(members):
        lo, hi = max(a for a, _ in spans), min(b for _, b in spans)
        t_fixed = hi if hi >= lo else None
    rows = []
    for k, s in members:
        row = next(r for r in s["rows"] if r["error"] == error)
        at_n = next(((t, y) for n, t, y in pts[k] if n == n_fixed), (None, None))
        rows.append({"kernel": k, "variant": s["variant"], "at_n": at_n[1], "wall_at_n": at_n[0],
                     "at_cost": at_cost(pts[k], t_fixed) if t_fixed is not None else None,
                     "observed": row.get("observed"), "se": row.get("se"), "expected": row.get("expected"),
                     "band": row.get("band"), "outcome": row["outcome"], "levels": [p[0] for p in pts[k]],
                     "sweep_wall_s": s.get("wall_time_s")})
    return n_fixed, t_fixed, rows
