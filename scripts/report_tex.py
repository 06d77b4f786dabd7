"""The publication bundle: verification.tex (a section of a few pages: one summary table and a few
chosen figures whose captions say what is compared with what, at which resolution) and
verification-supplement.tex (every variant, check and figure), the figures as PDF,
provenance.json and reproduce.sh. Both .tex files are meant for \\input in a paper (graphicx);
example.tex and example-supplement.tex wrap them into documents for a quick look."""
import json
import os
import re
import shutil
import unicodedata
from pathlib import Path

import report_kernels
from report_data import (OUTCOMES, claim_notes, f2, file_of, fmt, is_dirty, num, provenances, row_note, slug,
                         sweep_wide_failures, threads_text)

FAIL = r"\textbf{FAIL}"
FLOATS_PER_FLUSH = 8  # \clearpage after this many figure floats: LaTeX holds at most 18 unplaced floats
MATH = {"±": r"\pm", "×": r"\times", "≤": r"\le", "≥": r"\ge", "−": "-", "≈": r"\approx", "∞": r"\infty",
        "²": "^2", "³": "^3", "·": r"\cdot", "∫": r"\int", "∑": r"\sum", "√": r"\surd", "∇": r"\nabla", "∂": r"\partial"}


def tex(text):
    """Plain text to LaTeX: specials escaped, Greek letters and common symbols as math, anything
    else outside ASCII spelled as its Unicode name (pdflatex would stop on it)."""
    out = []
    for ch in str(text):
        if ch == "_":  # identifiers (drift_baseline_present) may break after an underscore
            out.append(r"\_\allowbreak{}")
        elif ch in "\\{}%&#$^~<>|":
            out.append({"\\": r"\textbackslash{}", "^": r"\^{}", "~": r"\~{}", "<": r"$<$", ">": r"$>$",
                        "|": r"$|$"}.get(ch, "\\" + ch))
        elif ch in ",=":  # settings (euler=26,integrator=chapter) may break after a comma or an equals sign
            out.append(ch + r"\allowbreak{}")
        elif ord(ch) < 128:
            out.append(ch)
        elif ch in MATH:
            out.append(f"${MATH[ch]}$")
        elif ch in "–—":
            out.append("--" if ch == "–" else "---")
        else:
            name = unicodedata.name(ch, "")
            m = re.match(r"GREEK (SMALL|CAPITAL) LETTER (\w+)$", name)
            if m:
                letter = m.group(2).lower()
                out.append(f"$\\{letter.capitalize() if m.group(1) == 'CAPITAL' else letter}$")
            else:
                out.append(f"[{name.lower() or '?'}]")
    return "".join(out)


def ragged(text):
    """A p{} table cell set ragged right (justified narrow cells stretch their spaces); its row must
    end in \\tabularnewline, since \\raggedright redefines \\\\."""
    return r"\raggedright " + text


def wide_row(text):
    """A row across the five columns of the section's table."""
    return r"\multicolumn{5}{p{0.9\linewidth}}{" + ragged(text) + r"} \tabularnewline"


def order_tex(row):
    """Observed order +- standard error; in parentheses where no order is claimed (information only)."""
    if not num(row.get("observed")):
        return "--"
    p = f"${f2(row['observed'])} \\pm {f2(row['se'])}$" if num(row.get("se")) else f"${f2(row['observed'])}$ (2 levels)"
    return p if num(row.get("expected")) else f"({p})"


def expected_tex(row):
    return f"${row['expected']:.3g} \\pm {row.get('band', 0):.3g}$" if num(row.get("expected")) else "none"


# Each outcome in its own colour, as in the HTML report (xcolor).
OUTCOME_TEX = {"verified": r"\textcolor[rgb]{0,0.4,0}{verified}", "known failure": r"\textcolor[rgb]{0.5,0.15,0.6}{known failure}",
               "no order claimed": r"\textcolor[rgb]{0.52,0.36,0}{no claim}", "fail": r"\textcolor[rgb]{0.7,0,0}{\textbf{fail}}"}


def outcome_tex(row):
    return OUTCOME_TEX.get(row["outcome"], tex(row["outcome"]))


def sci(v):
    """A number for a table: 1.23e-04 as $1.23\\times10^{-4}$."""
    if not num(v):
        return "--"
    if v == 0:
        return "0"
    m, x = f"{v:.2e}".split("e")
    return f"${m}\\times10^{{{int(x)}}}$" if int(x) not in (-1, 0, 1) else f"{v:.3g}"


