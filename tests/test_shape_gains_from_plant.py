"""The shape loop's integral gain from the body's measured plant at the loop's operating amplitude (issue 44 item 2;
docs/explanation/shape-tracking.md, "How the gains are derived").

``gait.shape_gain_i_per_cycle = -1`` sets the fundamental's integral gain to 0.65 / Re H per cycle, H the loop's
plant at the operating amplitude s* (s* |G(s*)| = 1, ``bodies.curvature_calibration.operating_plant``), and falls
back to the constant 2, saying so, where that plant is not found.  The model-plant tests are pure Python; the lattice
tests build two closed-loop snakes of the slithering grid (ratios 1 and 5: the feed-forward's identifications are
those tests/test_shape_tracking.py's lattice cases make; the one at twice the feed-forward on ratio 5 costs about a
CPU second) and run one 0.2 s lattice case.
"""
from __future__ import annotations

import cmath
import math

import pytest

from bench_myriapoda.bodies import curvature_calibration as cc
from bench_myriapoda.controllers.shape_tracking import (INTEGRAL_GAIN_FALLBACK_PER_CYCLE, INTEGRAL_GAIN_MAX_PER_CYCLE,
                                                        INTEGRAL_GAIN_MIN_PER_CYCLE, INTEGRAL_RATE_PER_CYCLE,
                                                        integral_gain_from_plant)
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import Creature, run_case

MU_F = 0.05
GRID = ("gait.curvature_amplitude=7", "gait.wavelength_bl=1", "gait.frequency_hz=0.140071",
        f"friction.mu_forward={MU_F}", "friction.model=coulomb", f"friction.mu_backward={1.5 * MU_F}",
        "metrics.warmup_cycles=3")
FROM_PLANT = "gait.shape_gain_i_per_cycle=-1"


def _plant(s_star: float, lag_deg: float = 0.0, gain: float | None = None) -> dict:
    return {"status": "ok", "s_star": s_star, "gain": 1.0 / s_star if gain is None else gain, "lag_deg": lag_deg,
            "runs": 1}


def _re_h(gain: float, lag_deg: float, kp: float, rho: float) -> float:
    g = rho * gain * cmath.exp(-1j * math.radians(lag_deg))
    return (g / (1.0 + kp * g)).real


def test_the_operating_amplitude_is_where_the_open_loop_reaches_the_command():
    """s* from identified (s, |G|, lag) points: the secant of s |G(s)| - 1 between the last point short of the command
    and the first beyond it, |G(s*)| = 1 / s* by definition, the lag interpolated; a point within the tolerance as it
    is; a feed-forward that overshoots at the bound s = 1; none without a bracket."""
    s_star, g, lag = cc.operating_amplitude([(1.0, 0.2, -28.0), (2.0, 0.86, -13.0)])
    assert s_star == pytest.approx(1.0 + 0.8 / (1.72 - 0.2))
    assert g == pytest.approx(1.0 / s_star)
    assert lag == pytest.approx(-28.0 + (s_star - 1.0) * 15.0)
    assert cc.operating_amplitude([(1.0, 0.95, -4.0)]) == (1.0, 0.95, -4.0)
    assert cc.operating_amplitude([(1.0, 1.3, 2.0)]) == (1.0, 1.3, 2.0)
    assert cc.operating_amplitude([(1.0, 0.2, -28.0), (2.0, 0.3, -20.0)]) is None


def test_the_search_identifies_at_most_its_runs_and_fails_without_a_bracket(monkeypatch):
    """``measure_operating_plant`` on a model Coulomb plant (|G(s)| = max(0, s - c) / s: nothing until the muscles'
    moment passes the friction's, then the free body) asks for at most ``OPERATING_MAX_RUNS`` identifications beyond
    the feed-forward's and finds s*; with a threshold beyond its reach, or the feed-forward's identification not ok,
    it says why (the tracker then falls back:
    ``test_without_the_plant_the_gain_is_the_constant_and_the_run_says_so``)."""
    asked = []

    def model(c):
        def plant_response(make_body, case, fill, wave, cache=True, scale=1.0):
            asked.append(scale)
            return {"status": "ok", "gain": [max(0.0, scale - c) / scale] * 3, "lag_deg": [-10.0] * 3}
        return plant_response

    base = {"status": "ok", "gain": [0.2] * 3, "lag_deg": [-28.0] * 3}
    monkeypatch.setattr(cc, "plant_response", model(0.8))
    res = cc.measure_operating_plant(None, None, None, None, base, cache=False)
    assert res["status"] == "ok" and res["runs"] == len(asked) <= cc.OPERATING_MAX_RUNS
    assert asked == [cc.OPERATING_FIRST_S]
    # between (1, 0.2) and (2, 1.2): s* = 1.8, where the model reaches the command exactly
    assert res["s_star"] == pytest.approx(1.8) and res["gain"] == pytest.approx(1.0 / 1.8)
    monkeypatch.setattr(cc, "plant_response", model(1.5))
    far = cc.measure_operating_plant(None, None, None, None, base, cache=False)
    assert far["status"] != "ok" and "did not reach the command" in far["status"]
    bad = cc.measure_operating_plant(None, None, None, None, {"status": "the open loop blew up"}, cache=False)
    assert bad["status"] != "ok" and bad["runs"] == 0


