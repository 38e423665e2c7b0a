"""Miller's gaits on the mass-spring body against analytic and published references.

See ../shared/reference/VALIDATION.md: the rectilinear worm's displacement per
cycle, the snake under isotropic and anisotropic friction, sidewinding's
diagonal travel and its reversal, the caterpillar on a slope.
"""
import math

import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case

WORM_DISPLACEMENT_REL_TOL = 0.05      # VALIDATION.md: within 5 % of eps * Lambda once the gait is steady
SNAKE_ISOTROPIC_MAX_BL_PER_CYCLE = 0.02
SIDEWINDER_MIN_TRAVEL_ANGLE_DEG = 45.0


def run(creature, scenario, gait=None, *sets, duration=None, keep_nodes=False):
    case = resolve_case(creature, "massspring", scenario, gait, duration=duration, overrides=list(sets))
    result = run_case(case, keep_nodes=keep_nodes)
    assert result.status == "ok", result.message
    return case, result


def test_worm_with_perfect_anchoring_moves_eps_lambda_per_cycle():
    case, r = run("worm", "flat", duration=30.0)
    eps = case.gait.amplitude
    wavelength = case.gait.wavelength_bl * case.creature.body_length_m
    expected = eps * wavelength
    got = r.metrics["displacement_per_cycle_m"]
    assert got == pytest.approx(expected, rel=WORM_DISPLACEMENT_REL_TOL), (got, expected)
    assert abs(r.metrics["travel_angle_deg"]) < 1.0


def test_worm_displacement_scales_with_amplitude():
    # eps * Lambda: halving eps halves the displacement (checks the law, not one calibrated point)
    case, r = run("worm", "flat", None, "gait.amplitude=0.1", duration=30.0)
    wavelength = case.gait.wavelength_bl * case.creature.body_length_m
    assert r.metrics["displacement_per_cycle_m"] == pytest.approx(0.1 * wavelength, rel=2 * WORM_DISPLACEMENT_REL_TOL)


def test_worm_fails_predictably_without_backward_anchoring():
    # VALIDATION.md: with friction that cannot anchor the compressed points the law must fail
    case, r = run("worm", "flat", None, "friction.model=coulomb", "friction.mu_forward=0.3",
                  "friction.mu_backward=0.3", "friction.mu_transverse=0.3", duration=20.0)
    expected = case.gait.amplitude * case.gait.wavelength_bl * case.creature.body_length_m
    assert abs(r.metrics["displacement_per_cycle_m"]) < 0.25 * expected


def test_snake_with_isotropic_friction_makes_almost_no_progress():
    _, r = run("snake", "flat", None, "friction.mu_forward=0.3", "friction.mu_backward=0.3",
               "friction.mu_transverse=0.3", duration=16.0)
    assert abs(r.metrics["speed_bl_per_cycle"]) < SNAKE_ISOTROPIC_MAX_BL_PER_CYCLE


def test_snake_speed_increases_monotonically_with_transverse_to_forward_ratio():
    mu_f = 0.1
    speeds = []
    for ratio in (1.0, 2.0, 4.0, 8.0):
        _, r = run("snake", "flat", None, f"friction.mu_forward={mu_f}", "friction.mu_backward=0.3",
                   f"friction.mu_transverse={ratio * mu_f}", duration=16.0)
        speeds.append(r.metrics["speed_bl_per_cycle"])
    assert all(b > a for a, b in zip(speeds, speeds[1:])), speeds
    assert speeds[-1] > 0.1, speeds  # a real forward gait at the highest ratio


def test_sidewinder_travels_diagonally_and_reverses_with_the_phase():
    _, undulation = run("snake", "flat", "lateral-undulation", duration=16.0)
    _, plus = run("snake", "flat", "sidewinding", duration=16.0)
    _, minus = run("snake", "flat", "sidewinding", "gait.vertical_phase_deg=-90", duration=16.0)
    assert abs(plus.metrics["travel_angle_deg"]) > SIDEWINDER_MIN_TRAVEL_ANGLE_DEG
    assert abs(plus.metrics["travel_angle_deg"]) > abs(undulation.metrics["travel_angle_deg"]) + 30.0
    # direction of travel reverses: the sideways components have opposite signs and comparable size
    lp, lm = plus.metrics["lateral_speed_m_per_s"], minus.metrics["lateral_speed_m_per_s"]
    assert lp * lm < 0 and min(abs(lp), abs(lm)) > 0.5 * max(abs(lp), abs(lm)), (lp, lm)


def test_caterpillar_climbs_a_30_degree_slope_without_sliding_back():
    case, r = run("caterpillar", "slope", None, "scenario.slope_deg=30", duration=16.0, keep_nodes=True)
    a = math.radians(30.0)
    uphill = np.array([math.cos(a), math.sin(a), 0.0])
    progress = r.series.com @ uphill
    period = case.gait.period_s
    t = r.series.t
    # sample the along-slope position once per gait cycle: it must grow every cycle after the ramp
    idx = [int(np.searchsorted(t, k * period)) for k in range(2, int(t[-1] / period))]
    per_cycle = np.diff(progress[idx])
    assert np.all(per_cycle > 0.0), per_cycle
    assert r.metrics["speed_bl_per_cycle"] > 0.05


def test_slope_check_catches_a_creature_that_slides_back():
    # the same climb with slippery Coulomb friction (mu = 0.1 < tan 30 deg) must fail the criterion above
    case, r = run("caterpillar", "slope", None, "scenario.slope_deg=30", "friction.model=coulomb",
                  "friction.mu_forward=0.1", "friction.mu_backward=0.1", "friction.mu_transverse=0.1", duration=8.0)
    a = math.radians(30.0)
    progress = r.series.com @ np.array([math.cos(a), math.sin(a), 0.0])
    assert progress[-1] - progress[0] < -0.1


def test_passive_caterpillar_holds_on_the_slope():
    _, r = run("caterpillar", "slope", None, "scenario.passive=true", duration=5.0)
    assert abs(r.series.com[-1] - r.series.com[0]).max() < 0.01
