"""
Compare the body models on the worm
===================================

The same creature, gait and scenario on each of the three body models: Miller's mass-spring
lattice, the fixed-corotational FEM body and the rigid/FEM hybrid. Every run is stored in one
results database, read back into pandas with :func:`bench_myriapoda.api.load_results`, and drawn: the
centre of mass's forward travel over time, and speed against throughput.
"""
import os
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

import bench_myriapoda as bm

SCALE = float(os.environ.get("BENCH_MYRIAPODA_EXAMPLE_SCALE", "1"))
# simulated seconds per run: the worm's wave has a 2 s period, the ramp and metrics.warmup_cycles take the first
# 4 s, and a speed needs metrics.min_steady_cycles = 2 steady cycles after them (else it is reported too short)
DURATION = max(8.0, 10.0 * SCALE)
store = Path(tempfile.mkdtemp()) / "bodies.sqlite"

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
for body in ("massspring", "fem", "hybrid"):
    r = bm.run("worm", body, "flat", duration=DURATION, store=store)
    track = r.series_frame()
    left.plot(track["t_s"], track["com_x_m"] - track["com_x_m"].iloc[0], label=body)

df = bm.load_results(store)
print(df[["body", "status", "speed_bl_per_cycle", "steps_per_s"]])
for _, row in df.iterrows():
    right.scatter(row["steps_per_s"], row["speed_bl_per_cycle"], s=60)
    right.annotate(row["body"], (row["steps_per_s"], row["speed_bl_per_cycle"]), textcoords="offset points",
                   xytext=(6, 4))
left.set(xlabel="time [s]", ylabel="forward travel of the centre of mass [m]", title="worm, rectilinear gait")
left.legend()
right.set(xscale="log", xlabel="throughput [steps/s]", ylabel="speed [body lengths / cycle]",
          title="speed against cost", ylim=(0, 1.3 * df["speed_bl_per_cycle"].max()))
fig.tight_layout()
plt.show()
