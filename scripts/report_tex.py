"""The publication bundle (scripts/bundle.sh): verification.tex, the main part of a paper (at most
four two-column pages: report_paper.py), verification-supplement.tex (every variant, check and
figure, with the error definitions, provenance and references), the figures as PDF at print size,
verification.bib, provenance.json, the source of the results' commit (source.tar.gz, `git
archive`), the sweep.json files the figures and tables come from (results.tar.gz) and reproduce.sh,
which rebuilds all of it from the folder alone. example.tex and example-supplement.tex wrap the two
parts into documents; bundle.sh compiles them."""
import datetime
import hashlib
import json
import os
import platform
import shutil
import subprocess
import sys
import tarfile
from pathlib import Path

import report_bib
import report_compare
import report_paper
from report_data import (claim_notes, claim_tex, claim_window_tex, f2, file_of, fmt, is_dirty, num, one_sided,
                         provenances, row_note, slug, sweep_wide_failures, threads_text)
from report_math import error_name, latex, prose

FAIL = r"\textbf{FAIL}"
# A list whose bullet is math's (cmsy, Type 1): LaTeX's \textbullet comes from the TS1 encoding,
# which Computer Modern has as a bitmap (Type 3) font only, and journal preflight checks reject those.
ITEMIZE = r"\begin{itemize}\small\renewcommand{\labelitemi}{$\bullet$}"
COMPARISONS = {f"{key}s": key for key in report_compare.PARAMETERS}  # the figures report.py makes of report_compare, by kind
FLOATS_PER_FLUSH = 8  # \clearpage after this many figure floats: LaTeX holds at most 18 unplaced floats


def tex(text):
    """Plain text with ASCII formulas as LaTeX (report_math)."""
    return latex(text)


def ragged(text):
    """A p{} table cell set ragged right (justified narrow cells stretch their spaces); its row must
    end in \\tabularnewline, since \\raggedright redefines \\\\."""
    return r"\raggedright " + text


def order_tex(row):
    """Observed order +- standard error; in parentheses where no order is claimed (information only)."""
    if not num(row.get("observed")):
        return "--"
    p = f"${f2(row['observed'])} \\pm {f2(row['se'])}$" if num(row.get("se")) else f"${f2(row['observed'])}$ (2 levels)"
    return p if num(row.get("expected")) else f"({p})"


def expected_tex(row):
    return claim_tex(row, "none")


