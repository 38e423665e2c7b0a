"""Coupling a body to the shallow-water layer of its scenario (myriapod paper Sec. 6.2, Fig. 12).

The paper couples the centipede's legs to a Kass-Miller shallow-water simulator
so that ripples spread from the feet and a wake forms behind the creature.
Here every body model takes part the same way, through its ``scene()``:

* legged creatures push the water with their leg tips (the feet);
* legless bodies (Miller's worm and snake, the FEM worm) with the vertices of
  their surface (lattice nodes, FEM surface nodes), the body pushing water aside.

The coupling runs once per observation chunk (the runner's sample period, e.g.
1/60 s): the pushing points' velocities are their displacement over the last
chunk divided by its duration, ``ShallowWater.disturb`` moves water accordingly
(volume-conserving), and the water then advances over the chunk in sub-steps
whose Courant number stays below ``scenario.water_courant``.  The water does not
push back on the body: at the paper's scale (a 1 cm layer under 1 m segments)
its forces are negligible next to the ground contact, and the paper shows the
water as a visual and sensory layer.  This one-way coupling is a modelling
choice, stated in the README.
"""
from __future__ import annotations

import math

import numpy as np

from .terrain import terrain_from_scenario
from .water import GRAVITY, ShallowWater


ENERGY_SAMPLE_HZ = 10.0  # wake energy samples per simulated second


def has_water(scenario) -> bool:
    return scenario.water_depth_m > 0.0


class WaterCoupling:
    """The scenario's water layer and the points of a body that push it.

    ``water``: the ``ShallowWater``; ``energy``: wake energy [J] after each chunk;
    ``times``: the chunk end times [s].
    """

    def __init__(self, scenario, world=None):
        """The water over ``world``'s terrain (the run's ``world.World``; built from the scenario when None)."""
        x0, x1, z0, z1 = scenario.water_region_m
        kind, f = terrain_from_scenario(scenario) if world is None else world.terrain
        self.water = ShallowWater(x1 - x0, z1 - z0, scenario.water_cell_m,
                                  level_m=scenario.ground_height_m + scenario.water_depth_m, bed=(kind, f),
                                  origin=(x0, z0), g=GRAVITY if scenario.gravity_m_s2 <= 0 else scenario.gravity_m_s2,
                                  damping=scenario.water_damping_per_s)
        self.radius = scenario.water_point_radius_m
        self.courant = scenario.water_courant
        depth_max = float(self.water.depth().max())
        # the largest sub-step with sqrt(g d_max) dt / dx <= courant
        self.max_dt = (self.courant * self.water.dx / math.sqrt(self.water.g * depth_max)) if depth_max > 0 else math.inf
        self._prev: np.ndarray | None = None
        self._last_energy_t = -math.inf
        self.energy: list[float] = []  # wave_energy_estimate() at ENERGY_SAMPLE_HZ [J]
        self.times: list[float] = []
        self.submerged: list[int] = []

    @staticmethod
    def pushing_points(body) -> np.ndarray:
        """(k, 3) [m] the points of ``body`` that push water: leg tips, else its surface vertices."""
        scene = body.scene()
        if scene.legs is not None:
            return np.ascontiguousarray(scene.legs[:, 2, :])
        parts = [v for v, _, _ in scene.triangles]
        return np.concatenate(parts) if parts else np.zeros((0, 3))

    def start(self, body) -> None:
        """Remember the points at t = 0 (no push yet)."""
        self._prev = self.pushing_points(body)

    def advance(self, body, t_end: float, duration_s: float) -> None:
        """One chunk of ``duration_s`` [s] ending at ``t_end``: push with the body's motion, then step the water."""
        pts = self.pushing_points(body)
        if self._prev is None or self._prev.shape != pts.shape or duration_s <= 0:
            self._prev = pts
            return
        vel = (pts - self._prev) / duration_s
        # the points pushed during the chunk from where they were at its start
        n = self.water.disturb(self._prev, vel, self.radius, duration_s)
        self.water.advance(duration_s, self.max_dt)
        self._prev = pts
        self.submerged.append(n)
        # the energy needs a Poisson solve (milliseconds): sampled at ENERGY_SAMPLE_HZ, and at the end
        if t_end - self._last_energy_t >= 1.0 / ENERGY_SAMPLE_HZ:
            self._record_energy(t_end)
        self._t_end = t_end

    def _record_energy(self, t: float) -> None:
        self.times.append(t)
        self.energy.append(self.wave_energy_estimate())
        self._last_energy_t = t

    def wave_energy_estimate(self) -> float:
        """2 x the potential energy of the surface's deviation from rest [J]: the wake energy sampled in time.

        For linear progressive waves kinetic and potential energy are equal on average, so twice the
        potential energy (a sum over the grid) estimates the total without the Poisson solve that
        ``ShallowWater.wake_energy`` needs for the kinetic part (about 1 s on a 500 x 240 grid);
        the final ``wake_energy`` metric is the exact one.
        """
        w = self.water
        wet = w.h > w.b
        dev = np.where(wet, w.h - w.rest_level(), 0.0)
        return float(w.rho * w.g * np.sum(dev * dev) * w.cell_area)

    def metrics(self) -> dict[str, float]:
        """``wake_energy`` [J] at the end of the run (exact: potential + kinetic), ``wake_energy_max`` [J] the
        largest sampled estimate (``wave_energy_estimate``), and the mean number of submerged points."""
        if not self.submerged:
            return {"wake_energy": 0.0, "wake_energy_max": 0.0, "water_points_submerged_mean": 0.0}
        if self.times[-1] < self._t_end:
            self._record_energy(self._t_end)
        return {"wake_energy": float(self.water.wake_energy()), "wake_energy_max": float(max(self.energy)),
                "water_points_submerged_mean": float(np.mean(self.submerged))}

    def surface(self) -> np.ndarray:
        """(nx, nz) [m] the water surface height minus its rest level, a copy (for animations)."""
        return (self.water.h - self.water.rest_level()).astype(np.float32)
