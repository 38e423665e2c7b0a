"""Terrains of a scenario as the (kind, parameters) pair that kernels query."""
from __future__ import annotations

import math

import numpy as np

from .terrain_kernels import N_TERRAIN_PARAMS, PLANE, SLAB, SLOPE

TERRAIN_KINDS = {"plane": PLANE, "slope": SLOPE, "slab": SLAB, "none": PLANE}
NO_GROUND_HEIGHT_M = -1.0e9  # terrain "none": a plane so far below that nothing ever reaches it


def terrain_from_scenario(sc) -> tuple[int, np.ndarray]:
    """(kind code, float64 parameter vector) of a ``ScenarioConfig``'s terrain (see terrain_kernels)."""
    f = np.zeros(N_TERRAIN_PARAMS)
    f[0] = NO_GROUND_HEIGHT_M if sc.terrain == "none" else sc.ground_height_m
    kind = TERRAIN_KINDS[sc.terrain]
    if kind == SLOPE:
        f[1] = math.radians(sc.slope_deg)
    elif kind == SLAB:
        f[1] = sc.ground_height_m + sc.slab_height_m
        f[2] = sc.slab_edge_x_m
        f[3] = min(sc.slab_edge_radius_m, sc.slab_height_m)
    return kind, f


def placement_terrain(sc) -> tuple[int, np.ndarray]:
    """The surface a body is placed above at t = 0.

    The scenario's terrain, except for ``none``: its stand-in plane lies far
    below (``NO_GROUND_HEIGHT_M``), and a body placed above it would sit where
    float64 cannot resolve a time step's motion, so ``none`` places bodies above
    ``ground_height_m`` instead.
    """
    kind, f = terrain_from_scenario(sc)
    if sc.terrain == "none":
        f = f.copy()
        f[0] = sc.ground_height_m
    return kind, f
