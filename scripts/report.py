#!/usr/bin/env python3
"""Turns a folder of sphv results into a report a reader can use: reports/<name>/index.html (the
summary: per case and variant each error's outcome), one page per case (the claim, every check
labelled verification or drift, figures, the files behind every point) and, when a kill matrix
exists, a page on the mutation tests. Every figure is PNG and vector PDF; each point's
result.json, log and particle CSV are copied (or hard-linked) under data/, so the folder can be
moved as a whole.

usage: report.py RESULTS_DIR [--name NAME] [--reports DIR] [--mutants FILE]
                 [--bundle DIR [--allow-dirty] [--with-runs] [--source-repo DIR | --source-archive FILE]]
RESULTS_DIR holds summary.json and CASE/[VARIANT/]sweep.json as `sphv verify --out` writes them,
or the sweep.json files of `sphv sweep`, or bench.json of `sphv bench` (a benchmark page). --bundle also writes a publication bundle
(report_tex.py); the report written with it links no point files (the bundle's results.tar.gz holds their numbers)."""
import argparse
import html
import os
import shutil
import sys
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from urllib.parse import quote

sys.path.insert(0, str(Path(__file__).resolve().parent))
import report_figures as figs  # noqa: E402
import report_compare  # noqa: E402
from report_data import (OUTCOMES, claim_notes, claim_order_text, counts, errors_of, expected_text, file_of, fmt,  # noqa: E402
                         is_dirty, load, num, order_text, provenances, read_json, row_note, row_reason, slug, sweep_wide_failures, threads_text, variant_named)

ROOT = Path(__file__).resolve().parent.parent
CSS = """body{font-family:sans-serif;max-width:1250px;margin:auto;padding:0 12px;line-height:1.35}
table{border-collapse:collapse;margin:8px 0}td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px;vertical-align:top}
th{background:#f2f2f2;text-align:left}td.num{text-align:right;white-space:nowrap}td.nw{white-space:nowrap}td.var{overflow-wrap:anywhere;max-width:160px}tr.first td{border-top:2px solid #888}
.verified{color:#060}.known{color:#80269a}.noclaim{color:#845b00}.provisional{color:#a05000;font-style:italic}.fail{color:#b00;font-weight:bold}.drift{color:#666}
p.verdict{font-size:22px;font-weight:bold;margin:6px 0}p.verdict.pass{color:#060}p.verdict.fail{color:#b00}
ul.claims{font-size:14px}ul.claims li{margin:3px 0}
.counts span{display:inline-block;margin-right:18px;font-size:18px}.why{font-size:12px;color:#333;min-width:200px;max-width:400px}
div.figs{display:flex;flex-wrap:wrap;gap:8px}figure{margin:0;width:600px}div.wide figure{width:1200px}figcaption{font-size:12px}
img{max-width:100%;border:1px solid #ddd}.prov{font-size:12px;color:#333}p.claim{font-size:15px;background:#f6f8fa;padding:8px}"""
CLS = {"verified": "verified", "known failure": "known", "provisional": "provisional", "no order claimed": "noclaim",
       "fail": "fail"}


def e(text):
    return html.escape(str(text), quote=True)


def page(title, body):
    return (f"<!doctype html><html><head><meta charset='utf-8'><title>{e(title)}</title><style>{CSS}</style>"
            f"</head><body>{body}</body></html>\n")


LABEL = {"verified": "verified", "known failure": "known failures", "provisional": "provisional",
         "no order claimed": "no order claimed", "fail": "fail"}


def outcome_count(c, outcome):
    """'3 verified', '1 known failure', '2 known failures'."""
    n = c.get(outcome, 0)
    return f"{n} {LABEL[outcome] if n != 1 or outcome != 'known failure' else outcome}"


def outcome_cell(outcome):
    return f"<td class='{CLS.get(outcome, 'fail')}'>{e(outcome)}</td>"


def order_cell(row):
    """The observed order; greyed where no order is claimed (shown for information, not judged)."""
    if num(row.get("expected")):
        return f"<td class='num'>{e(order_text(row))}</td>"
    return f"<td class='num drift' title='no order claimed: the fit is shown for information only'>{e(order_text(row))}</td>"


def case_page_name(case):
    return f"case-{slug(case)}.html"


def variant_anchor(s):
    return f"v-{slug(s['variant'])}"


def figures_anchor(variant):
    """The anchor of a variant's figures on its case page."""
    return f"fig-{slug(variant)}"


def figure_anchor(s, error):
    """The anchor of one error's convergence figure on its case page."""
    return f"fig-{slug(s['variant'])}-{slug(error)}"


def link_file(src, dst):
    """Hard link (no copy of large particle files) where the file system allows, else a copy."""
    dst.parent.mkdir(parents=True, exist_ok=True)
    try:
        os.link(src, dst)
    except OSError:
        shutil.copy2(src, dst)


