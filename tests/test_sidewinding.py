"""Sidewinding as Miller describes it (Miller 1988 Sec. 4, Image 3; issue 11 item 6), on every body.

"A vertical sinusoidal flexing of the snake which is 90 degrees out of phase with respect to the
horizontal undulations ... has the effect of lifting all but a small portion of the snake off the
ground", and "the diagonal nature of the locomotion is apparent".  Three behaviours, one test each:

* the travel is diagonal and its sideways direction reverses when the vertical wave's phase flips
  sign (+90 -> -90 degrees);
* a minority of the segments touch the ground (``segment_contact_fraction`` < 0.5);
* the cross-sections do not roll over (``roll_max_deg`` < 90 over every segment and the whole run).

The snake's own preset (models/snake.toml, [gaits.sidewinding]) on each body.  The runs are shorter
than the Miller image run (ramp 2 s + 3 cycles; the metrics skip the first 2 cycles) and shared by
the tests of a body.  The hybrid body needs a 1/12000 s step at the sidewinder's stiffness (about a
minute per run), so it runs with BENCH_LONG_TESTS=1 only.
"""
from __future__ import annotations

import os

import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case

DURATION_S = 8.0
DIAGONAL_DEG = (15.0, 75.0)     # |travel angle| from the mean body axis: neither along nor across it
REVERSAL_RATIO = 0.5            # the reversed gait's sideways speed at least half the other's
MIN_GROUND_BL_PER_CYCLE = 0.05  # it really travels
CONTACT_MAX = 0.5
ROLL_MAX_DEG = 90.0

LONG = pytest.mark.skipif(not os.environ.get("BENCH_LONG_TESTS"),
                          reason="about a minute per hybrid run at 1/12000 s; set BENCH_LONG_TESTS=1")
BODIES = [pytest.param("massspring"), pytest.param("fem"), pytest.param("hybrid", marks=LONG)]
_RUNS: dict[tuple[str, float], tuple] = {}


def run(body: str, phase_deg: float = 90.0):
    if (body, phase_deg) not in _RUNS:
        case = resolve_case("snake", body, "flat", "sidewinding", duration=DURATION_S,
                            overrides=[f"gait.vertical_phase_deg={phase_deg}"])
        res = run_case(case)
        assert res.status == "ok", res.message
        _RUNS[body, phase_deg] = (case, res.metrics)
    return _RUNS[body, phase_deg]


def ground_speed_bl_per_cycle(case, m) -> float:
    """Speed over the ground [body lengths per gait cycle] from the forward and sideways speeds."""
    lateral = m["lateral_speed_m_per_s"] * case.gait.period_s / case.creature.body_length_m
    return float((m["speed_bl_per_cycle"] ** 2 + lateral ** 2) ** 0.5)


@pytest.mark.parametrize("body", BODIES)
def test_sidewinder_travels_diagonally_and_reverses_with_the_phase(body):
    case, plus = run(body, 90.0)
    _, minus = run(body, -90.0)
    lo, hi = DIAGONAL_DEG
    for m in (plus, minus):
        assert lo < abs(m["travel_angle_deg"]) < hi, (plus["travel_angle_deg"], minus["travel_angle_deg"])
        assert ground_speed_bl_per_cycle(case, m) > MIN_GROUND_BL_PER_CYCLE
    lp, lm = plus["lateral_speed_m_per_s"], minus["lateral_speed_m_per_s"]
    assert lp * lm < 0 and min(abs(lp), abs(lm)) > REVERSAL_RATIO * max(abs(lp), abs(lm)), (lp, lm)
    assert plus["travel_angle_deg"] * minus["travel_angle_deg"] < 0


@pytest.mark.parametrize("body", BODIES)
def test_sidewinder_touches_the_ground_with_a_minority_of_its_segments(body):
    _, m = run(body)
    assert m["segment_contact_fraction"] < CONTACT_MAX, m["segment_contact_fraction"]


@pytest.mark.parametrize("body", BODIES)
def test_sidewinder_cross_sections_do_not_roll(body):
    _, m = run(body)
    assert m["roll_max_deg"] < ROLL_MAX_DEG, m["roll_max_deg"]
    assert m["posture_fault"] == 0.0


