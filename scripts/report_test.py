#!/usr/bin/env python3
"""Test of the report (ctest report_*): runs report.py on a results folder and checks what a
reader relies on: no warning on stderr, every href and src resolves inside the folder, the
counts at the top match the rows of the sweep.json files, a convergence figure (PNG and PDF)
for every claimed error of every variant and none for errors without an order claim, a
run-time figure per claimed error, every figure entry its own file, the bundle's provenance
(each point's own threads, dates and wall time), the kernel and scheme comparisons (which variants
each compares, like for like or said not to be, its numbers recomputed from the sweeps, a variant
with nothing to compare with said to be so), and with --mutants the kill matrix page. With --dirty it
also checks that a bundle of results whose provenance records a dirty tree is refused
(--allow-dirty is exercised by bundle_test.sh).

usage: report_test.py RESULTS_DIR WORK_DIR [--mutants FILE] [--dirty]"""
import html
import json
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from urllib.parse import unquote

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import report_math  # noqa: E402
import report_paper  # noqa: E402
import report_tex  # noqa: E402
from report_check_links import broken_links  # noqa: E402
from report_data import file_of, num, series, slug  # noqa: E402

failures = []


def expect(cond, what):
    if not cond:
        failures.append(what)


def report(results, reports, *extra):
    return subprocess.run([sys.executable, str(HERE / "report.py"), str(results), "--name", "t", "--reports", str(reports), *extra],
                          capture_output=True, text=True)


def first_screen(index, sweeps, out):
    """The index opens with the verdict, then (when anything fails) the failing rows with links to
    their variants, then one line per case linking its page, and only then the full table."""
    failing = [(s, r) for s in sweeps for r in s["rows"] if r["outcome"] == "fail"]
    n = len(sweeps)
    bad = sum(not s["passed"] for s in sweeps)
    verdict = re.search(r"<p class='verdict (pass|fail)'>(PASS|FAIL): ([^<]*)", index)
    expect(verdict and (verdict.group(2) == "FAIL") == (bad > 0), f"verdict line {verdict and verdict.group(0)} for {bad} failing variants")
    at = {k: index.find(f"id='{k}'") for k in ("failing", "cases", "all")}
    expect(0 < at["cases"] < at["all"], f"the per-case lines do not precede the full table: {at}")
    if failing:
        expect(0 < at["failing"] < at["cases"], f"the failing rows do not come first: {at}")
        section = index[at["failing"]:at["cases"]]
        for s, r in failing:
            href = f"case-{slug(s['case'])}.html#v-{slug(s['variant'])}"
            # The error itself links to its convergence figure, where one is drawn.
            drawn = (out / "fig" / slug(s["case"]) / f"{slug(s['variant'])}_{slug(r['error'])}_convergence.png").is_file()
            err = re.escape(r["error"])
            cell = (rf"<a href='case-{re.escape(slug(s['case']))}\.html#fig-{re.escape(slug(s['variant']))}-{re.escape(slug(r['error']))}'>{err}</a>"
                    if drawn else err)
            expect(re.search(rf"<a href='{re.escape(href)}'>[^<]*</a></td><td class='nw'>{cell}</td>", section),
                   f"failing row {s['case']} {s['variant']} {r['error']} not listed first with a link to {href}"
                   + (" and its figure" if drawn else ""))
        expect("href='#failing'" in index[:at["failing"]], "the verdict line does not link the failing rows")
    cases = index[at["cases"]:at["all"]]
    for case in {s["case"] for s in sweeps}:
        expect(f"<a href='case-{slug(case)}.html'>{case}</a>" in cases, f"no line for case {case} linking its page")


