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

import pytest

from bench_myriapoda.bodies.fem.system import DT_PAPER
from bench_myriapoda.bodies.fem.benchmarks import fem_chain, fem_terrain

N_STEPS = 200
TERRAIN = fem_terrain()


@pytest.mark.parametrize("resolution, unit, n_tets", [(3, "nodes", 816), (3, "cells", 2754)],
                         ids=["2x2x2cells-816tets", "3x3x3cells-2754tets"])
def test_bench_fem_chain_advance(benchmark, resolution, unit, n_tets):
    body, x0, v0 = fem_chain(resolution, unit)  # the scene of `bench-myriapoda regress`
    assert body.n_tets == n_tets

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
    benchmark.extra_info["n_nodes"] = body.n_nodes
    if benchmark.stats is not None:
        median = benchmark.stats.stats.median
        benchmark.extra_info["ns_per_tet_step"] = median / N_STEPS / n_tets * 1e9
        benchmark.extra_info["steps_per_s"] = N_STEPS / median
