"""Throughput of a walking centipede (issue 13 targets, one core, dt = 1/3000 s: hybrid >= 25,000 steps/s,
massspring >= 40,000, fem >= 10,000; the fused path against the Python path side by side).

Time it with:
    python -m pytest tests/benchmarks/test_bench_myriapod.py --benchmark-enable --benchmark-only
The segment-count sweep gives the cost scaling from 6 to 100 segments.
"""
import pytest

from bench_myriapoda.harness.throughput_suite import (
    CENTIPEDE_WALK_IN_STEPS as WALK_IN_STEPS,
)
from bench_myriapoda.harness.throughput_suite import walking_centipede

STEPS_PER_CALL = 300


@pytest.mark.parametrize("body,segments,fused", [("hybrid", 6, True), ("hybrid", 18, True), ("hybrid", 36, True),
                                                 ("hybrid", 100, True), ("hybrid", 18, False),
                                                 ("massspring", 18, True), ("massspring", 18, False),
                                                 ("fem", 18, True), ("fem", 18, False)])
def test_centipede_walk_step(benchmark, body, segments, fused):
    # fused: one compiled call per chunk (fused.legged_walk); False: the controller sequenced from Python
    # every step, for the ratio
    case, b = walking_centipede(segments, body, fused=fused)  # compiled and walked in for WALK_IN_STEPS (1.5 s)
    t = [WALK_IN_STEPS * case.dt]

    def chunk():
        done, status = b.advance(t[0], STEPS_PER_CALL)
        t[0] += done * case.dt
        assert status == 0

    benchmark.pedantic(chunk, rounds=8 if segments < 100 else 4, iterations=1, warmup_rounds=1)
    if benchmark.stats is not None:
        median = benchmark.stats.stats.median
        benchmark.extra_info["steps_per_s"] = STEPS_PER_CALL / median
        benchmark.extra_info["realtime_factor"] = STEPS_PER_CALL * case.dt / median
        benchmark.extra_info["segments"] = segments
        benchmark.extra_info["body"] = body
        benchmark.extra_info["fused"] = b.stepper.fused is not None