def distinct_figures(out, stdout):
    """Every figure entry of every page has its own PNG and PDF: a name cut short (at a dot, say)
    makes several entries show one file, which the link check cannot see."""
    entries = []
    for page in sorted(out.glob("*.html")):
        for fig in re.findall(r"<figure(?: id='[^']*')?>.*?</figure>", page.read_text()):
            png = re.search(r"<img src='([^']+)'", fig).group(1)
            pdf = re.search(r"<a href='([^']+\.pdf)'>PDF</a>", fig).group(1)
            entries.append((page.name, unquote(png), unquote(pdf)))
    for k, ext in ((1, "PNG"), (2, "PDF")):
        files = [x[k] for x in entries]
        shared = sorted({f for f in files if files.count(f) > 1})
        expect(not shared, f"figure entries sharing a {ext} file: {shared}")
    on_disk = len(list(out.glob("fig/**/*.png")))
    expect(on_disk == len(entries), f"{on_disk} PNG files under fig/ for {len(entries)} figure entries")
    m = re.search(r"; (\d+) figures\)", stdout)
    expect(m and int(m.group(1)) == len(entries), f"report.py says {m and m.group(1)} figures, the pages show {len(entries)}")


KEYS = ("kernel", "scheme")  # the parameters the report compares variants in


def settings(s):
    return dict(x.split("=", 1) for x in s["settings"] if "=" in x)


def held_params(s):
    """The parameters every run of the sweep recorded alike, less the level n."""
    ps = [r.get("params", {}) for r in s["runs"]]
    return {k: v for k, v in ps[0].items() if k != "n" and all(p.get(k) == v for p in ps)}


def param_differences(a, b, key):
    """The names of the recorded parameters besides key in which two sweeps differ."""
    pa, pb = held_params(a), held_params(b)
    return sorted(k for k in set(pa) | set(pb) if k != key and pa.get(k) != pb.get(k))


def compared_groups(sweeps, key):
    """The comparisons the report must show in key, read here without report_compare.py:
    [(case, label, [(value, sweep)] base first, nearest)]. Sweeps whose settings are the same
    but for key, two values or more (a sweep not setting key runs the value its runs record),
    are a like-for-like group; a variant setting key with no such sibling pairs with the sweep of
    another value reporting one of its errors whose recorded parameters differ least (then the
    one with fewest settings): nearest. Also returns the variants with nothing to pair with."""
    by_rest = {}
    for s in sweeps:
        st = settings(s)
        v = st.pop(key, None) or s["runs"][0].get("params", {}).get(key)
        if v:
            by_rest.setdefault((s["case"], tuple(sorted(st.items()))), []).append((v, s))
    out, lone = [], []
    for (case, rest), members in by_rest.items():
        label = ",".join(f"{a}={b}" for a, b in rest) or "default"
        if len({v for v, _ in members}) >= 2:
            out.append((case, label, sorted(members, key=lambda m: key in settings(m[1])), False))
        elif key in settings(members[0][1]):
            v, s = members[0]
            errs = {r["error"] for r in s["rows"]}
            others = [(len(param_differences(o, s, key)), len(o["settings"]), w, o) for (c, _), ms in by_rest.items() if c == case
                      for w, o in ms if w != v and errs & {r["error"] for r in o["rows"]}]
            if others:
                *_, w, base = min(others, key=lambda x: x[:2])
                out.append((case, label, [(w, base), (v, s)], True))
            else:
                lone.append((case, s["variant"]))
    return out, lone


def table_rows(section):
    """The rows of a comparison table as (error, value, variant, numbers, claim): the numbers are the
    error at fixed n, the wall time there and the error at fixed cost, as shown; claim the row's last
    cell, the claim with its window."""
    rows, err = [], None
    for tr in re.findall(r"<tr[^>]*>(.*?)</tr>", section)[1:]:
        m = re.match(r"<td rowspan=\d+>([^<]*)<br>", tr)
        if m:
            err = html.unescape(m.group(1))
        cells = re.findall(r"<td class='(?:nw|var)'>([^<]*)</td>", tr)
        nums = re.findall(r"<td class='num'>(?:<b>)?([^<]*)", tr)
        claim = re.findall(r"<td class='num'>([^<]*)</td><td class='(?:verified|known|provisional|noclaim|fail)'>", tr)
        rows.append((err, html.unescape(cells[0]), html.unescape(cells[1]), nums[:3], html.unescape(claim[-1]) if claim else None))
    return rows


def near(shown, want, rel=2e-3):
    try:
        return want is not None and abs(float(shown) / want - 1) < rel
    except ValueError:
        return False


