"""
A dt x stiffness stability sweep
================================

Explicit and semi-implicit integrators are stable only up to a time step that shrinks as the body
stiffens. This sweep runs Miller's worm on the mass-spring lattice over a grid of time steps and
spring stiffnesses and draws each run's fate: stable to the end, or the time at which it blew up
(status ``unstable``, metric ``t_fail_s``). A run that blows up is a result, not a crash.
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import bench_myriapoda as bm
from bench_myriapoda.bodies.massspring.body import MILLER_PRESETS

SCALE = float(os.environ.get("BENCH_MYRIAPODA_EXAMPLE_SCALE", "1"))
DURATION = 2.0 * max(SCALE, 0.5)
base = bm.resolve("worm", "massspring", "flat")
dt0 = base.dt                                      # the body's default step [s]
k0 = MILLER_PRESETS[base.body.preset]["stiffness"]  # Miller's k per unit mass [1/frame^2] of the worm's preset
dts = dt0 * np.array([0.5, 1.0, 2.0, 4.0, 8.0] if SCALE >= 1 else [1.0, 2.0, 4.0, 8.0])
stiffnesses = k0 * np.array([0.25, 1.0, 4.0, 16.0] if SCALE >= 1 else [0.25, 1.0, 4.0])

fate = np.zeros((len(stiffnesses), len(dts)))     # t_fail / duration; 1 = stable to the end
for i, k in enumerate(stiffnesses):
    for j, dt in enumerate(dts):
        r = bm.run("worm", "massspring", "flat", duration=DURATION, dt=dt, body__stiffness=float(k))
        fate[i, j] = 1.0 if r.status == "ok" else r.metrics["t_fail_s"] / DURATION
        print(f"k = {k:10.4g}  dt = {dt:.3g} s: {r.status}")

fig, ax = plt.subplots(figsize=(7, 4.5))
im = ax.imshow(fate, origin="lower", cmap="RdYlGn", vmin=0, vmax=1, aspect="auto")
ax.set_xticks(range(len(dts)), [f"{dt * 1e3:.3g}" for dt in dts])
ax.set_yticks(range(len(stiffnesses)), [f"{k / k0:g} x" for k in stiffnesses])
ax.set(xlabel="time step dt [ms]", ylabel="body.stiffness (x the preset's)", title="worm on the lattice: stable (green) or when it blew up")
for i in range(len(stiffnesses)):
    for j in range(len(dts)):
        ax.text(j, i, "ok" if fate[i, j] == 1 else f"{fate[i, j] * DURATION:.2f} s", ha="center", va="center")
fig.colorbar(im, ax=ax, label="t_fail / duration")
fig.tight_layout()
plt.show()
