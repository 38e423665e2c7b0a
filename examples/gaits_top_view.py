"""Draw the README's picture of Miller's gaits seen from above (reports/examples/gaits_top_view.png).

Four runs on the mass-spring body, flat ground: the worm's rectilinear crawl, the snake's lateral
undulation, and the sidewinder with its vertical wave at +90 and -90 degrees of phase.  Each panel
draws the body's centre line at six instants, coloured by time (viridis, dark = start), and the
centre of mass's path; the title gives the run's own metrics.

    python3 examples/gaits_top_view.py [OUT.png] [--duration S]
"""
from __future__ import annotations

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import bench_myriapoda as bm  # noqa: E402

RUNS = (  # (title, creature, gait, extra configuration keys)
    ("worm, rectilinear", "worm", "rectilinear", {}),
    ("snake, lateral undulation", "snake", "lateral-undulation", {}),
    ("snake, sidewinding", "snake", "sidewinding", {}),
    ("sidewinding, phase -90 deg", "snake", "sidewinding", {"gait.vertical_phase_deg": -90.0}),
)
SNAPSHOTS = 6


def draw(out: Path, duration_s: float) -> None:
    fig, axes = plt.subplots(1, len(RUNS), figsize=(14.2, 3.8), dpi=100)
    colours = plt.get_cmap("viridis")(np.linspace(0.0, 1.0, SNAPSHOTS))
    for ax, (title, creature, gait, keys) in zip(axes, RUNS):
        res = bm.run(creature, "massspring", "flat", gait=gait, duration=duration_s, set=keys)
        s, m = res.series, res.metrics
        # x forward, z to the creature's right, drawn with z increasing downwards (seen from above)
        for colour, k in zip(colours, np.linspace(0, len(s.t) - 1, SNAPSHOTS).astype(int)):
            c = s.segment_centers[k]
            ax.plot(c[:, 0], c[:, 2], color=colour, lw=2.0)
            ax.plot(c[0, 0], c[0, 2], "o", color=colour, ms=4)  # the head
        ax.plot(s.com[:, 0], s.com[:, 2], "k--", lw=0.9, label="centre of mass")
        ax.set_title(f"{title}\n{m['speed_bl_per_cycle']:.3f} BL/cycle, travel {m['travel_angle_deg']:.0f} deg",
                     fontsize=10)
        ax.set_xlabel("x [m]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.invert_yaxis()
    axes[0].set_ylabel("z [m]")
    axes[0].legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out)
    print(f"wrote {out}")


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", nargs="?", default="reports/examples/gaits_top_view.png", type=Path)
    ap.add_argument("--duration", type=float, default=10.0, help="simulated seconds per run (default 10)")
    args = ap.parse_args()
    draw(args.out, args.duration)