def long_table(head, spec, rows, caption, label):
    """A table that breaks across pages (longtable: a float taller than a page cannot be placed and
    loses its rows), ruled with booktabs, its head repeated on every page it continues on."""
    cols = len(head.split("&"))
    return [r"{\footnotesize\setlength{\tabcolsep}{3pt}", f"\\begin{{longtable}}{{{spec}}}",
            f"\\caption{{{caption}}}\\label{{{label}}}\\\\", r"\toprule", head + r" \\ \midrule", r"\endfirsthead",
            f"\\caption[]{{{caption} (continued)}}\\\\", r"\toprule", head + r" \\ \midrule", r"\endhead",
            r"\midrule \multicolumn{%d}{r}{\emph{continued on the next page}} \\" % cols, r"\endfoot",
            r"\bottomrule", r"\endlastfoot", *rows, r"\end{longtable}}"]


def copy_figure(case, stem, figs):
    """Copies a figure's PDF into the bundle, named after its case (stems repeat across cases),
    with the stem's dots spelled "p" ("gamma_1p4"): graphicx takes a file name's first dot for
    the start of its extension."""
    name = f"{slug(case)}_{stem.name}".replace(".", "p") + ".pdf"
    shutil.copy(file_of(stem, "pdf"), figs / name)
    return name


def figure(files, caption, width):
    body = r"\hfill".join(f"\\includegraphics[width={width}\\linewidth]{{figures/{f}}}" for f in files)
    return [r"\begin{figure}[htbp]\centering", body, f"\\caption{{{caption}}}", r"\end{figure}"]


def convergence_caption(case, s, row):
    defs = s.get("error_defs", {})
    lv = s["levels"]
    return (f"{tex(case)} ({tex(s['variant'])}): {tex(row['error'])}"
            + (f", {tex(defs[row['error']])}" if row["error"] in defs else "")
            + f", against $n$ ({tex(s.get('n_counts', ''))}) at $n = {lv[0]}$ to ${lv[-1]}$ ({len(lv)} levels): "
            f"{tex(s.get('summary', ''))}. Observed order {order_tex(row)} (least-squares fit, solid), expected "
            f"{expected_tex(row)} (dashed, through the finest point; band shaded); {outcome_tex(row)}.")


HYDRO = ("sod", "sedov", "noh", "sound_wave", "kh")  # the cases that verify the hydrodynamics: the section shows them first


def run_caption(case, s, name):
    title = next((f["title"] for f in s["runs"][-1].get("figures", []) if f["name"] == name), name.replace("_", " "))
    return f"{tex(case)} ({tex(s['variant'])}), finest run $n = {s['levels'][-1]}$: {tex(title)}."


def hydro_figures(sweeps, made):
    """Per hydrodynamics case present, its default variant's density profile at the finest level
    (else its first profile, or kh's mode amplitude against time) and the convergence of its density error (else its first error with
    an order claim), where drawn."""
    pairs = []
    for case in HYDRO:
        if case not in sweeps:
            continue
        s = sweeps[case][0]
        mine = [m for m in made if m[0] == case and m[1] is not None and m[1]["variant"] == s["variant"]]
        runs = [m for m in mine if m[3] == "run"]
        prof = next((m for m in runs if m[2] == "profile_rho"),
                    next((m for m in runs if m[2].startswith("profile") or m[2] == "mode_amplitude"), None))
        convs = [m for m in mine if m[3] == "convergence"]
        conv = next((m for m in convs if "rho" in m[2]), convs[0] if convs else None)
        pair = [m for m in (prof, conv) if m]
        if pair:
            pairs.append(pair)
    return pairs


def chosen(made, skip=()):
    """The convergence figures for the section: verified errors (expected order at least 1/2) of
    distinct cases (not in skip) with the widest range of n (then the most levels), at most four."""
    cands = []
    for case, s, err, kind, stem in made:
        if kind != "convergence" or case in skip:
            continue
        row = next(r for r in s["rows"] if r["error"] == err)
        if row["outcome"] == "verified" and len(s["levels"]) >= 3 and row["expected"] >= 0.5:  # a real convergence
            cands.append((-(s["levels"][-1] / s["levels"][0]), -len(s["levels"]), case, s, row, stem))
    picked, cases = [], set()
    for *_, case, s, row, stem in sorted(cands, key=lambda c: c[:3]):
        if case not in cases:
            picked.append((case, s, row, stem))
            cases.add(case)
    return picked[:4]


