"""Throughput of the FEM advance kernel: a 17-segment deformable chain on the ground.

The chain (paper presets: E = 4000, nu = 0.4, rho = 1, gamma = 50, dt = 1/3000 s;
segments 1 x 1 x 1) is dropped from 5 cm while spinning about the vertical at
2 rad/s, so the timed steps see gravity, ground contact with friction and element
rotations (the warm-started rotation solve does real work).  Each round restarts
from the same state and runs N_STEPS steps in one numba call.  JIT compile (or
cache load) is timed separately and reported in extra_info.  Target: under
100 ns per tet per step on one core.

    python3 -m pytest tests/benchmarks/test_bench_fem.py --benchmark-enable --benchmark-only
"""
from __future__ import annotations

import time

import numpy as np
import pytest

from bench_myriapoda.bodies.fem.mesh import chain_grid
from bench_myriapoda.bodies.fem.system import DT_PAPER, FEMSystem
from bench_myriapoda.world import terrain_kernels as T

N_SEGMENTS = 17
N_STEPS = 200
TERRAIN = (T.PLANE, np.zeros(T.N_TERRAIN_PARAMS))


@pytest.mark.parametrize("resolution, unit, n_tets", [(3, "nodes", 816), (3, "cells", 2754)],
                         ids=["2x2x2cells-816tets", "3x3x3cells-2754tets"])
def test_bench_fem_chain_advance(benchmark, resolution, unit, n_tets):
    nodes, tets, _seg = chain_grid(N_SEGMENTS, 1.0, cross_section=(1.0, 1.0),
                                   resolution=resolution, resolution_unit=unit)
    assert len(tets) == n_tets
    body = FEMSystem(nodes, tets)
    centre = nodes.mean(axis=0)
    x0 = nodes + [0.0, 0.05, 0.0]
    v0 = np.cross([0.0, 2.0, 0.0], nodes - centre)

    t0 = time.perf_counter()
    body.advance(1, dt=DT_PAPER, terrain=TERRAIN)  # JIT compile or cache load, and the factorization
    compile_s = time.perf_counter() - t0

    def reset():
        body.x[:] = x0
        body.v[:] = v0

    def run():
        return body.advance(N_STEPS, dt=DT_PAPER, terrain=TERRAIN, friction=0.5)

    result = benchmark.pedantic(run, setup=reset, rounds=20, warmup_rounds=2)
    assert result.ok and result.steps == N_STEPS
    assert body.x[:, 1].min() >= 0.0 and body.count_inverted() == 0
    benchmark.extra_info["compile_or_cache_load_s"] = compile_s
    benchmark.extra_info["n_tets"] = n_tets
    benchmark.extra_info["n_nodes"] = len(nodes)
    if benchmark.stats is not None:
        median = benchmark.stats.stats.median
        benchmark.extra_info["ns_per_tet_step"] = median / N_STEPS / n_tets * 1e9
        benchmark.extra_info["steps_per_s"] = N_STEPS / median
