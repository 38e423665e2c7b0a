"""Obstacle queries through the grid (issue 16): a walking centipede among 120 cylinders, and query cost
against the obstacle count.

* ``test_bench_walk_flat_vs_cylinders``: the walking 18-segment hybrid centipede per
  step on flat ground and among 40, 120 and 1,000 low random cylinders (Fig. 13's sizes,
  spread over the ground under and ahead of the body at one density); target: within
  1.5x of flat ground.
* ``test_bench_obstacle_query``: one ``signed_distance`` + ``surface_normal`` pair per
  point for 10^5 points 0-1.5 m above the ground (where bodies and legs query) among 10,
  100 and 1,000 cylinders at Fig. 13's density (the paved square grows with the count),
  through the grid and through the loop it replaced (``obstacles_below_brute``);
  ns_per_query in extra_info.  The grid's cost should not grow with the count.

    python3 -m pytest tests/benchmarks/test_bench_obstacles.py --benchmark-enable --benchmark-only
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit

from bench_myriapoda.harness.throughput_suite import CENTIPEDE_WALK_IN_STEPS as WALK_IN_STEPS
from bench_myriapoda.world import terrain_kernels as TK
from walking_hybrid import STEPS_PER_CALL, query_loop, time_walk_chunks, walker  # noqa: F401 (STEPS_PER_CALL: for scripts)
N_POINTS = 100_000
FIG13_DENSITY = 120 / 30.0 ** 2   # cylinders per m^2 (fig13-cylinders at 120 cylinders)
# 120 of Fig. 13's low cylinders on the ground around and ahead of the body, which lies along -x.  Layout
# seed 2: with seeds 0 and 1 the hybrid body standing among them becomes unstable ("runaway speed") within
# 1.6 s, with or without the legs' collision -- a limit of the body on cylinder edges, not of the queries
CYLINDERS_120 = ["scenario.obstacle_cylinders=120", "scenario.obstacle_radius_m=[0.3, 0.8]",
                 "scenario.obstacle_height_m=[0.1, 0.4]", "scenario.obstacle_region_m=[-30.0, 15.0, -15.0, 15.0]",
                 "scenario.obstacle_clear_radius_m=1.0", "scenario.terrain_seed=2"]


def cylinders(n: int) -> list[str]:
    """``CYLINDERS_120``'s layout with ``n`` cylinders at the same density: its region scaled about its centre by
    sqrt(n / 120) (issue 30 asks for 40, 120 and 1,000)."""
    if n == 120:
        return CYLINDERS_120
    s = math.sqrt(n / 120.0)
    x0, x1, z0, z1 = -30.0, 15.0, -15.0, 15.0
    cx, cz, hx, hz = 0.5 * (x0 + x1), 0.5 * (z0 + z1), 0.5 * (x1 - x0) * s, 0.5 * (z1 - z0) * s
    region = f"scenario.obstacle_region_m=[{cx - hx:.3f}, {cx + hx:.3f}, {cz - hz:.3f}, {cz + hz:.3f}]"
    # layout seed 5 at 1,000: with seeds 2, 3, 4 and 6 the body becomes unstable ("runaway speed") on a
    # cylinder's edge within 3 s (the limit noted at CYLINDERS_120, not the queries'); seed 2 serves 40
    seed = f"scenario.terrain_seed={5 if n == 1000 else 2}"
    return [f"scenario.obstacle_cylinders={n}" if o.startswith("scenario.obstacle_cylinders=") else
            region if o.startswith("scenario.obstacle_region_m=") else
            seed if o.startswith("scenario.terrain_seed=") else o for o in CYLINDERS_120]


@pytest.mark.parametrize("ground", ["flat", "cylinders-40", "cylinders-120", "cylinders-1000"])
def test_bench_walk_flat_vs_cylinders(benchmark, ground):
    case, b = walker(cylinders(int(ground.split("-")[1])) if ground != "flat" else [])
    benchmark.extra_info["ground"] = ground
    time_walk_chunks(benchmark, case, b, WALK_IN_STEPS, rounds=16)


@njit(cache=True, error_model="numpy")
def brute_loop(kind, f, p):
    """The same pair through the loop over every obstacle (what the queries did before the grid)."""
    acc = 0.0
    for i in range(p.shape[0]):
        phi, j = TK.obstacles_below_brute(f, p[i, 0], p[i, 1], p[i, 2], p[i, 1] - f[0])
        if j >= 0:
            nx, ny, nz = TK._obstacle_normal(f, j, p[i, 0], p[i, 1], p[i, 2])
        else:
            nx, ny, nz = 0.0, 1.0, 0.0
        acc += phi + nx + 2.0 * ny + 3.0 * nz
    return acc


def paved(n: int, seed: int = 1):
    """(f, points (N_POINTS, 3)): n Fig. 13 cylinders on the plane y = 0 at FIG13_DENSITY, and query points
    0-1.5 m above the ground over the paved square."""
    half = 0.5 * math.sqrt(n / FIG13_DENSITY)
    rng = np.random.default_rng(seed)
    recs = [TK.cylinder_record(rng.uniform(-half, half), rng.uniform(-half, half), rng.uniform(0.3, 0.8), -1.0,
                               rng.uniform(0.1, 0.4)) for _ in range(n)]
    f = TK.with_obstacles(TK.header(0.0), recs)
    p = np.column_stack([rng.uniform(-half, half, N_POINTS), rng.uniform(0.0, 1.5, N_POINTS),
                         rng.uniform(-half, half, N_POINTS)])
    return f, p


@pytest.mark.parametrize("impl", ["grid", "loop"])
@pytest.mark.parametrize("n", [10, 100, 1000])
def test_bench_obstacle_query(benchmark, n, impl):
    f, p = paved(n)
    fn = query_loop if impl == "grid" else brute_loop
    a, b = query_loop(TK.PLANE, f, p[:1000]), brute_loop(TK.PLANE, f, p[:1000])
    assert a == b  # the grid answers as the loop
    benchmark.pedantic(fn, args=(TK.PLANE, f, p), rounds=7, iterations=1, warmup_rounds=1)
    benchmark.extra_info.update(cylinders=n, impl=impl)
    if benchmark.stats is not None:
        benchmark.extra_info["ns_per_query"] = benchmark.stats.stats.median / N_POINTS * 1e9