def threads_tex(provs):
    """The OpenMP threads the points ran on, each point's own count (its result.json)."""
    t = sorted({q["threads"] for q in provs if num(q.get("threads"))})
    if not t:
        return "an unrecorded number of OpenMP threads"
    if len(t) == 1:
        return f"{t[0]} OpenMP thread{'s' if t[0] != 1 else ''} per point"
    return f"{t[0]} to {t[-1]} OpenMP threads per point (each point's count in its result.json)"


def provenance_text(sweeps, tier):
    provs = provenances(sweeps)
    p = provs[0] if provs else {}
    commits = sorted({str(q.get("git_commit")) for q in provs})
    return (f"Every number in this section was produced by sphv at commit \\texttt{{{tex(', '.join(c[:12] for c in commits))}}}"
            + (" (mixed commits)" if len(commits) > 1 else "")
            + (r" \textbf{from a tree with uncommitted changes}" if any(is_dirty(q) for q in provs) else "")
            + f", {tex(p.get('compiler', ''))} ({tex(p.get('build_type', ''))}, flags {tex(str(p.get('cxx_flags', '')).strip())}), "
            f"on {tex(p.get('cpu', ''))} with {threads_tex(provs)}, instruction-set path "
            f"{tex(str(p.get('isa_path', 'portable')))} (pair loops and tree walk), tier {tex(tier)}; "
            r"\texttt{reproduce.sh} re-runs it. ")


def main_section(sweeps, tier, made, figs):
    rows, n_rows = [], {k: 0 for k in OUTCOMES}
    for case, ss in sorted(sweeps.items()):
        for s in ss:
            for r in s["rows"]:
                n_rows[r["outcome"]] = n_rows.get(r["outcome"], 0) + 1
        s = ss[0]
        shown = [r for r in s["rows"] if num(r.get("expected")) or r["outcome"] == "fail"]
        if rows:
            rows[-1] += r" \midrule"
        block = rows
        block.append(wide_row(r"\textbf{" + tex(case) + "}: " + tex(s.get("summary", ""))))
        for r in shown:
            block.append(f"\\quad {tex(r['error'])} & {sci(r.get('fine_value'))} ($n={s['levels'][-1]}$) & {order_tex(r)} & "
                        f"{expected_tex(r)} & {outcome_tex(r)} \\\\")
        notes = []
        unclaimed = [r["error"] for r in s["rows"] if r not in shown]
        if unclaimed:
            notes.append(f"{len(unclaimed)} error{'s' if len(unclaimed) > 1 else ''} with no order claimed, bounds hold "
                         f"({tex(', '.join(unclaimed[:3]))}{', ...' if len(unclaimed) > 3 else ''})")
        if len(ss) > 1:
            more = [r["outcome"] for v in ss[1:] for r in v["rows"]]
            notes.append(f"{len(ss) - 1} further variant{'s' if len(ss) > 2 else ''}: {more.count('verified')} verified, "
                         f"{more.count('known failure')} known failure{'s' if more.count('known failure') != 1 else ''}, "
                         f"{more.count('no order claimed')} no claim, {more.count('fail')} fail")
        if notes:
            block.append(wide_row(r"\quad\emph{" + "; ".join(notes) + " (supplement)}"))
    t = [r"% Generated by scripts/report.py --bundle (scripts/bundle.sh): \input{verification} in a paper (needs graphicx, booktabs, longtable, xcolor).",
         r"\section{Verification}\label{sec:verification}",
         provenance_text(sweeps, tier) +
         r"Each case compares the SPH result with a reference independent of the code (quadrature, analytic solution, exact "
         r"Riemann solver, SUNDIALS, direct summation). Each error is measured at several resolutions $n$; its observed order "
         r"$p$ is minus the least-squares slope of $\log$ error against $\log n$, with the standard error of that fit. "
         r"An error is \emph{verified} when $p$ lies within the expected order $\pm$ (band $+\,2$ standard errors), "
         r"that standard error is at most the band, and the error is under its bound; \emph{no claim} means the error has "
         r"no convergent limit, as the case states (a round-off quantity, an error at fixed $\theta$ or fixed $\Delta t$, an "
         r"operator on a jittered set at fixed $h/\Delta x$, a degenerate input, or one level only) and its bounds hold; "
         r"\emph{known failure} means the case states why the "
         r"error misses its order and names the variant or setting that does converge; \emph{fail} means a check on "
         f"that error failed. Over all {sum(len(ss) for ss in sweeps.values())} case variants: {n_rows['verified']} errors "
         f"verified, {n_rows['known failure']} known failure{'s' if n_rows['known failure'] != 1 else ''}, "
         f"{n_rows['no order claimed']} with no order claimed, {n_rows['fail']} failing. Table~\\ref{{tab:verification}} "
         r"lists the default variant of each case; the supplement (\texttt{verification-supplement.tex}) holds every variant, "
         r"every check (against the reference or, labelled \emph{drift}, against the code's own earlier output) and every figure.", ""]
    t += long_table(r"case: compared against; error & at finest $n$ & observed order & expected & outcome",
                    "l l l l l", rows, "Verification summary: each case (in bold, with what it is compared against) and the "
                "errors of its default variant that carry an order claim or fail.", "tab:verification")
    hydro = [m for pair in hydro_figures(sweeps, made) for m in pair]
    for k in range(0, len(hydro), 2):  # two per float: readable at half the text width
        pair = hydro[k:k + 2]
        names = [copy_figure(case, stem, figs) for case, _, _, _, stem in pair]
        caps = [f"({'ab'[j]}) " + (run_caption(case, s, name) if kind == "run" else
                                  convergence_caption(case, s, next(r for r in s["rows"] if r["error"] == name)))
                for j, (case, s, name, kind, _) in enumerate(pair)]
        t += figure(names, ("Left to right: " if len(pair) > 1 else "") + " ".join(caps), 0.49 if len(pair) > 1 else 0.6)
    # The other cases' widest convergence, in one float, only beside at most one float of the
    # hydrodynamics: with the summary table of a full catalogue the section then stays within 4 pages.
    picked = chosen(made, HYDRO)[:2] if len(hydro) <= 2 else []
    if picked:
        names = [copy_figure(case, stem, figs) for case, s, row, stem in picked]
        caps = " ".join(f"({'ab'[j]}) {convergence_caption(case, s, row)}" for j, (case, s, row, _) in enumerate(picked))
        t += figure(names, "Convergence" + (", left to right: " if len(picked) > 1 else ": ") + caps, 0.49 if len(picked) > 1 else 0.6)
    return "\n".join(t) + "\n"