def point_files(results, out, s, copy=True):
    """Copies what stands behind each point into out/data and returns, per level, the links; with
    copy False (the publication bundle: the points' numbers are in its results.tar.gz) none."""
    if not copy:
        return [[] for _ in s["levels"]]
    links = []
    for n in s["levels"]:
        src = results / s["_dir"] / f"n{n}"
        have = []
        for name in ("result.json", "particles.csv", "log.txt"):
            if (src / name).is_file():
                rel = Path("data") / s["_dir"] / f"n{n}" / name
                link_file(src / name, out / rel)
                have.append((name, rel.as_posix()))
        links.append(have)
    if (results / s["_dir"] / "sweep.json").is_file():
        link_file(results / s["_dir"] / "sweep.json", out / "data" / s["_dir"] / "sweep.json")
    return links


def provenance_html(sweeps, tier):
    provs = provenances(sweeps)
    keys = ["git_commit", "build_type", "compiler", "cxx_flags", "isa_path", "host", "cpu", "cores"]
    parts = [f"<b>tier</b> {e(tier)}"]
    for k in keys:
        vals = sorted({str(p.get(k)) for p in provs if k in p})
        if vals:
            parts.append(f"<b>{e(k)}</b> {e(' | '.join(vals))}" + (" <span class='fail'>(mixed)</span>" if len(vals) > 1 else ""))
    threads = sorted({p["threads"] for p in provs if num(p.get("threads"))})
    if threads:  # points run on different counts by design (sphv verify gives long ones every core)
        parts.append(f"<b>threads per point</b> {threads[0]}" + (f" to {threads[-1]} (each run's count: case pages)" if len(threads) > 1 else ""))
    dirty = sum(is_dirty(p) for p in provs)
    parts.append(f"<b>tree</b> <span class='fail'>dirty in {dirty} of {len(provs)} runs</span>" if dirty else
                 "<b>tree</b> clean (no run records uncommitted changes)")
    dates = sorted(str(p["date"]) for p in provs if "date" in p)
    if dates:
        parts.append(f"<b>run</b> {e(dates[0])} to {e(dates[-1])}")
    return "<p class='prov'>" + "; ".join(parts) + ".</p>"


def summary_table(sweeps, missing):
    t = ["<table><tr><th>case</th><th>variant</th><th>error</th><th>finest n</th><th>error at finest n</th>"
         "<th>observed order ± s.e.</th><th>claim [window]</th><th>outcome</th><th>reason</th><th>sweep wall s</th></tr>"]
    for case, ss in sorted(sweeps.items()):
        for s in ss:
            href = f"{case_page_name(case)}#{variant_anchor(s)}"
            rows = s["rows"] or [None]
            wide = sweep_wide_failures(s)
            for k, row in enumerate(rows):
                head = (f"<td class='nw'><a href='{e(href)}'>{e(case)}</a></td><td class='var'>{e(s['variant'])}</td>" if k == 0 else "<td></td><td></td>")
                tail = f"<td class='num'>{fmt(s.get('wall_time_s'), '.2f')}</td>" if k == 0 else "<td></td>"
                first = " class='first'" if k == 0 else ""
                if row is None:
                    t.append(f"<tr{first}>{head}<td colspan=5>no error rows (checks only)</td>"
                             f"<td class='{'fail' if not s['passed'] else ''}'>{'fail' if not s['passed'] else 'pass'}</td>"
                             f"<td class='why'>{e('failed: ' + ', '.join(wide)) if wide else ''}</td>{tail}</tr>")
                    continue
                reason = row_reason(s, row)
                if k == 0 and wide:
                    reason += "; sweep-wide failed: " + ", ".join(wide)
                t.append(f"<tr{first}>{head}<td class='nw'>{e(row['error'])}</td><td class='num'>{s['levels'][-1] if s['levels'] else '–'}</td>"
                         f"<td class='num'>{fmt(row.get('fine_value'))}</td>{order_cell(row)}"
                         f"<td class='num'>{e(expected_text(row))}</td>{outcome_cell(row['outcome'])}"
                         f"<td class='why'>{e(reason)}</td>{tail}</tr>")
    for m in missing:
        t.append(f"<tr class='first'><td>{e(m['case'])}</td><td>{e(m['variant'])}</td><td colspan=5>in summary.json but no "
                 f"sweep.json was written</td><td class='fail'>fail</td><td></td><td class='num'>{fmt(m.get('wall_time_s'), '.2f')}</td></tr>")
    return "".join(t) + "</table>"


def counts_html(c, fail_href=None):
    """The summary line: each outcome's count in its colour; the failures link to their rows."""
    fail = f"{c['fail']} fail"
    if fail_href and c["fail"]:
        fail = f"<a class='fail' href='{fail_href}'>{fail}</a>"
    return ("<p class='counts'>" + "".join(f"<span class='{CLS[k]}'>{outcome_count(c, k)}</span>" for k in OUTCOMES[:-1])
            + f"<span class='fail'>{fail}</span></p>")


