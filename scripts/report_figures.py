"""The report's figures: every figure is written as PNG (for the page) and vector PDF (for a paper).
Each function returns the file stem it wrote, or None when there is nothing to draw (no empty plots).

Figures are drawn at the size they print: COLUMN wide for one column of a two-column journal page
(84 mm, MNRAS's, the narrowest of the common ones), PAGE wide for a figure across both (174 mm), in
Computer Modern at 8 pt and more, the family of the document; the bundle includes them unscaled.
Fonts are embedded as TrueType (pdf.fonttype 42): no Type 3 font, which journal preflight checks
reject. Labels carry their formulas as mathtext (report_math)."""
import functools
import logging

import matplotlib

matplotlib.use("Agg")
import matplotlib.mathtext  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

from report_data import claim, file_of, num, series  # noqa: E402
from report_math import mathtext  # noqa: E402

COLUMN, PAGE = 84 / 25.4, 174 / 25.4  # inches
plt.rcParams.update({"pdf.fonttype": 42, "ps.fonttype": 42, "font.family": "serif", "font.serif": ["cmr10"],
                     "mathtext.fontset": "cm", "axes.formatter.use_mathtext": True, "axes.unicode_minus": False,
                     "font.size": 8, "axes.titlesize": 8, "axes.labelsize": 8, "legend.fontsize": 8,
                     "xtick.labelsize": 8, "ytick.labelsize": 8, "legend.handlelength": 1.5, "legend.borderaxespad": 0.3,
                     "legend.labelspacing": 0.25, "legend.handletextpad": 0.4, "lines.markersize": 3.5,
                     "axes.linewidth": 0.6, "grid.linewidth": 0.4, "savefig.dpi": 300})
# fontTools, which subsets the embedded fonts, warns of the 1990s timestamps in Computer Modern's TrueType files.
logging.getLogger("fontTools").setLevel(logging.ERROR)
PNG_DPI = 180  # a COLUMN-wide figure is 595 px on the report's page


def share_mathtext_parses():
    """matplotlib (3.6, Debian's) caches a formula's layout per parser object, 50 at a time, and every
    figure's renderers make parsers of their own: the tick labels and axis labels that every figure
    repeats are parsed anew in each, a quarter of the report's time. One cache for all parsers of an
    output kind (raster or vector) keeps them: the layout depends only on the formula, dpi, font and
    kind, so the figures are the same to the byte. Where matplotlib's cache is not the expected
    lru_cache, it is left as it is."""
    parser = matplotlib.mathtext.MathTextParser
    parse = getattr(parser._parse_cached, "__wrapped__", None)
    if parse is None:
        return
    one_of_kind = {}

    @functools.lru_cache(4096)
    def shared(kind, s, dpi, prop):
        return parse(one_of_kind[kind], s, dpi, prop)

    def parse_cached(self, s, dpi, prop):
        one_of_kind.setdefault(self._output_type, self)
        return shared(self._output_type, s, dpi, prop)

    parser._parse_cached = parse_cached


share_mathtext_parses()


class LogLabels(matplotlib.ticker.LogFormatterSciNotation):
    """Log-axis labels as $10^{-3}$ and $2\\times10^{-3}$ in pure mathtext: matplotlib's own wrap
    them in \\mathdefault, the text font, and Computer Modern's text font has no times sign."""

    def __call__(self, x, pos=None):
        label = super().__call__(x, pos)
        return label.replace(r"\mathdefault", "")


def save(fig, stem, **margins):
    stem.parent.mkdir(parents=True, exist_ok=True)
    # Fixed margins with room for labels of up to three lines (wrap()): "tight" bounding boxes or
    # constrained layout cost a further draw of every figure, nearly doubling the report's time.
    fig.subplots_adjust(**({"left": 0.16, "right": 0.97, "bottom": 0.15, "top": 0.89} | margins))
    for ax in fig.axes:  # a log axis over less than a decade labels some minor ticks too (one major tick says little;
        for axis in (ax.xaxis, ax.yaxis):  # over more, minor labels run into each other)
            if axis.get_scale() != "log":
                continue
            if isinstance(axis.get_major_formatter(), matplotlib.ticker.LogFormatter):
                axis.set_major_formatter(LogLabels(labelOnlyBase=True))
            if isinstance(axis.get_minor_formatter(), matplotlib.ticker.LogFormatter):
                axis.set_minor_formatter(LogLabels(labelOnlyBase=False, minor_thresholds=(1, 0.5)))
    fig.savefig(file_of(stem, "png"), dpi=PNG_DPI)
    # dpi: that of rasterised particle clouds only; no creation date, so that the same figure is the same file.
    fig.savefig(file_of(stem, "pdf"), dpi=300, metadata={"CreationDate": None})
    plt.close(fig)
    return stem


