"""Bodies and trajectories seen from above (x forward, z to the creature's right)."""
from __future__ import annotations

from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..harness.recorder import Series  # noqa: E402


def draw_terrain_top(ax, scenario: dict) -> None:
    """The scenario's terrain features seen from above (x right, z down): the slab's edge, the slope's direction."""
    kind = scenario.get("terrain", "plane")
    if kind == "slab":
        edge = scenario["slab_edge_x_m"]
        ax.axvline(edge, color="saddlebrown", lw=1.2, ls="-")
        ax.axvspan(ax.get_xlim()[0], edge, color="burlywood", alpha=0.25, lw=0)
        ax.text(edge, 0.02, " slab edge", transform=ax.get_xaxis_transform(), fontsize=6, color="saddlebrown")
    elif kind == "slope":
        ax.text(0.02, 0.02, f"slope {scenario['slope_deg']:g} deg, rising toward +x", transform=ax.transAxes,
                fontsize=6, color="saddlebrown")


def plot_top_views(runs: Sequence[tuple[str, Series]], path: Path, snapshots: int = 6,
                   scenarios: Sequence[dict] | None = None) -> Path:
    """One panel per run: body centre lines at evenly spaced times (light to dark) and the COM path.

    ``scenarios``: each run's scenario section (``Case.to_dict()["scenario"]``), to draw its terrain.
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
            draw_terrain_top(ax, scenarios[r])
        ax.set_xlabel("x [m]")
        ax.invert_yaxis()  # z points to the right of a creature facing +x: draw it downward, as seen from above
    axes[0][0].set_ylabel("z [m]")
    axes[0][0].legend(fontsize=7, loc="best")
    fig.tight_layout()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
