"""Measure how far the golden runs move between code generations on one machine (issue 28).

The tolerances of ``tests/golden/compare.py`` come from this script: it runs the golden cases of
``capture_myriapod_golden.py`` once per code generation, each in a fresh process with a fresh, empty
``NUMBA_CACHE_DIR`` (so numba compiles every kernel for that target), and compares the runs.

* ``native``: numba's host CPU (AVX-512 where the machine has it), numpy's full SIMD dispatch;
* ``haswell``: ``NUMBA_CPU_NAME=haswell NUMBA_CPU_FEATURES=`` (AVX2 + FMA, no AVX-512) and numpy's AVX-512
  kernels disabled (``NPY_DISABLE_CPU_FEATURES``): what an AVX2-only machine compiles and runs.  The empty
  ``NUMBA_CPU_FEATURES`` matters: with ``NUMBA_CPU_NAME=haswell`` alone numba keeps the *host's* features
  and, on an AVX-512 machine, emits AVX-512 code with Haswell's tuning (seen: zmm registers in the asm);
* ``generic``: ``NUMBA_CPU_NAME=generic`` (baseline x86-64: SSE2, no FMA) and numpy at its X86_V2 baseline;
* ``znver3``: ``NUMBA_CPU_NAME=znver3 NUMBA_CPU_FEATURES=`` (AMD Zen 3: AVX2 + FMA, LLVM's AMD cost model)
  with numpy as for ``haswell``: the closest this machine comes to the AMD EPYC's own code generation;
* ``haswell-avx512``: ``NUMBA_CPU_NAME=haswell`` alone (numpy as for ``haswell``), the host's AVX-512
  features with Haswell's tuning: what the variable alone gives.

Usage (from the repository root; each target compiles every kernel, minutes of CPU)::

    python3 tests/golden/measure_cpu_divergence.py all DIR [TARGET ...]  # every target (or those named)
    python3 tests/golden/measure_cpu_divergence.py compare DIR           # the tables, from DIR/*.npz
    ENV python3 tests/golden/measure_cpu_divergence.py pytest DIR/T.npz  # pytest -m golden, then save its runs
"""
from __future__ import annotations

import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = pathlib.Path(__file__).parent
NO_AVX512 = "X86_V4 AVX512_ICL AVX512_SPR"  # numpy's dispatch groups that use AVX-512
TARGETS = {
    "native": {},
    "haswell": {"NUMBA_CPU_NAME": "haswell", "NUMBA_CPU_FEATURES": "", "NPY_DISABLE_CPU_FEATURES": NO_AVX512},
    "generic": {"NUMBA_CPU_NAME": "generic", "NPY_DISABLE_CPU_FEATURES": "X86_V3 " + NO_AVX512},
    "znver3": {"NUMBA_CPU_NAME": "znver3", "NUMBA_CPU_FEATURES": "", "NPY_DISABLE_CPU_FEATURES": NO_AVX512},
    "haswell-avx512": {"NUMBA_CPU_NAME": "haswell", "NPY_DISABLE_CPU_FEATURES": NO_AVX512},
}
# times [s] up to which the growth table gives the largest distance so far
TIMES = (0.1, 0.25, 0.5, 1.0, 2.0, 3.0)

def run_target(out: pathlib.Path) -> None:
    """Run every golden case in this process (its environment picks the target) and save arrays + metrics."""
    sys.path.insert(0, str(HERE))
    from capture_myriapod_golden import GOLDEN_CASES, run_arrays

    saved, meta = {}, {}
    for name, body, scenario, duration in GOLDEN_CASES:
        t0 = time.perf_counter()
        arrays, metrics = run_arrays(body, scenario, duration)
        meta[name] = {"wall_s": time.perf_counter() - t0,
                      "metrics": {k: (float(v) if np.isfinite(v) else None) for k, v in metrics.items()}}
        for k, a in arrays.items():
            saved[f"{name}/{k}"] = a
        print(name, f"{meta[name]['wall_s']:.1f} s", flush=True)
    np.savez(out, meta=json.dumps(meta), **saved)


def pytest_and_save(out: pathlib.Path) -> int:
    """Run the golden tests (``pytest -m golden``) in this process, then save the runs they made, as
    ``run`` would: one compile serves both the test and the measurement."""
    import pytest

    rc = pytest.main(["-n", "0", "-m", "golden", str(HERE.parent / "test_body_wave.py")])  # in this process: its runs are read below
    runs = sys.modules["test_body_wave"]._wave_off_run
    saved, meta = {}, {}
    for name, *_ in sys.modules["capture_myriapod_golden"].GOLDEN_CASES:
        arrays, metrics = runs(name)
        meta[name] = {"metrics": {k: (float(v) if np.isfinite(v) else None) for k, v in metrics.items()}}
        saved.update({f"{name}/{k}": a for k, a in arrays.items()})
    np.savez(out, meta=json.dumps(meta), **saved)
    return int(rc)


