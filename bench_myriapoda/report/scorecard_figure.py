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
    fig, (ax, strip) = plt.subplots(2, 1, figsize=(WIDE_IN, 6.0), sharex=True, layout="constrained",
                                    gridspec_kw={"height_ratios": [5, 1]})
    creatures = sorted({p[0] for p in points})
    colors = {c: plt.get_cmap("tab10")(i % 10) for i, c in enumerate(creatures)}
    kinds = sorted({p[4] for p in points if p[2] is not None})
    markers = body_markers({p[1] for p in points})
    none_x = []
    for creature, body, err, cost, _kind in points:
        m = markers[body]
        if err is None:
            strip.scatter([cost], [0], marker=m, s=70, color=colors[creature], edgecolor="k")
            strip.annotate(f"{creature}/{body}", (cost, 0), xytext=(4, 6 if len(none_x) % 2 else -12),
                           textcoords="offset points", fontsize=LABEL_PT)
            none_x.append(cost)
            continue
        y = max(err, ERROR_FLOOR)
        ax.scatter([cost], [y], marker=m, s=90, color=colors[creature], edgecolor="k", zorder=3)
        ax.annotate(f"{creature}/{body}", (cost, y), xytext=(6, 4), textcoords="offset points", fontsize=LABEL_PT)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylabel("error (" + " / ".join(kinds) + ")" if kinds else "error")
    ax.grid(True, which="both", alpha=0.3)
    ax.set_title("Scorecard: error against cost per creature (colour) and body model (marker); "
                 "lower left is better")
    handles = [plt.Line2D([], [], marker=markers[b], ls="", color="grey", markeredgecolor="k", label=b)
               for b in sorted({p[1] for p in points})]
    handles += [plt.Line2D([], [], marker="o", ls="", color=colors[c], label=c) for c in creatures]
    ax.legend(handles=handles, loc="best", ncols=2)
    strip.set_yticks([0], ["no error\nmeasure"])
    strip.set_ylim(-1, 1)
    strip.set_xlabel("cost: CPU seconds per simulated second (log)")
    strip.grid(True, axis="x", which="both", alpha=0.3)
    if not any(p[2] is not None for p in points):
        ax.text(0.5, 0.5, "no pair has an error measure", transform=ax.transAxes, ha="center")
    return save_figure(fig, path)
