"""
The centipede's gait diagram
============================

The paper's centipede (Fang, Jiang and Terzopoulos 2013) on its rigid/FEM hybrid body, walking on
flat ground under the decentralized leg controller. Each leg's state over the last second
(swing SF1 and SF2, STANCE, the backward swings and ADJUST), as in the paper's Fig. 10: with a
retrograde wave the swings travel from the tail to the head.
"""
import os
import tempfile
from pathlib import Path

import bench_myriapoda as bm
from bench_myriapoda.report.figure_files import show_png
from bench_myriapoda.report.gait_diagram import plot_gait_diagram

SCALE = float(os.environ.get("BENCH_MYRIAPODA_EXAMPLE_SCALE", "1"))
r = bm.run("centipede", "hybrid", "walk", duration=max(2.5, 5.0 * SCALE))
print(r)
print("wave:", r.labels.get("wave_direction"), " phase lag:", r.metrics.get("phase_lag_mean"),
      " duty factor:", r.metrics.get("duty_factor_mean"))

t, states, _tips = r.raw.extra["leg_timeline"]       # (T,) [s], (T, n_legs) state codes, (T, n_legs, 3) [m]
png = plot_gait_diagram(t, states, Path(tempfile.mkdtemp()) / "gait.png", last_seconds=1.0,
                        title=f"centipede / hybrid / walk: {r.labels.get('wave_direction', '')} wave")
show_png(png)