def run_all(d: pathlib.Path, only: list[str] | None = None) -> None:
    """Each target (or those named) in its own process with a fresh JIT cache, serially (one compile at a time)."""
    d.mkdir(parents=True, exist_ok=True)
    for target, extra in TARGETS.items():
        if only and target not in only:
            continue
        with tempfile.TemporaryDirectory(prefix=f"numba-{target}-") as cache:
            env = {**os.environ, **extra, "NUMBA_CACHE_DIR": cache}
            t0 = time.perf_counter()
            subprocess.run([sys.executable, __file__, "run", str(d / f"{target}.npz")], env=env, check=True)
            print(f"{target}: {time.perf_counter() - t0:.0f} s with compilation", flush=True)


def _growth(a: np.ndarray, b: np.ndarray, t: np.ndarray) -> list[float]:
    """max |a - b| [m] over all samples up to each of ``TIMES`` (nan past the run's end)."""
    dev = np.abs(a - b).reshape(len(a), -1).max(axis=1)
    return [float(dev[t <= T + 1e-9].max()) if T <= t[-1] + 0.01 else float("nan") for T in TIMES]


def _rel(a, b) -> float:
    a, b = np.asarray(a, float), np.asarray(b, float)
    d, scale = np.abs(a - b), np.maximum(np.abs(a), np.abs(b))
    return float(np.max(np.divide(d, scale, out=np.zeros_like(d), where=d > 0), initial=0.0))


def compare(d: pathlib.Path) -> None:
    """Per golden case and pair of targets: the growth of the largest distance of any segment centre or leg
    tip, whether the leg states differ, the worst relative difference of the whole-run statistics and of
    the metrics; then the worst of all of them over every case and pair."""
    sys.path.insert(0, str(HERE))
    from compare import _stats

    runs = {t: np.load(d / f"{t}.npz") for t in TARGETS if (d / f"{t}.npz").exists()}
    names = list(runs)
    worst = {"growth": [0.0] * len(TIMES), "stat": (0.0, ""), "metric": (0.0, "")}
    print("largest |a - b| [m] of a segment centre or leg tip up to t = " + ", ".join(f"{T:g}" for T in TIMES))
    for case in json.loads(str(runs[names[0]]["meta"])):
        print(f"-- {case}")
        for i, ta in enumerate(names):
            for tb in names[i + 1:]:
                A, B = runs[ta], runs[tb]
                leg_t = A[f"{case}/leg_t"]
                n_c = A[f"{case}/segment_centers"].shape[0]
                t_c = np.arange(n_c) * (leg_t[-1] + leg_t[1]) / (n_c - 1)  # centres: evenly over the run
                g = np.fmax(_growth(A[f"{case}/segment_centers"], B[f"{case}/segment_centers"], t_c),
                            _growth(A[f"{case}/leg_tips"], B[f"{case}/leg_tips"], leg_t))
                worst["growth"] = list(np.fmax(worst["growth"], g))
                states = int((A[f"{case}/leg_states"] != B[f"{case}/leg_states"]).sum())
                st = max((_rel(v, _stats(B[f"{case}/{k}"])[name]), f"{case} {k} {name}")
                         for k in ("segment_centers", "leg_tips") for name, v in _stats(A[f"{case}/{k}"]).items())
                ma, mb = (json.loads(str(X["meta"]))[case]["metrics"] for X in (A, B))
                me = max(((_rel(v, mb[k]) if None not in (v, mb[k]) else (0.0 if v == mb[k] else np.inf)),
                          f"{case} {k}") for k, v in ma.items())
                worst["stat"], worst["metric"] = max(worst["stat"], st), max(worst["metric"], me)
                print(f"   {ta:>14s} vs {tb:14s} " + " ".join(f"{x:8.1e}" for x in g)
                      + f" | leg states differ: {states} | stats rel {st[0]:.1e} | metrics rel {me[0]:.1e} ({me[1]})")
    print("worst of all: " + " ".join(f"{T:g} s: {x:.1e}" for T, x in zip(TIMES, worst["growth"]))
          + f"; statistics rel {worst['stat'][0]:.1e} ({worst['stat'][1]})"
          + f"; metrics rel {worst['metric'][0]:.1e} ({worst['metric'][1]})")

if __name__ == "__main__":
    mode, path = sys.argv[1], pathlib.Path(sys.argv[2])
    if mode == "all":
        run_all(path, sys.argv[3:])
    else:
        sys.exit({"run": run_target, "compare": compare, "pytest": pytest_and_save}[mode](path))
