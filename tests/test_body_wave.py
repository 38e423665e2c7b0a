"""The body wave (issue 16, beyond the paper) and the goldens of the centipede's runs.

With the body wave off and the legs' collision off, the centipede's runs equal the
goldens (``tests/golden/capture_myriapod_golden.py``, first captured from the code
before issue 16): the walk on all three bodies and the hybrid among the Fig. 13
cylinders -- so the new options change nothing when unused and the obstacle grid
answers as the loop did.  Equal means bit for bit on the build that captured the
goldens and within tolerances measured between code generations on any other
(``tests/golden/compare.py``, issue 28).  With a wave, the sweep
of ``scenarios/matrix/body-wave.toml`` runs and its speed per stride depends on
the phase offset; the report draws it.
"""
from __future__ import annotations

import copy
import functools
import json
import math
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bench_myriapoda.harness.matrix import expand_matrix
from bench_myriapoda.report.body_wave import has_body_wave_sweep, plot_speed_per_stride_vs_offset

GOLDEN = Path(__file__).parent / "golden"
sys.path.insert(0, str(GOLDEN))
import compare as G  # noqa: E402
from capture_myriapod_golden import GOLDEN_CASES, run_arrays  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
# the wave's phase and wave number set to other values: with amplitude 0 they must not matter
WAVE_OFF = ["legs.collide=false", "controller.body_wave_amplitude=0", "controller.body_wave_phase_rad=1.0",
            "controller.body_wave_number=3.0"]
CASE_IDS = [c[0] for c in GOLDEN_CASES]


@functools.lru_cache(maxsize=None)
def _wave_off_run(name: str) -> tuple[dict, dict]:
    """(arrays, metrics) of the golden case ``name`` with the wave and the collision off: one run per case,
    shared by the two tests below."""
    _, body, scenario, duration = next(c for c in GOLDEN_CASES if c[0] == name)
    return run_arrays(body, scenario, duration, WAVE_OFF)


def _golden(name: str) -> dict:
    return json.loads((GOLDEN / f"{name}.json").read_text())


@pytest.mark.slow
@pytest.mark.golden
@pytest.mark.parametrize("name", CASE_IDS)
def test_wave_off_and_collision_off_equal_the_golden(name):
    """The run with the wave and the collision off against its golden (``compare.compare_to_golden``): every
    segment centre and leg tip over the first ``HORIZON_S`` = 0.5 s within ``HEAD_ATOL_M`` = 1e-8 m and the
    leg states there equal; the whole-run statistics of centres and tips and every metric within a relative
    1e-7 (``STAT_RTOL``, ``METRIC_RTOL``), the leg-state fractions within ``STATE_FRACTION_ATOL`` = 1e-3; on
    the build that captured the golden, every array's SHA-256 too (bit for bit).

    Measured divergence between code generations on one Xeon (AVX-512), numba native vs
    ``NUMBA_CPU_NAME=haswell NUMBA_CPU_FEATURES=`` (AVX2) vs ``NUMBA_CPU_NAME=generic`` (SSE2, no FMA), each
    compiled into a fresh cache (``tests/golden/measure_cpu_divergence.py``): the largest distance of any
    centre or tip grows from 6.4e-14 m at 0.1 s to 1.3e-10 m at 0.5 s and 5.7e-9 m over the whole 3 s (the
    hybrid walks, against generic; native, haswell and ``NUMBA_CPU_NAME=znver3 NUMBA_CPU_FEATURES=`` are bit
    for bit equal there; FEM at most 8.8e-14 m, mass-spring bit for bit in all); whole-run statistics and
    metrics at most 2.2e-10 relative (travel_angle_deg); leg states never differ.  The tolerances are about
    100 times that."""
    arrays, metrics = _wave_off_run(name)
    problems = G.compare_to_golden(_golden(name), arrays, metrics)
    assert not problems, "\n".join(problems)