def math_wrap(text, width):
    """A label as mathtext in lines of about width characters, never broken inside a formula."""
    words, inside = [], False
    for w in mathtext(text).split(" "):
        if inside:  # a formula that holds spaces stays one word
            words[-1] += " " + w
        else:
            words.append(w)
        if (w.count("$") - w.count(r"\$")) % 2:
            inside = not inside
    lines, line = [], ""
    for w in words:
        if line and len(line) + 1 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = f"{line} {w}".strip()
    return "\n".join(lines + [line])


def fit_line(n, y, p):
    """The least-squares line of slope -p through log y against log n."""
    logc = np.mean(np.log(y) + p * np.log(n))
    return np.exp(logc - p * np.log(n))


def level_ticks(ax, n):
    ax.set_xticks(n, [f"{v:g}" for v in n])  # the levels themselves, not powers of ten
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())


def order_label(p, se):
    return (f"$p = {p:.2f}" + (f" \\pm {se:.2f}$" if num(se) else "$")).replace("-0.00", "0.00")


def convergence(case, s, row, stem):
    """Error against n for one claimed error of one variant: the measured points, the harness's
    least-squares fit (its order and standard error) and the expected order with its band,
    drawn through the finest point. Case, variant and outcome are in the caption."""
    e = row["error"]
    pts = series(s, e)
    c = claim(s, e)
    if len(pts) < 2 or c is None:
        return None
    n, y = (np.array(v, float) for v in zip(*pts))
    fig, ax = plt.subplots(figsize=(COLUMN, 2.4))
    ax.loglog(n, y, "o", color="C0", label="measured")
    if num(row.get("observed")):
        ax.loglog(n, fit_line(n, y, row["observed"]), "-", color="C0", lw=1, label="fit, " + order_label(row["observed"], row.get("se")))
    q, band = c["expected"], c.get("band", 0.0) or 0.0
    guide = lambda order: y[-1] * (n / n[-1]) ** (-order)  # noqa: E731
    claimed = f"$\\geq {q:.3g}$" if c.get("at_least") else f"${q:.3g} \\pm {band:.3g}$"
    ax.loglog(n, guide(q), "--", color="C3", lw=1, label="expected " + claimed)
    if band > 0:
        ax.fill_between(n, guide(q - band), guide(q + band), color="C3", alpha=0.12, lw=0)
    level_ticks(ax, n)
    ax.set_xlabel("$n$")  # what n counts is in the caption
    ax.set_ylabel(mathtext(e))  # the error's definition is in the caption
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    return save(fig, stem, left=0.23, bottom=0.17, top=0.97)  # room for minor labels (2 x 10^-2) beside the label


