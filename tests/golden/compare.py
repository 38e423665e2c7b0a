"""A run against its golden, at tolerances measured between code generations (issue 28).

A golden (``tests/golden/NAME.json``, written by ``capture_myriapod_golden.py``) holds, for one run:

* ``arrays``: each recorded array's dtype, shape and SHA-256 (``digest``), its values over the first
  ``HORIZON_S`` seconds (``head``), and statistics over the whole run (``stats``);
* ``metrics``: the run's metrics (``None`` where not finite);
* ``captured``: the build it was captured with (``build_fingerprint``).

``compare_to_golden`` checks the head at ``HEAD_ATOL_M``, the statistics at ``STAT_RTOL`` / ``STAT_ATOL_M``
and the metrics at ``METRIC_RTOL`` / ``METRIC_ATOL``; on the build the golden was captured with it also checks
every digest, so there the comparison stays bit for bit.  The tolerances were measured with
``measure_cpu_divergence.py`` (the figures are in the constants' docstrings and in
docs/explanation/determinism.md).
"""
from __future__ import annotations

import hashlib
import math
import os

import numpy as np

# Measured with measure_cpu_divergence.py on one machine (Intel Xeon "emeraldrapids", AVX-512; numba 0.68.1,
# llvmlite 0.50.0, numpy 2.4.6), between five code generations, each compiled into a fresh NUMBA_CACHE_DIR:
# native (AVX-512), haswell (NUMBA_CPU_NAME=haswell NUMBA_CPU_FEATURES=, AVX2 + FMA), znver3 (likewise, AMD
# Zen 3), generic (NUMBA_CPU_NAME=generic: SSE2, no FMA) and haswell-avx512 (NUMBA_CPU_NAME=haswell alone,
# which keeps the host's AVX-512).  The largest distance between any two of them, over the four golden runs:
#
#   segment centre or leg tip [m], up to t =  0.1 s   0.25 s   0.5 s    1 s      3 s (whole run)
#                                             6.4e-14  8.8e-11  1.3e-10  3.9e-9   5.7e-9
#   whole-run statistics (relative)           2.2e-10
#   metrics (relative)                        2.2e-10
#
# The worst pairs are all against generic (no FMA); native, haswell, znver3 and haswell-avx512 are bit for bit
# equal except in the FEM walk (at most 8.8e-14 m; haswell and znver3 equal there too), and the mass-spring walk
# is bit for bit equal in all five.  The tolerances are about 100 times the measured distance, meant to cover
# other machines' code generation (CPU tuning, C library), which was not measured; a change of the physics
# moves the bits far more.

HORIZON_S = 0.5
"""Seconds of simulated time whose samples a golden keeps value by value (``head``).

The walks are contact-rich: a difference in the last bit grows, from 6e-14 m at 0.1 s to 1.3e-10 m at
0.5 s and 4e-9 m at 1 s (measured, above); over 0.5 s the head is compared at a tolerance 77 times the
largest measured distance and 1e-8 m is still far below any physical change of the gait."""

HEAD_ATOL_M = 1e-8
"""Largest allowed |run - golden| [m] of any segment centre or leg tip during the first ``HORIZON_S`` s
(measured between code generations: at most 1.3e-10 m).  Leg states there must be equal."""

STAT_RTOL = 1e-7
"""Relative tolerance of the whole-run statistics (mean, std, min and max of each coordinate of the segment
centres and leg tips).  Measured: at most 2.2e-10."""

STAT_ATOL_M = 1e-8
"""Absolute floor [m] of the statistics' tolerance, for statistics near zero (measured: at most 1.6e-10 m)."""

STATE_FRACTION_ATOL = 1e-3
"""Largest allowed change of the fraction of leg-state entries (all samples x legs) in each state over the whole
run.  Measured: no leg state ever differed (0 of 32,400 entries in the hybrid walks).  One entry is 3e-5 of
the fractions, so this admits one leg's transition some 30 samples (0.1 s) late, or a few shorter ones,
while a changed gait moves the fractions by percents."""