def failing_rows(sweeps, missing, drawn=frozenset()):
    """Every failure, with a link to its variant: failing error rows (to the error's convergence
    figure where one is drawn: drawn holds (case, variant, error)), sweep-wide failures of a sweep
    with no failing row, and summary.json entries without a sweep.json."""
    t = []
    for case, ss in sorted(sweeps.items()):
        for s in ss:
            href = e(f"{case_page_name(case)}#{variant_anchor(s)}")
            link = f"<td class='nw'><a href='{href}'>{e(case)}</a></td><td class='var'><a href='{href}'>{e(s['variant'])}</a></td>"
            bad = [r for r in s["rows"] if r["outcome"] == "fail"]
            for r in bad:
                fig = (f"<a href='{e(case_page_name(case) + '#' + figure_anchor(s, r['error']))}'>{e(r['error'])}</a>"
                       if (case, s["variant"], r["error"]) in drawn else e(r["error"]))
                t.append(f"<tr>{link}<td class='nw'>{fig}</td><td class='num'>{fmt(r.get('fine_value'))}</td>{order_cell(r)}"
                         f"<td class='num'>{e(expected_text(r))}</td><td class='why'>{e(row_reason(s, r))}</td></tr>")
            if not s["passed"] and not bad:
                wide = sweep_wide_failures(s)
                t.append(f"<tr>{link}<td>(whole sweep)</td><td colspan=3></td><td class='why'>"
                         f"{e('failed: ' + ', '.join(wide)) if wide else 'failed (see the case page)'}</td></tr>")
    for m in missing:
        t.append(f"<tr><td>{e(m['case'])}</td><td>{e(m['variant'])}</td><td colspan=4></td>"
                 f"<td class='why'>in summary.json but no sweep.json was written</td></tr>")
    if not t:
        return ""
    return ("<h2 id='failing'>Failing</h2><table><tr><th>case</th><th>variant</th><th>error</th><th>error at finest n</th>"
            "<th>observed order ± s.e.</th><th>claim [window]</th><th>reason</th></tr>" + "".join(t) + "</table>")


def cases_table(sweeps, missing):
    """One line per case: its variants, each outcome's count and its run time, linking its page."""
    t = ["<h2 id='cases'>Cases</h2><table><tr><th>case</th><th>variants</th>" + "".join(
        f"<th class='{CLS[k]}'>{e(LABEL[k])}</th>" for k in OUTCOMES) + "<th>run time s</th></tr>"]
    for case, ss in sorted(sweeps.items()):
        c = {k: sum(r["outcome"] == k for s in ss for r in s["rows"]) for k in OUTCOMES}
        failed = sum(not s["passed"] for s in ss) + sum(m["case"] == case for m in missing)
        t.append(f"<tr><td class='nw'><a href='{e(case_page_name(case))}'>{e(case)}</a></td><td class='num'>{len(ss)}"
                 + (f" (<span class='fail'>{failed} failing</span>)" if failed else "") + "</td>"
                 + (checks_only_cell(ss, len(OUTCOMES)) if not any(s["rows"] for s in ss) else
                    "".join(f"<td class='num{' ' + CLS[k] if c[k] and k in ('fail', 'known failure', 'provisional') else ''}'>{c[k]}</td>" for k in OUTCOMES))
                 + f"<td class='num'>{sum(s.get('wall_time_s', 0) for s in ss):.1f}</td></tr>")
    for case in sorted({m["case"] for m in missing} - set(sweeps)):
        t.append(f"<tr><td>{e(case)}</td><td class='num'><span class='fail'>no sweep.json</span></td>"
                 + "<td></td>" * len(OUTCOMES) + "<td></td></tr>")
    return "".join(t) + "</table>"


def checks_only_cell(ss, span):
    """A case with no error rows (a stability map) by its verification checks, not by zero counts."""
    checks = [c for s in ss for c in s["checks"] if c.get("kind", "verification") != "drift"]
    ok = sum(c["pass"] for c in checks)
    return (f"<td colspan={span} class='{'verified' if ok == len(checks) else 'fail'}'>checks only: {ok} of {len(checks)} "
            "verification checks pass</td>")


def comparison_links(sweeps):
    """Per parameter compared (report_compare.py), a line linking each case page's comparison in
    it, where a case has one."""
    lines = []
    for key in report_compare.PARAMETERS:
        cases = [case for case, ss in sorted(sweeps.items()) if report_compare.groups(ss, key)]
        if cases:
            lines.append(f"<p id='{key}-comparisons'>{e(key.capitalize())} comparisons (error at fixed n and at fixed cost, "
                         f"order and wall time per {e(key)}): "
                         + ", ".join(f"<a href='{e(case_page_name(c))}#{e(key)}s'>{e(c)}</a>" for c in cases) + ".</p>")
    return "".join(lines)


