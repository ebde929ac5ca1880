"""The report's figures, drawn with matplotlib (Agg: no display needed).

Each function takes numbers already taken from the JSON, draws one PNG at a modest DPI (the
committed report must stay small) and returns nothing; the caller names the file.
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)
from matplotlib.ticker import FuncFormatter  # noqa: E402

DPI = 80
_MARKERS = "osD^v<>phX*P"
# Okabe and Ito's eight colours, told apart by people with any common colour-vision deficiency.
OKABE_ITO = ("#000000", "#E69F00", "#56B4E9", "#009E73", "#F0E442", "#0072B2", "#D55E00", "#CC79A7")


def _style(i):
    cmap = plt.get_cmap("tab20")
    return {"color": cmap(i % 20), "marker": _MARKERS[i % len(_MARKERS)],
            "linestyle": ["-", "--", "-.", ":"][(i // 20) % 4]}


def _safe_style(i):
    """A series' colour-blind-safe colour, marker and line style (16 before a repeat)."""
    return {"color": OKABE_ITO[i % 8], "marker": _MARKERS[i % len(_MARKERS)],
            "linestyle": ["-", "--"][(i // 8) % 2]}


def _label_ends(ax, ends, fontsize=7):
    """Names each line at its right end, nudged apart vertically (log scale) so none overlap."""
    if not ends:
        return
    lo, hi = ax.get_ylim()
    gap = 0.045 * (math.log10(hi) - math.log10(lo))
    placed = []
    for x, y, text, color in sorted(ends, key=lambda e: e[1]):
        ly = math.log10(y)
        if placed and ly < placed[-1] + gap:
            ly = placed[-1] + gap
        placed.append(ly)
        ax.annotate(text, (x, y), xytext=(x + 0.03, 10 ** ly), textcoords="data", fontsize=fontsize,
                    color=color, va="center", arrowprops={"arrowstyle": "-", "color": color, "lw": 0.4})


def _save(fig, path):
    fig.savefig(path, dpi=DPI, bbox_inches="tight")
    plt.close(fig)


def _percent_axis(ax, values):
    """Error rates span 0 to 100% with the interesting part near 0: symlog in percent."""
    ax.set_yscale("symlog", linthresh=0.01, linscale=0.5)
    top = max([v for v in values if v is not None] + [0.01])
    ax.set_ylim(-0.002, max(1.0, top) * 1.6)
    ax.yaxis.set_major_formatter(FuncFormatter(lambda y, _: ("%g%%" % y) if y >= 0 else ""))


def heatmap(rows, cols, values, counts, path, title, colorbar_label="error rate"):
    """values[i][j]: a rate in [0, 1] or None; counts[i][j]: the number printed in the cell."""
    import numpy as np
    from matplotlib.colors import LogNorm
    data = np.array([[v if v is not None else np.nan for v in r] for r in values], dtype=float)
    positive = data[np.isfinite(data) & (data > 0)]
    vmin = max(positive.min(), 1e-5) if positive.size else 1e-5
    masked = np.where(data > 0, data, np.nan)
    fig, ax = plt.subplots(figsize=(1.0 + 0.55 * len(cols), 1.2 + 0.32 * len(rows)))
    cmap = plt.get_cmap("magma_r").copy()
    cmap.set_bad("#f4f4f4")
    im = ax.imshow(masked, aspect="auto", cmap=cmap, norm=LogNorm(vmin=vmin, vmax=max(1.0, vmin * 10)))
    ax.set_xticks(range(len(cols)), cols, rotation=60, ha="right", fontsize=8)
    ax.set_yticks(range(len(rows)), rows, fontsize=8)
    for i, r in enumerate(counts):
        for j, c in enumerate(r):
            if c is None:
                continue
            dark = np.isfinite(masked[i, j]) and masked[i, j] > math.sqrt(vmin)
            ax.text(j, i, str(c), ha="center", va="center", fontsize=6,
                    color="white" if dark else "#333333")
    fig.colorbar(im, ax=ax, label=colorbar_label + " (grey: none)")
    ax.set_title(title, fontsize=10)
    _save(fig, path)


def _pareto_axes(ax, points, front_points, frontier, floor):
    """points: this panel's [(name, x, y)]; front_points: the whole mode's, for its frontier line."""
    for i, (name, x, y) in enumerate(points):
        st = _safe_style(i)
        yy = y if y > 0 else floor
        ax.scatter([x], [yy], color=st["color"], marker=st["marker"], s=50,
                   edgecolors="red" if name in frontier else "none", linewidths=1.2, zorder=3, label=name)
        ax.annotate(name, (x, yy), textcoords="offset points", xytext=(5, 4 if i % 2 else -9), fontsize=7,
                    color=st["color"])
    front = sorted(((x, y if y > 0 else floor) for n, x, y in front_points if n in frontier))
    if front:
        fx, fy = [], []
        for j, (x, y) in enumerate(front):
            if j:
                fx.append(x)
                fy.append(fy[-1])
            fx.append(x)
            fy.append(y)
        ax.plot(fx, fy, color="#888888", linewidth=1, linestyle="--", zorder=2)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.axhline(floor, color="#999999", linewidth=0.6)
    ax.grid(True, which="both", alpha=0.25)
    ax.tick_params(labelsize=7)


def pareto_panels(panels, path, xlabel, ylabel):
    """panels: [(mode, [(group, [(name, x ns, y rate)])], every point of the mode, the names on its
    Pareto frontier)]: a row per group, a column per mode, shared axes; the dashed line is the
    mode's frontier over every group, its points ringed in red."""
    cols = max(1, len(panels))
    rows = max([len(groups) for _, groups, _, _ in panels] + [1])
    fig, axes = plt.subplots(rows, cols, figsize=(10, 2.9 * rows + 0.6), sharex=True, sharey=True, squeeze=False)
    ys = [p[2] for _, _, points, _ in panels for p in points]
    positive = [y for y in ys if y > 0]
    floor = (min(positive) if positive else 1e-3) / 4
    for c, (mode, groups, every, frontier) in enumerate(panels):
        for r, (group, points) in enumerate(groups):
            _pareto_axes(axes[r][c], points, every, frontier, floor)
            axes[r][c].set_title("%s, %s mode" % (group, mode), fontsize=9)
        for r in range(len(groups), rows):
            axes[r][c].axis("off")
    axes[0][0].text(0.01, 0.02, "bottom line: no errors", transform=axes[0][0].transAxes, fontsize=7, color="#666666")
    fig.supxlabel(xlabel, fontsize=9)
    fig.supylabel(ylabel, fontsize=9)
    fig.tight_layout()
    _save(fig, path)


def ratio_panels(panels, path, xlabel, ylabel):
    """panels: [(mode, [(group, {name: [(R, ns)]}, marks [(R, ns, text)])])]: a row per group, a
    column per mode, shared log y; each line named at its end."""
    cols = max(1, len(panels))
    rows = max([len(groups) for _, groups in panels] + [1])
    fig, axes = plt.subplots(rows, cols, figsize=(10, 2.9 * rows + 0.6), sharex=True, sharey=True, squeeze=False)
    for c, (mode, groups) in enumerate(panels):
        for r, (group, series, marks) in enumerate(groups):
            ax = axes[r][c]
            ends = []
            for i, (name, pts) in enumerate(series.items()):
                st = _safe_style(i)
                ax.plot([p[0] for p in pts], [p[1] for p in pts], label=name, color=st["color"],
                        marker=st["marker"], markersize=3, linestyle=st["linestyle"], linewidth=1.2)
                ends.append((pts[-1][0], pts[-1][1], name, st["color"]))
            # The break-evens are circled, not labelled: their labels crowd each other, and the
            # section's table lists them.
            for mr, mt, _ in marks:
                ax.plot([mr], [mt], marker="o", markersize=9, markerfacecolor="none", markeredgecolor="red")
            ax.set_yscale("log")
            ax.set_xlim(-0.03, 1.45)  # room for the names at the lines' ends
            ax.set_xticks([0, 0.2, 0.4, 0.6, 0.8, 1.0])
            ax.set_title("%s, %s mode" % (group, mode), fontsize=9)
            ax.grid(True, which="both", alpha=0.25)
            ax.tick_params(labelsize=7)
            _label_ends(ax, ends)
        for r in range(len(groups), rows):
            axes[r][c].axis("off")
    fig.supxlabel(xlabel, fontsize=9)
    fig.supylabel(ylabel, fontsize=9)
    fig.tight_layout()
    _save(fig, path)


def sweep_lines(series, path, xlabel, title, xscale=None, xticks=None):
    """series: {name: [(x, rate or None)]}: error rate against a swept quantity."""
    fig, ax = plt.subplots(figsize=(8.5, 4.8))
    allv = []
    for i, (name, pts) in enumerate(series.items()):
        st = _style(i)
        xs = [p[0] for p in pts if p[1] is not None]
        ys = [100.0 * p[1] for p in pts if p[1] is not None]
        allv += ys
        ax.plot(xs, ys, label=name, color=st["color"], marker=st["marker"], markersize=4,
                linestyle=st["linestyle"], linewidth=1.1)
    if xscale:
        ax.set_xscale(xscale)
    if xticks:
        ax.set_xticks([t[0] for t in xticks], [t[1] for t in xticks], fontsize=8)
    _percent_axis(ax, allv)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("overlap error rate")
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.25)
    if series:
        ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    _save(fig, path)


def paired_bars(names, left, right, labels, path, ylabel, title):
    """Two bars per name (e.g. double and float error rates, in [0, 1])."""
    import numpy as np
    x = np.arange(len(names))
    fig, ax = plt.subplots(figsize=(max(6, 0.55 * len(names) + 2), 4.5))
    lv = [100.0 * (v or 0) for v in left]
    rv = [100.0 * (v or 0) for v in right]
    ax.bar(x - 0.2, lv, 0.4, label=labels[0], color="#1f77b4")
    ax.bar(x + 0.2, rv, 0.4, label=labels[1], color="#ff7f0e")
    ax.set_xticks(x, names, rotation=50, ha="right", fontsize=8)
    _percent_axis(ax, lv + rv)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, axis="y", which="both", alpha=0.25)
    ax.legend(fontsize=8)
    _save(fig, path)


def small_multiples(panels, path, xlabel, title, xscale="log"):
    """panels: [(title, {label: [(x, rate)]})]: one small plot per algorithm, shared axes."""
    n = len(panels)
    cols = min(4, max(1, n))
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols, 2.5 * rows), sharex=True, sharey=True,
                             squeeze=False)
    allv = [100.0 * p[1] for _, s in panels for pts in s.values() for p in pts if p[1] is not None]
    for k, (ptitle, series) in enumerate(panels):
        ax = axes[k // cols][k % cols]
        for i, (label, pts) in enumerate(series.items()):
            xs = [p[0] for p in pts if p[1] is not None]
            ys = [100.0 * p[1] for p in pts if p[1] is not None]
            ax.plot(xs, ys, label=label, color=["#1f77b4", "#ff7f0e"][i % 2], marker="o", markersize=3,
                    linestyle=["-", "--"][i % 2], linewidth=1.1)
        ax.set_title(ptitle, fontsize=8)
        ax.set_xscale(xscale)
        _percent_axis(ax, allv)
        ax.grid(True, which="both", alpha=0.25)
        ax.tick_params(labelsize=7)
    for k in range(n, rows * cols):
        axes[k // cols][k % cols].axis("off")
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper right", fontsize=8)
    fig.suptitle(title, fontsize=10)
    fig.supxlabel(xlabel, fontsize=9)
    fig.supylabel("overlap error rate", fontsize=9)
    _save(fig, path)


def grouped_ratio_bars(groups, series, path, ylabel, title, rotation=0):
    """groups: category names; series: {label: [value per group]}, log y. `rotation` turns long
    category names (degrees), and widens the figure to hold them."""
    import numpy as np
    x = np.arange(len(groups))
    width = 0.8 / max(1, len(series))
    fig, ax = plt.subplots(figsize=(max(7, 0.9 * len(groups) + 2) if rotation else 7, 4.2))
    for i, (label, vals) in enumerate(series.items()):
        v = [np.nan if a is None else a for a in vals]
        bars = ax.bar(x - 0.4 + width * (i + 0.5), v, width, label=label)
        for b, a in zip(bars, vals):
            if a is not None:
                ax.annotate("%.3g" % a, (b.get_x() + b.get_width() / 2, a), ha="center", va="bottom", fontsize=7)
    ax.set_xticks(x, groups, **({"rotation": rotation, "ha": "right", "fontsize": 8} if rotation else {}))
    ax.set_yscale("log")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, axis="y", which="both", alpha=0.25)
    ax.legend(fontsize=8)
    _save(fig, path)


# Yu-He draw their cases in three orthographic views: V (front: x-z), H (top: x-y), W (side: y-z).
VIEWS = [("front (x-z)", 0, 2), ("top (x-y)", 0, 1), ("side (y-z)", 1, 2)]


def gallery(rows, path, title):
    """rows: [(caption, t1 [[x,y,z]*3], t2 [[x,y,z]*3])]: one row of three views per case.

    Each case is drawn centred on its bounding box and divided by its size, so a pair at 2^-40
    or 2^40 reads like one at 1; the caption says what the frame is.
    """
    from matplotlib.patches import Polygon
    n = max(1, len(rows))
    fig, axes = plt.subplots(n, 3, figsize=(9, 3.1 * n), squeeze=False)
    for i, (caption, t1, t2) in enumerate(rows):
        pts_all = t1 + t2
        centre = [(max(v[k] for v in pts_all) + min(v[k] for v in pts_all)) / 2 for k in range(3)]
        size = max(max(v[k] for v in pts_all) - min(v[k] for v in pts_all) for k in range(3)) or 1.0
        u1 = [[(v[k] - centre[k]) / size for k in range(3)] for v in t1]
        u2 = [[(v[k] - centre[k]) / size for k in range(3)] for v in t2]
        for j, (vname, a, b) in enumerate(VIEWS):
            ax = axes[i][j]
            for tri, color, label in ((u1, "#1f77b4", "T1"), (u2, "#ff7f0e", "T2")):
                pts = [(v[a], v[b]) for v in tri]
                ax.add_patch(Polygon(pts, closed=True, facecolor=color, alpha=0.35, edgecolor=color,
                                     linewidth=1.2, label=label))
                ax.scatter([p[0] for p in pts], [p[1] for p in pts], color=color, s=10, zorder=3)
            ax.set_xlim(-0.6, 0.6)
            ax.set_ylim(-0.6, 0.6)
            ax.set_aspect("equal")
            ax.tick_params(labelsize=6)
            ax.set_xlabel("xyz"[a], fontsize=7, labelpad=1)
            ax.set_ylabel("xyz"[b], fontsize=7, labelpad=1)
            ax.set_title(vname, fontsize=7)
        axes[i][1].set_title("%s\ncentre (%.6g, %.6g, %.6g), unit %.6g\n%s" % (
            caption, centre[0], centre[1], centre[2], size, VIEWS[1][0]), fontsize=7)
        if i == 0:
            axes[0][2].legend(fontsize=7, loc="upper right")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    _save(fig, path)
