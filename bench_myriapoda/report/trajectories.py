"""Bodies and trajectories seen from above (x forward, z to the creature's right)."""
from __future__ import annotations

from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..harness.recorder import Series  # noqa: E402
from .figure_files import save_figure  # noqa: E402


def draw_terrain_top(ax, scenario: dict, food: dict | None = None) -> None:
    """The scenario's world seen from above (x right, z down): slab edge, slope direction, height-field
    contours, mesh silhouette, obstacles (cylinders as discs, boxes as rectangles) and food (green dots).

    scenario, food: the stored case's sections (``Case.to_dict()["scenario"]``, ``["food"]``).
    """
    from matplotlib.patches import Circle, Polygon

    from ..core.schema import FoodConfig
    from ..world.food import food_sources
    from ..world.terrain import terrain_description
    from .series_plots import scenario_config, stored_section
    from .terrain_drawing import draw_terrain_shape

    kind = scenario.get("terrain", "plane")
    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    ax.autoscale(False)  # the world is drawn within the body's view, not the view widened to the whole world
    if kind == "slab":
        edge = scenario["slab_edge_x_m"]
        ax.axvline(edge, color="saddlebrown", lw=1.2, ls="-")
        ax.axvspan(xlim[0], edge, color="burlywood", alpha=0.25, lw=0)
        ax.text(edge, 0.02, " slab edge", transform=ax.get_xaxis_transform(), fontsize=6, color="saddlebrown")
    elif kind == "slope":
        ax.text(0.02, 0.02, f"slope {scenario['slope_deg']:g} deg, rising toward +x", transform=ax.transAxes,
                fontsize=6, color="saddlebrown")
    sc = scenario_config(scenario)
    desc = terrain_description(sc)
    draw_terrain_shape(ax, None, desc.kind, desc.f, xlim, None, ylim)  # height field / mesh as they are
    for c in desc.cylinders:
        ax.add_patch(Circle((c["x"], c["z"]), c["radius"], color="dimgray", alpha=0.8, zorder=1))
    for b in desc.boxes:
        (cx, _, cz), (hx, _, hz), yaw = b["centre"], b["half_extents"], np.radians(b["yaw_deg"])
        corners = np.array([[-hx, -hz], [hx, -hz], [hx, hz], [-hx, hz]])
        rot = np.array([[np.cos(yaw), np.sin(yaw)], [-np.sin(yaw), np.cos(yaw)]])
        ax.add_patch(Polygon(corners @ rot.T + [cx, cz], color="dimgray", alpha=0.8, zorder=1))
    if food:
        src = food_sources(sc, stored_section(FoodConfig, food))
        if len(src):
            ax.plot(src[:, 0], src[:, 2], "o", color="limegreen", mec="darkgreen", ms=5, zorder=4, label="food")


def plot_top_views(runs: Sequence[tuple[str, Series]], path: Path, snapshots: int = 6,
                   scenarios: Sequence[dict] | None = None, foods: Sequence[dict | None] | None = None) -> Path:
    """One panel per run: body centre lines at evenly spaced times (light to dark) and the COM path.

    ``scenarios``, ``foods``: each run's scenario and food sections (``Case.to_dict()``), to draw its
    terrain, obstacles and food.
    """
    n = len(runs)
    fig, axes = plt.subplots(1, n, figsize=(3.2 * n, 3.4), squeeze=False)
    for r, (ax, (title, s)) in enumerate(zip(axes[0], runs)):
        idx = np.linspace(0, len(s.t) - 1, snapshots).astype(int)
        cmap = plt.get_cmap("viridis")
        for k, i in enumerate(idx):
            c = s.segment_centers[i]
            ax.plot(c[:, 0], c[:, 2], "-", color=cmap(k / max(snapshots - 1, 1)), lw=2)
            ax.plot(c[0, 0], c[0, 2], "o", color=cmap(k / max(snapshots - 1, 1)), ms=4)
        ax.plot(s.com[:, 0], s.com[:, 2], "k--", lw=0.8, label="centre of mass")
        ax.set_title(title, fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
        if scenarios is not None:
            draw_terrain_top(ax, scenarios[r], foods[r] if foods is not None else None)
        ax.set_xlabel("x [m]")
        ax.invert_yaxis()  # z points to the right of a creature facing +x: draw it downward, as seen from above
    axes[0][0].set_ylabel("z [m]")
    axes[0][0].legend(fontsize=7, loc="best")
    fig.tight_layout()
    return save_figure(fig, path, dpi=110)
