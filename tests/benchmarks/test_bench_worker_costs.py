"""Fixed costs of the local executor's workers, per worker and per case (issue 31, item 2).

``harness/worker_costs.py`` runs the real worker (its pipe protocol, ``executors._start_slot``) on a warm
JIT cache: per worker its start (fork from the server, or a spawned interpreter's imports), the first
case's kernel loading and its stop; per case the harness's overhead around a short case's own steps and
the parent's result write (recording and store row).  Each is measured with the compile plans off (as
before: every worker loads its kernels from the cache for its first case of a group) and on (the fork
server loaded the recorded groups' top-level kernels once, ``compile_plan.preload_cached``).  Time it with::

    python3 -m pytest tests/benchmarks/test_bench_worker_costs.py --benchmark-enable --benchmark-only -s

``extra_info`` holds every figure (medians and maxima over the workers, seconds).  In the normal test run
(benchmarks disabled) it measures one worker once as a smoke test.  Nothing about a time is asserted
(timings are a benchmark's figures, not a test's).
"""
import math

import pytest

from bench_myriapoda.harness import worker_costs
from bench_myriapoda.jit.worker_start import start_method


@pytest.mark.parametrize("plans", [False, True], ids=["plans-off", "plans-on"])
def test_worker_fixed_costs(benchmark, plans, monkeypatch):
    monkeypatch.setenv("BENCH_MYRIAPODA_COMPILE_PLAN", "on")  # restored after the test (measure sets it)
    counts = [1] if benchmark.disabled else [1, 2]
    rows = []

    def run():
        rows.clear()
        worker_costs.measure(1, start_method(), plans)  # loads the probe case's kernels into the cache (warm)
        for n in counts:
            rows.append(worker_costs.measure(n, start_method(), plans))

    benchmark.pedantic(run, rounds=1, iterations=1)
    for row in rows:
        assert row["plans"] is plans
        for key in ("start_s", "kernel_load_s", "case_s", "store_s", "stop_s"):
            assert math.isfinite(row[key]["median"]) and row[key]["max"] >= 0.0, key
        benchmark.extra_info[f"workers={row['workers']}"] = row
    if not plans:
        assert rows[0]["preloaded"] == [0, 0]
