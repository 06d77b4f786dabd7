"""The benchmark page of report.py (a folder with bench.json from `sphv bench`, scripts/bench.sh)."""
import html

import report_figures as figs
from report_data import file_of, fmt, is_dirty, read_json


def pct(x):
    return "" if x is None else f"{100 * x:.1f} %"


def times(x):
    return "" if x is None else f"{x:.2f}x"


def dirty_note(pr):
    """The uncommitted changes the bench was built with, if its provenance records any."""
    if not is_dirty(pr):
        return ""
    changes = (pr.get("source_tree") or {}).get("changes") or []
    listed = ": " + ", ".join(html.escape(c.strip()) for c in changes) if changes else ""
    return f" <span class='fail'>with uncommitted changes{listed}</span>"


def bench_body(results, out):
    b = read_json(results / "bench.json")
    pr = b["provenance"]
    e = html.escape
    scheme = f"; hydro stages: scheme {e(b['scheme'])} (sph/schemes/)" if "scheme" in b else ""
    body = [f"<h1>sphv benchmarks</h1><p>{e(b['benchmark'])}{scheme}; {e(str(pr.get('cpu')))}, {pr.get('cores')} cores, build "
            f"{e(str(pr.get('build_type')))} ({e(str(pr.get('cxx_flags')))}), {e(str(pr.get('compiler')))}, commit "
            f"{e(str(pr.get('git_commit')))}{dirty_note(pr)}, instruction-set path {e(str(pr.get('isa_path', 'portable')))} (pair loops and tree "
            f"walk). Benchmarks, not tests: nothing fails on a time.</p><div class='figs'>"]
    for f in b["figures"]:
        stem = figs.run_figure(f, "", out / "fig" / "bench" / f["name"])
        if stem:
            png, pdf = (file_of(stem, x).relative_to(out).as_posix() for x in ("png", "pdf"))
            body.append(f"<figure><a href='{e(png)}'><img src='{e(png)}' alt='{e(f['title'])}'></a>"
                        f"<figcaption>{e(f['title'])} (<a href='{e(pdf)}'>PDF</a>)</figcaption></figure>")
    body.append("</div><table><tr><th>stage</th><th>N</th><th>threads</th><th>seconds</th><th>particle updates/s</th>"
                "<th>pair interactions/s</th><th>ns per pair</th><th>speed-up over 1 thread</th><th>of measured peak</th></tr>")
    for r in b["rows"]:
        body.append(f"<tr><td>{e(r['stage'])}</td><td class='num'>{r['n']}</td><td class='num'>{r['threads']}</td>"
                    f"<td class='num'>{fmt(r['seconds'], '.4g')}</td><td class='num'>{fmt(r['particle_updates_per_s'], '.3e')}</td>"
                    f"<td class='num'>{fmt(r['pairs_per_s'], '.3e')}</td>"
                    f"<td class='num'>{fmt(r.get('ns_per_pair'), '.2f')}</td>"
                    f"<td class='num'>{times(r.get('speedup'))}</td>"
                    f"<td class='num'>{pct(r.get('fraction_of_peak'))}</td></tr>")
    body.append("</table><p>Fitted cost slopes (time ~ N^slope): " +
                ", ".join(f"{e(k)} {fmt(v, '.2f')}" for k, v in b["fitted_slopes"].items()) +
                ". Bytes per particle (hydro state + neighbour list, counted): " +
                ", ".join(f"N={k}: {v:.0f}" for k, v in b["bytes_per_particle"].items()) +
                "; peak resident memory per particle (measured, whole process): " +
                ", ".join(f"N={k}: {v:.0f}" for k, v in b.get("peak_resident_bytes_per_particle", {}).items()) +
                "; neighbour searches per full hydro step (lists reused while they cover): " +
                ", ".join(f"N={k}: {v:.2f}" for k, v in b.get("searches_per_step", {}).items()) + ".</p>")
    if "full_step_window" in b:
        body.append(f"<p>Full hydro step: evolve's own (Courant step, neighbour lists reused while they cover), timed "
                    f"over the {b['full_step_window']} steps after the first, each step at its least over the runs. \"Stored shuffled\": the same step from "
                    f"the particles stored in a random order (as another code's snapshot may hold them), with evolve's "
                    f"reordering of their storage along the search's cells, and without it.</p>")
    body.append("<p>Speed-up: a stage's time on one thread over its time on this many, the thread counts taking turns "
                "run by run.</p>")
    pk = b.get("peak")
    if pk:
        def at(n, runs):  # one N's peak on each thread count, before / after its runs, and as a multiple of one thread's
            one = runs.get("1")
            return f"N={n}: " + ", ".join(
                f"{t} thread(s) {v[0]:.3e} / {v[1]:.3e} flop/s" +
                (f" ({v[0] / one[0]:.2f}x / {v[1] / one[1]:.2f}x one thread's)" if one and t != "1" else "")
                for t, v in runs.items())
        body.append(f"<p>Share of peak: the hydro forces at {pk['force_pair_flops']:.0f} floating-point operations a pair "
                    f"(counted from the source, verification/commands/bench_hydro.hpp) against this CPU's double-precision peak, "
                    f"measured ({e(pk['method'])}; {e(pk['isa'])}), the larger of before and after. The peak on several "
                    f"threads against one thread's is what the machine gave the speed-ups (a virtual machine's cores "
                    f"can give well short of their number): " +
                    "; ".join(at(n, runs) for n, runs in pk["flops_per_s"].items()) + ".</p>")
    return "".join(body)
