"""Behaviour metrics (paper Sec. 4.3, 5.2, 6.2): food, obstacles, path, clearance.

JSON names (issue 6):

* ``food_reached`` -- food sources eaten; ``time_to_first_food_s`` -- when the
  first was eaten (nan: none);
* ``obstacle_contacts`` -- antenna contact events (rising edges, both antennae);
* ``obstacle_penetration_max_m`` -- max over samples of -min obstacle phi over
  the body's sample points (segment centres, rigid box corners and leg tips);
  0 when no point was ever inside an obstacle;
* ``path_length_m`` -- length of the head's path;
* ``terrain_clearance_min_m`` -- the smallest signed distance of a segment centre
  (rigid and link centres) to the terrain (the ground and the obstacles).

Legged creatures measure these while they walk (``BehaviourSampler``, every
controller timeline sample); the runner gives ``path_length_m`` and
``terrain_clearance_min_m`` of any body from its observation series
(``series_behaviour_metrics``).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..world.terrain_kernels import H_NOBST, obstacles_below, signed_distance


@njit(cache=True)
def obstacle_penetration(f, points):
    """Depth [m] of the deepest of points (m, 3) inside an obstacle: max(0, -min obstacle phi), 0 without obstacles.

    Each point's search stops at phi = 0 (``obstacles_below`` with cutoff 0: the exact phi of a point
    inside, no search for the nearest obstacle of a point outside).  The cutoff changes no value: a
    penetration is max(0, -phi).  Issue 30: with cutoff inf (the nearest obstacle's distance, wherever
    it was) the fused walk's samples cost about 18 us per step among obstacles, more than the
    centipede's obstacle queries."""
    deepest = 0.0
    if f[H_NOBST] <= 0.0:
        return deepest
    for i in range(points.shape[0]):
        d, _ = obstacles_below(f, points[i, 0], points[i, 1], points[i, 2], 0.0)
        deepest = max(deepest, -d)
    return deepest


@njit(cache=True)
def min_signed_distance(kind, f, points):
    """min over points (m, 3) of the terrain's signed distance (ground and obstacles)."""
    best = np.inf
    for i in range(points.shape[0]):
        d = signed_distance(kind, f, points[i, 0], points[i, 1], points[i, 2])
        best = min(best, d)
    return best


@njit(cache=True)
def rows_min_signed_distance(kind, f, points, out):
    """out[r] = ``min_signed_distance(kind, f, points[r])`` for points (k, m, 3) [m]; out (k,) [m] overwritten
    (the same comparisons in the same order, so the same doubles)."""
    for r in range(points.shape[0]):
        best = np.inf
        for i in range(points.shape[1]):
            d = signed_distance(kind, f, points[r, i, 0], points[r, i, 1], points[r, i, 2])
            best = min(best, d)
        out[r] = best


@njit(cache=True)
def rows_obstacle_penetration(f, body, tips, out):
    """out[r] = (``obstacle_penetration(f, body[r])``, ``obstacle_penetration(f, tips[r])``) [m] for body
    (k, m, 3) and tips (k, j, 3) [m]; out (k, 2) overwritten (the same calls on the same rows: the same doubles)."""
    for r in range(body.shape[0]):
        out[r, 0] = obstacle_penetration(f, body[r])
        out[r, 1] = obstacle_penetration(f, tips[r])


def path_length(points: np.ndarray) -> float:
    """Length [m] of the polyline through points (T, 3)."""
    p = np.asarray(points, dtype=float)
    if len(p) < 2:
        return 0.0
    return float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum())


def series_behaviour_metrics(series, case, world) -> dict[str, float]:
    """``path_length_m`` (the head end's path) and ``terrain_clearance_min_m`` of a recorded run (world: the
    run's ``world.world.World``, whose terrain the clearance is measured to)."""
    out = {"path_length_m": path_length(series.head)}
    if case.scenario.terrain == "none":
        out["terrain_clearance_min_m"] = float("nan")
    else:
        kind, f = world.terrain
        pts = np.ascontiguousarray(np.asarray(series.segment_centers, dtype=float).reshape(-1, 3))
        out["terrain_clearance_min_m"] = float(min_signed_distance(kind, f, pts))
    return out


