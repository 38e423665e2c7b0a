"""
Snake speed against friction anisotropy
=======================================

Lateral undulation on the mass-spring lattice against the kinematic model of slithering of Hu,
Nirody, Scott and Shelley (2009, PNAS 106:10081), :func:`bench_myriapoda.reference.slithering.steady_slithering`.
One wave on the body, commanded curvature x body length 7, Froude number 0.1 and a backward
coefficient 1.5 times the forward one; the transverse coefficient is swept. The reference is drawn
for a belly as wide as the body (two contact lines at its edges, as the lattice's bottom nodes are)
and for Hu et al.'s line.
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import bench_myriapoda as bm
from bench_myriapoda.reference.slithering import steady_slithering

SCALE = float(os.environ.get("BENCH_MYRIAPODA_EXAMPLE_SCALE", "1"))
RATIOS = (1.0, 1.5, 2.0, 3.0, 5.0, 10.0) if SCALE >= 1 else (1.0, 2.0, 5.0, 10.0)
AMPLITUDE, MU_B = 7.0, 1.5
SNAKE = {"creature.segments": 20, "creature.mass_kg": 0.4, "gait.wavelength_bl": 1.0,
         "gait.curvature_amplitude": AMPLITUDE, "gait.frequency_hz": 0.25, "gait.ramp_s": 2.0,
         "metrics.warmup_cycles": 1, "friction.froude": 0.1, "friction.mu_forward": 1.0,
         "friction.mu_backward": MU_B}

speeds, width_bl = [], None
for ratio in RATIOS:
    # 12 s = 3 periods: the ramp, one period of warm-up, two measured
    r = bm.run("snake", "massspring", "flat", "lateral-undulation", duration=12.0,
               set={**SNAKE, "friction.mu_transverse": ratio})
    speeds.append(r.metrics["speed_bl_per_cycle"])
    width_bl = r.case.creature.width_m / r.metrics["body_length_m"]
    print(f"mu_t / mu_f = {ratio:5.1f}: {speeds[-1]:.3f} BL/cycle ({r.status})")

grid = np.linspace(1.0, 10.0, 37)
wide = [steady_slithering(AMPLITUDE, 1.0, 1.0, MU_B, m, width_bl=width_bl).speed_bl_per_cycle for m in grid]
line = [steady_slithering(AMPLITUDE, 1.0, 1.0, MU_B, m).speed_bl_per_cycle for m in grid]

fig, ax = plt.subplots(figsize=(7, 4.5))
ax.plot(grid, wide, "k-", label=f"kinematic reference, belly {width_bl:.2f} BL wide")
ax.plot(grid, line, "k--", label="kinematic reference, a line (Hu et al.)")
ax.plot(RATIOS, speeds, "o", color="C0", label="massspring lattice")
ax.set(xscale="log", xlabel="friction anisotropy mu_t / mu_f", ylabel="forward speed [body lengths / cycle]",
       title="lateral undulation, A = 7, Fr = 0.1")
ax.legend()
fig.tight_layout()
plt.show()