def index_page(name, sweeps, missing, tier, mutants_link, drawn=frozenset()):
    c = counts(sweeps)
    n_sweeps = sum(len(ss) for ss in sweeps.values()) + len(missing)
    failing = sum(not s["passed"] for ss in sweeps.values() for s in ss) + len(missing)
    wall = sum(s.get("wall_time_s", 0) for ss in sweeps.values() for s in ss)
    verdict = (f"<p class='verdict fail'>FAIL: {failing} of {n_sweeps} case variants fail (<a href='#failing'>the failing rows</a>)</p>"
               if failing else f"<p class='verdict pass'>PASS: all {n_sweeps} case variants pass</p>")
    body = [f"<h1>sphv verification report: {e(name)}</h1>", verdict, counts_html(c, "#failing"),
            failing_rows(sweeps, missing, drawn), cases_table(sweeps, missing), comparison_links(sweeps),
            f"<p>{len(sweeps)} cases, {n_sweeps} case variants, summed run time {wall:.1f} s. Each count is of errors of a case "
            "variant at its finest level. <b class='verified'>verified</b>: the observed order lies in the claim's window "
            "(expected ± band, the band at most 0.3 unless derived from theory, the lower edge above half the claimed order; "
            "or \u201cat least p\u201d where theory gives only a bound), never widened by the fit's standard error, which "
            "must be at most half the band; the local order of the two finest levels lies within the window ± 0.25; and the "
            "error is under its bound (a drift baseline, the code's own earlier output, is labelled as one); "
            "<b class='known'>known failure</b>: the error misses its claimed order for a reason the case states, and the "
            "variant the case names as its experiment verifies the same error; <b class='provisional'>provisional</b>: "
            "inside the former window, expected ± (band + 2 s.e.), but not the acceptance rule's (the row names the parts "
            "it fails): not verified, and listed until its levels, its claim or its experiment are settled; <b class='noclaim'>no order claimed</b>: the case says why, and its other checks pass; "
            "<b class='fail'>fail</b>: a check on that error failed. Click a case for its claim, figures and every check.</p>",
            provenance_html(sweeps, tier)]
    if mutants_link:
        body.append(f"<p><a href='{mutants_link}'>Mutation testing: which seeded faults the gates catch</a></p>")
    body.append("<h2 id='all'>Every error of every variant</h2>" + summary_table(sweeps, missing))
    return page(f"sphv report: {name}", "".join(body))


def claim_sentence(case, ss):
    s = ss[0]
    claimed = [f"{e(r['error'])} converges at "
               + claim_order_text(s.get("claims", {}).get(r["error"]) or {"expected": r["expected"], "band": r.get("band", 0)})
               for r in s["rows"] if num(r.get("expected"))]
    no_claim = [r["error"] for r in s["rows"] if not num(r.get("expected"))]
    text = f"<b>{e(case)}</b>: {e(s.get('summary', ''))}. "
    if claimed:
        text += f"Claim ({e(s['variant'])} variant): " + ", ".join(claimed) + f" in n ({e(s.get('n_counts', ''))}), each under its bound"
        text += f"; no order claimed for {e(', '.join(no_claim))}." if no_claim else "."
    elif no_claim:
        text += f"No order is claimed ({e(', '.join(no_claim))}): the checks bound the errors themselves."
    c = {k: sum(r["outcome"] == k for s in ss for r in s["rows"]) for k in OUTCOMES}
    if any(s["rows"] for s in ss):
        text += f" Over {len(ss)} variant{'s' if len(ss) > 1 else ''}: " + ", ".join(outcome_count(c, k) for k in OUTCOMES) + "."
    else:  # a stability map: no error rows, its checks are the result
        checks = [ch for s in ss for ch in s["checks"] if ch.get("kind", "verification") != "drift"]
        text += (f" Checks only (no error carries an order): {sum(ch['pass'] for ch in checks)} of {len(checks)} verification "
                 f"checks pass over {len(ss)} variant{'s' if len(ss) > 1 else ''} (<a href='#checks'>the checks</a>).")
    notes = claim_notes(ss)
    claims = ("<ul class='claims'>" + "".join(
        f"<li><span class='{'known' if 'known failure' in claimed else ''}'>{e(claimed)}</span>: {e(why)}</li>"
        for claimed, why in notes) + "</ul>") if notes else ""
    return f"<p class='claim'>{text}</p>{claims}"


