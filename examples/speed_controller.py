"""A user controller in plain Python, run on all three body models (docs: "Write your own controller").

The worm's compression wave (Miller's rectilinear gait) as a tiny central pattern generator whose
amplitude a proportional controller adjusts, ten times a second, so that the worm crawls at a
target speed.  It reads only the observation (segment velocities and frames) and writes only the
actuation (the AXIAL muscle channel), so the same object drives every body.
"""
import numpy as np

import bench_myriapoda as bm
from bench_myriapoda.core.protocols import AXIAL


class SpeedController:
    rate_hz = 10.0                                 # control ticks per second; the body holds the command between

    def __init__(self, target_bl_per_s=0.05, gain=2.0, frequency_hz=0.5, waves_per_body=2.0):
        self.target, self.gain = target_bl_per_s, gain
        self.f, self.k = frequency_hz, waves_per_body

    def reset(self, case, body_info, rng):
        self.length = body_info["body_length_m"]
        self.s = body_info["muscle_s"] / self.length   # each muscle segment's place along the body [BL]
        self.amplitude = 0.1

    def step(self, obs, t, act):
        forward = obs.seg_rot[0][:, 0]               # the head segment's axis, pointing forward
        speed = float(np.mean(obs.seg_vel @ forward)) / self.length   # [BL/s]
        if t > 2.0:                                  # let the wave form before steering the speed
            self.amplitude = np.clip(self.amplitude + self.gain * (self.target - speed) / self.rate_hz, 0.02, 0.3)
        wave = np.sin(2 * np.pi * (self.k * self.s - self.f * t))   # travels head to tail
        act.muscle[0, :, AXIAL] = min(t, 1.0) * self.amplitude * wave
        act.muscles_on = True


if __name__ == "__main__":
    for body in ("massspring", "fem", "hybrid"):
        result = bm.run(creature="worm", body=body, scenario="flat", duration=8.0, controller=SpeedController())
        print(f"{body:10s} {result.status}: {result.metrics['speed_m_per_s'] / result.metrics['body_length_m']:.4f} BL/s")
