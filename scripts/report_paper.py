"""The bundle's main part (verification.tex): at most four pages of a two-column paper in the style
of the methods papers people cite (Price 2012, Rosswog 2015, SPHENIX): Table 1, one line per case
(its headline error, levels, window and observed order), Sod's four profiles and the Sedov and Noh
radial profiles at three resolutions against their exact solutions, and one convergence figure of
the hydrodynamics cases with each known failure beside the experiment that converges.

The numbers are the harness's: the window of a claim is the acceptance interval its order check
recorded in sweep.json (or a "window" the row or the claim carries), never one computed here."""
from report_data import OUTCOMES, claim_tex, f2, num, series, variant_named
import re

import report_figures as figs
from report_math import error_name, latex, mathtext, prose

TUBE = ("sod", (("profile_rho", "density $\\rho$"), ("profile_v", "velocity $v_x$"), ("profile_p", "pressure $p$"),
                ("profile_u", "specific internal energy $u$")))
RADIAL = (("sedov", "profile_rho", "Sedov: density $\\rho$"), ("sedov", "profile_v", "Sedov: velocity $v_r$"),
          ("noh", "profile_rho", "Noh: density $\\rho$"), ("noh", "profile_u", "Noh: internal energy $u$"))
# The cases of the convergence figure, in this order, then other cases with a verified claim over
# three levels or more, up to PANELS panels.
CONVERGENCE = ("sod", "sedov", "noh", "sound_wave", "gresho", "kh", "evrard", "square")
PANELS = 8
SHORT = {"verified": "verified", "known failure": "known failure", "provisional": "provisional",
         "no order claimed": "no claim", "fail": "fail"}
OUTCOME_TEX = {"verified": r"\textcolor[rgb]{0,0.4,0}{verified}", "known failure": r"\textcolor[rgb]{0.5,0.15,0.6}{known failure}",
               "provisional": r"\textcolor[rgb]{0.63,0.31,0}{\emph{provisional}}",
               "no order claimed": r"\textcolor[rgb]{0.52,0.36,0}{no claim}", "fail": r"\textcolor[rgb]{0.7,0,0}{\textbf{fail}}"}