def comparison_checks(out, sweeps, key):
    """Each case with a comparison in key shows it (anchor #<key>s, a link from the index): per
    group a figure, then a table with a row per error and member. Checked against the sweeps'
    own numbers: the members and their order (the base first; a variant without a like-for-like
    sibling paired with the nearest sweep, which the group says is not like for like, naming the
    parameters that differ); per error the error and the wall time at the finest level every
    member ran, and the error at the fixed cost, interpolated log-log on each member's
    error-against-wall-time curve at the cheapest curve's end, recomputed here; the group's
    sentence gives each member's error ratio to the base's and the ratio of their wall times."""
    groups, lone = compared_groups(sweeps, key)
    with_section = {case for case, *_ in groups} | {case for case, _ in lone}
    expect(groups or lone or not any(f"{key}=" in x for s in sweeps for x in s["settings"]), f"{key} variants found no group")
    index = (out / "index.html").read_text()
    for case in {s["case"] for s in sweeps}:
        text = (out / f"case-{slug(case)}.html").read_text()
        shown = f"id='{key}s'" in text
        expect(shown == (case in with_section), f"{case}: {key} comparison shown {shown}, expected {case in with_section}")
        linked = f"case-{slug(case)}.html#{key}s" in index
        expect(linked == any(c == case for c, *_ in groups), f"index: {key} comparison link of {case} {linked}")
    for case, variant in lone:
        text = (out / f"case-{slug(case)}.html").read_text()
        expect(f"Not compared: {html.escape(variant, quote=True)}." in text, f"{case}: {variant} has nothing to compare with, unsaid")
    for case, label, members, nearest in groups:
        text = (out / f"case-{slug(case)}.html").read_text()
        start = text.find(f"<h3 id='{key}s-{slug(label)}'>")
        expect(start > 0, f"{case} {label}: no {key} group")
        section = text[start:text.find("</table>", start)]  # heading, sentence, figure, table
        stem = out / "fig" / slug(case) / f"{key}s_{slug(label)}"
        expect(file_of(stem, "png").is_file() and file_of(stem, "pdf").is_file(), f"{case} {label}: no {key} figure")
        expect(0 < section.find("<figure>") < section.find("<table>"), f"{case} {label}: the {key} table before its figure")
        base_value, base = members[0]
        for value, s in members[1:]:
            diff = param_differences(base, s, key)
            if nearest or diff:
                expect("Not like for like" in section and all(re.search(rf"\b{re.escape(d)} \(", section) for d in diff),
                       f"{case} {label}: {s['variant']} against {base['variant']} does not say that {diff} differ")
            else:
                expect(f"Like for like: the members differ in {key} alone." in section, f"{case} {label}: like for like unsaid")
        rows = table_rows(section)
        errors = [r["error"] for r in base["rows"] if all(any(x["error"] == r["error"] for x in s["rows"]) for _, s in members)]
        expect([(err, v, s["variant"]) for err in errors for v, s in members] == [r[:3] for r in rows],
               f"{case} {label}: table rows {[r[:3] for r in rows]}, expected {[(err, v, s['variant']) for err in errors for v, s in members]}")
        for err in errors:
            curves = {v: [(n, r["wall_time_s"], r["errors"][err]) for n, r in zip(s["levels"], s["runs"]) if r["errors"].get(err, 0) > 0]
                      for v, s in members}
            n_fixed = max(set.intersection(*({n for n, _, _ in c} for c in curves.values())))
            cost = min(max(t for _, t, _ in c) for c in curves.values())
            got = {r[1]: r[3] for r in rows if r[0] == err}
            for v, s in members:  # the claim as the sweep states it: a one-sided claim is "at least p", never "p ± 0"
                row = next(r for r in s["rows"] if r["error"] == err)
                lo, hi = (list(row.get("window") or []) + [None, None])[:2]
                want = ("none" if not num(row.get("expected")) else f"at least {lo:.3g}" if num(lo) and not num(hi)
                        else f"[{lo:.3g}, {hi:.3g}]" if num(lo) and num(hi) else f"{row['expected']:.3g}")
                shown = next((r[4] for r in rows if r[0] == err and r[1] == v), None)
                expect(shown is not None and want in shown, f"{case} {label} {err} {v}: claim shown {shown!r}, the sweep's {want!r}")
            at_n = {}
            for v, c in curves.items():
                at_n[v] = next((t, y) for n, t, y in c if n == n_fixed)
                want = None
                for (_, t0, y0), (_, t1, y1) in zip(c, c[1:]):
                    if t0 <= cost <= t1:
                        want = math.exp(math.log(y0) + (math.log(y1) - math.log(y0)) * math.log(cost / t0) / math.log(t1 / t0))
                        break
                cells = got.get(v, [])
                expect(len(cells) == 3 and near(cells[0], at_n[v][1]) and near(cells[1], at_n[v][0], 5e-3) and near(cells[2], want),
                       f"{case} {label} {err} {v}: at n = {n_fixed}, its wall time, at fixed cost {cells}; the sweep's "
                       f"{at_n[v][1]:.4g}, {at_n[v][0]:.3g}, recomputed {want}")
            for v, _ in members[1:]:
                ratio, wall = at_n[v][1] / at_n[base_value][1], at_n[v][0] / at_n[base_value][0]
                said = f"{err} {ratio:.2g}×"
                expect(said in section and f"at {wall:.2g}× its wall time" in section,
                       f"{case} {label}: the sentence lacks '{said}' or the wall time ratio {wall:.2g} of {v} to {base_value}")