METRIC_RTOL = 1e-7
"""Relative tolerance of the run's metrics, all computed over the whole run.  Measured: at most 2.2e-10
(``travel_angle_deg``, ``lateral_speed_m_per_s``; ``energy_drift_rel`` 1.3e-10)."""

METRIC_ATOL = 1e-9
"""Absolute floor of the metrics' tolerance, in each metric's own unit: a metric recorded as 0 may come out
as round-off (measured: no metric recorded as 0 moved)."""

# the arrays a golden holds, and the rate at which each one's head is kept (every STRIDE-th sample)
HEAD_STRIDE = {"segment_centers": 2, "leg_tips": 10, "leg_states": 2}  # 30 Hz: 16 samples in 0.5 s
TIME_OF = {"segment_centers": "t", "leg_tips": "leg_t", "leg_states": "leg_t"}


def build_fingerprint() -> dict:
    """What fixes the bits of a run: the machine as the results store records it (``machine_fingerprint``:
    CPU model, platform with its C library, Python, numpy, numba), llvmlite, and the target numba compiles
    for (CPU name and feature string, after ``NUMBA_CPU_NAME`` / ``NUMBA_CPU_FEATURES``) and numpy's disabled
    SIMD kernels (``NPY_DISABLE_CPU_FEATURES``).  The CPU model alone is not enough: a virtual machine
    reports a generic name ("Intel(R) Xeon(R) Processor") whatever the instruction set."""
    import llvmlite
    from llvmlite import binding as ll
    from numba.core import config

    from bench_myriapoda.harness.machine import machine_fingerprint

    m = machine_fingerprint()
    return {"cpu_model": m["cpu_model"], "platform": m["platform"], "python": m["python"], "numpy": m["numpy"],
            "numba": m["numba"], "llvmlite": llvmlite.__version__,
            "numba_cpu_name": config.CPU_NAME or ll.get_host_cpu_name(),
            "numba_cpu_features": (config.CPU_FEATURES if config.CPU_FEATURES is not None
                                   else ll.get_host_cpu_features().flatten()),
            "npy_disable_cpu_features": os.environ.get("NPY_DISABLE_CPU_FEATURES", "")}


def array_digest(a: np.ndarray) -> dict:
    """dtype, shape and SHA-256 of the C-ordered bytes of ``a``: equal digests <=> bit-for-bit equal arrays."""
    a = np.ascontiguousarray(a)
    return {"dtype": a.dtype.str, "shape": list(a.shape), "sha256": hashlib.sha256(a.tobytes()).hexdigest()}


def _head(a: np.ndarray, t: np.ndarray, stride: int) -> np.ndarray:
    """Every ``stride``-th sample of ``a`` up to ``HORIZON_S`` (sample times ``t`` [s]; a sample at the
    horizon up to 1 ns of round-off counts as in)."""
    return a[: int(np.searchsorted(t, HORIZON_S + 1e-9, side="right"))][::stride]


def _stats(a: np.ndarray) -> dict:
    """Whole-run statistics: per coordinate (last axis) of a float array, over time and parts; for leg
    states, the fraction of entries in each state."""
    if a.dtype.kind == "f":
        flat = a.reshape(-1, a.shape[-1])
        return {"mean": flat.mean(axis=0).tolist(), "std": flat.std(axis=0).tolist(),
                "min": flat.min(axis=0).tolist(), "max": flat.max(axis=0).tolist()}
    states, counts = np.unique(a, return_counts=True)
    return {"fraction": {str(int(s)): float(c / a.size) for s, c in zip(states, counts)}}


def golden_record(arrays: dict, metrics: dict, case: dict) -> dict:
    """The golden of one run: ``arrays`` from ``run_arrays`` (sample times ``t`` of the segment centres and
    ``leg_t`` of the legs included), its ``metrics``; ``case`` says which run it is."""
    rec = {"case": case, "captured": build_fingerprint(), "horizon_s": HORIZON_S, "arrays": {}, "metrics": {}}
    for key, stride in HEAD_STRIDE.items():
        a = arrays[key]
        rec["arrays"][key] = {**array_digest(a), "head_stride": stride,
                              "head": _head(a, arrays[TIME_OF[key]], stride).tolist(), "stats": _stats(a)}
    leg_t = arrays["leg_t"]  # the legs' sample times: the grid's ends
    rec["arrays"]["leg_t"] = {**array_digest(leg_t), "first": float(leg_t[0]), "last": float(leg_t[-1])}
    rec["metrics"] = {k: (float(v) if math.isfinite(v) else None) for k, v in sorted(metrics.items())}
    return rec


