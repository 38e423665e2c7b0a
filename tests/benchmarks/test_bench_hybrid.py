"""Throughput of the hybrid body's coupled step: 18 rigid segments, 17 FEM links on flat ground.

The chain of ``models/chain.toml`` lengthened to 18 boxes of 1 m (density 1 kg/m^3)
joined by 17 links of 0.5 m at 3x3x3 nodes (48 tets each, 816 tets), App. A material,
dt = 1/3000 s.  It starts 1 cm above the plane turning about the vertical at
0.2 rad/s, so the timed steps see all three coupling steps, FEM node contact with
friction, box-corner contact with sliding friction, and link rotations.  Each round
restarts from the same state and runs N_STEPS coupled steps in one numba call.  JIT
compile (or cache load) is timed separately and reported in extra_info.

    python3 -m pytest tests/benchmarks/test_bench_hybrid.py --benchmark-enable --benchmark-only
"""
from __future__ import annotations

import time

from bench_myriapoda.bodies.friction_kernels import CONTACT_DISTANCE
from bench_myriapoda.bodies.hybrid import kernels as K
from bench_myriapoda.bodies.hybrid.benchmarks import CHAIN, chain_state
from bench_myriapoda.bodies.hybrid.benchmarks import HYBRID_RIGID as N_RIGID
from bench_myriapoda.harness.throughput_suite import bare_body

N_TETS = 816
N_STEPS = 300


def test_bench_hybrid_18_segment_chain_coupled_step(benchmark):
    _case, body = bare_body("hybrid", CHAIN)  # the scene of `bench-myriapoda regress`
    assert body.fem.n_tets == N_TETS and body.rigid.n == N_RIGID
    fields = list(chain_state(body).values())  # every array of its dynamic state, by name
    start = [a.copy() for a in fields]

    t0 = time.perf_counter()
    body.compile()  # JIT compile or cache load; leaves the state as it was
    compile_s = time.perf_counter() - t0

    def reset():
        for dst, src in zip(fields, start):
            dst[...] = src

    def run():
        return body.advance(0.0, N_STEPS)

    steps, status = benchmark.pedantic(run, setup=reset, rounds=20, warmup_rounds=2)
    assert status == K.OK and steps == N_STEPS
    assert body.box_corners()[:, 1].min() < body.fric[CONTACT_DISTANCE]  # the boxes reached the ground in the timed steps
    benchmark.extra_info["compile_or_cache_load_s"] = compile_s
    benchmark.extra_info["n_tets"] = N_TETS
    benchmark.extra_info["n_rigid"] = N_RIGID
    benchmark.extra_info["n_nodes"] = body.fem.n_nodes
    if benchmark.stats is not None:
        median = benchmark.stats.stats.median
        benchmark.extra_info["steps_per_s"] = N_STEPS / median
        benchmark.extra_info["us_per_step"] = median / N_STEPS * 1e6
        benchmark.extra_info["ns_per_tet_step"] = median / N_STEPS / N_TETS * 1e9
