"""
Your own creature file
======================

A creature is a TOML file: its body plan (``[creature]``), friction, its gaits and the body models
it runs on, each with its own keys (``bench-myriapoda keys`` lists every one). Pass the file's path
wherever a creature name goes. This one is a short, stiff-bodied worm with one long wave, run next
to Miller's worm on the lattice; the figure shows both centre lines from above at six instants.
"""
import os
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import bench_myriapoda as bm

SCALE = float(os.environ.get("BENCH_MYRIAPODA_EXAMPLE_SCALE", "1"))
creature = Path(tempfile.mkdtemp()) / "stubby.toml"
creature.write_text("""
[creature]
name = "stubby"
description = "a short worm: 10 segments, one compression wave on the body"
segments = 10
segment_length_m = 0.05
width_m = 0.04
height_m = 0.04
mass_kg = 0.04
default_gait = "rectilinear"
gaits = ["rectilinear"]

[friction]
model = "miller"
contact_distance_m = 0.004
miller_mu_slide = 0.03

[gaits.rectilinear]
amplitude = 0.25
wavelength_bl = 1.0
frequency_hz = 0.5
volume_conserving = true
ramp_s = 1.0

[bodies.massspring]
preset = "miller-worm"
frame_rate_hz = 60.0

[collision]
r_n = 0.0
r_t = 1.0
""")

fig, ax = plt.subplots(figsize=(9, 3.5))
for name, color in ((str(creature), "C1"), ("worm", "C0")):
    r = bm.run(name, "massspring", "flat", duration=max(4.0, 8.0 * SCALE))
    centres = r.series.segment_centers                    # (T, n_seg, 3) [m]
    for k, i in enumerate(np.linspace(0, len(centres) - 1, 6).astype(int)):
        ax.plot(centres[i, :, 0], centres[i, :, 2], "-", color=color, alpha=0.3 + 0.7 * k / 5,
                label=f"{r.case.creature.name}: {r.metrics['speed_bl_per_cycle']:.3f} BL/cycle" if k == 5 else None)
ax.set(xlabel="x [m] (forward)", ylabel="z [m]", title="centre lines from above (darker = later)", aspect="equal")
ax.legend(loc="upper left")
fig.tight_layout()
plt.show()
