"""Bodies and trajectories seen from above (x forward, z to the creature's right)."""
from __future__ import annotations

from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..harness.recorder import Series  # noqa: E402


def plot_top_views(runs: Sequence[tuple[str, Series]], path: Path, snapshots: int = 6) -> Path:
    """One panel per run: body centre lines at evenly spaced times (light to dark) and the COM path."""
    n = len(runs)
    fig, axes = plt.subplots(1, n, figsize=(3.2 * n, 3.4), squeeze=False)
    for ax, (title, s) in zip(axes[0], runs):
        idx = np.linspace(0, len(s.t) - 1, snapshots).astype(int)
        cmap = plt.get_cmap("viridis")
        for k, i in enumerate(idx):
            c = s.segment_centers[i]
            ax.plot(c[:, 0], c[:, 2], "-", color=cmap(k / max(snapshots - 1, 1)), lw=2)
            ax.plot(c[0, 0], c[0, 2], "o", color=cmap(k / max(snapshots - 1, 1)), ms=4)
        ax.plot(s.com[:, 0], s.com[:, 2], "k--", lw=0.8, label="centre of mass")
        ax.set_title(title, fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
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
