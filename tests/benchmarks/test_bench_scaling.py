"""Cost per step against size: the fitted exponent p of time per step ~ segments^p (issue target 0.9-1.1).

Miller's snake (mass-spring lattice) and the walking hybrid centipede at 6 to 200 segments
(``throughput_suite.SCALING_SEGMENTS``), each compiled and settled, then timed in CPU seconds
(the fastest of three runs).  Time it with:

    python3 -m pytest tests/benchmarks/test_bench_scaling.py --benchmark-enable --benchmark-only

``extra_info`` holds the exponent and the microseconds per step at every size.  In the normal
test run (benchmarks disabled) it runs once on the two smallest sizes as a smoke test; the
exponent is never asserted (timings are noisy on a shared machine).
"""
import math

import pytest

from bench_myriapoda.harness.throughput_suite import SCALING_SEGMENTS, fit_exponent, time_per_step

STEPS = {"snake": 3000, "centipede": 600}


@pytest.mark.parametrize("kind", ["snake", "centipede"])
def test_cost_per_step_against_segments(benchmark, kind):
    sizes = SCALING_SEGMENTS[:2] if benchmark.disabled else SCALING_SEGMENTS
    steps = 30 if benchmark.disabled else STEPS[kind]
    per_step = {}

    def sweep():
        for n in sizes:
            per_step[n] = time_per_step(kind, n, steps, repeats=1 if benchmark.disabled else 3)

    benchmark.pedantic(sweep, rounds=1, iterations=1)
    assert all(math.isfinite(t) and t > 0 for t in per_step.values())
    exponent = fit_exponent(list(per_step), list(per_step.values()))
    assert math.isfinite(exponent)
    benchmark.extra_info["exponent"] = exponent
    benchmark.extra_info["us_per_step"] = {str(n): t * 1e6 for n, t in per_step.items()}
