"""Throughput of the shallow-water layer: ns per cell per step on a 256 x 256 grid.

Kass-Miller implicit step with the alternating-direction tridiagonal solves
(bench_myriapoda.world.water).  4 mm cells, 5 cm still water (c = 0.70 m/s),
dt at Courant number 0.5, a ripple spreading from a Gaussian bump.  Every round
restarts from the same state and runs N_STEPS steps inside one numba call;
compile (or cache load) happens before timing and is reported in extra_info,
with ns_per_cell_step from the fastest round.

    python3 -m pytest tests/benchmarks/test_bench_water.py --benchmark-enable --benchmark-only
"""
from __future__ import annotations

import math
import time

import numpy as np

from bench_myriapoda.world.water import ShallowWater

N = 256
DX = 0.004  # [m]
DEPTH = 0.05  # [m]
DT = 0.5 * DX / math.sqrt(9.81 * DEPTH)  # [s], Courant number 0.5
N_STEPS = 100


def test_bench_water_256x256(benchmark):
    water = ShallowWater(N * DX, N * DX, DX, depth_m=DEPTH)
    water.add_gaussian_bump(0.0, 0.0, 0.01 * DEPTH, 4 * DX)
    h0, hp0 = water.h.copy(), water.h_prev.copy()
    v0 = water.volume()

    t0 = time.perf_counter()
    water.step(DT, 1)  # JIT compile or cache load
    compile_s = time.perf_counter() - t0
    walls: list[float] = []

    def reset():
        water.h[...] = h0
        water.h_prev[...] = hp0

    def run():
        t = time.perf_counter()
        water.step(DT, N_STEPS)
        walls.append(time.perf_counter() - t)

    benchmark.pedantic(run, setup=reset, rounds=10, warmup_rounds=1)
    ns = min(walls) / (N_STEPS * N * N) * 1e9
    benchmark.extra_info.update({"grid": f"{N}x{N}", "steps_per_round": N_STEPS, "courant": 0.5,
                                 "ns_per_cell_step": ns, "compile_s": compile_s})
    print(f"\nshallow water {N}x{N}: {ns:.1f} ns per cell per step (fastest of {len(walls)} rounds)")
    # The physics still holds under load: the ripple spread and the volume is kept.
    assert abs(water.volume() / v0 - 1.0) < 1e-9
    assert np.all(np.isfinite(water.h))
    assert np.max(water.h) < DEPTH + 0.01 * DEPTH