def kernel_tables(case, ss):
    """Per group of variants differing only in the kernel (report_kernels.py), a table: per error
    and kernel the error at the fixed n, its wall time, the error at the fixed cost, the observed
    order and the outcome."""
    t = []
    for label, members in report_kernels.groups(ss):
        rows = []
        for err in report_kernels.errors(members):
            n_fixed, t_fixed, comp = report_kernels.comparison(members, err)
            for j, r in enumerate(comp):
                head = (ragged(f"{tex(err)} ($n={fmt(n_fixed, 'g', '--')}$, {fmt(t_fixed, '.3g', '--')} s)") if j == 0 else "")
                rows.append(f"{head} & {tex(r['kernel'])} & {sci(r['at_n'])} & {fmt(r['wall_at_n'], '.3g', '--')} & {sci(r['at_cost'])} & "
                            f"{order_tex(r)} & {outcome_tex(r)} \\tabularnewline")
            rows[-1] += r" \midrule" if err != report_kernels.errors(members)[-1] else ""
        t += long_table("error (fixed $n$, fixed cost) & kernel & at fixed $n$ & wall s & at fixed cost & observed & outcome",
                        r"p{2.6cm} l l l l l l", rows,
                        f"{tex(case)} ({tex(label)}): the kernels compared. Fixed $n$: the finest level every kernel ran; fixed cost: "
                        "each kernel's error interpolated (log error linear in log wall time) at the largest wall time every "
                        "kernel's sweep reached; observed order of each kernel's sweep.", f"tab:supp-kernels-{slug(case)}-{slug(label)}")
    return t