def alone_checks(results, work):
    """A scheme variant whose case has no sweep of another scheme is shown as not compared (a
    results folder holding it alone), not dropped in silence."""
    variant = next((f.parent for f in sorted(results.glob("**/sweep.json")) if "scheme=" in f.parent.name), None)
    if variant is None:
        return
    alone = work / "alone"
    shutil.copytree(variant, alone / variant.relative_to(results))
    res = report(alone, work / "alone-report")
    sweeps = [json.loads(f.read_text()) for f in sorted(alone.glob("**/sweep.json"))]
    expect(res.returncode == 0 and res.stderr == "", f"report of a lone scheme variant: exit {res.returncode} {res.stderr}")
    expect(compared_groups(sweeps, "scheme")[1], "the lone scheme variant found a sibling")
    comparison_checks(work / "alone-report" / "t", sweeps, "scheme")


def bundle_checks(results, work, sweeps):
    """The bundle's provenance takes each point's own threads, dates and wall time (result.json),
    not the process that wrote sweep.json; each figure of the supplement is its own file."""
    res = report(results, work, "--bundle", str(work / "bundle"), "--allow-dirty")  # the refusal is tested with --dirty
    if res.returncode != 0:
        return expect(False, f"bundle: exit {res.returncode} {res.stderr}")
    runs = [r for s in sweeps for r in s["runs"]]
    threads = sorted({r["provenance"]["threads"] for r in runs})
    dates = sorted(r["provenance"]["date"] for r in runs)
    prov = json.loads((work / "bundle" / "provenance.json").read_text())
    expect(prov.get("threads_per_point") == threads, f"provenance.json threads {prov.get('threads_per_point')}, the points ran on {threads}")
    expect(prov.get("points_ran") == [dates[0], dates[-1]], f"provenance.json points_ran {prov.get('points_ran')}, points ran {dates[0]} to {dates[-1]}")
    wall = sum(r["wall_time_s"] for r in runs)
    expect(abs(prov.get("points_wall_time_s", -1) - wall) < 1e-9 * wall, f"provenance.json wall time {prov.get('points_wall_time_s')}, points {wall}")
    main_tex = (work / "bundle" / "verification.tex").read_text()
    said = f"{threads[0]} to {threads[-1]} OpenMP threads per point" if len(threads) > 1 else f"{threads[0]} OpenMP thread"
    expect(said in main_tex, f"verification.tex does not say '{said}'")
    # Table 1: one line per case, a known failure with the variant that converges instead.
    table = main_tex[main_tex.find(r"\label{tab:verification}"):main_tex.find(r"\end{tabular}")]
    for case in {s["case"] for s in sweeps}:
        lines = [line for line in table.splitlines() if line.startswith(report_math.prose(case) + " &")]
        expect(len(lines) == 1, f"Table 1 has {len(lines)} lines for {case}")
        default = min((s for s in sweeps if s["case"] == case), key=lambda s: (s["variant"] != "default", s["variant"]))  # as load() orders
        row = report_paper.headline(default)
        if lines and row and row["outcome"] == "known failure":
            v, r = report_paper.experiment([s for s in sweeps if s["case"] == case], default, row)
            expect(v is None or report_math.prose(v["variant"]) in lines[0], f"Table 1: {case}'s known failure does not name its experiment")
        if lines and row and report_paper.window(default, row):
            # A one-sided claim records no upper edge (None): the table says "\ge lo".
            lo, hi = report_paper.window(default, row)
            shown = f"[{lo:.2f}, {hi:.2f}]" if hi is not None and lo is not None else (
                f"\\ge {lo:.2f}" if lo is not None else f"\\le {hi:.2f}")
            expect(shown in lines[0], f"Table 1: {case} does not show the window {shown} its order check recorded")
    expect(r"\includegraphics{figures/paper_paper_convergence" in main_tex, "verification.tex has no convergence figure")
    expect(os.access(work / "bundle" / "reproduce.sh", os.X_OK), "reproduce.sh is not executable")
    # Provenance with the tool versions and the bundle's time; the references the issue names.
    expect({"Python", "python3-matplotlib", "libeigen3-dev", "libsundials-dev", "libhdf5-dev", "pdflatex"} <= set(prov.get("tools", {}))
           and prov.get("bundle_time"), f"provenance.json lacks tool versions or the bundle's time: {sorted(prov)}")
    refs = (work / "bundle" / "verification-supplement-references.tex").read_text()
    for key in ("chapter", "toro2009", "sedov1959", "noh1987", "evrard1988", "gresho1990", "mcnally2012", "dehnen2012"):
        expect(f"]{{{key}}}" in refs, f"the supplement's bibliography lacks {key}")
    supp = (work / "bundle" / "verification-supplement.tex").read_text()
    included = re.findall(r"\\includegraphics(?:\[[^]]*\])?\{figures/([^}]*)\}", supp)
    shared = sorted({f for f in included if included.count(f) > 1})
    expect(included and not shared, f"supplement figures sharing a file: {shared}")
    known = sum(r["outcome"] == "known failure" for s in sweeps for r in s["rows"])
    coloured = sum(report_tex.OUTCOME_TEX["known failure"] in line for line in supp.splitlines() if "&" in line)
    expect(coloured == known, f"the supplement's tables colour {coloured} known failures of {known}")
    m = re.search(r"; (\d+) figures\)", res.stdout)
    expect(m and int(m.group(1)) == len(included), f"supplement includes {len(included)} figures of {m and m.group(1)}")
    for key in KEYS:
        for case, label, _, _ in compared_groups(sweeps, key)[0]:
            expect(f"tab:supp-{key}s-{slug(case)}-{slug(label)}" in supp and f"{slug(case)}_{key}s_{slug(label)}".replace(".", "p") in supp,
                   f"the supplement lacks the {key} table or figure of {case} {label}")


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    results, work = Path(args[0]), Path(args[1])
    mutants = args[args.index("--mutants") + 1] if "--mutants" in args else None
    shutil.rmtree(work, ignore_errors=True)
    res = report(results, work, *(["--mutants", mutants] if mutants else []))
    expect(res.returncode == 0, f"report.py exit {res.returncode}")
    expect(res.stderr == "", f"report.py wrote to stderr (warnings?):\n{res.stderr}")
    out = work / "t"

    bad, n_links, n_pages = broken_links(out)
    expect(not bad, "broken links:\n  " + "\n  ".join(bad))
    expect(n_links > 0, "no links at all")

    sweeps = [json.loads(f.read_text()) for f in sorted(results.glob("**/sweep.json"))]
    outcomes = [r["outcome"] for s in sweeps for r in s["rows"]]
    index = (out / "index.html").read_text()
    for name in ("verified", "known failure", "no order claimed", "fail"):
        n = outcomes.count(name)
        label = f"{n} {name}{'s' if name == 'known failure' and n != 1 else ''}"
        expect(re.search(rf">{label}</(span|a)>", index), f"index does not count {label}")
    if "known failure" in outcomes:  # the fixture has one
        expect(re.search(r"<td class='known'>known failure</td>", index), "a known failure row is not shown in its own colour")
    first_screen(index, sweeps, out)
    for s in sweeps:
        page = out / f"case-{slug(s['case'])}.html"
        expect(page.is_file() and f"case-{slug(s['case'])}.html" in index, f"no linked page for {s['case']}")
        text = page.read_text() if page.is_file() else ""
        expect("<p class='claim'>" in text, f"{page.name} does not open with the claim")
        if "<figure>" in text:
            expect(text.index("<figure>") < text.index("<table>"), f"{page.name}: tables before the figures")
        for c in s.get("claims", {}).values():  # each claim's reason once, not once per row or check
            if c.get("why"):
                expect(text.count(html.escape(c["why"], quote=True)) == 1,
                       f"{page.name}: the claim's reason appears {text.count(html.escape(c['why'], quote=True))} times: {c['why']}")
        for c in s["checks"]:
            expect(re.search(rf"<td>{re.escape(c['name'])}</td><td>[^<]*</td><td[^>]*>{c.get('kind', 'verification')}</td>", text),
                   f"{page.name}: check {c['name']} not listed with its kind")
        fig = out / "fig" / slug(s["case"])
        for r in s["rows"]:
            stem = fig / f"{slug(s['variant'])}_{slug(r['error'])}_convergence"
            want = num(r.get("expected")) and len(series(s, r["error"])) >= 2
            for ext in ("png", "pdf"):
                expect(file_of(stem, ext).is_file() == want,
                       f"{s['case']} {s['variant']} {r['error']}: convergence {ext} {'missing' if want else 'drawn without an order claim'}")
            if want:
                expect((fig / f"wall_{slug(r['error'])}.pdf").is_file(), f"{s['case']} {r['error']}: no run-time figure")
                d = s.get("error_defs", {}).get(r["error"])  # the axis shows the name, the caption the definition
                expect(not d or re.search(rf"<figcaption>{re.escape(r['error'])} \({re.escape(html.escape(d, quote=True))}\) against n",
                                          text), f"{page.name}: the {r['error']} convergence caption does not define it")
    for png in out.glob("fig/**/*.png"):
        expect(png.with_name(png.name[:-4] + ".pdf").is_file(), f"{png.name} has no PDF")
    distinct_figures(out, res.stdout)
    for key in KEYS:
        comparison_checks(out, sweeps, key)
    alone_checks(results, work)
    if mutants:
        km = json.loads(Path(mutants).read_text())
        killed = sum(bool(m["killed"]) for m in km["mutants"])
        expect("href='mutants.html'" in index, "index does not link the mutants page")
        text = (out / "mutants.html").read_text() if (out / "mutants.html").is_file() else ""
        expect(f"<b>{killed} of {len(km['mutants'])}</b> killed" in text, "mutants page does not count the kills")

    bundle_checks(results, work, sweeps)
    if "--dirty" in args:  # results recorded as produced from a dirty tree are not bundled
        dirty = work / "dirty"
        shutil.copytree(results, dirty)
        f = next(dirty.glob("**/sweep.json"))
        s = json.loads(f.read_text())
        s["runs"][0]["provenance"]["source_tree"] = {"dirty": True, "changes": [" M sph/kernel/cubic_spline.hpp"]}
        f.write_text(json.dumps(s))
        res = report(dirty, work, "--bundle", str(work / "bundle"))
        expect(res.returncode == 2 and "uncommitted changes" in res.stderr, f"dirty results bundled: exit {res.returncode} {res.stderr}")

    for f in failures:
        print(f"FAIL: {f}")
    if failures:
        sys.exit(1)
    print(f"PASS: report of {len(sweeps)} sweeps, {len(outcomes)} rows, {n_links} links in {n_pages} pages")


if __name__ == "__main__":
    main()