def check_rows(s, checks):
    claimed = {c.get("why") for c in s.get("claims", {}).values()} - {None, ""}
    return "".join(
        f"<tr><td>{e(c['name'])}</td><td>{e(c.get('error') or '(whole sweep)')}</td>"
        f"<td class='{'drift' if c.get('kind') == 'drift' else ''}'>{e(c.get('kind', 'verification'))}</td>"
        f"<td class='num'>{fmt(c.get('value'), '.4g')}</td><td class='num'>[{fmt(c.get('lo'), '.4g')}, {fmt(c.get('hi'), '.4g')}]</td>"
        f"<td class='{'verified' if c['pass'] else 'fail'}'>{'pass' if c['pass'] else 'FAIL'}</td><td class='why'>{e(c.get('why', '')) if c.get('why') not in claimed else '<i>the claim&#39;s reason (above)</i>'}</td></tr>"
        for c in checks)


def definition(ss, error):
    """' (the definition)' of an error for a caption (its axis shows only the name)."""
    text = next((s["error_defs"][error] for s in ss if error in s.get("error_defs", {})), "")
    return f" ({text})" if text else ""


def figure_html(out, stem, caption, anchor=None, extra=""):
    """A figure with its caption (plain text, escaped here) and extra, HTML appended to it."""
    png, pdf = (quote(file_of(stem, x).relative_to(out).as_posix()) for x in ("png", "pdf"))
    ident = f" id='{e(anchor)}'" if anchor else ""
    return (f"<figure{ident}><a href='{e(png)}'><img src='{e(png)}' alt='{e(caption)}'></a>"
            f"<figcaption>{e(caption)}{extra} (<a href='{e(pdf)}'>PDF</a>)</figcaption></figure>")


def comparison_section(case, ss, key, out, figdir, made):
    """Per group of variants compared in the parameter key (report_compare.py): what the others
    change against the first, whether the group is like for like, its figure (error against n and
    against wall time, per value), then its table; "" when the case has none."""
    parts = []
    for g in report_compare.groups(ss, key):
        errs = report_compare.errors(g.members)
        anchor = f"{key}s-{slug(g.label)}"
        parts.append(f"<h3 id='{e(anchor)}'>{e(report_compare.title(g))}</h3>"
                     f"<p>{e(report_compare.unlike_text(g))} " + " ".join(report_compare.effects(g, e, e)) + "</p>")
        stem = figs.comparison(g.members, errs, figdir / f"{key}s_{slug(g.label)}")
        if stem:
            made.append((case, None, g.label, f"{key}s", stem))
            parts.append("<div class='figs wide'>" + figure_html(out, stem, comparison_caption(case, g)) + "</div>")
        t = [f"<table><tr><th>error</th><th>{e(key)}</th><th>variant</th><th>levels n</th><th>error at fixed n</th><th>wall s at fixed n</th>"
             "<th>error at fixed cost</th><th>observed ± s.e.</th><th>claim [window]</th><th>outcome</th></tr>"]
        for err in errs:
            n_fixed, t_fixed, rows = report_compare.comparison(g.members, err)
            best = {k: min((r[k] for r in rows if num(r[k])), default=None) for k in ("at_n", "at_cost")}
            cell = lambda r, k: (f"<td class='num'>{'<b>' if r[k] == best[k] and num(r[k]) else ''}{fmt(r[k], '.3e')}"  # noqa: E731
                                 f"{'</b>' if r[k] == best[k] and num(r[k]) else ''}</td>")
            for j, r in enumerate(rows):
                head = (f"<td rowspan={len(rows)}>{e(err)}<br><span class='prov'>fixed n = {fmt(n_fixed, 'g')}, "
                        f"fixed cost {fmt(t_fixed, '.3g')} s</span></td>") if j == 0 else ""
                t.append(f"<tr{' class=first' if j == 0 else ''}>{head}<td class='nw'>{e(r['value'])}</td><td class='var'>{e(r['variant'])}</td>"
                         f"<td>{e(', '.join(map(str, r['levels'])))}</td>{cell(r, 'at_n')}<td class='num'>{fmt(r['wall_at_n'], '.3g')}</td>"
                         f"{cell(r, 'at_cost')}{order_cell(r)}<td class='num'>{e(expected_text(r))}</td>{outcome_cell(r['outcome'])}</tr>")
        parts.append("".join(t) + "</table>")
    lone = report_compare.alone_text(ss, key)
    if lone:
        parts.append(f"<p>{e(lone)}</p>")
    if not parts:
        return ""
    return (f"<h2 id='{e(key)}s'>{e(key.capitalize())} comparison</h2><p>Variants compared in the parameter <code>{e(key)}</code>: "
            f"those whose settings are the same but for the {e(key)} (like for like); a variant setting the {e(key)} with no such "
            f"sibling is compared with the sweep of another {e(key)} whose parameters differ least, and the group names "
            "what differs. Per error: the error at a fixed resolution (the finest n every member ran) with its wall time; at a "
            "fixed cost (each member's error interpolated, linearly in log error against log wall time, between the two runs "
            "that bracket the largest wall time every member's sweep reached); the observed order of the sweep and its "
            "outcome. The lowest error at fixed n and at fixed cost in bold; the ratios in each group's sentence are to its "
            "first member's. Wall times are single measurements of each run "
            f"(on {e(threads_text(r for s in ss for r in s['runs']))}) and carry the machine's noise.</p>" + "".join(parts))


