"""Capture the golden runs of tests/test_body_wave.py (``python3 tests/golden/capture_myriapod_golden.py``).

The goldens were captured from the code *before* issue 16 (commit fcb6297): the
centipede on the three bodies walking on flat ground, and the hybrid among the
Fig. 13 cylinders.  tests/test_body_wave.py reruns the same cases with the body
wave off and the legs' obstacle collision off and asserts bitwise equality, so
neither the new options nor the obstacle grid change anything when unused.
Rerun this only to re-baseline deliberately.

Bitwise equality needs no copy of the arrays: each case keeps, in ``NAME.arrays.json``, every array's
dtype, shape and SHA-256 of its bytes (``array_digest``), and in ``NAME.json`` the run's metrics.
"""
from __future__ import annotations

import hashlib
import json
import pathlib
import sys

import numpy as np

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case

HERE = pathlib.Path(__file__).parent
# (name, body, scenario, duration [s]): short, but past ADJUSTMENT into the walk
GOLDEN_CASES = [("walk-hybrid", "hybrid", "walk", 3.0), ("walk-massspring", "massspring", "walk", 1.5),
                ("walk-fem", "fem", "walk", 1.0), ("fig13-hybrid", "hybrid", "fig13-cylinders", 3.0)]


def run_arrays(body: str, scenario: str, duration: float, overrides=()) -> tuple[dict, dict]:
    """(arrays, metrics) of one run: segment centres (T, n, 3), leg states (T', n_legs), tips (T', n_legs, 3)."""
    r = run_case(resolve_case("centipede", body, scenario, duration=duration, overrides=list(overrides)))
    if r.status != "ok":
        raise RuntimeError(f"{body}/{scenario}: {r.status} {r.message}")
    t, states, tips = r.extra["leg_timeline"]
    arrays = {"segment_centers": r.series.segment_centers, "leg_t": t, "leg_states": states, "leg_tips": tips}
    return arrays, r.metrics


def array_digest(a: np.ndarray) -> dict:
    """dtype, shape and SHA-256 of the C-ordered bytes of ``a``: equal digests <=> bit-for-bit equal arrays."""
    a = np.ascontiguousarray(a)
    return {"dtype": a.dtype.str, "shape": list(a.shape), "sha256": hashlib.sha256(a.tobytes()).hexdigest()}


def main() -> None:
    names = sys.argv[1:] or [c[0] for c in GOLDEN_CASES]
    for name, body, scenario, duration in GOLDEN_CASES:
        if name not in names:
            continue
        arrays, metrics = run_arrays(body, scenario, duration)
        (HERE / f"{name}.arrays.json").write_text(json.dumps({k: array_digest(a) for k, a in arrays.items()},
                                                              indent=1, sort_keys=True))
        (HERE / f"{name}.json").write_text(json.dumps({k: (v if np.isfinite(v) else None) for k, v in
                                                        metrics.items()}, indent=1, sort_keys=True))
        print(name, arrays["segment_centers"].shape)


if __name__ == "__main__":
    main()
