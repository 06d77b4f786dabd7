"""The comparison of a case's variants that differ in one parameter (PARAMETERS: the kernel, the
scheme): per error at a fixed resolution (the finest n every member ran), at a fixed cost (each
member's error interpolated, log-log, on its error-against-wall-time curve at one wall time every
member reached) and by observed order, with each member's wall time, and per member a sentence of
what it changes against the first (the group's base). Generic: any case whose sweeps carry the
parameter (in their settings or their runs' params) gets one.

A group is like for like when its members' settings are the same but for the parameter. A variant
setting the parameter without such a sibling is compared with the sweep, of another value, whose
parameters differ least, and the group names the parameters that differ: a comparison of unlike
runs is never silent."""
import math
from dataclasses import dataclass, field

from report_data import num

PARAMETERS = ("kernel", "scheme")


@dataclass
class Group:
    """Sweeps of one case compared in the parameter key: members [(value, sweep)], the base first
    (the sweep running the case's default value where one does). label names the settings the
    members share besides key ("default" for none); for a nearest pair, the variant's own. differs:
    per member after the base, the other parameters in which it differs from the base, as
    (name, base's value, member's value). nearest: no sweep of another value shares the variant's
    settings, so the base is the one that differs least."""
    key: str
    label: str
    members: list
    differs: list = field(default_factory=list)
    nearest: bool = False


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


def value_of(s, key):
    """The value of key a sweep ran with: its setting, else its runs' recorded parameter; None when
    the sweep records neither (a case without the parameter)."""
    v = settings_of(s).get(key)
    if v:
        return v
    for run in s.get("runs", []):
        v = run.get("params", {}).get(key)
        if isinstance(v, str) and v:
            return v
    return None


def fixed_params(s):
    """The parameters every run of the sweep recorded with one value, less the level (the parameter
    equal to each run's n): what the sweep holds fixed; None when its runs record no params."""
    params = [run.get("params") for run in s.get("runs", [])]
    if not params or not all(isinstance(p, dict) for p in params):
        return None
    level = {k for k in params[0] if all(p.get(k) == n for p, n in zip(params, s["levels"]))}
    return {k: v for k, v in params[0].items() if k not in level and all(p.get(k) == v for p in params[1:])}


def differences(base, other, key):
    """[(name, base's value, other's value)]: the parameters besides key in which two sweeps differ,
    from their runs' recorded params where both record them (a default a setting leaves implicit
    counts too), else from their settings."""
    a, b = fixed_params(base), fixed_params(other)
    if a is None or b is None:
        a, b = settings_of(base), settings_of(other)
    names = list(a) + [k for k in b if k not in a]
    return [(k, a.get(k), b.get(k)) for k in names if k != key and a.get(k) != b.get(k)]


def rest_of(s, key):
    """The sweep's settings besides key, in a form that groups compare."""
    return tuple(sorted((k, v) for k, v in settings_of(s).items() if k != key))


def label_of(rest):
    return ",".join(f"{k}={v}" for k, v in rest) or "default"


def shares_an_error(a, b):
    return bool({r["error"] for r in a["rows"]} & {r["error"] for r in b["rows"]})


def groups(ss, key):
    """[Group]: the like-for-like groups of a case's sweeps in key (two values or more, in the order
    met, the default variant's group first), and for each variant setting key with no like-for-like
    sibling the pair with its nearest sweep of another value (fewest differing parameters, then
    fewest settings). A variant with no sweep of another value to compare with is in none:
    alone() names it."""
    valued = [(v, s) for v, s in ((value_of(s, key), s) for s in ss) if v is not None]
    found = {}
    for v, s in valued:
        members = found.setdefault(rest_of(s, key), [])
        if v not in [m[0] for m in members]:
            members.append((v, s))
    out = []
    for rest, members in found.items():
        if len(members) >= 2:
            members = sorted(members, key=lambda m: key in settings_of(m[1]))  # stable: the default value first
            out.append(Group(key, label_of(rest), members, [differences(members[0][1], s, key) for _, s in members[1:]]))
            continue
        v, s = members[0]
        if key not in settings_of(s):
            continue
        others = [(len(differences(o, s, key)), len(settings_of(o)), j, w, o)
                  for j, (w, o) in enumerate(valued) if w != v and shares_an_error(o, s)]
        if others:
            *_, w, base = min(others, key=lambda c: c[:3])
            out.append(Group(key, label_of(rest), [(w, base), (v, s)], [differences(base, s, key)], nearest=True))
    return out


def alone(ss, key):
    """The variants setting key that no group holds: the case has no sweep of another value
    reporting an error of theirs."""
    held = {id(s) for g in groups(ss, key) for _, s in g.members}
    return [s["variant"] for s in ss if key in settings_of(s) and id(s) not in held]


