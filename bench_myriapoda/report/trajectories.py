"""Bodies and trajectories seen from above (x forward, z to the creature's right)."""
from __future__ import annotations

from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..harness.recorder import Series  # noqa: E402
from matplotlib.cm import ScalarMappable  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

from .figure_files import WIDE_IN, save_figure  # noqa: E402


def draw_terrain_top(ax, scenario: dict, food: dict | None, world) -> None:
    """The scenario's world seen from above (x right, z down): slab edge, slope direction, height-field
    contours, mesh silhouette, obstacles (cylinders as discs, boxes as rectangles) and food (green dots).

    scenario, food: the stored case's sections (``Case.to_dict()["scenario"]``, ``["food"]``); world: the
    case's ``world.world.World``, built once by the caller (``MatrixResults.world``): its terrain and food
    are drawn (``food`` only says whether to draw the food).
    """
    from matplotlib.patches import Circle, Polygon

    from ..world.terrain import terrain_description
    from .series_plots import scenario_config
    from .terrain_drawing import draw_terrain_shape

    kind = scenario.get("terrain", "plane")
    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    ax.autoscale(False)  # the world is drawn within the body's view, not the view widened to the whole world
    if kind == "slab":
        edge = scenario["slab_edge_x_m"]
        ax.axvline(edge, color="saddlebrown", lw=1.2, ls="-")
        ax.axvspan(xlim[0], edge, color="burlywood", alpha=0.25, lw=0)
        ax.text(edge, 0.02, " slab edge", transform=ax.get_xaxis_transform(), fontsize=9, color="saddlebrown",
                clip_on=True)
    elif kind == "slope":
        ax.text(0.02, 0.02, f"slope {scenario['slope_deg']:g} deg, rising toward +x", transform=ax.transAxes,
                fontsize=9, color="saddlebrown")
    sc = scenario_config(scenario)
    desc = terrain_description(sc, world.terrain)
    draw_terrain_shape(ax, None, desc.kind, desc.f, xlim, None, ylim)  # height field / mesh as they are
    for c in desc.cylinders:
        ax.add_patch(Circle((c["x"], c["z"]), c["radius"], color="dimgray", alpha=0.8, zorder=1))
    for b in desc.boxes:
        (cx, _, cz), (hx, _, hz), yaw = b["centre"], b["half_extents"], np.radians(b["yaw_deg"])
        corners = np.array([[-hx, -hz], [hx, -hz], [hx, hz], [-hx, hz]])
        rot = np.array([[np.cos(yaw), np.sin(yaw)], [-np.sin(yaw), np.cos(yaw)]])
        ax.add_patch(Polygon(corners @ rot.T + [cx, cz], color="dimgray", alpha=0.8, zorder=1))
    if food:
        src = world.food
        if len(src):
            ax.plot(src[:, 0], src[:, 2], "o", color="limegreen", mec="darkgreen", ms=5, zorder=4, label="food")


MIN_SHORT_SIDE = 0.15    # the short side of a panel's view is at least this fraction of the long side
PATH_MIN_SPAN = 0.05     # the path panel spans at least this fraction of the body length


def _limits(points: np.ndarray, min_span: float, pad_frac: float = 0.06):
    """(x limits, z limits) [m] around points (N, 3), padded; the long side at least ``min_span`` [m], the
    short side at least MIN_SHORT_SIDE of the long one."""
    p = points[np.all(np.isfinite(points), axis=1)]
    if not len(p):
        return (-1.0, 1.0), (-1.0, 1.0)
    lo, hi = p[:, [0, 2]].min(axis=0), p[:, [0, 2]].max(axis=0)
    span = max(float((hi - lo).max()), min_span, 1e-6)
    half = np.maximum(0.5 * (hi - lo), 0.5 * MIN_SHORT_SIDE * span)
    if (hi - lo).max() < min_span:  # a body that barely moved: a square window of min_span
        half[:] = 0.5 * span
    else:
        half[np.argmax(hi - lo)] = 0.5 * span
    half += pad_frac * span
    mid = 0.5 * (lo + hi)
    return (mid[0] - half[0], mid[0] + half[0]), (mid[1] - half[1], mid[1] + half[1])


def body_limits(s: Series):
    """View limits [m] of every segment centre of a run (the body at all times)."""
    return _limits(s.segment_centers.reshape(-1, 3), 0.0)