class BehaviourSampler:
    """Accumulates the obstacle penetration, the terrain clearance and the head's path at samples.

    ``sample(centres, corners, tips, head)``: segment centres (n, 3), rigid box
    corners (m, 3) (or an empty array), leg tips (k, 3), head centre (3,) [m].
    """

    def __init__(self, kind: int, f: np.ndarray, terrain_none: bool = False):
        self.kind = int(kind)
        self.f = np.ascontiguousarray(f, dtype=np.float64)
        self.has_obstacles = bool(self.f[H_NOBST] > 0)
        self.terrain_none = terrain_none
        self.pen_body = 0.0      # segment centres and box corners
        self.pen_legs = 0.0      # leg tips
        self.clearance_min = math.inf
        self.path = 0.0
        self._last_head: np.ndarray | None = None

    def sample(self, centres: np.ndarray, corners: np.ndarray, tips: np.ndarray, head: np.ndarray) -> None:
        centres = np.ascontiguousarray(centres, dtype=np.float64)
        if self.has_obstacles:
            body = np.ascontiguousarray(np.vstack([centres, np.asarray(corners, dtype=np.float64).reshape(-1, 3)]))
            self.pen_body = max(self.pen_body, obstacle_penetration(self.f, body))
            self.pen_legs = max(self.pen_legs, obstacle_penetration(self.f, np.ascontiguousarray(tips, dtype=np.float64)))
        if not self.terrain_none:
            self.clearance_min = min(self.clearance_min, min_signed_distance(self.kind, self.f, centres))
        head = np.array(head, dtype=float)
        if self._last_head is not None:
            self.path += float(np.linalg.norm(head - self._last_head))
        self._last_head = head

    def sample_many(self, centres: np.ndarray, heads: np.ndarray, corners: np.ndarray | None = None,
                    tips: np.ndarray | None = None) -> None:
        """k ``sample`` calls at once: centres (k, n, 3), heads (k, 3) [m]; with obstacles also the box
        corners (k, m, 3) and tips (k, j, 3) [m] of every sample.

        The fused legged path replays a chunk's samples through this: one compiled call for the
        clearance (and one for the obstacle penetration) and a short loop for the path instead of k
        calls, with the same doubles as k ``sample`` calls (min and max are exact; each path increment
        is ``np.linalg.norm``'s sqrt(d . d) of the same difference, added in the same order;
        tests/test_fused_walk.py).
        """
        k = centres.shape[0]
        if k == 0:
            return
        if self.has_obstacles:
            if corners is None or tips is None:
                raise ValueError("BehaviourSampler.sample_many: obstacles need the corners and tips of every sample")
            body = np.ascontiguousarray(np.concatenate([np.asarray(centres, dtype=np.float64),
                                                        np.asarray(corners, dtype=np.float64)], axis=1))
            pen = np.empty((k, 2))
            rows_obstacle_penetration(self.f, body, np.ascontiguousarray(tips, dtype=np.float64), pen)
            for pb, pl in pen.tolist():
                self.pen_body = max(self.pen_body, pb)
                self.pen_legs = max(self.pen_legs, pl)
        if not self.terrain_none:
            mins = np.empty(k)
            rows_min_signed_distance(self.kind, self.f, np.ascontiguousarray(centres, dtype=np.float64), mins)
            for m in mins.tolist():
                self.clearance_min = min(self.clearance_min, m)
        heads = np.array(heads, dtype=float)
        if self._last_head is not None:
            prev = np.concatenate([self._last_head[None], heads[:-1]])
            first = 0
        else:
            prev = np.concatenate([heads[:1], heads[:-1]])
            first = 1
        d = heads - prev
        path = self.path
        for r in range(first, k):
            path += float(np.sqrt(d[r].dot(d[r])))
        self.path = path
        self._last_head = heads[-1].copy()

    def metrics(self) -> dict[str, float]:
        return {"obstacle_penetration_max_m": max(self.pen_body, self.pen_legs),
                "obstacle_penetration_body_max_m": self.pen_body,
                "obstacle_penetration_legs_max_m": self.pen_legs,
                "path_length_m": self.path,
                "terrain_clearance_min_m": self.clearance_min if math.isfinite(self.clearance_min) else float("nan")}
