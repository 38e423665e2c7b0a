"""Food: point sources sensed by the antennae and eaten by the head (paper Sec. 5.2, 6.2).

A source k at p_k with intensity I_k gives the signal

    S(x) = sum_k I_k / max(|x - p_k|, softening)^2

at a point x (the paper's "intensity gradients that decrease with squared
radial distance"; the softening keeps the signal finite at a source).  Eaten
sources no longer count.

Sources of a case (``food_sources``): the explicit ``food.sources`` (x, y, z,
intensity; y above the base surface at (x, z)) plus ``food.count`` random ones,
uniform in ``food.region_m``, none within ``food.clear_radius_m`` of the origin
(the start) nor within ``food.obstacle_clearance_m`` of an obstacle, at
``food.height_m`` above the surface, from ``default_rng([food.seed, 2])``
(independent of the case seed, like the random obstacles' ``terrain_seed``).

Eating (``FoodField.eat``): a source within ``reach_radius_m`` of the head
centre in the head's own x-z plane, and within twice that along the head's y
axis, is eaten; its time is recorded.  Measuring in the head's plane makes the
reach independent of how high the body stands above food lying on the ground.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..core.errors import InputError
from . import terrain as T
from .terrain_kernels import obstacles_phi

MAX_PLACEMENT_TRIES = 1000  # per random source


@njit(cache=True)
def food_signal(pos, intensity, active, soft2, x, y, z):
    """S at (x, y, z): sum over active sources of intensity / max(d^2, soft2)."""
    s = 0.0
    for k in range(pos.shape[0]):
        if active[k]:
            d2 = (x - pos[k, 0]) ** 2 + (y - pos[k, 1]) ** 2 + (z - pos[k, 2]) ** 2
            s += intensity[k] / max(d2, soft2)
    return s


@njit(cache=True)
def food_signals(pos, intensity, active, soft2, points, out):
    """out[i] = S(points[i]) for points (m, 3)."""
    for i in range(points.shape[0]):
        out[i] = food_signal(pos, intensity, active, soft2, points[i, 0], points[i, 1], points[i, 2])


@njit(cache=True)
def food_signals_at_tips(pos, intensity, active, soft2, points, out):
    """out[a] = S(points[a, -1]) for chains points (m, k, 3): the signal at each chain's last point."""
    for a in range(points.shape[0]):
        k = points.shape[1] - 1
        out[a] = food_signal(pos, intensity, active, soft2, points[a, k, 0], points[a, k, 1], points[a, k, 2])


@njit(cache=True)
def food_within_reach(pos, active, c, R, reach, out):
    """out[k] = active source k lies within ``reach`` of c in the x-z plane of frame R and within 2 reach
    along its y axis; returns how many."""
    n = 0
    for k in range(pos.shape[0]):
        out[k] = False
        if not active[k]:
            continue
        dx, dy, dz = pos[k, 0] - c[0], pos[k, 1] - c[1], pos[k, 2] - c[2]
        u = dx * R[0, 0] + dy * R[1, 0] + dz * R[2, 0]
        v = dx * R[0, 1] + dy * R[1, 1] + dz * R[2, 1]
        w = dx * R[0, 2] + dy * R[1, 2] + dz * R[2, 2]
        if u * u + w * w <= reach * reach and abs(v) <= 2.0 * reach:
            out[k] = True
            n += 1
    return n


def _source(sc) -> str:
    return f"scenario {sc.name!r}" if getattr(sc, "name", "") else "scenario"