def path_limits(s: Series):
    """View limits [m] of the centre of mass's path, each side at least PATH_MIN_SPAN body lengths."""
    c = s.segment_centers
    length = float(np.nansum(np.linalg.norm(np.diff(c[0], axis=0), axis=1))) if len(c) else 1.0
    return _limits(s.com, PATH_MIN_SPAN * length)


def _time_line(ax, xy: np.ndarray, t: np.ndarray, norm, cmap, lw: float) -> None:
    """A path (T, 2) coloured by its time t (T,) [s]."""
    seg = np.stack([xy[:-1], xy[1:]], axis=1)
    ax.add_collection(LineCollection(seg, colors=cmap(norm(0.5 * (t[:-1] + t[1:]))), linewidths=lw))


def plot_top_views(runs: Sequence[tuple[str, Series]], path: Path, snapshots: int = 6,
                   scenarios: Sequence[dict] | None = None, foods: Sequence[dict | None] | None = None,
                   worlds: Sequence | None = None) -> Path:
    """One row per run, seen from above: the body, and its path zoomed in.

    Left panel: the body's centre line at ``snapshots`` evenly spaced times, a dot at the head, and the
    centre-of-mass path (dashed), over the scenario's terrain, obstacles and food.  Right panel: the
    centre of mass's path alone, zoomed to it, dots at the snapshot times -- a centipede 26 m long that
    walks 1 m shows its path here.  Everything is coloured by time with ``viridis``, dark
    purple at t = 0 to yellow at the end, as the colour bar shows.  Both panels have equal scales in x
    and z.  ``scenarios``, ``foods``: each run's scenario and food sections (``Case.to_dict()``); ``worlds``:
    each run's built ``world.world.World`` (``draw_terrain_top``; required with ``scenarios``).
    """
    n = len(runs)
    body_lim = [body_limits(s) for _, s in runs]
    path_lim = [path_limits(s) for _, s in runs]
    width = WIDE_IN
    wb, wp = 0.64 * (width - 1.6), 0.36 * (width - 1.6)  # panel widths [in]

    def aspect(lim):
        (x0, x1), (z0, z1) = lim
        return (z1 - z0) / (x1 - x0)

    heights = [min(4.6, max(1.7, aspect(b) * wb, aspect(q) * wp)) + 0.85 for b, q in zip(body_lim, path_lim)]
    t_max = max(float(s.t[-1]) for _, s in runs) or 1.0
    norm = Normalize(0.0, t_max)
    cmap = plt.get_cmap("viridis")
    fig = plt.figure(figsize=(width, sum(heights) + 0.9), layout="constrained")
    grid = fig.add_gridspec(n, 2, height_ratios=heights, width_ratios=[wb, wp])
    axes = []
    for r, ((title, s), blim, plim) in enumerate(zip(runs, body_lim, path_lim)):
        ax, axp = fig.add_subplot(grid[r, 0]), fig.add_subplot(grid[r, 1])
        axes += [ax, axp]
        idx = np.unique(np.linspace(0, len(s.t) - 1, snapshots).astype(int))
        for i in idx:
            c = s.segment_centers[i]
            color = cmap(norm(float(s.t[i])))
            ax.plot(c[:, 0], c[:, 2], "-", color=color, lw=2)
            ax.plot(c[0, 0], c[0, 2], "o", color=color, ms=4)
        ax.plot(s.com[:, 0], s.com[:, 2], "k--", lw=0.9, label="centre of mass")
        _time_line(axp, s.com[:, [0, 2]], s.t, norm, cmap, 2.0)
        axp.scatter(s.com[idx, 0], s.com[idx, 2], c=cmap(norm(s.t[idx])), s=22, zorder=3, edgecolors="k",
                    linewidths=0.4)
        ax.set_title(f"{title}: body")
        axp.set_title("centre-of-mass path, zoomed")
        axp.xaxis.set_major_locator(MaxNLocator(4))  # long tick labels of a small window must not overlap
        for a, ((x0, x1), (z0, z1)) in ((ax, blim), (axp, plim)):
            a.set_xlim(x0, x1)
            a.set_ylim(z1, z0)  # z points to the right of a creature facing +x: down, seen from above
            a.set_aspect("equal", adjustable="box")
            a.set_xlabel("x [m]")
            a.set_ylabel("z [m]")
        if scenarios is not None:
            draw_terrain_top(ax, scenarios[r], foods[r] if foods is not None else None, worlds[r])
    axes[0].legend(loc="best")
    bar = fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=axes, orientation="horizontal", shrink=0.5,
                       aspect=40, pad=0.02)
    bar.set_label("time [s]")
    return save_figure(fig, path)
