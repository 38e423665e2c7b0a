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
from scipy.spatial.transform import Rotation

from ..world.terrain_kernels import signed_distance
from .rigid import CORNER_SIGNS


MAX_LIFT_ITERATIONS = 60


def initial_transform(rest_points: np.ndarray, case, world) -> tuple[np.ndarray, np.ndarray]:
    """Rotation R (3, 3) and translation t (3,) [m] with world = R @ rest + t.

    rest_points: (n, 3) [m] every material point of the body, used for the clearance; world: the run's
    ``world.world.World`` (its terrain).
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
    kind, f = world.placement_terrain()
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


def place_points(rest_points: np.ndarray, case, world) -> np.ndarray:
    """World positions (n, 3) [m] at t = 0, with the scenario's seeded random perturbation (world: as
    ``initial_transform``)."""
    R, t = initial_transform(rest_points, case, world)
    x = rest_points @ R.T + t
    if case.scenario.perturbation_m > 0:
        x += np.random.default_rng(case.seed).normal(scale=case.scenario.perturbation_m, size=x.shape)
    return np.ascontiguousarray(x)


def place_box_chain(case, world, nodes, attached, centres, half, rigid, x, v) -> None:
    """A chain of rigid boxes and its link nodes (the hybrid and the legged mass-spring bodies) placed by the
    rule above, from their rest build: nodes (n_nodes, 3) [m], attached (n_nodes,) bool (the nodes on the
    boxes), box centres (n_boxes, 3) [m] and half extents half (3,) [m].  The lowest point is a node or a box
    corner; the scenario's random perturbation moves the free nodes only (the attached ones stay on their
    boxes).  OVERWRITES x (n_nodes, 3) [m], v (n_nodes, 3) [m/s] (zero) and the poses of the boxes ``rigid``
    (``rigid.RigidBoxes``; at rest)."""
    corners = (centres[:, None, :] + CORNER_SIGNS * half).reshape(-1, 3)
    R0, t = initial_transform(np.vstack([nodes, corners]), case, world)
    q0 = np.roll(Rotation.from_matrix(R0).as_quat(), 1)  # scipy (x, y, z, w) -> (w, x, y, z)
    placed = nodes @ R0.T + t
    sc = case.scenario
    if sc.perturbation_m > 0:
        free = ~attached
        placed[free] += np.random.default_rng(case.seed).normal(scale=sc.perturbation_m, size=(free.sum(), 3))
    x[:] = placed
    v[:] = 0.0
    c = centres @ R0.T + t
    for i in range(len(centres)):
        rigid.set_pose(i, c=c[i], q=q0, v=np.zeros(3), w=np.zeros(3))