# Each outcome in its own colour, as in the HTML report (xcolor).
OUTCOME_TEX = {"verified": r"\textcolor[rgb]{0,0.4,0}{verified}", "known failure": r"\textcolor[rgb]{0.5,0.15,0.6}{known failure}",
               "provisional": r"\textcolor[rgb]{0.63,0.31,0}{\emph{provisional}}",
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


def figure(files, caption, label=""):
    """A float of one or two figures side by side, at the size they were drawn (print size)."""
    body = r"\hfill".join(f"\\includegraphics{{figures/{f}}}" for f in files)
    return [r"\begin{figure}[htbp]\centering", body, f"\\caption{{{caption}}}" + (f"\\label{{{label}}}" if label else ""),
            r"\end{figure}"]


def convergence_caption(case, s, row):
    defs = s.get("error_defs", {})
    lv = s["levels"]
    return (f"{prose(case)} ({prose(s['variant'])}): {tex(row['error'])}"
            + (f", {tex(defs[row['error']])}" if row["error"] in defs else "")
            + f", against $n$ ({tex(s.get('n_counts', ''))}) at $n = {lv[0]}$ to ${lv[-1]}$ ({len(lv)} levels): "
            f"{tex(s.get('summary', ''))}. Observed order {order_tex(row)} (least-squares fit, solid), expected "
            f"{expected_tex(row)} (dashed, through the finest point{band_words(row)}); {outcome_tex(row)}.")


def band_words(row):
    """The figure shades a two-sided claim's band; a one-sided claim has none to shade."""
    return "" if one_sided(row) else "; band shaded"


def run_caption(case, s, name):
    title = next((f["title"] for f in s["runs"][-1].get("figures", []) if f["name"] == name), name.replace("_", " "))
    return f"{prose(case)} ({prose(s['variant'])}), finest run $n = {s['levels'][-1]}$: {tex(title)}."


def threads_tex(provs):
    """The OpenMP threads the points ran on, each point's own count (its result.json)."""
    t = sorted({q["threads"] for q in provs if num(q.get("threads"))})
    if not t:
        return "an unrecorded number of OpenMP threads"
    if len(t) == 1:
        return f"{t[0]} OpenMP thread{'s' if t[0] != 1 else ''} per point"
    return f"{t[0]} to {t[-1]} OpenMP threads per point (each point's count in its result.json)"


def provenance_text(sweeps, tier):
    """The main part's one sentence of provenance (the supplement has the whole of it)."""
    provs = provenances(sweeps)
    p = provs[0] if provs else {}
    commits = sorted({str(q.get("git_commit")) for q in provs})
    return (f"Every number in this section was produced by sphv at commit \\texttt{{{prose(', '.join(c[:12] for c in commits))}}}"
            + (" (mixed commits)" if len(commits) > 1 else "")
            + (r" \textbf{from a tree with uncommitted changes}" if any(is_dirty(q) for q in provs) else "")
            + f", built with {prose(p.get('compiler', ''))}, on {prose(p.get('cpu', ''))} with {threads_tex(provs)}, "
            f"tier {prose(tier)}; \\texttt{{reproduce.sh}} in the bundle re-runs it from the source it carries "
            r"(provenance and tool versions: supplement). ")


def comparison_tables(case, ss, key):
    """Per group of variants compared in the parameter key (report_compare.py): what the others
    change against the first and whether the group is like for like, then a table: per error and
    member the error at the fixed n, its wall time, the error at the fixed cost, the observed order,
    the claim with its window (as the HTML report's table) and the outcome."""
    t = []
    for g in report_compare.groups(ss, key):
        rows = []
        errs = report_compare.errors(g.members)
        for err in errs:
            n_fixed, t_fixed, comp = report_compare.comparison(g.members, err)
            for j, r in enumerate(comp):
                head = (ragged(f"{tex(err)} ($n={fmt(n_fixed, 'g', '--')}$, {fmt(t_fixed, '.3g', '--')} s)") if j == 0 else "")
                rows.append(f"{head} & {ragged(prose(r['value']))} & {ragged(prose(r['variant']))} & {sci(r['at_n'])} & "
                            f"{fmt(r['wall_at_n'], '.3g', '--')} & {sci(r['at_cost'])} & {order_tex(r)} & {ragged(claim_window_tex(r, 'none'))} & "
                            f"{outcome_tex(r)} \\tabularnewline")
            rows[-1] += r" \midrule" if err != errs[-1] else ""
        t.append(f"{prose(case)}, {prose(key)}s compared ({prose(report_compare.title(g))}): {prose(report_compare.unlike_text(g))} "
                 + " ".join(report_compare.effects(g, prose, error_name)))
        t += long_table(f"error (fixed $n$, fixed cost) & {prose(key)} & variant & at fixed $n$ & wall s & at fixed cost & observed & "
                        "claim [window] & outcome", r"p{2.2cm} p{1.6cm} p{1.8cm} l l l l p{1.7cm} l", rows,
                        f"{prose(case)} ({prose(report_compare.title(g))}): the {prose(key)}s compared"
                        + (" (not like for like: see the text)" if g.nearest or any(g.differs) else "")
                        + f". Fixed $n$: the finest level every {prose(key)} ran; fixed cost: each {prose(key)}'s error "
                        "interpolated (log error linear in log wall time) at the largest wall time every sweep reached; "
                        "observed order of each sweep; the claim with the window its order must lie in.",
                        f"tab:supp-{key}s-{slug(case)}-{slug(g.label)}")
    lone = report_compare.alone_text(ss, key)
    if lone:
        t.append(prose(lone))
    return t


def figure_order(mine):
    """A case's figures in the order a reader wants them: per variant its profiles and convergence,
    then error against wall time, then the comparisons (kernels, then schemes)."""
    rank = {"run": 0, "convergence": 0, "wall": 1} | {f"{key}s": 2 + j for j, key in enumerate(report_compare.PARAMETERS)}
    return sorted(mine, key=lambda m: rank.get(m[3], 3))  # stable: the variants keep their order


def figure_caption(case, ss, m):
    _, s, name, kind, _ = m
    if kind == "convergence":
        return convergence_caption(case, s, next(r for r in s["rows"] if r["error"] == name))
    if kind in COMPARISONS:
        key = COMPARISONS[kind]
        g = next(g for g in report_compare.groups(ss, key) if g.label == name)
        return (f"{prose(case)} ({prose(report_compare.title(g))}): {prose(key)}s compared, every error "
                r"against $n$ (top) and against the wall time of each run (bottom); dotted: the fixed resolution and the fixed "
                f"cost of Table~\\ref{{tab:supp-{kind}-{slug(case)}-{slug(name)}}}.")
    if kind == "wall":
        d = next((v["error_defs"][name] for v in ss if name in v.get("error_defs", {})), "")
        return (f"{prose(case)}: {tex(name)}" + (f", {tex(d)}," if d else "") + " against the wall time of each run, one line per "
                f"variant; runs on {threads_text([r for v in ss for r in v['runs']])}.")
    return run_caption(case, s, name)


def case_figures(case, ss, made, figs):
    """The figure floats of a case: two column-wide figures side by side, a wider one alone."""
    t, row = [], []
    floats = 0

    def flush():
        nonlocal row, floats
        if row:
            names = [copy_figure(case, m[4], figs) for m in row]
            side = ("Left: ", "Right: ") if len(row) == 2 else ("",)
            t.extend(figure(names, " ".join(side[j] + figure_caption(case, ss, m) for j, m in enumerate(row))))
            floats += 1
            if floats % FLOATS_PER_FLUSH == 0:
                t.append(r"\clearpage")
        row = []

    for m in figure_order([m for m in made if m[0] == case]):
        if m[3] in COMPARISONS:
            flush()
            row = [m]
            flush()
        else:
            row.append(m)
            if len(row) == 2:
                flush()
    flush()
    return t


def checks_table(case, ss):
    checks = []
    for s in ss:
        for c in s["checks"]:
            if c.get("kind") != "drift":
                checks.append(f"{ragged(prose(s['variant']))} & {ragged(prose(c['name']))} & {fmt(c.get('value'), '.4g', '--')} & "
                              f"[{fmt(c.get('lo'), '.4g', '--')}, {fmt(c.get('hi'), '.4g', '--')}] & "
                              f"{'pass' if c['pass'] else FAIL} & {ragged(tex(c.get('why', '')))} \\tabularnewline")
    if not checks:
        return []
    return long_table("variant & verification check & value & allowed & & why", r"p{2.4cm} p{3.4cm} l l l p{4.6cm}", checks,
                      f"{prose(case)}: verification checks (against a reference independent of the code).",
                      f"tab:supp-checks-{slug(case)}")


def case_section(case, ss, made, figs):
    s0 = ss[0]
    t = [f"\\subsection{{{prose(case)}}}\\label{{sec:supp-{slug(case)}}}",
         f"{tex(s0.get('summary', ''))}. $n$: {tex(s0.get('n_counts', ''))}. "
         f"Variants: {len(ss)}; levels of the default: ${', '.join(str(n) for n in s0['levels'])}$."]
    defs = {k: v for s in ss for k, v in s.get("error_defs", {}).items()}
    if defs:
        t += [r"\paragraph{Errors}", ITEMIZE] + [f"\\item {error_name(k)}: {tex(v)}" for k, v in defs.items()] + [r"\end{itemize}"]
    notes = claim_notes(ss)
    if notes:  # each claim's reason once; the table's rows give only their own
        t += [r"\paragraph{Claims}", ITEMIZE] + [f"\\item {tex(claimed)}: {tex(why)}" for claimed, why in notes] + [r"\end{itemize}"]
    rows = []
    for s in ss:
        for k, r in enumerate(s["rows"]):
            rows.append(f"{ragged(prose(s['variant'])) if k == 0 else ''} & {ragged(tex(r['error']))} & {sci(r.get('fine_value'))} ($n={s['levels'][-1]}$) & "
                        f"{order_tex(r)} & {expected_tex(r)} & {outcome_tex(r)} & {ragged(tex(row_note(s, r)))} \\tabularnewline")
    if rows:
        t += long_table("variant & error & at finest $n$ & observed & expected & outcome & own reason", r"p{2.0cm} p{2.3cm} l l l l p{3.4cm}",
                        rows, f"{prose(case)}: every variant (the claims' reasons are listed above).", f"tab:supp-{slug(case)}")
    else:
        t.append(r"No error carries an order: this case is judged by its checks alone (Table~"
                 f"\\ref{{tab:supp-checks-{slug(case)}}}).")
    t += checks_table(case, ss)
    for key in report_compare.PARAMETERS:
        t += comparison_tables(case, ss, key)
    drift = [(s, c) for s in ss for c in s["checks"] if c.get("kind") == "drift"]
    bad = [f"{s['variant']}: {c['name']}" for s, c in drift if not c["pass"]]
    wide = [f"{s['variant']}: {n}" for s in ss for n in sweep_wide_failures(s)]
    t.append(f"{len(drift)} drift checks (own earlier output, not verification), {len(bad)} failing"
             + (f": {prose('; '.join(bad))}" if bad else "") + "." + (f" Sweep-wide failures: {prose('; '.join(wide))}." if wide else ""))
    gci = [(s["variant"], k, g) for s in ss for k, g in s.get("gci", {}).items()]
    if gci:
        t.append(r"Roache's GCI \citep{roache1994} (finest pair, relative): " + "; ".join(
            f"{prose(v)} {tex(k)} $= {fmt(g.get('fine_value'), '.6g', '--')} \\pm {fmt(g.get('gci'), '.2e', '--')}$" for v, k, g in gci) + ".")
    t.append("")
    t += case_figures(case, ss, made, figs)
    t.append(r"\clearpage")
    return t


def provenance_section(prov):
    """The supplement's provenance: what produced the numbers, what made the bundle, and when."""
    rows = [("commit", prose(", ".join(prov["git_commits"]))),
            ("source tree", "clean (no run records uncommitted changes)" if not prov["dirty_runs"] else
             f"\\textbf{{uncommitted changes}} in {prov['dirty_runs']} of {prov['points']} runs"),
            ("source archive", f"\\texttt{{source.tar.gz}} (\\texttt{{git archive}}), SHA-256 \\texttt{{{prov['source_sha256'][:16]}}}\\dots"
             if prov.get("source_sha256") else "none (the commit is not in the repository that made the bundle)"),
            ("tier", prose(prov["tier"])), ("points", f"{prov['points']}, summed wall time {prov['points_wall_time_s']:.0f} s"),
            ("points ran", prose(" to ".join(prov["points_ran"])) if prov["points_ran"] else "not recorded"),
            ("threads per point", prose(", ".join(map(str, prov["threads_per_point"])) or "not recorded")),
            ("compiler", prose(prov.get("compiler", ""))), ("build type, flags", prose(f"{prov.get('build_type', '')}, {prov.get('cxx_flags', '')}")),
            ("instruction-set path", prose(str(prov.get("isa_path", "")))), ("CPU", prose(f"{prov.get('cpu', '')} ({prov.get('cores', '?')} cores)")),
            ("host", prose(prov.get("uname", ""))), ("bundle made", prose(prov["bundle_time"]))]
    rows += [(prose(k), prose(v)) for k, v in prov["tools"].items()]
    body = [f"{k} & {ragged(v)} \\tabularnewline" for k, v in rows]
    return ([r"\subsection{Provenance}\label{sec:supp-provenance}",
             r"What produced the numbers (each point's \texttt{result.json} records it) and what made this bundle. Library and "
             r"tool versions are those of the Debian packages installed where the bundle was made; the compiler is the one "
             r"the points record. \texttt{reproduce.sh} rebuilds everything from \texttt{source.tar.gz}."]
            + long_table("item & value", r"p{3.6cm} p{12cm}", body, "Provenance of the results and of the bundle.", "tab:supp-provenance"))


def supplement(sweeps, made, figs, prov):
    t = [r"% Generated by scripts/report.py --bundle: \input{verification-supplement} (needs graphicx, booktabs, longtable,",
         r"% xcolor, natbib). Figures are drawn at print size (84 mm wide, two side by side) and included unscaled.",
         r"\begingroup\setlength{\emergencystretch}{2em}% long names and formulas: stretch a line rather than overfill it",
         r"\section{Verification supplement}\label{sec:verification-supplement}",
         r"Every case variant behind the verification section: each error's definition and outcome, every check "
         r"(\emph{verification}: against an independent reference; \emph{drift}: against the code's own earlier output, "
         r"which shows only that nothing changed) and every figure, a case's profiles and convergence first, then its "
         r"error against wall time. Figures show the finest run unless they plot against $n$ or wall time. The observed "
         r"order $p$ of an error $E$ measured at levels $n_1 < \dots < n_k$ is the least-squares slope of $-\ln E$ "
         r"against $\ln n$, given with the standard error of that slope.", ""]
    t += provenance_section(prov) + [r"\clearpage"]
    for case, ss in sorted(sweeps.items()):
        t += case_section(case, ss, made, figs)
    t.append(r"\endgroup")
    return "\n".join(t) + "\n"


EXAMPLE = r"""% A two-column page of a journal (174 mm text, 84 mm columns: MNRAS's) with the main part in it.
\documentclass[10pt,twocolumn]{article}
\usepackage[a4paper,textwidth=174mm,columnsep=6mm,top=20mm,bottom=22mm]{geometry}
\usepackage{graphicx,booktabs,xcolor}
\usepackage[round]{natbib}
\begin{document}
\input{verification}
\input{verification-references}
\end{document}
"""
EXAMPLE_SUPPLEMENT = r"""% The supplement as a document of its own: contents, the supplement, references.
\documentclass[10pt]{article}
\usepackage[a4paper,textwidth=174mm,top=20mm,bottom=22mm]{geometry}
\usepackage{graphicx,booktabs,longtable,xcolor}
\usepackage[round]{natbib}
\usepackage[hidelinks]{hyperref}
\title{sphv: verification supplement}
\date{}
\begin{document}
\maketitle
\tableofcontents
\clearpage
\input{verification-supplement}
\clearpage\addcontentsline{toc}{section}{References}
\input{verification-supplement-references}
\end{document}
"""


def write_bundle(bundle, sweeps, tier, made, results, source_repo, with_runs):
    bundle = Path(bundle)
    figs = bundle / "figures"
    shutil.rmtree(figs, ignore_errors=True)
    figs.mkdir(parents=True, exist_ok=True)
    commits = sorted({str(p.get("git_commit")) for p in provenances(sweeps)})
    prov = bundle_provenance(sweeps, tier)
    prov["source_sha256"] = source_archive(bundle / "source.tar.gz", source_repo, commits)
    prov["tools"] = tool_versions()
    figdir = bundle / "paper-figures"
    (bundle / "verification.tex").write_text(
        report_paper.section(sweeps, figdir, lambda stem: copy_figure("paper", stem, figs), provenance_text(sweeps, tier)))
    shutil.rmtree(figdir, ignore_errors=True)  # drawn for the bundle only: copied into figures/
    (bundle / "verification-supplement.tex").write_text(supplement(sweeps, made, figs, prov))
    (bundle / "verification.bib").write_text(report_bib.bibtex())
    (bundle / "verification-references.tex").write_text(
        report_bib.thebibliography(report_bib.cited((bundle / "verification.tex").read_text())))
    (bundle / "verification-supplement-references.tex").write_text(report_bib.thebibliography())
    (bundle / "example.tex").write_text(EXAMPLE)
    (bundle / "example-supplement.tex").write_text(EXAMPLE_SUPPLEMENT)
    results_archive(bundle / "results.tar.gz", results, sweeps)
    runs = bundle / "runs.tar.xz"
    runs.unlink(missing_ok=True)
    if with_runs:  # every point's files (particles, logs): large, so only on request
        with tarfile.open(runs, "w:xz", preset=6) as tar:  # not the references the points shared (a cache)
            tar.add(results, arcname="runs", filter=lambda f: None if ".references" in Path(f.name).parts else f)
    (bundle / "provenance.json").write_text(json.dumps(prov, indent=1) + "\n")
    script = bundle / "reproduce.sh"
    script.write_text(reproduce_script(commits, tier, prov["source_sha256"], with_runs))
    script.chmod(0o755)
    print(f"bundle: {bundle / 'verification.tex'} and verification-supplement.tex, {len(list(figs.glob('*.pdf')))} figures")


def source_archive(dst, source, commits):
    """source.tar.gz: `git archive` of the one commit the results came from, from the repository
    source, or source itself when it is such an archive (a rebuild from one: its commit must be the
    results'); its SHA-256, or None (and no archive) when the results name no single commit there."""
    if Path(source).is_file():
        archived = subprocess.run(f"gzip -dc '{source}' | git get-tar-commit-id", shell=True, capture_output=True,
                                  text=True).stdout.strip()
        if len(commits) != 1 or archived != commits[0]:
            print(f"bundle: warning: no source archive: {source} holds commit '{archived}', the results {', '.join(commits)}",
                  file=sys.stderr)
            return None
        if Path(source).resolve() != dst.resolve():
            shutil.copy(source, dst)
        return hashlib.sha256(dst.read_bytes()).hexdigest()
    dst.unlink(missing_ok=True)
    if len(commits) != 1:
        return None
    try:
        subprocess.run(["git", "-C", str(source), "archive", "--format=tar.gz", "-o", str(dst.resolve()), f"{commits[0]}^{{commit}}"],
                       check=True, capture_output=True)
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"bundle: warning: no source archive: commit {commits[0]} is not in {source} "
              f"({(getattr(e, 'stderr', b'') or b'').decode().strip() or e})", file=sys.stderr)
        dst.unlink(missing_ok=True)
        return None
    return hashlib.sha256(dst.read_bytes()).hexdigest()


