#!/usr/bin/env python3
"""Turns a folder of sphv results into reports/<name>/: index.html, every figure as PNG and
vector PDF, tables.tex (errors, observed orders, GCI) and the verdict summary.

usage: report.py RESULTS_DIR [--name NAME] [--reports DIR] [--bundle DIR]
RESULTS_DIR holds CASE/VARIANT/sweep.json as `sphv verify` writes them (a single sweep
folder with sweep.json works too). --bundle also writes a publication bundle: figures as
PDF, tables.tex, verification.tex (to \\input in a paper), provenance.json and
reproduce.sh with the exact commands behind every number."""
import argparse
import html
import json
import math
import os
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load_sweeps(root):
    files = sorted(root.glob("**/sweep.json"))
    if not files and not (root / "bench.json").exists():
        sys.exit(f"report.py: error: no sweep.json or bench.json under {root}")
    sweeps = {}
    for f in files:
        s = json.loads(f.read_text())
        sweeps.setdefault(s["case"], []).append(s)
    for runs in sweeps.values():  # the default variant first
        runs.sort(key=lambda s: (s["variant"] != "default", s["variant"]))
    return sweeps


def finite(v):
    return v is not None and isinstance(v, (int, float)) and math.isfinite(v) and v > 0


def save(fig, out, stem):
    fig.tight_layout()
    for ext in ("png", "pdf"):
        fig.savefig(out / f"{stem}.{ext}", dpi=110)
    plt.close(fig)
    return f"{stem}.png"


def errors_with_orders(s):
    """Errors with an expected order first, then the others (floors are shown, not hidden)."""
    names = list(s["expected_order"]) + sorted(set(s["observed_order"]) - set(s["expected_order"]))
    return [e for e in names if any(finite(r["errors"].get(e)) for r in s["runs"])]