def comparison_caption(case, g):
    return (f"{case} [{report_compare.title(g)}]: every error of each {g.key} against n (top) and against "
            "the wall time of each run (bottom); dotted: the fixed resolution and the fixed cost of the table")


def case_page(case, ss, results, out, made, copy=True):
    figdir = out / "fig" / slug(case)
    body = ["<p><a href='index.html'>&larr; summary of all cases</a></p>", f"<h1>{e(case)}</h1>", claim_sentence(case, ss)]
    # Profiles and convergence first, then error against run time, then the comparisons (kernel, scheme).
    body.append("<h2>Figures</h2><p>Per variant its profiles (finest run) and the convergence of each error with an order "
                "claim; errors without one are tabulated per level. Then each error against run time and the "
                "comparisons of kernels and schemes. Each figure links its vector PDF.</p>")
    for s in ss:
        v = slug(s["variant"])
        body.append(f"<h3 id='{figures_anchor(s['variant'])}'>{e(s['variant'])}</h3><div class='figs'>")
        if s["runs"]:
            for f in s["runs"][-1].get("figures", []):
                stem = figs.run_figure(f, figdir / f"{v}_run_{slug(f['name'])}")
                if stem:
                    made.append((case, s, f["name"], "run", stem))
                    body.append(figure_html(out, stem, f"{f['title']} (finest run, n = {s['levels'][-1]})"))
        for row in s["rows"]:
            stem = figs.convergence(case, s, row, figdir / f"{v}_{slug(row['error'])}_convergence") if num(row.get("expected")) else None
            if stem:
                made.append((case, s, row["error"], "convergence", stem))
                exp = (row.get("experiment") or s.get("claims", {}).get(row["error"], {}).get("experiment")
                       if row["outcome"] == "known failure" else None)
                target = variant_named(ss, exp, besides=s) if exp else None
                link = (f" <a href='#{e(figures_anchor(target['variant']))}'>converges instead: {e(exp)}</a>" if target else
                        f" (converges instead: {e(exp)})" if exp else "")
                body.append(figure_html(out, stem, f"{row['error']}{definition([s], row['error'])} against n "
                                                   f"({s.get('n_counts', 'resolution')}), {s['variant']}: {row['outcome']}",
                                        anchor=figure_anchor(s, row["error"]), extra=link))
        body.append("</div>")
        unclaimed = [err for err in errors_of(s) if not any(r["error"] == err and num(r.get("expected")) for r in s["rows"])]
        if unclaimed:
            body.append("<table><tr><th>error (no order claimed)</th>" + "".join(f"<th>n = {n}</th>" for n in s["levels"]) + "</tr>")
            for err in unclaimed:
                body.append(f"<tr><td>{e(err)}</td>" + "".join(f"<td class='num'>{fmt(r.get('errors', {}).get(err), '.3e')}</td>"
                                                            for r in s["runs"]) + "</tr>")
            body.append("</table>")

    claimed = [n for n in dict.fromkeys(r["error"] for s in ss for r in s["rows"] if num(r.get("expected")))]
    walls = []
    for err in claimed:
        stem = figs.wall_time(case, ss, err, figdir / f"wall_{slug(err)}")
        if stem:
            made.append((case, None, err, "wall", stem))
            walls.append(figure_html(out, stem, f"{err}{definition(ss, err)} against the wall time of each run, every variant; "
                                                  f"runs on {threads_text(r for s in ss for r in s['runs'])}"))
    if walls:
        body.append("<h3>Error against run time</h3><div class='figs'>" + "".join(walls) + "</div>")
    body += [comparison_section(case, ss, key, out, figdir, made) for key in report_compare.PARAMETERS]

    defs = {}
    for s in ss:
        for k, v in s.get("error_defs", {}).items():
            defs.setdefault(k, v)
    if defs:
        body.append("<table><tr><th>error</th><th>definition</th></tr>" +
                    "".join(f"<tr><td>{e(k)}</td><td>{e(v)}</td></tr>" for k, v in defs.items()) + "</table>")
    tier = ss[0].get("tier") or "none (levels given on the command line)"
    body.append(f"<p>n: {e(ss[0].get('n_counts', ''))}. Tier: {e(tier)}.</p>")

    body.append("<h2>Outcome per error</h2><table><tr><th>variant</th><th>error</th><th>levels n</th><th>error at finest n</th>"
                "<th>observed ± s.e.</th><th>claim [window]</th><th>outcome</th><th>what it rests on (beyond the claim above)</th></tr>")
    for s in ss:
        for k, row in enumerate(s["rows"]):
            body.append(f"<tr{' class=first' if k == 0 else ''}><td>{e(s['variant']) if k == 0 else ''}</td><td>{e(row['error'])}</td>"
                        f"<td>{e(', '.join(map(str, s['levels'])))}</td><td class='num'>{fmt(row.get('fine_value'))}</td>"
                        f"{order_cell(row)}<td class='num'>{e(expected_text(row))}</td>{outcome_cell(row['outcome'])}"
                        f"<td class='why'>{e(row_note(s, row))}</td></tr>")
    body.append("</table>")

    body.append("<h2 id='checks'>Every check</h2><p><b>verification</b>: against an independent reference (analytic solution, exact "
                "solver, SUNDIALS, direct sum, published table). <b>drift</b>: against the code's own earlier output "
                "(reference/baselines), which only shows that nothing changed.</p>")
    head = "<tr><th>check</th><th>error</th><th>kind</th><th>value</th><th>allowed</th><th></th><th>why</th></tr>"
    for s in ss:
        ver = [c for c in s["checks"] if c.get("kind", "verification") != "drift"]
        drift = [c for c in s["checks"] if c.get("kind") == "drift"]
        bad_rows = [r["error"] for r in s["rows"] if r["outcome"] == "fail"]
        status = "passed" if s["passed"] else "<span class=fail>FAILED</span>" + (
            f" (failing errors: {e(', '.join(bad_rows))}; see the outcome table)" if bad_rows else "")
        body.append(f"<h3 id='{variant_anchor(s)}'>{e(s['variant'])}: {status}</h3>")
        body.append(f"<table>{head}{check_rows(s, ver)}</table>" if ver else "<p>No verification check.</p>")
        if drift:
            bad = sum(not c["pass"] for c in drift)
            body.append(f"<details{' open' if bad else ''}><summary>{len(drift)} drift checks, {bad} failing</summary>"
                        f"<table>{head}{check_rows(s, drift)}</table></details>")
        if s.get("gci"):
            body.append("<p>Roache's grid convergence index of the finest pair:</p><table><tr><th>functional</th><th>value</th>"
                        "<th>order used</th><th>F<sub>s</sub></th><th>GCI (relative)</th></tr>" +
                        "".join(f"<tr><td>{e(k)}</td><td class='num'>{fmt(g.get('fine_value'), '.6g')}</td>"
                                f"<td class='num'>{fmt(g.get('order'), '.2f')}</td><td class='num'>{fmt(g.get('Fs'), 'g')}</td>"
                                f"<td class='num'>{fmt(g.get('gci'), '.2e')}</td></tr>" for k, g in s["gci"].items()) + "</table>")

    body.append("<h2>Runs and their files</h2><table><tr><th>variant</th><th>n</th><th>particles</th><th>wall s</th>"
                "<th>threads</th><th>verdict</th><th>files</th></tr>")
    for s in ss:
        links = point_files(results, out, s, copy)
        for n, run, have in zip(s["levels"], s["runs"], links):
            files = " ".join(f"<a href='{e(quote(rel))}'>{e(name)}</a>" for name, rel in have) or (
                "(not kept)" if copy else "in the bundle's results.tar.gz (sweep.json) and, made --with-runs, runs.tar.xz")
            body.append(f"<tr><td>{e(s['variant'])}</td><td class='num'>{n}</td><td class='num'>{run.get('n_particles', '–')}</td>"
                        f"<td class='num'>{fmt(run.get('wall_time_s'), '.3g')}</td><td class='num'>{run.get('provenance', {}).get('threads', '–')}</td>"
                        f"<td>{e(run.get('verdict', ''))}</td><td>{files}</td></tr>")
    body.append("</table>")
    return page(f"sphv: {case}", "".join(body))