def results_archive(dst, results, sweeps):
    """results.tar.gz: summary.json and every sweep.json (each point's errors, checks and the data
    of its figures): what the tables and figures are made from, without the particle files."""
    results = Path(results)
    with tarfile.open(dst, "w:gz", compresslevel=9) as tar:
        for f in [results / "summary.json"] + [results / s["_dir"] / "sweep.json" for ss in sweeps.values() for s in ss]:
            if f.is_file():
                tar.add(f, arcname=str(Path("results") / f.relative_to(results)))


def tool_versions():
    """The versions of the tools and libraries where the bundle is made (Debian packages, Python,
    matplotlib, pdflatex); a tool that is absent says so."""
    out = {}
    for pkg in ("g++", "cmake", "libeigen3-dev", "libsundials-dev", "libgsl-dev", "libhdf5-dev", "nlohmann-json3-dev",
                "libopenmpi-dev", "catch2", "python3-matplotlib", "python3-numpy", "texlive-binaries", "texlive-latex-base"):
        try:
            v = subprocess.run(["dpkg-query", "-W", "-f=${Version}", pkg], capture_output=True, text=True).stdout.strip()
        except OSError:
            v = ""
        out[pkg] = v or "not installed (or not a Debian system)"
    import matplotlib
    import numpy
    out["Python"] = platform.python_version()
    out["matplotlib (imported)"] = matplotlib.__version__
    out["numpy (imported)"] = numpy.__version__
    try:
        out["pdflatex"] = subprocess.run(["pdflatex", "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    except (OSError, IndexError):
        out["pdflatex"] = "not found"
    return out


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
    prov["bundle_time"] = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    return prov


def reproduce_script(commits, tier, sha256, with_runs):
    """reproduce.sh: from the bundle folder wherever it lies, checks source.tar.gz against the
    commit and hash the results recorded, unpacks it, builds sphv, reruns the tier and rewrites
    the bundle into reproduced/ beside it."""
    if len(commits) != 1 or commits[0] in ("unknown", "None", "") or not sha256:
        why = (f"the results come from commits {', '.join(commits)}, not one" if len(commits) != 1 else
               f"the results record commit '{commits[0]}', which the bundle's maker could not archive")
        return ("#!/usr/bin/env bash\n# The bundle carries no source archive of one commit: nothing to rebuild from.\n"
                f"echo 'reproduce.sh: error: {why}; rerun them at one commit and bundle again' >&2\nexit 2\n")
    c = commits[0]
    return f"""#!/usr/bin/env bash
# Re-runs every number behind this bundle from the source it carries and rewrites the bundle into
# reproduced/ in this folder. Works from a copy of the folder anywhere; needs git (to read the
# archive's commit), the Debian packages of scripts/install-deps.sh (--tex to compile the PDFs).
#   ./reproduce.sh          the tier the bundle was made from ({tier.split(',')[0]})
#   ./reproduce.sh quick    another tier
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
commit={c}
sha256={sha256}
tier=${{1:-{tier.split(',')[0]}}}
die() {{ echo "reproduce.sh: error: $*" >&2; exit 2; }}
[ -f "$here/source.tar.gz" ] || die "no source.tar.gz beside reproduce.sh"
got=$(sha256sum "$here/source.tar.gz" | cut -d' ' -f1)
[ -n "$got" ] && [ "$got" = "$sha256" ] || die "source.tar.gz has SHA-256 '$got', the bundle recorded $sha256"
# git reads the header only: gzip, cut short, must not fail the pipe
archived=$( (gzip -dc "$here/source.tar.gz" 2>/dev/null || true) | git get-tar-commit-id) || die "cannot read the commit of source.tar.gz (git get-tar-commit-id)"
[ -n "$archived" ] && [ "$archived" = "$commit" ] || die "source.tar.gz holds commit '$archived', the results came from $commit"
src=$here/source
rm -rf "$src" && mkdir -p "$src" && tar -xzf "$here/source.tar.gz" -C "$src"
cd "$src"
# Not a git checkout: the build records the archive's commit, checked above (verification/build_state.cmake);
# a repository around this folder (a copy inside a checkout) is not looked for.
export SPHV_ARCHIVE_COMMIT=$commit GIT_CEILING_DIRECTORIES=$here
bash scripts/build.sh sphv
rm -rf "$here/runs"
./build/sphv verify --tier "$tier" --out "$here/runs" || echo "reproduce.sh: a gate failed (exit $?): the bundle shows it"
bash scripts/bundle.sh --results "$here/runs" --out "$here/reproduced" --source-archive "$here/source.tar.gz"{' --with-runs' if with_runs else ''}
echo "reproduce.sh: rebuilt from commit $commit, tier $tier: $here/reproduced"
"""