def _perturbed(golden: dict, where: str, factor: float) -> dict:
    """A copy of ``golden`` with one recorded value moved by ``factor`` times its tolerance: the last head
    sample's first coordinate of the segment centres, the first coordinate's whole-run mean of the leg tips,
    the whole-run fraction of the first leg state, or the metric ``speed_m_per_s``."""
    g = copy.deepcopy(golden)
    if where == "head":
        g["arrays"]["segment_centers"]["head"][-1][0][0] += factor * G.HEAD_ATOL_M
    elif where == "stat":
        v = g["arrays"]["leg_tips"]["stats"]["mean"][0]
        g["arrays"]["leg_tips"]["stats"]["mean"][0] = v + factor * (G.STAT_ATOL_M + G.STAT_RTOL * abs(v))
    elif where == "states":
        fractions = g["arrays"]["leg_states"]["stats"]["fraction"]
        fractions[min(fractions)] += factor * G.STATE_FRACTION_ATOL
    else:
        v = g["metrics"]["speed_m_per_s"]
        g["metrics"]["speed_m_per_s"] = v + factor * (G.METRIC_ATOL + G.METRIC_RTOL * abs(v))
    return g


@pytest.mark.slow
@pytest.mark.golden
@pytest.mark.parametrize("name", CASE_IDS)
@pytest.mark.parametrize("where", ["head", "stat", "states", "metric"])
def test_a_golden_moved_just_past_its_tolerance_fails_and_well_inside_passes(name, where):
    """The tolerances are not vacuous: the same run against its golden with one recorded value moved by 1.5
    times the tolerance fails, naming that value; moved by 0.1 times it (on top of the run's own distance
    from the golden) it passes.  Compared without the digests (``bitwise=False``), as on another machine."""
    arrays, metrics = _wave_off_run(name)
    golden = _golden(name)
    assert not G.compare_to_golden(_perturbed(golden, where, 0.1), arrays, metrics, bitwise=False)
    problems = G.compare_to_golden(_perturbed(golden, where, 1.5), arrays, metrics, bitwise=False)
    key = {"head": "segment_centers: first", "stat": "leg_tips: whole-run mean",
           "states": "leg_states: whole-run fraction", "metric": "metric speed_m_per_s"}
    assert len(problems) == 1 and problems[0].startswith(key[where]), problems


def test_the_body_wave_matrix_sweeps_the_phase_offset():
    exp = expand_matrix(ROOT / "scenarios" / "matrix" / "body-wave.toml")
    offsets = sorted({c.axes.get("controller.body_wave_phase_rad") for c in exp.cases} - {None})
    assert "controller.body_wave_phase_rad" in exp.grid_keys
    assert len(offsets) >= 8 and offsets[0] == 0.0 and offsets[-1] > 5.0


@pytest.mark.slow
def test_the_speed_per_stride_depends_on_the_offset_and_is_plotted(tmp_path):
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.harness.runner import run_case

    speed = {}
    for phase in (0.785, 4.712):
        r = run_case(resolve_case("centipede", "hybrid", "straight", duration=6.0,
                                  overrides=["controller.body_wave_amplitude=0.1",
                                             f"controller.body_wave_phase_rad={phase}"]))
        assert r.status == "ok", r.message
        speed[phase] = r.metrics["speed_bl_per_stride"]
        assert r.metrics["body_undulation_amp_bl"] > 0.005  # the body does undulate (seen: ~0.02)
    assert all(math.isfinite(v) and v > 0 for v in speed.values())
    assert abs(speed[0.785] - speed[4.712]) > 0.1 * speed[4.712]  # (seen at 8 s: 0.033 vs 0.021)
    df = pd.DataFrame({"creature": "centipede", "body": "hybrid", "status": "ok",
                       "grid.controller.body_wave_phase_rad": [np.nan, 0.785, 4.712],
                       "grid.controller.body_wave_amplitude": [np.nan, 0.1, 0.1],
                       "metric.speed_bl_per_stride": [0.038, speed[0.785], speed[4.712]]})
    assert has_body_wave_sweep(df, ["controller.body_wave_phase_rad"])
    path = plot_speed_per_stride_vs_offset(df, tmp_path / "bw.png")
    assert path.stat().st_size > 5000
