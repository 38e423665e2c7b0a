"""Capture the golden runs of tests/test_body_wave.py (``python3 tests/golden/capture_myriapod_golden.py``).

The cases: the centipede on the three bodies walking on flat ground, and the hybrid among the Fig. 13
cylinders, with the configuration's defaults (body wave and leg collision off).  tests/test_body_wave.py
reruns them with the body wave and the legs' obstacle collision explicitly off and compares them with
``compare.compare_to_golden``: at the tolerances measured between code generations on any machine, bit for
bit on the build that captured them.  Rerun this only to re-baseline deliberately.

History: first captured from the code before issue 16 (commit fcb6297), then kept as SHA-256 digests
(88a970f); re-captured for issue 28 as values (``compare.golden_record``) from main at eb54d20, whose arrays
are bit for bit those digests (checked: every digest equal on the capturing Xeon) and whose metrics are
main's, including the three redefined since (path_following_error_bl, tracking_error_mean_m,
body_undulation_amp_bl of the mass-spring walk).
"""
from __future__ import annotations

import json
import pathlib
import sys

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case

HERE = pathlib.Path(__file__).parent
sys.path.insert(0, str(HERE))
from compare import golden_record  # noqa: E402

# (name, body, scenario, duration [s]): short, but past ADJUSTMENT into the walk
GOLDEN_CASES = [("walk-hybrid", "hybrid", "walk", 3.0), ("walk-massspring", "massspring", "walk", 1.5),
                ("walk-fem", "fem", "walk", 1.0), ("fig13-hybrid", "hybrid", "fig13-cylinders", 3.0)]


def run_arrays(body: str, scenario: str, duration: float, overrides=()) -> tuple[dict, dict]:
    """(arrays, metrics) of one run: sample times t (T,) [s] and segment centres (T, n, 3) [m]; leg sample
    times leg_t (T',) [s], leg states (T', n_legs) and tips (T', n_legs, 3) [m]."""
    r = run_case(resolve_case("centipede", body, scenario, duration=duration, overrides=list(overrides)))
    if r.status != "ok":
        raise RuntimeError(f"{body}/{scenario}: {r.status} {r.message}")
    t, states, tips = r.extra["leg_timeline"]
    arrays = {"t": r.series.t, "segment_centers": r.series.segment_centers, "leg_t": t, "leg_states": states,
              "leg_tips": tips}
    return arrays, r.metrics


def main() -> None:
    names = sys.argv[1:] or [c[0] for c in GOLDEN_CASES]
    for name, body, scenario, duration in GOLDEN_CASES:
        if name not in names:
            continue
        arrays, metrics = run_arrays(body, scenario, duration)
        case = {"name": name, "creature": "centipede", "body": body, "scenario": scenario, "duration_s": duration}
        (HERE / f"{name}.json").write_text(json.dumps(golden_record(arrays, metrics, case), sort_keys=True) + "\n")
        print(name, arrays["segment_centers"].shape)


if __name__ == "__main__":
    main()