def alone_text(ss, key):
    """Plain text naming the variants setting key that nothing is compared with; "" when none."""
    lone = alone(ss, key)
    return (f"Not compared: {', '.join(lone)}. No sweep of this case with another {key} reports the same errors: "
            "no like-for-like sibling exists, nor any other." if lone else "")


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
    """The comparison of one error over a group: (n_fixed, t_fixed, rows), rows one per member:
    value, error at n_fixed, its wall time, error at cost t_fixed, order with its s.e. and local orders,
    the claim with its window (a one-sided claim's has no upper edge), outcome.
    n_fixed: the finest level every member ran with a finite error; t_fixed: the largest wall time
    within every member's curve (the cheapest member's costliest run, where the others reach it),
    None when the curves share no wall time."""
    pts = [points(s, error) for _, s in members]
    common = set.intersection(*(set(p[0] for p in v) for v in pts)) if pts else set()
    n_fixed = max(common) if common else None
    spans = [(min(p[1] for p in v), max(p[1] for p in v)) for v in pts if v]
    t_fixed = None
    if len(spans) == len(members):
        lo, hi = max(a for a, _ in spans), min(b for _, b in spans)
        t_fixed = hi if hi >= lo else None
    rows = []
    for (value, s), p in zip(members, pts):
        row = next(r for r in s["rows"] if r["error"] == error)
        at_n = next(((t, y) for n, t, y in p if n == n_fixed), (None, None))
        rows.append({"value": value, "variant": s["variant"], "at_n": at_n[1], "wall_at_n": at_n[0],
                     "at_cost": at_cost(p, t_fixed) if t_fixed is not None else None,
                     "observed": row.get("observed"), "se": row.get("se"), "local_orders": row.get("local_orders"),
                     "expected": row.get("expected"), "band": row.get("band"), "window": row.get("window"),
                     "outcome": row["outcome"], "levels": [q[0] for q in p],
                     "sweep_wall_s": s.get("wall_time_s")})
    return n_fixed, t_fixed, rows


def ratio_text(r):
    return f"{r:.2g}×" if r < 100 else f"{r:.0f}×"


def effects(group, text=str, name=str):
    """Per member after the base, one sentence of what it changes against the base, from the
    numbers of comparison(): each error's ratio to the base's at the fixed n with the ratio of
    their wall times there, each error's ratio at the fixed cost, and the outcomes that differ.
    text renders plain text and name an error's name, in the format of the page (the sentence mixes
    the two, which no one formatter tells apart)."""
    base = group.members[0][0]
    out = []
    for j, (value, _) in enumerate(group.members[1:], start=1):
        at_n, at_equal_cost, outcomes = {}, {}, []
        for err in errors(group.members):
            n_fixed, t_fixed, rows = comparison(group.members, err)
            b, r = rows[0], rows[j]
            if num(b["at_n"]) and num(r["at_n"]):
                at_n.setdefault((n_fixed, r["wall_at_n"] / b["wall_at_n"]), []).append(
                    name(err) + text(f" {ratio_text(r['at_n'] / b['at_n'])}"))
            if num(b["at_cost"]) and num(r["at_cost"]):
                at_equal_cost.setdefault(t_fixed, []).append(name(err) + text(f" {ratio_text(r['at_cost'] / b['at_cost'])}"))
            if r["outcome"] != b["outcome"]:
                outcomes.append(name(err) + text(f" {r['outcome']} ({base}: {b['outcome']})"))
        parts = [text(f"at n = {n:g}: ") + text(", ").join(items)
                 + text(f" the error of {base}, at {ratio_text(wall)} its wall time") for (n, wall), items in at_n.items()]
        parts = parts or [text(f"no level in common with {base}")]
        parts += [text(f"at an equal wall time ({t:.3g} s): ") + text(", ").join(items) for t, items in at_equal_cost.items()] or [
            text(f"no wall time in common with {base}")]
        parts.append(text("outcomes: ") + text("; ").join(outcomes) if outcomes else text(f"the same outcomes as {base}"))
        out.append(text(f"{value} against {base}: ") + text("; ").join(parts) + text("."))
    return out


def title(group):
    """What a group compares: the settings its members share and their values, or for a nearest
    pair the two variants."""
    values = ", ".join(v for v, _ in group.members)
    if group.nearest:
        return f"{group.members[1][1]['variant']} against {group.members[0][1]['variant']}: {values}"
    return f"{group.label}: {values}"


def unlike_text(group):
    """Plain text saying which parameters besides the group's own differ between its members, or
    that they are like for like."""
    base_value, base = group.members[0]
    said = []
    for (value, s), diff in zip(group.members[1:], group.differs):
        if diff:
            said.append(f"{s['variant']} differs from {base['variant']} also in "
                        + ", ".join(f"{k} ({a} against {b})" for k, a, b in diff))
    if group.nearest:
        variant = group.members[1][1]["variant"]
        return (f"Not like for like: no sweep of another {group.key} has the settings of {variant} besides {group.key}; "
                f"compared with the nearest, {base['variant']} ({group.key} {base_value}). " + "; ".join(said) + ".")
    if said:
        return "Not like for like: " + "; ".join(said) + "."
    return f"Like for like: the members differ in {group.key} alone."