def supplement(sweeps, made, figs):
    t = [r"% Generated by scripts/report.py --bundle: \input{verification-supplement} (needs graphicx, booktabs, longtable, xcolor).",
         r"\section{Verification supplement}\label{sec:verification-supplement}",
         r"Every case variant behind the verification section: each error's outcome, every check (\emph{verification}: "
         r"against an independent reference; \emph{drift}: against the code's own earlier output, which shows only that "
         r"nothing changed) and every figure. Figures show the finest run unless they plot against $n$ or wall time.", ""]
    for case, ss in sorted(sweeps.items()):
        s0 = ss[0]
        t += [f"\\subsection{{{tex(case)}}}", f"{tex(s0.get('summary', ''))}. $n$: {tex(s0.get('n_counts', ''))}."]
        defs = {k: v for s in ss for k, v in s.get("error_defs", {}).items()}
        if defs:
            t += [r"\begin{itemize}\small"] + [f"\\item {tex(k)}: {tex(v)}" for k, v in defs.items()] + [r"\end{itemize}"]
        notes = claim_notes(ss)
        if notes:  # each claim's reason once; the table's rows give only their own
            t += [r"Claims:", r"\begin{itemize}\small"] + [f"\\item {tex(claimed)}: {tex(why)}" for claimed, why in notes] + [r"\end{itemize}"]
        rows = []
        for s in ss:
            for k, r in enumerate(s["rows"]):
                rows.append(f"{ragged(tex(s['variant'])) if k == 0 else ''} & {ragged(tex(r['error']))} & {sci(r.get('fine_value'))} ($n={s['levels'][-1]}$) & "
                            f"{order_tex(r)} & {expected_tex(r)} & {outcome_tex(r)} & {ragged(tex(row_note(s, r)))} \\tabularnewline")
        if rows:
            t += long_table("variant & error & at finest $n$ & observed & expected & outcome & own reason", r"p{2.0cm} p{2.2cm} l l l l p{3.0cm}",
                            rows, f"{tex(case)}: every variant (the claims' reasons are listed above).", f"tab:supp-{slug(case)}")
        checks = []
        for s in ss:
            for c in s["checks"]:
                if c.get("kind") != "drift":
                    checks.append(f"{ragged(tex(s['variant']))} & {tex(c['name'])} & {fmt(c.get('value'), '.4g', '--')} & "
                                  f"[{fmt(c.get('lo'), '.4g', '--')}, {fmt(c.get('hi'), '.4g', '--')}] & "
                                  f"{'pass' if c['pass'] else FAIL} \\tabularnewline")
        if checks:
            t += long_table("variant & verification check & value & allowed & ", r"p{3.2cm} l l l l", checks, f"{tex(case)}: verification checks.",
                            f"tab:supp-checks-{slug(case)}")
        t += kernel_tables(case, ss)
        drift = [(s, c) for s in ss for c in s["checks"] if c.get("kind") == "drift"]
        bad = [f"{s['variant']}: {c['name']}" for s, c in drift if not c["pass"]]
        wide = [f"{s['variant']}: {n}" for s in ss for n in sweep_wide_failures(s)]
        t.append(f"{len(drift)} drift checks (own earlier output, not verification), {len(bad)} failing"
                 + (f": {tex('; '.join(bad))}" if bad else "") + "." + (f" Sweep-wide failures: {tex('; '.join(wide))}." if wide else ""))
        gci = [(s["variant"], k, g) for s in ss for k, g in s.get("gci", {}).items()]
        if gci:
            t.append("Roache's GCI (finest pair, relative): " + "; ".join(
                f"{tex(v)} {tex(k)} $= {fmt(g.get('fine_value'), '.6g', '--')}$ $\\pm$ {fmt(g.get('gci'), '.2e', '--')}" for v, k, g in gci) + ".")
        t.append("")
        mine = [m for m in made if m[0] == case]
        pairs = [mine[k:k + 2] for k in range(0, len(mine), 2)]
        for k, pair in enumerate(pairs):
            names, caps = [], []
            for j, (_, s, name, kind, stem) in enumerate(pair):
                names.append(copy_figure(case, stem, figs))
                side = ("left", "right")[j] if len(pair) == 2 else ""
                if kind == "convergence":
                    row = next(r for r in s["rows"] if r["error"] == name)
                    cap = convergence_caption(case, s, row)
                elif kind == "kernels":
                    members = next(m for label, m in report_kernels.groups(ss) if label == name)
                    cap = (f"{tex(case)} ({tex(name)}): kernels {tex(', '.join(k for k, _ in members))} compared, every error against "
                           r"$n$ (top) and against the wall time of each run (bottom); dotted: the fixed resolution and the fixed cost "
                           f"of Table~\\ref{{tab:supp-kernels-{slug(case)}-{slug(name)}}}.")
                elif kind == "wall":
                    d = next((v["error_defs"][name] for v in ss if name in v.get("error_defs", {})), "")
                    cap = (f"{tex(case)}: {tex(name)}" + (f", {tex(d)}," if d else "") + " against the wall time of each run, one line per variant; "
                           f"runs on {threads_text([r for v in ss for r in v['runs']])}.")
                else:
                    cap = run_caption(case, s, name)
                caps.append((f"{side.capitalize()}: " if side else "") + cap)
            t += figure(names, " ".join(caps), 0.49 if len(pair) == 2 else 0.6)
            if (k + 1) % FLOATS_PER_FLUSH == 0:
                t.append(r"\clearpage")
        t.append(r"\clearpage")
    return "\n".join(t) + "\n"