def _close(got, want, rtol: float, atol: float) -> bool:
    return bool(np.all(np.abs(np.asarray(got, float) - np.asarray(want, float))
                       <= atol + rtol * np.abs(np.asarray(want, float))))


def compare_to_golden(golden: dict, arrays: dict, metrics: dict, bitwise: bool | None = None) -> list[str]:
    """Every way the run (``arrays``, ``metrics``) differs from ``golden`` beyond the tolerances; empty if none.

    ``bitwise`` (default: the current build is the one the golden was captured with) also demands every
    array's digest."""
    problems = []
    if golden.get("horizon_s") != HORIZON_S:
        problems.append(f"golden kept {golden.get('horizon_s')} s, HORIZON_S is {HORIZON_S}: re-capture it")
    if bitwise is None:
        bitwise = golden["captured"] == build_fingerprint()
    for key, g in golden["arrays"].items():
        a = np.ascontiguousarray(arrays[key])
        if [a.dtype.str, list(a.shape)] != [g["dtype"], g["shape"]]:
            problems.append(f"{key}: dtype/shape {a.dtype.str} {list(a.shape)}, golden {g['dtype']} {g['shape']}")
            continue
        if bitwise and array_digest(a)["sha256"] != g["sha256"]:
            problems.append(f"{key}: not bit for bit the golden on the build it was captured with")
        if key == "leg_t":
            if not _close([a[0], a[-1]], [g["first"], g["last"]], METRIC_RTOL, METRIC_ATOL):
                problems.append(f"{key}: samples from {a[0]!r} to {a[-1]!r} s, "
                                f"golden {g['first']!r} to {g['last']!r}")
            continue
        head = _head(a, np.asarray(arrays[TIME_OF[key]]), g["head_stride"])
        want = np.asarray(g["head"], dtype=a.dtype)
        if head.shape != want.shape:
            problems.append(f"{key}: head of {head.shape}, golden {want.shape}")
        elif a.dtype.kind == "f":
            dev = float(np.abs(head - want).max())
            if not dev <= HEAD_ATOL_M:
                problems.append(f"{key}: first {HORIZON_S} s off by {dev:.3g} m > HEAD_ATOL_M {HEAD_ATOL_M:g}")
        elif not np.array_equal(head, want):
            problems.append(f"{key}: first {HORIZON_S} s differ in {int((head != want).sum())} entries")
        st = _stats(a)
        for name, want_s in g["stats"].items():
            got_s = st[name]
            if isinstance(want_s, dict):  # state fractions: each state's fraction close (absent: 0)
                states = sorted(set(want_s) | set(got_s))
                got_s, want_s = [got_s.get(k, 0.0) for k in states], [want_s.get(k, 0.0) for k in states]
                ok = _close(got_s, want_s, 0.0, STATE_FRACTION_ATOL)
            else:
                ok = _close(got_s, want_s, STAT_RTOL, STAT_ATOL_M)
            if not ok:
                problems.append(f"{key}: whole-run {name} {got_s}, golden {want_s} (STAT_RTOL {STAT_RTOL:g}, "
                                f"STATE_FRACTION_ATOL {STATE_FRACTION_ATOL:g})")
    for key, want in golden["metrics"].items():
        got = metrics.get(key, float("nan"))
        if want is None or not math.isfinite(got):
            if (want is None) != (not math.isfinite(got)):
                problems.append(f"metric {key}: {got}, golden {want}")
        elif not _close(got, want, METRIC_RTOL, METRIC_ATOL):
            problems.append(f"metric {key}: {got!r}, golden {want!r} (METRIC_RTOL {METRIC_RTOL:g})")
    return problems
