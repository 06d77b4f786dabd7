#!/usr/bin/env python3
"""Test of the report (ctest report_*): runs report.py on a results folder and checks what a
reader relies on: no warning on stderr, every href and src resolves inside the folder, the
counts at the top match the rows of the sweep.json files, a convergence figure (PNG and PDF)
for every claimed error of every variant and none for errors without an order claim, a
run-time figure per claimed error, every figure entry its own file, the bundle's provenance
(each point's own threads, dates and wall time), the kernel comparison of a case with variants
differing only in `kernel` (its fixed-cost errors recomputed), and with --mutants the kill matrix page. With --dirty it
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


def kernel_groups(sweeps):
    """{(case, shared settings): {kernel: sweep}} of the sweeps that differ only in the setting
    `kernel` (the default variant's kernel from its runs' params), read here without
    report_kernels.py, two kernels or more."""
    found = {}
    for s in sweeps:
        st = dict(x.split("=", 1) for x in s["settings"] if "=" in x)
        k = st.pop("kernel", None) or s["runs"][0].get("params", {}).get("kernel")
        if k:
            found.setdefault((s["case"], ",".join(f"{a}={b}" for a, b in sorted(st.items())) or "default"), {})[k] = s
    return {g: m for g, m in found.items() if len(m) >= 2}


def kernel_checks(out, sweeps):
    """Each case with kernel variants shows one kernel comparison per group (figure, then a table
    with a row per kernel and error); the error at the fixed cost is each kernel's, interpolated
    log-log on its error-against-wall-time curve at the cheapest curve's end, recomputed here;
    a case without kernel variants shows none."""
    groups = kernel_groups(sweeps)
    with_kernels = {case for case, _ in groups}
    expect(with_kernels or not any("kernel=" in x for s in sweeps for x in s["settings"]), "kernel variants found no group")
    index = (out / "index.html").read_text()
    for case in {s["case"] for s in sweeps}:
        text = (out / f"case-{slug(case)}.html").read_text()
        expect(("id='kernels'" in text) == (case in with_kernels), f"{case}: kernel comparison shown {'id=' in text}, expected {case in with_kernels}")
        expect((f"case-{slug(case)}.html#kernels" in index) == (case in with_kernels), f"index: kernel link of {case}")
    for (case, label), members in groups.items():
        text = (out / f"case-{slug(case)}.html").read_text()
        section = text[text.find("id='kernels'"):text.find("<h2>Outcome per error</h2>")]
        stem = out / "fig" / slug(case) / f"kernels_{slug(label)}"
        expect(file_of(stem, "png").is_file() and file_of(stem, "pdf").is_file(), f"{case} {label}: no kernel figure")
        expect(section.find("<figure>") < section.find("<table>"), f"{case}: the kernel table before its figure")
        for err in [r["error"] for r in next(iter(members.values()))["rows"]]:
            curves = {}
            for k, s in members.items():
                curves[k] = sorted((r["wall_time_s"], r["errors"][err], n) for n, r in zip(s["levels"], s["runs"]) if err in r["errors"])
            cost = min(c[-1][0] for c in curves.values())
            for k, c in curves.items():
                want = None
                for (t0, y0, _), (t1, y1, _) in zip(c, c[1:]):
                    if t0 <= cost <= t1:
                        want = math.exp(math.log(y0) + (math.log(y1) - math.log(y0)) * math.log(cost / t0) / math.log(t1 / t0))
                        break
                row = re.search(rf"<td class='nw'>{re.escape(k)}</td>(.*?)</tr>", section)
                cells = re.findall(r"<td class='num'>(?:<b>)?([^<]*)", row.group(1)) if row else []
                expect(want is not None and len(cells) >= 3 and abs(float(cells[2]) / want - 1) < 1e-3,
                       f"{case} {label} {err} {k}: error at fixed cost {cells[2:3]}, recomputed {want}")


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
            lo, hi = report_paper.window(default, row)
            expect(f"[{lo:.2f}, {hi:.2f}]" in lines[0], f"Table 1: {case} does not show the window [{lo:.2f}, {hi:.2f}] its order check recorded")
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
    for case, label in kernel_groups(sweeps):
        expect(f"tab:supp-kernels-{slug(case)}-{slug(label)}" in supp and f"{slug(case)}_kernels_{slug(label)}".replace(".", "p") in supp,
               f"the supplement lacks the kernel table or figure of {case} {label}")


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
    kernel_checks(out, sweeps)
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
