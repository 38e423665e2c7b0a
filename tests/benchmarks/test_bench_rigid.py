"""Throughput of the rigid-box core: 18 segment-sized boxes on the ground.

Nine boxes rest, nine start sliding at 1 m/s in different directions and come to
rest after ~0.2 s, as rigid segments of an 18-segment myriapod would on a plane.
Every round restarts from the same state and runs N_STEPS steps inside one
numba call.  Compile (or cache load) happens before timing and is reported
separately in extra_info.

    python3 -m pytest tests/benchmarks/test_bench_rigid.py --benchmark-enable --benchmark-only
"""
from __future__ import annotations

import time

import numpy as np

from bench_myriapoda.bodies.rigid import STATUS_OK
from bench_myriapoda.harness.throughput_suite import RIGID_BOXES as N_BOXES
from bench_myriapoda.harness.throughput_suite import RIGID_DT as DT
from bench_myriapoda.harness.throughput_suite import RIGID_HALF as HALF
from bench_myriapoda.harness.throughput_suite import RIGID_STATE_FIELDS as STATE_FIELDS
from bench_myriapoda.harness.throughput_suite import rigid_contact_settings, rigid_scene

N_STEPS = 3000  # one simulated second per call
SETTINGS = rigid_contact_settings()


def test_bench_rigid_18_boxes_on_ground(benchmark):
    boxes = rigid_scene()  # the scene of `bench-myriapoda regress`
    initial = {k: getattr(boxes, k).copy() for k in STATE_FIELDS}

    t0 = time.perf_counter()
    boxes.advance(1, DT, contact=SETTINGS)  # JIT compile or cache load
    compile_s = time.perf_counter() - t0

    def reset():
        for k, value in initial.items():
            getattr(boxes, k)[...] = value

    def run():
        return boxes.advance(N_STEPS, DT, contact=SETTINGS)

    n_done, status = benchmark.pedantic(run, setup=reset, rounds=10, warmup_rounds=1)
    assert (n_done, status) == (N_STEPS, STATUS_OK)
    # The physics still holds under load: everything ends at rest on the plane.
    assert np.abs(boxes.v).max() < 1e-6
    assert np.abs(boxes.c[:, 1] - HALF[1]).max() < 2e-5

    benchmark.extra_info["n_boxes"] = N_BOXES
    benchmark.extra_info["steps_per_call"] = N_STEPS
    benchmark.extra_info["compile_or_cache_load_s"] = compile_s
    if benchmark.stats is not None:  # None under --benchmark-disable (smoke run)
        median = benchmark.stats.stats.median
        benchmark.extra_info["steps_per_second"] = N_STEPS / median
        benchmark.extra_info["body_steps_per_second"] = N_STEPS * N_BOXES / median
        benchmark.extra_info["realtime_factor"] = N_STEPS * DT / median
