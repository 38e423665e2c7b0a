"""The scorecard's summary figure: error against cost for every creature x body pair of a matrix.

A work-precision view of the whole matrix: x is the cost (CPU seconds per simulated second, log),
y the pair's error (its speed error against the reference, or the share of failed validate checks
where no speed reference applies; log), one colour per creature and one marker per body model.
Pairs with no error measure are drawn on a strip under the axes at their cost, so every pair of
the scorecard is on the figure.
"""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402

from .figure_files import LABEL_PT, WIDE_IN, save_figure  # noqa: E402

MARKER_CYCLE = ("^", "o", "s", "D", "v", "P", "X")  # body models in name order (fem, hybrid, massspring, ...)
ERROR_FLOOR = 1e-3  # errors below this (0.1 %) are drawn at it: a log axis has no zero


def body_markers(bodies) -> dict[str, str]:
    """One marker per body model: the catalog's body models (and ``bodies``) in name order take ``MARKER_CYCLE``
    in turn, so a body keeps its marker whichever bodies a figure shows, no body is named here, and the
    shipped three keep the markers they always had (fem ^, hybrid o, massspring s)."""
    from ..core import registry

    registry.load_all()
    names = sorted(set(registry.BODIES) | set(bodies))
    return {b: MARKER_CYCLE[i % len(MARKER_CYCLE)] for i, b in enumerate(names)}


def plot_error_vs_cost(points: list[tuple[str, str, float | None, float, str]], path: Path | str) -> Path:
    """points: (creature, body, error or None, cost [CPU s per simulated s], error kind); writes ``path``."""
    return save_figure(draw_error_vs_cost(points), path)


def draw_error_vs_cost(points: list[tuple[str, str, float | None, float, str]]):
    """The figure of ``plot_error_vs_cost``, its labels placed apart (``place_labels``); returns the figure."""
    fig, (ax, strip) = plt.subplots(2, 1, figsize=(WIDE_IN, 6.0), sharex=True, layout="constrained",
                                    gridspec_kw={"height_ratios": [5, 1]})
    creatures = sorted({p[0] for p in points})
    colors = {c: plt.get_cmap("tab10")(i % 10) for i, c in enumerate(creatures)}
    kinds = sorted({p[4] for p in points if p[2] is not None})
    labelled = []  # (axes, x, y, text)
    markers = body_markers({p[1] for p in points})
    for creature, body, err, cost, _kind in points:
        m = markers[body]
        if err is None:
            strip.scatter([cost], [0], marker=m, s=70, color=colors[creature], edgecolor="k")
            labelled.append((strip, cost, 0.0, f"{creature}/{body}"))
            continue
        y = max(err, ERROR_FLOOR)
        ax.scatter([cost], [y], marker=m, s=90, color=colors[creature], edgecolor="k", zorder=3)
        labelled.append((ax, cost, y, f"{creature}/{body}"))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylabel("error (" + " / ".join(kinds) + ")" if kinds else "error")
    ax.grid(True, which="both", alpha=0.3)
    ax.set_title("Scorecard: error against cost per creature (colour) and body model (marker); "
                 "lower left is better")
    handles = [plt.Line2D([], [], marker=markers[b], ls="", color="grey", markeredgecolor="k", label=b)
               for b in sorted({p[1] for p in points})]
    handles += [plt.Line2D([], [], marker="o", ls="", color=colors[c], label=c) for c in creatures]
    legend = ax.legend(handles=handles, loc="best", ncols=2)
    strip.set_yticks([0], ["no error\nmeasure"])
    strip.set_ylim(-1, 1)
    strip.set_xlabel("cost: CPU seconds per simulated second (log)")
    strip.grid(True, axis="x", which="both", alpha=0.3)
    if not any(p[2] is not None for p in points):
        ax.text(0.5, 0.5, "no pair has an error measure", transform=ax.transAxes, ha="center")
    if labelled:  # pad the x range so that a label next to the outermost points stays inside
        xs = [x for _, x, _, _ in labelled]
        ax.set_xlim(min(xs) / 2.0, max(xs) * 4.0)
    place_labels(fig, labelled, avoid=[legend])
    return fig


# offsets tried for a label, in points from its marker: close first, then further out with a leader line
_RINGS = (8.0, 18.0, 30.0, 46.0, 66.0, 90.0)
_DIRECTIONS = ((1, 0.4), (1, -1.2), (-1, 0.4), (-1, -1.2), (0.2, 1.4), (0.2, -2.4), (1, 1.4), (-1, 1.4),
               (1, -2.4), (-1, -2.4))


def place_labels(fig, labelled, avoid=()) -> list:
    """Annotate each (axes, x, y, text) at the first offset (``_RINGS`` x ``_DIRECTIONS``) where its text
    box overlaps no label placed before it, no marker and none of ``avoid`` (artists, e.g. the legend), and
    stays inside its axes; a label moved away from its marker gets a thin leader line.  Returns the
    annotations.  Greedy, in order of x: with 18 pairs on a 1100 px figure every label finds a free place
    (tests/test_report_presentation.py); if none is free, the least-overlapping candidate is used."""
    fig.canvas.draw()  # the constrained layout settles the axes before text boxes are measured
    renderer = fig.canvas.get_renderer()
    taken = [a.get_window_extent(renderer) for a in avoid if a is not None]
    marker_px = 7.0
    for ax_, x, y, _t in labelled:
        px, py = ax_.transData.transform((x, y))
        taken.append(_box(px - marker_px, py - marker_px, px + marker_px, py + marker_px))
    out = []
    for ax_, x, y, text in sorted(labelled, key=lambda t: (t[1], t[2])):
        frame = ax_.get_window_extent(renderer)
        best = None
        for r in _RINGS:
            for dx, dy in _DIRECTIONS:
                off = (dx * r, dy * r * 0.6)
                ann = ax_.annotate(text, (x, y), xytext=off, textcoords="offset points", fontsize=LABEL_PT,
                                   ha="left" if dx >= 0 else "right", va="center")
                ann.set_in_layout(False)  # placed inside the axes: the layout must not move for it
                bb = ann.get_window_extent(renderer)
                inside = (bb.x0 >= frame.x0 and bb.x1 <= frame.x1 and bb.y0 >= frame.y0 and bb.y1 <= frame.y1)
                clash = sum(_overlap(bb, t) for t in taken) + (0.0 if inside else 1e6)
                if best is None or clash < best[0]:
                    if best is not None:
                        best[1].remove()
                    best = (clash, ann, bb, r)
                else:
                    ann.remove()
                if clash == 0.0:
                    break
            if best[0] == 0.0:
                break
        _, ann, bb, r = best
        if r > _RINGS[0]:
            ann.remove()
            ann = ax_.annotate(text, (x, y), xytext=ann.xyann, textcoords="offset points", fontsize=LABEL_PT,
                               ha=ann.get_ha(), va="center",
                               arrowprops={"arrowstyle": "-", "color": "0.45", "lw": 0.7, "shrinkA": 1,
                                           "shrinkB": 5})
            ann.set_in_layout(False)
        taken.append(bb)
        out.append(ann)
    return out


def _box(x0, y0, x1, y1):
    from matplotlib.transforms import Bbox

    return Bbox([[x0, y0], [x1, y1]])


def _overlap(a, b) -> float:
    """Area [px^2] two boxes share (0 when apart)."""
    w = min(a.x1, b.x1) - max(a.x0, b.x0)
    h = min(a.y1, b.y1) - max(a.y0, b.y0)
    return w * h if w > 0 and h > 0 else 0.0