def _lattice(*sets):
    case = resolve_case("snake", "massspring", "flat", "sidewinding", duration=DURATION_S, overrides=list(sets))
    res = run_case(case)
    assert res.status == "ok", res.message
    return res.metrics


def test_equal_lateral_and_vertical_waves_roll_the_lattice_like_a_log():
    # the first cause, kept as a check: with the vertical wave as strong as the lateral one (the rest
    # shape a helix, whose travelling wave is each cross-section spinning in a still shape) and Miller's
    # snake stiffness, the lattice lies down and rolls over instead of lifting its arches
    m = _lattice("gait.vertical_curvature_amplitude=10", "body.stiffness=0.5")
    assert m["roll_max_deg"] > ROLL_MAX_DEG and m["segment_contact_fraction"] > CONTACT_MAX


def test_millers_snake_stiffness_cannot_lift_the_vertical_wave():
    # the second cause: with the preset's weaker vertical wave but Miller's snake stiffness the muscles'
    # bending moment cannot carry the body's weight between contact patches: it stays on the ground
    m = _lattice("body.stiffness=0.5")
    assert m["segment_contact_fraction"] > 0.9


def test_the_sidewinders_braced_body_holds_for_that_gait_only():
    # [gaits.sidewinding.bodies.<body>] in models/snake.toml: the creature's other gaits keep its bodies
    for body, key in (("massspring", "stiffness"), ("fem", "youngs_modulus_pa"), ("hybrid", "youngs_modulus_pa")):
        side = resolve_case("snake", body, "flat", "sidewinding")
        slither = resolve_case("snake", body, "flat", "lateral-undulation")
        assert getattr(side.body, key) == pytest.approx(16.0 * getattr(slither.body, key), rel=1e-6), body
    # --set still wins over the gait's body keys
    assert resolve_case("snake", "massspring", "flat", "sidewinding", overrides=["body.stiffness=1"]).body.stiffness == 1


def test_the_reports_sidewinder_verdict_applies_image_3s_criteria():
    # report/validation.py judges a drawn sidewinding figure with validation.miller.judge_sidewinder
    from bench_myriapoda.validation.core import FAIL, PASS
    from bench_myriapoda.validation.miller import judge_sidewinder
    good = {"travel_angle_deg": -60.0, "segment_contact_fraction": 0.3, "roll_max_deg": 50.0}
    assert judge_sidewinder(good).verdict == PASS
    # the log-roller of issue 11: steep travel angle, 95 % contact, rolled over
    assert judge_sidewinder({"travel_angle_deg": 80.0, "segment_contact_fraction": 0.95,
                             "roll_max_deg": 180.0}).verdict == FAIL
    for key, bad in (("travel_angle_deg", 5.0), ("segment_contact_fraction", 0.6), ("roll_max_deg", 120.0)):
        assert judge_sidewinder({**good, key: bad}).verdict == FAIL, key


def _drift(overrides, duration_s: float = 16.0) -> float:
    case = resolve_case("snake", "massspring", "flat", "sidewinding", duration=duration_s, overrides=overrides)
    res = run_case(case)
    assert res.status == "ok", res.message
    return res.metrics["heading_drift_deg_per_cycle"]


def test_the_lattice_sidewinders_turn_is_a_steady_property_of_the_gait_not_of_its_start():
    # The lattice sidewinder turns about 19 degrees per cycle (issue 11).  Not a start-up transient: a
    # 0.01 s ramp instead of 2 s gives the same steady turn.  Not a chirality of the lattice: the
    # mirror-image gait (lateral wave negated, i.e. phase 180, vertical -90) turns exactly the other
    # way.  It falls with the number of waves on the body (1 wave: 63, 2 waves: 7 degrees per cycle,
    # measured): an end effect of a finite body under a travelling helical wave.
    base = _drift([])
    assert 10.0 < abs(base) < 30.0, base
    assert _drift(["gait.ramp_s=0.01"]) == pytest.approx(base, abs=1.0)
    assert _drift(["gait.phase_deg=180", "gait.vertical_phase_deg=-90"]) == pytest.approx(-base, abs=0.1)
    assert abs(_drift(["gait.wavelength_bl=0.5"])) < 0.5 * abs(base)