def three_levels(s):
    """Indices of the runs a profile figure shows: all of up to three, else the coarsest, the
    middle and the finest."""
    k = len(s["runs"])
    return list(range(k)) if k <= 3 else [0, k // 2, k - 1]


def run_figures(s, name):
    """(n, the figure named name) of three levels of a sweep, where that run drew it."""
    out = []
    for k in three_levels(s):
        f = next((f for f in s["runs"][k].get("figures", []) if f["name"] == name), None)
        if f:
            out.append((s["levels"][k], f))
    return out


def headline(s):
    """The row a case's line in Table 1 shows: a failing row first (a failure is never hidden),
    else its claimed rows in the order verified, known failure; a density L1 error before others."""
    claimed = [r for r in s["rows"] if num(r.get("expected")) or r["outcome"] == "fail"]
    if not claimed:
        return None
    rank = {"fail": 0, "verified": 1, "known failure": 2, "provisional": 3, "no order claimed": 4}
    return min(claimed, key=lambda r: (rank.get(r["outcome"], 5), not r["error"].startswith("L1"), "rho" not in r["error"]))


def experiment(ss, s, row):
    """The variant a known failure names as the one that converges, with its row of the same error."""
    name = row.get("experiment") or s.get("claims", {}).get(row["error"], {}).get("experiment")
    if not name:
        return None, None
    v = variant_named(ss, name, besides=s)
    r = next((r for r in v["rows"] if r["error"] == row["error"]), None) if v else None
    return v, r


def window(s, row):
    """The acceptance window of a row's order claim as the results record it: a "window" of the row
    or claim, else the order check's [lo, hi] (order_E, or known_failure_order_E whose band the
    order stays outside); None without one."""
    for w in (row.get("window"), s.get("claims", {}).get(row["error"], {}).get("window")):
        if isinstance(w, (list, tuple)) and len(w) == 2:
            return tuple(w)
    for name in (f"order_{row['error']}", f"known_failure_order_{row['error']}"):
        c = next((c for c in s["checks"] if c["name"] == name), None)
        if c:
            return c.get("lo"), c.get("hi")
    return None


def window_tex(s, row):
    w = window(s, row)
    if not w:
        return "--"
    lo, hi = (f2(v) if num(v) else None for v in w)
    side = "outside " if row["outcome"] == "known failure" else ""
    if lo is None and hi is None:
        return "--"
    if hi is None:
        return f"{side}$\\ge {lo}$"
    if lo is None:
        return f"{side}$\\le {hi}$"
    return f"{side}$[{lo}, {hi}]$"


def order_tex(row):
    if not num(row.get("observed")):
        return "--"
    return f"${f2(row['observed'])} \\pm {f2(row['se'])}$" if num(row.get("se")) else f"${f2(row['observed'])}$"


def expected_tex(row):
    return claim_tex(row, "--")


def levels_tex(s):
    lv = s["levels"]
    return "--" if not lv else f"{lv[0]}" if len(lv) == 1 else f"{lv[0]}--{lv[-1]} ({len(lv)})"


def table_line(case, ss):
    s = ss[0]
    row = headline(s)
    name = prose(case)
    if row is None:
        checks = [c for c in s["checks"] if c.get("kind", "verification") == "verification"]
        ok = sum(c["pass"] for c in checks)
        verdict = OUTCOME_TEX["verified"] if ok == len(checks) else OUTCOME_TEX["fail"]
        return (f"{name} & \\multicolumn{{5}}{{l}}{{checks only: {ok} of {len(checks)} verification checks pass}} & "
                f"{verdict.replace('verified', 'pass')} \\\\")
    outcome = OUTCOME_TEX.get(row["outcome"], latex(row["outcome"]))
    if row["outcome"] == "known failure":
        v, r = experiment(ss, s, row)
        if r is not None:
            outcome += (f"; {prose(v['variant'])}: ${f2(r['observed'])}$" if num(r.get("observed")) else
                        f"; {prose(v['variant'])}") + ("" if r["outcome"] == "verified" else f" ({SHORT[r['outcome']]})")
    return (f"{name} & {error_name(row['error'])} & {levels_tex(s)} & {expected_tex(row)} & {window_tex(s, row)} & "
            f"{order_tex(row)} & \\parbox[t]{{3.1cm}}{{\\raggedright {outcome}}} \\\\")


def table(sweeps):
    lines = [table_line(case, ss) for case, ss in sorted(sweeps.items())]
    return [r"\begin{table*}", r"\centering\footnotesize\setlength{\tabcolsep}{3pt}",
            r"\caption{Verification summary, one line per case: the headline error of its default variant (a failing "
            r"error first, else a verified one), the levels $n$ (first--last, their number), the claimed order, the "
            r"window within which the observed order $p$ must lie (as the harness's order check recorded it; for a known "
            r"failure the band its order stays outside) and $p$ with the standard error of the fit. A known failure "
            r"names the variant that converges and its order (in brackets where that variant does not verify it). Every "
            r"variant's rows: supplement.}\label{tab:verification}",
            r"\begin{tabular}{@{}l l l l l l l@{}}", r"\toprule",
            r"case & error & $n$ & claimed & window & observed $p$ & outcome \\ \midrule",
            *lines, r"\bottomrule", r"\end{tabular}", r"\end{table*}"]


def default(sweeps, case):
    return sweeps[case][0] if case in sweeps else None


def tube_figure(sweeps, figdir):
    """Sod's four profiles at three levels, or None without the case."""
    case, fields = TUBE
    s = default(sweeps, case)
    if not s:
        return None
    panels = [{"runs": run_figures(s, name), "title": title, "xlabel": "$x$"} for name, title in fields]
    stem = figs.profiles(panels, figdir / "paper_sod_profiles")
    if not stem:
        return None
    lv = ", ".join(str(n) for n, _ in max((p["runs"] for p in panels), key=len))
    title = next((f.get("title", "") for p in panels for _, f in p["runs"][-1:]), "")
    when = re.search(r"(\d)D\b.*\bt = ([0-9.eE+-]+)", title)
    where = f"{when.group(1)}D, $t = {float(when.group(2)):g}$" if when else ""
    return stem, (f"Sod shock tube ({prose(s['variant'])} variant{'; ' + where if where else ''}): the particles at "
                  f"$n = {lv}$ ({latex(s.get('n_counts', ''))}; coarse to fine: orange, green, blue, or green and blue for two) against the exact "
                  r"Riemann solution \citep{toro2009} (black) at the end time. Errors and orders: Table~\ref{tab:verification}.")


def radial_figure(sweeps, figdir):
    panels = []
    for case, name, title in RADIAL:
        s = default(sweeps, case)
        if s:
            panels.append({"runs": run_figures(s, name), "title": title, "case": case, "s": s})
    panels = [p for p in panels if p["runs"]]
    if not panels:
        return None
    stem = figs.profiles(panels, figdir / "paper_radial_profiles")
    if not stem:
        return None
    parts = []
    for case in dict.fromkeys(p["case"] for p in panels):
        p = next(p for p in panels if p["case"] == case)
        lv = ", ".join(str(n) for n, _ in p["runs"])
        cite = {"sedov": r"\citep{sedov1959}", "noh": r"\citep{noh1987}"}.get(case, "")
        parts.append(f"{prose(case.capitalize())} ({prose(p['s']['variant'])} variant, $n = {lv}$, "
                     f"{latex(p['s'].get('n_counts', ''))}) against its exact solution {cite}")
    return stem, ("Radial profiles at the end time, particles coarse to fine in orange, green, blue (green and blue where a "
                  "case ran two levels): " + "; ".join(parts)
                  + r". Radii in units of the panels' axes. Errors and orders: Table~\ref{tab:verification}.")


def convergence_panels(sweeps):
    """Per case of CONVERGENCE present, then other cases with a verified claim over three levels or
    more: its default's headline error; a known failure with its experiment's same error beside it."""
    order = [c for c in CONVERGENCE if c in sweeps] + sorted(c for c in sweeps if c not in CONVERGENCE)
    panels = []
    for case in order:
        ss = sweeps[case]
        s = ss[0]
        if case not in CONVERGENCE:  # its first variant whose headline row is verified
            s = next((v for v in ss if (headline(v) or {}).get("outcome") == "verified"), s)
        row = headline(s)
        if row is None or row["outcome"] == "no order claimed":
            continue
        if case not in CONVERGENCE and (row["outcome"] != "verified" or len(s["levels"]) < 3):
            continue
        curves = [curve(s, row)]
        if row["outcome"] == "known failure":
            v, r = experiment(ss, s, row)
            if r is not None:
                curves.append(curve(v, r))
        curves = [c for c in curves if c and len(c["n"]) >= 2]
        if curves:
            panels.append({"title": mathtext(f"{case}: ") + error_name(row["error"], for_tex=False), "case": case, "curves": curves, "rows": [row]})
        if len(panels) == PANELS:
            break
    return panels


def curve(s, row):
    pts = series(s, row["error"])
    if not pts:
        return None
    n, y = zip(*pts)
    # A long variant name would fill a narrow panel: the caption names it.
    return {"label": mathtext(s["variant"]) if len(s["variant"]) <= 14 else "experiment", "variant": s["variant"],
            "n": n, "y": y, "observed": row.get("observed"), "se": row.get("se"), "outcome": row["outcome"],
            "expected": row.get("expected"), "error": row["error"]}


def convergence_figure(sweeps, figdir):
    panels = convergence_panels(sweeps)
    stem = figs.convergence_panels(panels, figdir / "paper_convergence")
    if not stem:
        return None
    known = [p for p in panels if len(p["curves"]) > 1]
    text = ("Convergence of the headline error of each hydrodynamics case (default variant; Table~\\ref{tab:verification}) "
            "against resolution $n$: points as measured, lines the least-squares fits with the observed order $p$, dotted "
            "the claimed order through the finest point. Filled blue: verified; brown: no order claimed; red: fail; open purple, "
            "dashed: a known failure")
    if known:
        text += (", drawn beside the variant that converges instead (" + "; ".join(
            f"{prose(p['case'])}: {prose(p['curves'][1]['variant'])}" for p in known) + ")")
    return stem, text + ". What $n$ counts per case: supplement."


def figure_tex(name, caption, label):
    return [r"\begin{figure*}", r"\centering", f"\\includegraphics{{figures/{name}}}", f"\\caption{{{caption}}}\\label{{{label}}}",
            r"\end{figure*}"]


def section(sweeps, figdir, copy, provenance_sentence):
    """verification.tex. copy(stem) puts a figure into the bundle and returns its file name."""
    n_rows = {k: sum(r["outcome"] == k for ss in sweeps.values() for s in ss for r in s["rows"]) for k in OUTCOMES}
    n_var = sum(len(ss) for ss in sweeps.values())
    made = [(m, label) for m, label in ((tube_figure(sweeps, figdir), "fig:sod"), (radial_figure(sweeps, figdir), "fig:radial"),
                                         (convergence_figure(sweeps, figdir), "fig:convergence")) if m]
    shown = {label for _, label in made}
    refs = []
    if "fig:sod" in shown or "fig:radial" in shown:
        refs.append("Fig" + ("s.~\\ref{fig:sod} and~\\ref{fig:radial}" if {"fig:sod", "fig:radial"} <= shown else
                             f".~\\ref{{{'fig:sod' if 'fig:sod' in shown else 'fig:radial'}}}") + " show the shock problems at three resolutions")
    if "fig:convergence" in shown:
        refs.append("Fig.~\\ref{fig:convergence} the convergence of each hydrodynamics case")
    t = [r"% Generated by scripts/report.py --bundle (scripts/bundle.sh): \input{verification} in a two-column paper",
         r"% (needs graphicx, booktabs, xcolor and natbib's \citep, \citet, \citealt; the references: verification.bib).",
         r"% Figures are drawn at print size (84 mm column, 174 mm page) and included unscaled: their text prints at 8 pt.",
         r"\section{Verification}\label{sec:verification}",
         provenance_sentence +
         r"Each case compares the SPH result with a reference independent of the code: an exact solution (Sod's "
         r"shock tube, \citealt{toro2009}; the Sedov--Taylor blast, \citealt{sedov1959}; Noh's implosion, "
         r"\citealt{noh1987}; the Gresho--Chan vortex, \citealt{gresho1990}), a linear theory (sound waves; the Kelvin--Helmholtz growth of \citealt{mcnally2012}), "
         r"an independent solver (a 1D Lagrangian code for the collapse of \citealt{evrard1988} and for the Sedov blast "
         r"from the run's own finite deposit; SUNDIALS for heat "
         r"conduction), a direct summation (gravity) or a quadrature (kernels, \citealt{dehnen2012}). The equations are "
         r"those of \citet{chapter}.",
         "",
         r"Each error $E$ is measured at levels $n_1 < \dots < n_k$ of resolution. Its observed order $p$ is the slope of "
         r"the least-squares fit of $-\ln E$ against $\ln n$, with the standard error $\sigma_p$ of that slope. A claim "
         r"$p_0 \pm b$ is \emph{verified} when $p$ lies in the claim's window (Table~\ref{tab:verification}: the "
         r"acceptance interval of the harness's order check, as recorded with the results), the fit resolves the order "
         r"and $E$ lies under its bound; \emph{no claim} means the error has no convergent limit, as the case states, and "
         r"its bounds hold; a \emph{known failure} misses its order for a reason the case states and names the variant "
         r"that converges instead; \emph{provisional} means the error lies inside the former window $p_0 \pm (b + 2\sigma_p)$ "
         r"but not the acceptance rule's, and is not counted as verified; \emph{fail} means a check on that error failed. "
         f"Over all {n_var} variants of the {len(sweeps)} cases: {n_rows['verified']} errors verified, {n_rows['known failure']} "
         f"known failure{'s' if n_rows['known failure'] != 1 else ''}, {n_rows.get('provisional', 0)} provisional, "
         f"{n_rows['no order claimed']} with no order claimed, {n_rows['fail']} failing. " + ("; ".join(refs) + "; " if refs else "") +
         r"the supplement (\texttt{verification-supplement.tex}) holds every variant, check, error definition and figure.", ""]
    t += table(sweeps)
    for (stem, caption), label in made:
        t += figure_tex(copy(stem), caption, label)
    return "\n".join(t) + "\n"
