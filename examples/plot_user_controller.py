"""
Write your own controller
=========================

A controller is a plain Python object with ``reset(case, body_info, rng)`` and
``step(observation, t, actuation)``. It reads what the body reports (segment poses, velocities,
contacts) and writes muscle strains; the same object drives every body model. This one is closed
loop: the worm crawls with Miller's compression wave until its head passes a finish line, then fades
the wave out over ``fade_s`` seconds. What happens next is physics, not the controller: the
compressed segments lengthen again as the strain fades, and the directional friction (no backward
sliding) turns that lengthening into a last forward glide before the worm stops.
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import bench_myriapoda as bm
from bench_myriapoda.core.protocols import AXIAL

SCALE = float(os.environ.get("BENCH_MYRIAPODA_EXAMPLE_SCALE", "1"))


class CrawlToLine:
    """Crawl until the head's centre is ``distance_m`` ahead of where it started, then stop."""

    rate_hz = 20.0                                   # control ticks per second; the body holds the command between

    def __init__(self, distance_m=0.1, amplitude=0.2, frequency_hz=0.5, waves_per_body=2.0, fade_s=2.0):
        self.distance, self.amplitude, self.fade_s = distance_m, amplitude, fade_s
        self.f, self.k = frequency_hz, waves_per_body

    def reset(self, case, body_info, rng):
        self.s = body_info["muscle_s"] / body_info["body_length_m"]   # muscle segments along the body [BL]
        self.start, self.stopped_at = None, None

    def step(self, obs, t, act):
        head_x = float(obs.seg_pos[0, 0])
        self.start = head_x if self.start is None else self.start
        if self.stopped_at is None and head_x - self.start >= self.distance:
            self.stopped_at = t                      # crossed the line: relax from now on
        fade = 1.0 if self.stopped_at is None else max(0.0, 1.0 - (t - self.stopped_at) / self.fade_s)
        wave = np.sin(2 * np.pi * (self.k * self.s - self.f * t))   # travels head to tail
        act.muscle[0, :, AXIAL] = min(t, 1.0) * fade * self.amplitude * wave
        act.muscles_on = True


controller = CrawlToLine(distance_m=0.1)
r = bm.run("worm", "massspring", "flat", duration=max(8.0, 12.0 * SCALE), controller=controller)
track = r.series_frame()
print(r, f"stopped at t = {controller.stopped_at}")

fig, ax = plt.subplots(figsize=(7, 4))
ax.plot(track["t_s"], track["head_x_m"] - track["head_x_m"].iloc[0], label="head")
ax.plot(track["t_s"], track["com_x_m"] - track["com_x_m"].iloc[0], label="centre of mass")
ax.axhline(controller.distance, color="k", ls="--", label="finish line")
if controller.stopped_at is not None:
    ax.axvspan(controller.stopped_at, controller.stopped_at + controller.fade_s, color="0.9",
               label="wave fading out")
ax.set(xlabel="time [s]", ylabel="forward travel [m]", title="a closed-loop controller of your own")
ax.legend()
fig.tight_layout()
plt.show()