def write_bundle(bundle, sweeps, tier, made, report_dir):
    bundle = Path(bundle)
    figs = bundle / "figures"
    shutil.rmtree(figs, ignore_errors=True)
    figs.mkdir(parents=True, exist_ok=True)
    (bundle / "verification.tex").write_text(main_section(sweeps, tier, made, figs))
    (bundle / "verification-supplement.tex").write_text(supplement(sweeps, made, figs))
    for name, part in (("example.tex", "verification"), ("example-supplement.tex", "verification-supplement")):
        (bundle / name).write_text("\\documentclass{article}\n\\usepackage{graphicx,booktabs,longtable,xcolor}\n\\usepackage[margin=2.5cm]{geometry}\n"
                                   f"\\begin{{document}}\n\\input{{{part}}}\n\\end{{document}}\n")
    (bundle / "provenance.json").write_text(json.dumps(bundle_provenance(sweeps, tier), indent=1) + "\n")
    commits = sorted({str(p.get("git_commit")) for p in provenances(sweeps)})
    (bundle / "reproduce.sh").write_text(reproduce_script(commits, tier))
    print(f"bundle: {bundle / 'verification.tex'} and verification-supplement.tex, {len(list(figs.glob('*.pdf')))} figures")


def bundle_provenance(sweeps, tier):
    """What the bundle's numbers were produced with. Build and host come from the first point (the
    report flags mixed ones); threads, dates and wall time are every point's own, as its
    result.json recorded them when it ran."""
    provs = provenances(sweeps)
    prov = {k: v for k, v in (provs[0] if provs else {}).items() if k not in ("threads", "date")}
    prov["git_commits"] = sorted({str(p.get("git_commit")) for p in provs})
    prov["dirty_runs"] = sum(is_dirty(p) for p in provs)
    prov["tier"] = tier
    prov["uname"] = " ".join(os.uname())
    prov["points"] = len(provs)
    prov["threads_per_point"] = sorted({p["threads"] for p in provs if num(p.get("threads"))})
    dates = sorted(str(p["date"]) for p in provs if "date" in p)
    prov["points_ran"] = [dates[0], dates[-1]] if dates else []
    prov["points_wall_time_s"] = sum(r["wall_time_s"] for ss in sweeps.values() for s in ss for r in s["runs"] if num(r.get("wall_time_s")))
    return prov


def reproduce_script(commits, tier):
    """reproduce.sh: re-runs the bundle from a checkout of the one commit its results came from
    (git_commit is the full hash; an abbreviated one from older results resolves as well)."""
    if len(commits) != 1 or commits[0] in ("unknown", "None"):
        return ("#!/usr/bin/env bash\n# The results behind this bundle do not name one commit: nothing to check out.\n"
                f"echo 'reproduce.sh: error: the results come from commits {', '.join(commits)}, not one; rerun them at one commit' >&2\nexit 2\n")
    c = commits[0]
    return ("#!/usr/bin/env bash\n# Re-runs every number behind this bundle and rewrites it, in a checkout of the repository at "
            f"commit {c}.\nset -e\ncd \"$(git rev-parse --show-toplevel)\"\n"
            f"[ \"$(git rev-parse HEAD)\" = \"$(git rev-parse --verify -q '{c}^{{commit}}')\" ] || "
            f"{{ echo \"reproduce.sh: error: HEAD is $(git rev-parse HEAD); check out commit {c} first\" >&2; exit 2; }}\n"
            f"bash scripts/bundle.sh --tier {tier.split(',')[0]} --out bundle\n")