def wall_time(case, ss, error, stem):
    """Error against the wall time of each run, one line per variant that reports the error (none
    when no variant has two points)."""
    lines = sum(any(num(r.get("errors", {}).get(error)) for r in s["runs"]) for s in ss)
    extra = 0.16 * lines  # the legend below the axes, one variant a line
    fig, ax = plt.subplots(figsize=(COLUMN, 2.3 + extra))
    drawn = longest = 0
    for k, s in enumerate(ss):
        pts = [(run.get("wall_time_s"), run.get("errors", {}).get(error), n) for n, run in zip(s["levels"], s["runs"])]
        pts = [p for p in pts if num(p[0]) and p[0] > 0 and num(p[1]) and p[1] > 0]
        if not pts:
            continue
        longest = max(longest, len(pts))
        t, y, n = zip(*pts)
        outcome = next((r["outcome"] for r in s["rows"] if r["error"] == error), "no claim")
        ax.loglog(t, y, "o-", color=f"C{k % 10}", ms=3, lw=0.8, label=mathtext(f"{s['variant']} ({outcome})"))
        if len(ss) <= 3:  # which level each point is: timings of small runs are noisy
            for tx, ty, nx in pts:
                ax.annotate(f"${nx:g}$", (tx, ty), textcoords="offset points", xytext=(3, 2), fontsize=8, color=f"C{k % 10}")
        drawn += 1
    if not drawn or longest < 2:  # one point per line says nothing about cost against accuracy
        plt.close(fig)
        return None
    ax.set_xlabel("wall time of the run [s]")
    ax.set_ylabel(mathtext(error))
    height = 2.3 + extra
    fig.legend(*ax.get_legend_handles_labels(), loc="lower left", bbox_to_anchor=(0.0, 0.0), frameon=False, fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    return save(fig, stem, left=0.23, bottom=(0.45 + extra) / height, top=1 - 0.08 / height)


def run_figure(f, stem):
    """A figure a run describes in its result.json (profiles, time series); points that a log
    axis cannot show are left out, and a figure with no point left is not drawn."""
    fig, ax = plt.subplots(figsize=(COLUMN, 2.6))
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
        style = {"points": dict(ls="none", marker=".", ms=2, rasterized=True), "dashed": dict(ls="--", marker=marker, ms=3),
                 "line": dict(ls="-", marker=marker, ms=3, lw=0.9)}
        ax.plot(x[ok], y[ok], label=mathtext(srs["label"]) or None, color=f"C{k % 10}", **style.get(srs["style"], {}))
        drawn += 1
    if not drawn:
        plt.close(fig)
        return None
    ax.set_xscale(f["xscale"])
    ax.set_yscale(f["yscale"])
    ax.set_xlabel(math_wrap(f["xlabel"], 60))
    ax.set_ylabel(math_wrap(f["ylabel"], 40))
    if any(line.get_label() and not line.get_label().startswith("_") for line in ax.get_lines()):
        ax.legend()
    ax.grid(True, alpha=0.3)
    return save(fig, stem, left=0.19, bottom=0.17, top=0.97)


def comparison(members, errors, stem):
    """The comparison of one group (report_compare.py): per error, the error against n (the
    observed order's slope) and below it against the wall time of each run (the fixed cost marked
    by a dotted line), one line per member, labelled by its value; at most three errors across the
    page, further ones in further pairs of rows."""
    import report_compare as rc  # noqa: E402 (the figures module stays free of the comparison's logic)
    if not errors:
        return None
    cols = min(3, len(errors))
    pairs = -(-len(errors) // cols)
    height = 0.9 + 3.1 * pairs
    fig, axes = plt.subplots(2 * pairs, cols, figsize=(PAGE, height), squeeze=False)
    for j in range(len(errors), pairs * cols):
        axes[2 * (j // cols)][j % cols].set_visible(False)
        axes[2 * (j // cols) + 1][j % cols].set_visible(False)
    drawn = 0
    for j, err in enumerate(errors):
        top, bottom = axes[2 * (j // cols)][j % cols], axes[2 * (j // cols) + 1][j % cols]
        n_fixed, t_fixed, _ = rc.comparison(members, err)
        for k, (value, s) in enumerate(members):
            pts = rc.points(s, err)
            if not pts:
                continue
            n, t, y = zip(*pts)
            style = dict(color=f"C{k % 10}", marker="os^vDP"[k % 6], ms=3, lw=0.8, label=mathtext(value))
            top.loglog(n, y, **style)
            bottom.loglog(t, y, **style)
            drawn += 1
        if n_fixed is not None:
            top.axvline(n_fixed, color="0.5", ls=":", lw=0.8)
        if t_fixed is not None:
            bottom.axvline(t_fixed, color="0.5", ls=":", lw=0.8)
        levels = sorted({p[0] for _, s in members for p in rc.points(s, err)})
        level_ticks(top, levels)
        top.set_title(mathtext(err))
        top.set_xlabel("$n$", labelpad=1)
        bottom.set_xlabel("wall time of the run [s]", labelpad=1)
        # Wall times in plain numbers at 1, 2, 5 per decade: narrow panels have no room for more.
        bottom.xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
        bottom.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        bottom.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        for ax in (top, bottom):
            ax.grid(True, which="both", alpha=0.3)
        if j % cols == 0:
            top.set_ylabel("error against $n$")
            bottom.set_ylabel("error against cost")
    if not drawn:
        plt.close(fig)
        return None
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper center", ncol=min(len(labels), 4), frameon=False, bbox_to_anchor=(0.5, 1.0 - 0.05 / height))
    return save(fig, stem, left=0.115, right=0.99, bottom=0.45 / height, top=1.0 - 0.62 / height, wspace=0.4, hspace=0.5)


LEVEL_COLOURS = ("#e6a024", "#3a9e6e", "#1f4e9c")  # coarse to fine: orange, green, blue (told apart in grey too)
OUTCOME_COLOURS = {"verified": "#1f4e9c", "known failure": "#80269a", "provisional": "#a05000", "no order claimed": "#845b00",
                   "fail": "#b00000"}


def profiles(panels, stem, height=1.85):
    """Profiles at up to three resolutions against the reference, one panel per quantity, across
    the page: panels are dicts with "runs" [(n, figure of a run's result.json)], "title". The
    particles of each level are drawn coarse to fine (fine on top), the reference's curve from the
    finest run on top of them."""
    panels = [p for p in panels if p["runs"]]
    if not panels:
        return None
    fig, axes = plt.subplots(1, len(panels), figsize=(PAGE, height), squeeze=False)
    # One legend for the figure: the levels by name where every panel has the same, else by rank
    # (the caption gives each case's n).
    same = len({tuple(n for n, _ in p["runs"]) for p in panels}) == 1
    for ax, p in zip(axes[0], panels):
        colours = LEVEL_COLOURS[-len(p["runs"]):]
        ranks = {1: ("fine",), 2: ("coarse", "fine")}.get(len(p["runs"]), ("coarse", "middle", "fine"))
        exact = None
        for (n, f), colour, rank in zip(p["runs"], colours, ranks):
            for srs in f["series"]:
                x = np.array([v if num(v) else np.nan for v in srs["x"]], float)
                y = np.array([v if num(v) else np.nan for v in srs["y"]], float)
                if srs["style"] == "points":
                    ax.plot(x, y, ls="none", marker=".", ms=1.6, mew=0, color=colour, rasterized=True,
                            label=f"$n = {n:g}$" if same else rank)
                else:
                    exact = (x, y, srs["label"])
        if exact:
            ax.plot(exact[0], exact[1], "-", color="k", lw=0.7, label=mathtext(exact[2]) if same else "exact")
        f = p["runs"][-1][1]
        ax.set_xlabel(p["xlabel"] if p.get("xlabel") else math_wrap(f["xlabel"], 30))
        ax.set_title(p["title"])  # already mathtext
        ax.grid(True, alpha=0.3)
        ax.tick_params(pad=2)
        if p.get("xlim"):
            ax.set_xlim(*p["xlim"])
    handles, labels = axes[0][0].get_legend_handles_labels()
    for h in handles:  # the legend's dots larger than the particles'
        if h.get_marker() == ".":
            h.set_markersize(6)
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), frameon=False, bbox_to_anchor=(0.5, 0.0),
               markerscale=1.0)
    return save(fig, stem, left=0.055, right=0.99, bottom=0.3, top=0.88, wspace=0.3)


def convergence_panels(panels, stem):
    """Convergence across the page, one panel per case: each curve an error against n with its
    least-squares fit, coloured by outcome (a known failure open and dashed, its experiment filled
    beside it); the claimed order dashed grey through the finest point of the first curve. panels
    are dicts with "title" and "curves" [{label, n, y, observed, se, outcome, expected}]."""
    panels = [p for p in panels if p["curves"]]
    if not panels:
        return None
    cols = min(4, len(panels))
    rows = -(-len(panels) // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(PAGE, 1.72 * rows + 0.1), squeeze=False)
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    for ax, p in zip(axes.flat, panels):
        levels = set()
        for k, c in enumerate(p["curves"]):
            n, y = np.array(c["n"], float), np.array(c["y"], float)
            levels |= set(c["n"])
            colour = OUTCOME_COLOURS.get(c["outcome"], "k")
            known = c["outcome"] == "known failure"
            ax.loglog(n, y, "os"[k % 2], color=colour, mfc="none" if known else colour, ms=3.5, mew=0.8)
            if num(c.get("observed")):
                ax.loglog(n, fit_line(n, y, c["observed"]), "--" if known else "-", color=colour, lw=0.9,
                          label=f"{c['label']}: {order_label(c['observed'], c.get('se'))}")
            if k == 0 and num(c.get("expected")):
                ax.loglog(n, y[-1] * (n / n[-1]) ** (-c["expected"]), ":", color="0.45", lw=0.9)
        level_ticks(ax, sorted(levels))
        ax.set_title(p["title"], pad=3)  # already mathtext
        ax.grid(True, which="major", alpha=0.3)
        ax.tick_params(pad=2)
        ax.legend(loc="best", fontsize=8, handlelength=1.4, borderpad=0.2, framealpha=0.8)
    for ax in axes[-1]:
        ax.set_xlabel("$n$", labelpad=1)
    return save(fig, stem, left=0.085, right=0.99, bottom=0.09 if rows > 1 else 0.17, top=0.94 if rows > 1 else 0.88,
                wspace=0.5, hspace=0.42)