def test_the_integral_gain_follows_the_measured_plant():
    """K_i = 0.65 / Re H per cycle, H = rho G / (1 + K_p rho G) at the operating amplitude: two plants whose measured
    |G| differ give gains in the ratio of their Re H, a larger proportional gain a larger integral one, and the gain
    is clamped to its documented range."""
    rho = 0.97
    for kp in (2.0, 0.5, 0.25):
        k1, why1 = integral_gain_from_plant(_plant(1.0), kp, rho)
        k2, why2 = integral_gain_from_plant(_plant(1.6, -13.0), kp, rho)
        assert k1 == pytest.approx(INTEGRAL_RATE_PER_CYCLE / _re_h(1.0, 0.0, kp, rho))
        assert k2 / k1 == pytest.approx(_re_h(1.0, 0.0, kp, rho) / _re_h(1.0 / 1.6, -13.0, kp, rho))
        assert k2 > 1.05 * k1 and "measured plant" in why1 and "s* = 1.600" in why2
    assert integral_gain_from_plant(_plant(1.0), 2.0, rho)[0] > 1.9 * integral_gain_from_plant(_plant(1.0), 0.5,
                                                                                               rho)[0]
    assert integral_gain_from_plant(_plant(8.0, 80.0), 2.0, rho)[0] == INTEGRAL_GAIN_MAX_PER_CYCLE
    assert integral_gain_from_plant(_plant(1.0, gain=5.0), 0.0, rho)[0] == INTEGRAL_GAIN_MIN_PER_CYCLE
    none, why = integral_gain_from_plant(_plant(1.0, 120.0), 0.0, rho)
    assert none is None and "no convergence" in why


def _grid(ratio: float, *extra: str, duration: float = 0.2):
    return resolve_case("snake", "massspring", "flat", "lateral-undulation", duration=duration,
                        overrides=[*GRID, f"friction.mu_transverse={ratio * MU_F}", *extra])


def test_two_grounds_give_the_integral_gains_of_their_measured_plants():
    """The lattice snake of the slithering grid on two grounds: at mu_t / mu_f = 1 the feed-forward already reaches
    the command (s* = 1, no further identification), at 5 it reaches a fifth of it and s* lies between 1 and 2 (one
    identification at twice the feed-forward).  The gains follow their measured plants: the ratio of the two K_i is
    that of the two Re H, and they differ (at the constant gain they would not)."""
    gains = {}
    for ratio in (1.0, 5.0):
        tracker = Creature(_grid(ratio, FROM_PLANT)).controller.tracker
        op = tracker.operating
        assert tracker.ki_from_plant and op is not None and op["status"] == "ok", tracker.ki_source
        assert op["s_star"] * op["gain"] == pytest.approx(1.0, abs=cc.OPERATING_TOL)
        gains[ratio] = (tracker.ki_per_cycle, _re_h(op["gain"], op["lag_deg"], tracker.kp, tracker.wave_smoothing), op)
    (k1, h1, op1), (k5, h5, op5) = gains[1.0], gains[5.0]
    assert op1["runs"] == 0 and op1["s_star"] == 1.0
    assert op5["runs"] == 1 and 1.0 < op5["s_star"] < 2.0
    assert k5 / k1 == pytest.approx(h1 / h5, rel=1e-9)
    assert k5 > 1.1 * k1


def test_without_the_plant_the_gain_is_the_constant_and_the_run_says_so():
    """``gait.shape_guard = false`` identifies no plant: at -1 the loop runs the constant 2 per cycle, and the run's
    metric and label say it came from no measurement.  At the default key the gain is the key's."""
    r = run_case(_grid(5.0, FROM_PLANT, "gait.shape_guard=false"))
    assert r.status == "ok", r.message
    assert r.metrics["shape_gain_i_per_cycle_used"] == INTEGRAL_GAIN_FALLBACK_PER_CYCLE
    assert r.metrics["shape_gain_i_from_plant"] == 0.0 and math.isnan(r.metrics["shape_operating_amplitude"])
    label = r.extra["labels"]["shape_gains"]
    assert "the constant" in label and "not found" in label
    keyed = Creature(_grid(5.0, "gait.shape_gain_i_per_cycle=1.5", "gait.shape_guard=false")).controller.tracker
    assert keyed.ki_per_cycle == 1.5 and not keyed.ki_from_plant
