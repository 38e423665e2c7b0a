"""Where a body starts: the same placement rule for every body backend.

Bodies are built in a rest frame with the head at the origin, lying along -x,
underside at y = 0 (creatures face +x; y up; z to the right).  At t = 0 the
body is turned to lie along a slope (head uphill) or to hang head up
(suspended scenarios), moved to ``start_x_m``, and lifted so its lowest point
is ``start_height_m`` above the surface (along the surface normal).
"""
from __future__ import annotations

import math

import numpy as np

from ..world.terrain import placement_terrain
from ..world.terrain_kernels import signed_distance


MAX_LIFT_ITERATIONS = 60


def initial_transform(rest_points: np.ndarray, case, world=None) -> tuple[np.ndarray, np.ndarray]:
    """Rotation R (3, 3) and translation t (3,) [m] with world = R @ rest + t.

    rest_points: (n, 3) [m] every material point of the body, used for the clearance; world: the run's
    ``world.world.World`` (its terrain; built from the scenario here when None).
    """
    sc = case.scenario
    R = np.eye(3)
    normal = np.array([0.0, 1.0, 0.0])
    if sc.suspended:
        # hang head up: the body axis (-x) turns to -y
        R = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    elif sc.terrain == "slope":
        # lie along the incline, head uphill: rotate about z by the slope angle
        a = math.radians(sc.slope_deg)
        c, s = math.cos(a), math.sin(a)
        R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
        normal = np.array([-s, c, 0.0])
    t = np.array([sc.start_x_m, 0.0, 0.0])
    kind, f = placement_terrain(sc) if world is None else world.placement_terrain()
    # Lift along the normal until the lowest point is start_height_m above the surface.  One step is
    # exact for the planar terrains; a mesh clamps phi to +-band far from its surface (and a height
    # field's phi is a first-order distance), so repeat until the clearance is right.
    for _ in range(MAX_LIFT_ITERATIONS):
        x = rest_points @ R.T + t
        phi = min(signed_distance(kind, f, *p) for p in x)
        t = t + (sc.start_height_m - phi) * normal
        if abs(sc.start_height_m - phi) < 1e-9 * max(1.0, abs(phi)):
            break
    return R, t


def place_points(rest_points: np.ndarray, case, world=None) -> np.ndarray:
    """World positions (n, 3) [m] at t = 0, with the scenario's seeded random perturbation (world: as
    ``initial_transform``)."""
    R, t = initial_transform(rest_points, case, world)
    x = rest_points @ R.T + t
    if case.scenario.perturbation_m > 0:
        x += np.random.default_rng(case.seed).normal(scale=case.scenario.perturbation_m, size=x.shape)
    return np.ascontiguousarray(x)