def write_case_page(job):
    case, ss, results, out, copy = job
    made = []
    (out / case_page_name(case)).write_text(case_page(case, ss, results, out, made, copy))
    return made


def mutants_page(km):
    ms = km.get("mutants", [])
    killed = sum(bool(m.get("killed")) for m in ms)
    by_ver = sum(bool(m.get("by_verification")) for m in ms)
    body = ["<p><a href='index.html'>&larr; summary of all cases</a></p><h1>Mutation testing</h1>",
            f"<p>Each mutant is a realistic fault applied to a copy of the code; the gates ran against it. "
            f"<b>{killed} of {len(ms)}</b> killed, <b>{by_ver}</b> of them by a verification check (not only a drift "
            f"baseline); {len(ms) - killed} survived. {'Quick subset. ' if km.get('quick') else ''}"
            f"Each row names the commit the fault was applied to. "
            f"Total wall time {fmt(km.get('total_wall_time_s'), '.0f')} s.</p>",
            "<table><tr><th>mutant</th><th>area</th><th>fault</th><th>outcome</th><th>first failed checks (case / variant: check, kind)</th>"
            "<th>failed tests</th><th>commit</th><th>wall s</th></tr>"]
    for m in ms:
        state = (f"not run: {m['error']}", "fail") if m.get("error") else \
                ("killed by verification", "verified") if m.get("by_verification") else \
                ("killed by drift only", "noclaim") if m.get("killed") else ("SURVIVED", "fail")
        checks = "<br>".join(f"{e(c.get('case'))} / {e(c.get('variant'))}: {e(c.get('check'))} "
                             f"<span class='{'drift' if c.get('kind') == 'drift' else ''}'>({e(c.get('kind'))})</span>"
                             for c in m.get("failed_checks", []))
        body.append(f"<tr><td>{e(m.get('id'))}</td><td>{e(m.get('area'))}</td><td class='why'>{e(m.get('description'))}</td>"
                    f"<td class='{state[1]}'>{state[0]}</td><td class='why'>{checks}</td>"
                    f"<td class='why'>{e(', '.join(map(str, m.get('failed_tests', []))))}</td>"
                    f"<td>{e(m.get('commit', ''))}</td><td class='num'>{fmt(m.get('wall_time_s'), '.0f')}</td></tr>")
    body.append("</table>")
    return page("sphv: mutation testing", "".join(body))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results", type=Path)
    ap.add_argument("--name", default="verify")
    ap.add_argument("--reports", type=Path, default=ROOT / "reports")
    ap.add_argument("--mutants", type=Path, help="kill matrix (default runs/mutants/kill_matrix.json if it exists)")
    ap.add_argument("--bundle", type=Path, help="also write a publication bundle to this folder")
    ap.add_argument("--allow-dirty", action="store_true", help="bundle results whose provenance records uncommitted changes")
    ap.add_argument("--with-runs", action="store_true", help="the bundle also carries every point's files (runs.tar.xz)")
    ap.add_argument("--source-repo", type=Path, default=ROOT, help="the git repository the bundle's source.tar.gz is archived from")
    ap.add_argument("--source-archive", type=Path, help="the bundle's source.tar.gz as it is (reproduce.sh: the archive it built from)")
    a = ap.parse_args()
    if not a.results.is_dir():
        print(f"report.py: error: {a.results} is not a directory", file=sys.stderr)
        sys.exit(2)
    out = a.reports / a.name
    if (a.results / "bench.json").is_file() and not any(a.results.glob("**/sweep.json")):  # scripts/bench.sh
        import report_bench
        shutil.rmtree(out / "fig", ignore_errors=True)
        out.mkdir(parents=True, exist_ok=True)
        (out / "index.html").write_text(page("sphv benchmarks", report_bench.bench_body(a.results, out)))
        print(f"report: {out / 'index.html'} (benchmarks)")
        return
    sweeps, missing, tier = load(a.results)
    dirty = sum(is_dirty(p) for p in provenances(sweeps))
    if a.bundle and dirty and not a.allow_dirty:
        print(f"report.py: error: {dirty} of {len(provenances(sweeps))} runs under {a.results} were produced from a tree "
              "with uncommitted changes (their provenance says so): commit, rerun, or pass --allow-dirty", file=sys.stderr)
        sys.exit(2)
    for old in ("fig", "data"):  # a report is rewritten whole: nothing stale from an earlier one
        shutil.rmtree(out / old, ignore_errors=True)
    for old in out.glob("*.html"):
        old.unlink()
    out.mkdir(parents=True, exist_ok=True)

    # The cases with the most runs first (their figures dominate): the workers then end together,
    # instead of one drawing the largest case alone at the end. The figures are listed in the cases'
    # order whatever order they were drawn in.
    jobs = [(case, ss, a.results, out, not a.bundle) for case, ss in sorted(sweeps.items())]
    work = sorted(jobs, key=lambda j: -sum(len(s.get("runs", [])) for s in j[1]))
    with ProcessPoolExecutor(max_workers=max(1, min(len(jobs), os.cpu_count() or 1))) as pool:  # figures dominate
        drawn_by_case = dict(zip((j[0] for j in work), pool.map(write_case_page, work)))
    made = [m for case, *_ in jobs for m in drawn_by_case[case]]
    km_file = a.mutants or ROOT / "runs" / "mutants" / "kill_matrix.json"
    mutants_link = None
    if a.mutants or km_file.is_file():
        (out / "mutants.html").write_text(mutants_page(read_json(km_file)))
        mutants_link = "mutants.html"
    drawn = {(m[0], m[1]["variant"], m[2]) for m in made if m[3] == "convergence"}
    (out / "index.html").write_text(index_page(a.name, sweeps, missing, tier, mutants_link, drawn))
    c = counts(sweeps)
    print(f"report: {out / 'index.html'} ({len(sweeps)} cases; " + ", ".join(outcome_count(c, k) for k in OUTCOMES)
          + f"; {len(made)} figures)")
    if a.bundle:
        import report_tex
        report_tex.write_bundle(a.bundle, sweeps, tier, made, a.results, a.source_archive or a.source_repo, a.with_runs)


if __name__ == "__main__":
    main()