def convergence_figure(case, s, out, stem):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    n = np.array([r["params"]["n"] for r in s["runs"]], float)
    for k, e in enumerate(errors_with_orders(s)):
        y = np.array([r["errors"].get(e) if finite(r["errors"].get(e)) else np.nan for r in s["runs"]], float)
        ok = np.isfinite(y)
        if ok.sum() == 0:
            continue
        col = f"C{k}"
        p_obs = s["observed_order"].get(e)
        p_exp = s["expected_order"].get(e)
        label = f"{e}: observed {p_obs:.2f}" if p_obs is not None else e
        if p_exp is not None:
            label += f" (expected {p_exp:g})"
        ax.loglog(n[ok], y[ok], "o", color=col, label=label)
        if ok.sum() >= 2 and p_obs is not None:  # the least-squares fit
            c = np.mean(np.log(y[ok]) + p_obs * np.log(n[ok]))
            ax.loglog(n[ok], np.exp(c - p_obs * np.log(n[ok])), "-", color=col, lw=1)
        if p_exp is not None:  # expected-order guide through the finest point
            i = np.where(ok)[0][-1]
            ax.loglog(n[ok], y[i] * (n[ok] / n[i]) ** (-p_exp), ":", color=col, lw=1)
    ax.set_xlabel(f"resolution n")
    ax.set_ylabel("error (relative or L1, see case)")
    ax.set_title(f"{case} [{s['variant']}]: error against resolution\n(solid: fit, dotted: expected order)", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    return save(fig, out, stem)


def headline(s):
    names = errors_with_orders(s)
    return names[0] if names else None


def work_precision_figure(case, sweeps, out, stem):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    drawn = False
    e = headline(sweeps[0])
    for k, s in enumerate(sweeps):
        pts = [(r["wall_time_s"], r["errors"].get(e)) for r in s["runs"] if finite(r["errors"].get(e)) and r["wall_time_s"] > 0]
        if pts:
            t, y = zip(*pts)
            ax.loglog(t, y, "o-", color=f"C{k % 10}", label=s["variant"])
            drawn = True
    if not drawn:
        plt.close(fig)
        return None
    ax.set_xlabel("wall time per run [s]")
    ax.set_ylabel(f"{e}")
    ax.set_title(f"{case}: error against run time, one line per variant", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    return save(fig, out, stem)


def run_figure(f, title_suffix, out, stem):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for k, srs in enumerate(f["series"]):
        x = np.array([v if v is not None else np.nan for v in srs["x"]], float)
        y = np.array([v if v is not None else np.nan for v in srs["y"]], float)
        marker = "o" if len(x) <= 12 else None  # short series (sweeps, benchmarks) show their points
        style = {"points": dict(ls="none", marker=".", ms=3), "dashed": dict(ls="--", marker=marker, ms=3),
                 "line": dict(ls="-", marker=marker, ms=3)}
        ax.plot(x, y, label=srs["label"], color=f"C{k % 10}", **style.get(srs["style"], {}))
    ax.set_xscale(f["xscale"])
    ax.set_yscale(f["yscale"])
    ax.set_xlabel(f["xlabel"])
    ax.set_ylabel(f["ylabel"])
    ax.set_title(f"{f['title']}{title_suffix}", fontsize=9)
    if f["series"]:
        ax.legend(fontsize=7)
    ax.grid(True, alpha=0.3)
    return save(fig, out, stem)


def fmt(v, spec=".3e"):
    return format(v, spec) if isinstance(v, (int, float)) and math.isfinite(v) else "-"


def tex_escape(s):
    out = str(s).replace("\\", "/")
    for a, b in (("{", r"\{"), ("}", r"\}"), ("_", r"\_"), ("%", r"\%"), ("&", r"\&"), ("#", r"\#"),
                 ("$", r"\$"), ("^", r"\^{}"), ("~", r"\~{}"), ("<", r"$<$"), (">", r"$>$")):
        out = out.replace(a, b)
    return out


def reproduce_command(s):
    prov = s["runs"][0].get("provenance", {})
    levels = ",".join(str(r["params"]["n"]) for r in s["runs"])
    sets = "".join(f" --set {kv}" for kv in s["settings"])
    return (f"build/sphv --threads {prov.get('threads', 1)} sweep {s['case']} --levels {levels}{sets} "
            f"--jobs 1 --out runs/bundle/{s['case']}/{s['variant']}")


def write_bundle(bundle, sweeps, report_dir, tables_tex):
    import shutil
    import subprocess
    figs = bundle / "figures"
    figs.mkdir(parents=True, exist_ok=True)
    for pdf in report_dir.glob("*.pdf"):
        shutil.copy(pdf, figs / pdf.name)
    (bundle / "tables.tex").write_text(tables_tex)
    first = next(iter(sweeps.values()))[0]["runs"][0]
    prov = dict(first.get("provenance", {}))
    prov["uname"] = " ".join(os.uname())
    prov["commands"] = [reproduce_command(s) for ss in sweeps.values() for s in ss]
    (bundle / "provenance.json").write_text(json.dumps(prov, indent=1) + "\n")
    (bundle / "reproduce.sh").write_text(
        "#!/usr/bin/env bash\n# Re-runs every sweep behind the bundle (from the repository root, at commit "
        f"{prov.get('git_commit')}), then rebuilds the report and this bundle.\nset -e\n"
        "bash scripts/build.sh\n" + "\n".join(prov["commands"]) +
        "\n/usr/bin/python3 scripts/report.py runs/bundle --name bundle --bundle bundle\n")
    t = [r"% Generated by scripts/report.py --bundle; \input{verification} in a paper (needs graphicx).",
         r"\section{Verification}",
         "All numbers below were produced by sphv at commit \\texttt{" + tex_escape(prov.get("git_commit")) +
         "}, compiled by " + tex_escape(prov.get("compiler")) + " (" + tex_escape(prov.get("build_type")) +
         ", flags \\texttt{" + tex_escape(prov.get("cxx_flags", "").strip()) + "}) on " +
         tex_escape(prov.get("cpu")) + " with " + str(prov.get("threads")) + " OpenMP threads, " +
         tex_escape(prov.get("date")) + ". The commands that reproduce every number are in \\texttt{reproduce.sh}. "
         "Observed orders are least-squares slopes of $\\log$ error against $\\log n$; GCI is Roache's grid "
         "convergence index of the finest pair ($F_s = 1.25$ with three or more levels).", ""]
    for case, ss in sorted(sweeps.items()):
        s0 = ss[0]
        t += [r"\subsection{" + tex_escape(case) + "}", tex_escape(s0.get("summary", "")) + ". Resolution $n$: " +
              tex_escape(s0.get("n_counts", "")) + ". Expected orders: " + tex_escape(s0.get("expected_why", "")) + ".", "",
              r"\begin{center}\begin{tabular}{llrrrr}\hline",
              r"variant & error & levels $n$ & error at finest & observed order & expected \\ \hline"]
        for s in ss:
            lv = [r["params"]["n"] for r in s["runs"]]
            for e in errors_with_orders(s):
                t.append(f"{tex_escape(s['variant'])} & {tex_escape(e)} & {lv[0]}--{lv[-1]} & {fmt(s['runs'][-1]['errors'].get(e))} & "
                         f"{fmt(s['observed_order'].get(e), '.2f')} & {fmt(s['expected_order'].get(e), 'g')} \\\\")
        t += [r"\hline\end{tabular}\end{center}"]
        gci = [(s["variant"], k, g) for s in ss for k, g in s["gci"].items()]
        if gci:
            t.append("GCI: " + "; ".join(f"{tex_escape(v)} {tex_escape(k)} = {fmt(g['fine_value'], '.6g')} "
                                         f"$\\pm$ {fmt(g['gci'], '.2e')} (relative)" for v, k, g in gci) + ".")
        checks = [c for s in ss for c in s["checks"]]
        t.append(f"Gates: {sum(c['pass'] for c in checks)} of {len(checks)} checks pass.")
        for pdf in sorted(figs.glob(f"{case}_*.pdf")):
            t += [r"\begin{figure}[htbp]\centering", r"\includegraphics[width=0.7\linewidth]{figures/" + pdf.name + "}",
                  r"\caption{" + tex_escape(case) + ": " + tex_escape(pdf.stem.split("_", 2)[-1].replace("_", " ")) + ".}",
                  r"\end{figure}"]
        t.append(r"\clearpage")
    (bundle / "verification.tex").write_text("\n".join(t) + "\n")
    (bundle / "example.tex").write_text("\\documentclass{article}\n\\usepackage{graphicx}\n\\begin{document}\n"
                                        "\\input{verification}\n\\end{document}\n")
    if shutil.which("pdflatex"):
        res = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "example.tex"], cwd=bundle,
                             capture_output=True, text=True)
        print("bundle: example.tex " + ("compiles" if res.returncode == 0 else "FAILS to compile: see example.log"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results", type=Path)
    ap.add_argument("--name", default="verify")
    ap.add_argument("--reports", type=Path, default=Path(__file__).resolve().parent.parent / "reports")
    ap.add_argument("--bundle", type=Path, help="also write a publication bundle to this folder")
    a = ap.parse_args()
    if not a.results.is_dir():
        sys.exit(f"report.py: error: {a.results} is not a directory")
    sweeps = load_sweeps(a.results)
    out = a.reports / a.name
    out.mkdir(parents=True, exist_ok=True)

    rows, tex_rows, body = [], [], []
    for case, ss in sorted(sweeps.items()):
        body.append(f"<h2 id='{case}'>{html.escape(case)}</h2>")
        imgs = []
        for k, s in enumerate(ss):
            imgs.append(convergence_figure(case, s, out, f"{case}_{k}_convergence"))
        wp = work_precision_figure(case, ss, out, f"{case}_work_precision")
        if wp:
            imgs.append(wp)
        for k, s in enumerate(ss):
            finest = s["runs"][-1]
            for f in finest["figures"]:
                suffix = f" [{s['variant']}, n={finest['params']['n']}]"
                imgs.append(run_figure(f, suffix, out, f"{case}_{k}_{f['name']}"))
        body.append("".join(f"<a href='{i}'><img src='{i}' width='480'></a>" for i in imgs))
        body.append("<table><tr><th>variant</th><th>error</th><th>n</th><th>value</th><th>observed</th>"
                    "<th>expected</th><th>wall s</th></tr>")
        for s in ss:
            for e in errors_with_orders(s):
                for r in s["runs"]:
                    body.append(f"<tr><td>{html.escape(s['variant'])}</td><td>{e}</td><td>{r['params']['n']}</td>"
                                f"<td>{fmt(r['errors'].get(e))}</td><td>{fmt(s['observed_order'].get(e), '.2f')}</td>"
                                f"<td>{fmt(s['expected_order'].get(e), 'g')}</td><td>{fmt(r['wall_time_s'], '.3g')}</td></tr>")
                fine = s["runs"][-1]
                tex_rows.append(f"{tex_escape(case)} & {tex_escape(s['variant'])} & {tex_escape(e)} & {fine['params']['n']} & "
                                f"{fmt(fine['errors'].get(e))} & {fmt(s['observed_order'].get(e), '.2f')} & "
                                f"{fmt(s['expected_order'].get(e), 'g')} \\\\")
        body.append("</table>")
        if any(s["gci"] for s in ss):
            body.append("<p>Roache's grid convergence index (finest pair):</p><table><tr><th>variant</th><th>functional</th>"
                        "<th>value</th><th>order</th><th>Fs</th><th>GCI</th></tr>")
            for s in ss:
                for k, g in s["gci"].items():
                    body.append(f"<tr><td>{html.escape(s['variant'])}</td><td>{k}</td><td>{fmt(g['fine_value'], '.6g')}</td>"
                                f"<td>{fmt(g['order'], '.2f')}</td><td>{g['Fs']}</td><td>{fmt(g['gci'])}</td></tr>")
            body.append("</table>")
        body.append("<p>Gates:</p><table><tr><th>variant</th><th>check</th><th>value</th><th>bounds</th><th>why</th><th></th></tr>")
        for s in ss:
            for c in s["checks"]:
                body.append(f"<tr><td>{html.escape(s['variant'])}</td><td>{html.escape(c['name'])}</td><td>{fmt(c['value'], '.4g')}</td>"
                            f"<td>[{fmt(c['lo'], 'g')}, {fmt(c['hi'], 'g')}]</td><td>{html.escape(c['why'])}</td>"
                            f"<td class='{'pass' if c['pass'] else 'fail'}'>{'pass' if c['pass'] else 'FAIL'}</td></tr>")
            verdicts = sorted({r["verdict"] for r in s["runs"]})
            rows.append((case, s["variant"], s["passed"], ", ".join(verdicts), s["wall_time_s"]))
        body.append("</table>")

    bench_file = a.results / "bench.json"
    if bench_file.exists():
        b = json.loads(bench_file.read_text())
        pr = b["provenance"]
        body.append(f"<h2 id='bench'>Benchmarks</h2><p>{html.escape(b['benchmark'])}; {html.escape(str(pr.get('cpu')))}, "
                    f"{pr.get('cores')} cores, build {html.escape(str(pr.get('build_type')))} "
                    f"({html.escape(str(pr.get('cxx_flags')))}), {html.escape(str(pr.get('compiler')))}. "
                    "Benchmarks, not tests: nothing fails on a time.</p>")
        body.append("".join(f"<img src='{run_figure(f, '', out, f['name'])}' width='560'>" for f in b["figures"]))
        body.append("<table><tr><th>stage</th><th>N</th><th>threads</th><th>seconds</th><th>particle updates/s</th>"
                    "<th>pair interactions/s</th></tr>")
        for r in b["rows"]:
            body.append(f"<tr><td>{html.escape(r['stage'])}</td><td>{r['n']}</td><td>{r['threads']}</td><td>{fmt(r['seconds'], '.4g')}</td>"
                        f"<td>{fmt(r['particle_updates_per_s'])}</td><td>{fmt(r['pairs_per_s'])}</td></tr>")
        body.append("</table><p>Fitted cost slopes (time ~ N^slope): " +
                    ", ".join(f"{html.escape(k)} {fmt(v, '.2f')}" for k, v in b["fitted_slopes"].items()) +
                    ". Bytes per particle (hydro state + neighbour list, counted): " +
                    ", ".join(f"N={k}: {v:.0f}" for k, v in b["bytes_per_particle"].items()) +
                    "; peak resident memory per particle (measured, whole process): " +
                    ", ".join(f"N={k}: {v:.0f}" for k, v in b.get("peak_resident_bytes_per_particle", {}).items()) + ".</p>")

    summary = ["<table><tr><th>case</th><th>variant</th><th>gates</th><th>run verdicts</th><th>sweep wall s</th></tr>"]
    for case, variant, passed, verdicts, wall in rows:
        summary.append(f"<tr><td><a href='#{case}'>{case}</a></td><td>{html.escape(variant)}</td>"
                       f"<td class='{'pass' if passed else 'fail'}'>{'pass' if passed else 'FAIL'}</td>"
                       f"<td>{html.escape(verdicts)}</td><td>{wall:.2f}</td></tr>")
    summary.append("</table>")
    prov = next(iter(sweeps.values()))[0]["runs"][0].get("provenance", {}) if sweeps else {}
    prov_html = ", ".join(f"{k}: {html.escape(str(v))}" for k, v in prov.items())
    page = f"""<!doctype html><html><head><meta charset='utf-8'><title>sphv report: {a.name}</title>
<style>body{{font-family:sans-serif;max-width:1500px;margin:auto}} table{{border-collapse:collapse;margin:8px 0}}
td,th{{border:1px solid #ccc;padding:2px 6px;font-size:13px}} .pass{{color:#070}} .fail{{color:#b00;font-weight:bold}}</style>
</head><body><h1>sphv verification report: {a.name}</h1><p>{prov_html}</p>
<h2>Summary of verdicts</h2>{''.join(summary)}{''.join(body)}
<p>Every figure is also saved as vector PDF beside its PNG; LaTeX tables: <a href='tables.tex'>tables.tex</a>.</p>
</body></html>"""
    (out / "index.html").write_text(page)
    tex = ["% Generated by scripts/report.py", r"\begin{tabular}{lllrrrr}", r"\hline",
           r"case & variant & error & $n$ & error at $n$ & observed order & expected order \\", r"\hline",
           *tex_rows, r"\hline", r"\end{tabular}", ""]
    (out / "tables.tex").write_text("\n".join(tex))
    print(f"report: {out / 'index.html'} ({len(sweeps)} cases)")
    if a.bundle and sweeps:
        write_bundle(a.bundle, sweeps, out, "\n".join(tex))
        print(f"bundle: {a.bundle / 'verification.tex'}")


if __name__ == "__main__":
    main()
