"""Cold start of the README's main job (issue 13): the quick matrix with an empty JIT cache, then warm.

Runs ``bench-myriapoda quick`` twice in subprocesses on a fresh numba cache directory
(``NUMBA_CACHE_DIR``; deleting the cache is the same as starting from an empty one): the first run
compiles every kernel the quick matrix needs, the second finds them all on disk.  Wall seconds of
both runs and the number of compiled signatures written to the cache go to ``extra_info``.  The
target is a cold run under 30 s on 2 cores (not asserted: wall time is a benchmark figure, not a test).

What is asserted: both runs finish every case and write the report, and the warm run compiles
nothing -- no new entry appears in the cache (a kernel numba cannot cache, or a signature that differs
from run to run, would recompile on every start).

Takes about two to four minutes on 2 cores, so it runs only when asked::

    BENCH_COLD_START=1 python3 -m pytest tests/benchmarks/test_bench_cold_start.py --benchmark-enable -s
"""
from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(os.environ.get("BENCH_COLD_START") != "1",
                                reason="cold start takes minutes; set BENCH_COLD_START=1")

REPO = Path(__file__).resolve().parents[2]


def cache_entries(cache_dir: Path) -> set[str]:
    """The compiled signatures in a numba cache directory: one ``.nbc`` file each."""
    return {str(p.relative_to(cache_dir)) for p in cache_dir.rglob("*.nbc")}


def quick_run(out: Path, cache_dir: Path, workers: int = 2) -> float:
    """Wall seconds of ``bench-myriapoda quick --out out --workers workers`` on the given numba cache."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache_dir))
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "bench_myriapoda.cli", "quick", "--out", str(out),
                           "--workers", str(workers)], cwd=REPO, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert (out / "index.html").is_file()
    return wall


def test_quick_matrix_cold_then_warm(benchmark, tmp_path):
    cache = tmp_path / "numba-cache"
    cache.mkdir()
    walls = {}

    def cold_then_warm():
        walls["cold_s"] = quick_run(tmp_path / "cold", cache)
        walls["signatures"] = len(cache_entries(cache))
        before = cache_entries(cache)
        walls["warm_s"] = quick_run(tmp_path / "warm", cache)
        walls["recompiled"] = sorted(cache_entries(cache) - before)

    benchmark.pedantic(cold_then_warm, rounds=1, iterations=1)
    benchmark.extra_info.update({k: walls[k] for k in ("cold_s", "warm_s", "signatures")})
    print(f"\nquick matrix, 2 workers: cold {walls['cold_s']:.1f} s, warm {walls['warm_s']:.1f} s, "
          f"{walls['signatures']} compiled signatures")
    assert walls["signatures"] > 0
    assert walls["recompiled"] == [], f"the warm run compiled again: {walls['recompiled'][:10]}"