def food_sources(sc, food, terrain: tuple[int, np.ndarray] | None = None) -> np.ndarray:
    """(n, 4) sources x, y, z [m], intensity of a scenario (``ScenarioConfig``) and ``FoodConfig``, on its
    terrain (kind, f) (``terrain.terrain_from_scenario(sc)``, built here when not given)."""
    # base_height reads only the base terrain's part of f; the obstacle test its obstacles
    kind, f = T.terrain_from_scenario(sc) if terrain is None else terrain
    out = []
    v = food.sources
    for i in range(0, len(v), 4):
        x, y, z, inten = v[i: i + 4]
        out.append((x, float(T.base_height(sc, kind, f, x, z)) + y, z, inten))
    n = int(food.count)
    if n:
        rng = np.random.default_rng([int(food.seed), 2])
        x0, x1, z0, z1 = food.region_m
        has_obst = f[T.TK.H_NOBST] > 0
        for _ in range(n):
            for _ in range(MAX_PLACEMENT_TRIES):
                x, z = rng.uniform(x0, x1), rng.uniform(z0, z1)
                y = float(T.base_height(sc, kind, f, x, z)) + food.height_m
                if math.hypot(x, z) < food.clear_radius_m:
                    continue
                if has_obst and obstacles_phi(f, x, y, z)[0] < food.obstacle_clearance_m:
                    continue
                out.append((x, y, z, food.intensity))
                break
            else:
                raise InputError(_source(sc), "food.count",
                                 f"no room for {n} random food sources in region_m {list(food.region_m)} clear of "
                                 f"the start (clear_radius_m {food.clear_radius_m}) and the obstacles "
                                 f"(obstacle_clearance_m {food.obstacle_clearance_m})")
    return np.array(out, dtype=float).reshape(-1, 4)


class FoodField:
    """The case's food sources, what is left of them and when each was eaten.

    pos (n, 3) [m]; intensity (n,); active (n,) bool; eaten_t (n,) [s] (nan: not eaten).
    """

    def __init__(self, sources: np.ndarray, softening_m: float = 0.1, reach_radius_m: float = 1.0):
        sources = np.asarray(sources, dtype=float).reshape(-1, 4)
        self.pos = np.ascontiguousarray(sources[:, :3])
        self.intensity = np.ascontiguousarray(sources[:, 3])
        self.active = np.ones(len(sources), dtype=np.bool_)
        self.eaten_t = np.full(len(sources), np.nan)
        self.soft2 = float(softening_m) ** 2
        self.reach = float(reach_radius_m)
        self._hit = np.zeros(len(sources), dtype=np.bool_)
        self._n_left = len(sources)

    @classmethod
    def from_case(cls, case, sources: np.ndarray | None = None) -> FoodField:
        """The field of ``case``'s food sources: ``sources`` (n, 4) when built already (``world.World.food``)."""
        fc = case.food
        return cls(food_sources(case.scenario, fc) if sources is None else sources, fc.softening_m, fc.reach_radius_m)

    def __len__(self) -> int:
        return len(self.intensity)

    @property
    def n_left(self) -> int:
        return self._n_left

    def signals(self, points: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        """S at each of points (m, 3) [m]."""
        points = np.ascontiguousarray(points, dtype=float).reshape(-1, 3)
        if out is None:
            out = np.zeros(len(points))
        if len(self.intensity) == 0:
            out[:] = 0.0
            return out
        food_signals(self.pos, self.intensity, self.active, self.soft2, points, out)
        return out

    def signals_at_tips(self, chains: np.ndarray, out: np.ndarray) -> np.ndarray:
        """S at the last point of each chain (m, k, 3) [m] (the antennae's tips), into out (m,)."""
        if self._n_left == 0:
            out[:] = 0.0
        else:
            food_signals_at_tips(self.pos, self.intensity, self.active, self.soft2, chains, out)
        return out

    def eat(self, c: np.ndarray, R: np.ndarray, t: float) -> int:
        """Eat the sources within reach of a head at (c (3,) [m], R (3, 3)) at time t [s]; how many."""
        if self._n_left == 0:
            return 0
        n = food_within_reach(self.pos, self.active, c, R, self.reach, self._hit)
        if n:
            self.active[self._hit] = False
            self.eaten_t[self._hit] = t
            self._n_left -= n
        return n

    def metrics(self) -> dict[str, float]:
        eaten = self.eaten_t[np.isfinite(self.eaten_t)]
        return {"food_reached": float(len(eaten)),
                "time_to_first_food_s": float(eaten.min()) if len(eaten) else float("nan"),
                "food_sources": float(len(self))}
