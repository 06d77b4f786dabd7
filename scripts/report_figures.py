"""The report's figures: every figure is written as PNG (for the page) and vector PDF (for a paper).
Each function returns the file stem it wrote, or None when there is nothing to draw (no empty plots)."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

from report_data import claim, file_of, num, series, wrap  # noqa: E402

plt.rcParams.update({"pdf.fonttype": 42, "font.size": 8, "axes.titlesize": 9, "legend.fontsize": 7})


def save(fig, stem, **margins):
    stem.parent.mkdir(parents=True, exist_ok=True)
    # Fixed margins with room for labels of up to three lines (wrap()): "tight" bounding boxes or
    # constrained layout cost a further draw of every figure, nearly doubling the report's time.
    fig.subplots_adjust(**({"left": 0.16, "right": 0.97, "bottom": 0.15, "top": 0.89} | margins))
    for ax in fig.axes:  # a log axis over less than a decade labels some minor ticks too (one major tick says little;
        for axis in (ax.xaxis, ax.yaxis):  # over more, minor labels run into each other)
            if axis.get_scale() == "log" and isinstance(axis.get_minor_formatter(), matplotlib.ticker.LogFormatter):
                axis.set_minor_formatter(matplotlib.ticker.LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(1, 0.5)))
    for ext in ("png", "pdf"):
        fig.savefig(file_of(stem, ext), dpi=110)
    plt.close(fig)
    return stem


def convergence(case, s, row, stem):
    """Error against n for one claimed error of one variant: the measured points, the harness's
    least-squares fit (its order and standard error) and the expected order with its band,
    drawn through the finest point."""
    e = row["error"]
    pts = series(s, e)
    c = claim(s, e)
    if len(pts) < 2 or c is None:
        return None
    n, y = (np.array(v, float) for v in zip(*pts))
    fig, ax = plt.subplots(figsize=(5.6, 4))
    ax.loglog(n, y, "o", color="C0", label=f"measured, n = {n[0]:g} to {n[-1]:g}")
    if num(row.get("observed")):
        p = row["observed"]
        logc = np.mean(np.log(y) + p * np.log(n))  # intercept of the fit with slope -p
        se = f" ± {row['se']:.2f}" if num(row.get("se")) else ""
        ax.loglog(n, np.exp(logc - p * np.log(n)), "-", color="C0", lw=1, label=f"least-squares fit: order {p:.2f}{se}")
    q, band = c["expected"], c.get("band", 0.0) or 0.0
    guide = lambda order: y[-1] * (n / n[-1]) ** (-order)  # noqa: E731
    ax.loglog(n, guide(q), "--", color="C3", lw=1, label=f"expected order {q:.3g} ± {band:.3g} (through the finest point)")
    if band > 0:
        ax.fill_between(n, guide(q - band), guide(q + band), color="C3", alpha=0.12, lw=0)
    ax.set_xticks(n, [f"{v:g}" for v in n])  # the levels themselves, not powers of ten
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("n")  # what n counts is in the caption
    ax.set_ylabel(e)  # the error's name; its definition is in the caption (a long one would be clipped)
    ax.set_title(f"{case} [{s['variant']}]: {e} against n ({row['outcome']})")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    return save(fig, stem)


def wall_time(case, ss, error, stem):
    """Error against the wall time of each run, one line per variant that reports the error (none
    when no variant has two points)."""
    fig, ax = plt.subplots(figsize=(5.6, 4))
    drawn = longest = 0
    for k, s in enumerate(ss):
        pts = [(run.get("wall_time_s"), run.get("errors", {}).get(error), n) for n, run in zip(s["levels"], s["runs"])]
        pts = [p for p in pts if num(p[0]) and p[0] > 0 and num(p[1]) and p[1] > 0]
        if not pts:
            continue
        longest = max(longest, len(pts))
        t, y, n = zip(*pts)
        outcome = next((r["outcome"] for r in s["rows"] if r["error"] == error), "no claim")
        ax.loglog(t, y, "o-", color=f"C{k % 10}", ms=4, lw=0.8, label=f"{s['variant']} ({outcome})")
        if len(ss) <= 3:  # which level each point is: timings of small runs are noisy
            for tx, ty, nx in pts:
                ax.annotate(f"n={nx:g}", (tx, ty), textcoords="offset points", xytext=(4, 3), fontsize=6, color=f"C{k % 10}")
        drawn += 1
    if not drawn or longest < 2:  # one point per line says nothing about cost against accuracy
        plt.close(fig)
        return None
    ax.set_xlabel("wall time of the run [s]")
    ax.set_ylabel(error)
    ax.set_title(f"{case}: {error} against run time, one line per variant")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    return save(fig, stem)


def run_figure(f, suffix, stem):
    """A figure a run describes in its result.json (profiles, time series); points that a log
    axis cannot show are left out, and a figure with no point left is not drawn."""
    fig, ax = plt.subplots(figsize=(5.6, 4))
    drawn = 0
    for k, srs in enumerate(f["series"]):
        x = np.array([v if num(v) else np.nan for v in srs["x"]], float)
        y = np.array([v if num(v) else np.nan for v in srs["y"]], float)
        ok = np.isfinite(x) & np.isfinite(y)
        if f["xscale"] == "log":
            ok &= x > 0
        if f["yscale"] == "log":
            ok &= y > 0
        if not ok.any():
            continue
        marker = "o" if ok.sum() <= 12 else None  # short series (sweeps, benchmarks) show their points
        style = {"points": dict(ls="none", marker=".", ms=3), "dashed": dict(ls="--", marker=marker, ms=3),
                 "line": dict(ls="-", marker=marker, ms=3)}
        ax.plot(x[ok], y[ok], label=srs["label"] or None, color=f"C{k % 10}", **style.get(srs["style"], {}))
        drawn += 1
    if not drawn:
        plt.close(fig)
        return None
    ax.set_xscale(f["xscale"])
    ax.set_yscale(f["yscale"])
    ax.set_xlabel(wrap(f["xlabel"], 70))
    ax.set_ylabel(wrap(f["ylabel"], 55))
    ax.set_title(wrap(f"{f['title']}{suffix}", 62))
    if any(line.get_label() and not line.get_label().startswith("_") for line in ax.get_lines()):
        ax.legend()
    ax.grid(True, alpha=0.3)
    return save(fig, stem)


def kernels(case, label, members, errors, stem):
    """The kernel comparison of one group (report_kernels.py): per error (a column), the error
    against n (top, the observed order's slope) and against the wall time of each run (bottom,
    the fixed cost marked by a dotted line), one line per kernel."""
    import report_kernels as rk  # noqa: E402 (the figures module stays free of the comparison's logic)
    if not errors:
        return None
    cols = len(errors)
    width = max(5.6, 3.0 * cols + 0.8)
    fig, axes = plt.subplots(2, cols, figsize=(width, 5.6), squeeze=False)
    drawn = 0
    for j, err in enumerate(errors):
        n_fixed, t_fixed, _ = rk.comparison(members, err)
        for k, (kernel, s) in enumerate(members):
            pts = rk.points(s, err)
            if not pts:
                continue
            n, t, y = zip(*pts)
            style = dict(color=f"C{k % 10}", marker="os^vDP"[k % 6], ms=4, lw=0.8, label=kernel)
            axes[0][j].loglog(n, y, **style)
            axes[1][j].loglog(t, y, **style)
            drawn += 1
        if n_fixed is not None:
            axes[0][j].axvline(n_fixed, color="0.5", ls=":", lw=0.8)
        if t_fixed is not None:
            axes[1][j].axvline(t_fixed, color="0.5", ls=":", lw=0.8)
        levels = sorted({p[0] for _, s in members for p in rk.points(s, err)})
        axes[0][j].set_xticks(levels, [f"{v:g}" for v in levels])  # the levels themselves
        axes[0][j].set_title(err)
        axes[0][j].set_xlabel("n")
        axes[1][j].set_xlabel("wall time of the run [s]")
        axes[0][j].xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        # Wall times in plain numbers at 1, 2, 5 per decade: narrow panels have no room for more.
        axes[1][j].xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
        axes[1][j].xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        axes[1][j].xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        for ax in axes[:, j]:
            ax.grid(True, which="both", alpha=0.3)
    if not drawn:
        plt.close(fig)
        return None
    axes[0][0].set_ylabel("error against n")
    axes[1][0].set_ylabel("error against cost")
    axes[0][0].legend(fontsize=6)
    fig.suptitle(wrap(f"{case} [{label}]: kernels compared (dotted: the fixed resolution and the fixed cost)", int(13 * width)), fontsize=9)
    return save(fig, stem, left=0.85 / width, right=0.98, bottom=0.09, top=0.88, wspace=0.35, hspace=0.38)
