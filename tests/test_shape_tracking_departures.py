"""Miller's dynamic snake kept (issue 44): how a body departs from a spline-following kinematic snake.

``metrics.spline_departure`` measures the two departures Miller (Sec. 4) describes: the tail's lateral swing
relative to mid-body (``tail_swing_ratio``) and sideways slip (``sideways_slip_ratio``).  Checked here on
constructed motions whose answer is known, and on the lattice snake against a kinematic snake of its own commanded
shape: a tracker that pinned every segment to the commanded wave, moving like the kinematic snake, would read the
same as the reference and fail the last test.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.core.series import Series
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.metrics.spline_departure import sideways_slip_ratio, spline_departure_metrics, tail_swing_ratio


def series_of(t: np.ndarray, xz: np.ndarray) -> Series:
    """A Series of centre lines xz (T, n, 2) [m] on the ground (y = 0), head first."""
    c = np.stack([xz[..., 0], np.zeros(xz.shape[:2]), xz[..., 1]], axis=2)
    return Series(t=t, com=c.mean(axis=1), head=c[:, 0], tail=c[:, -1], segment_centers=c,
                  energy=np.zeros((len(t), 3)), nodes=None)


def spline_follower(amplitude: float = 10.0, wavelength_bl: float = 0.5, length: float = 2.5, n: int = 50,
                    frequency: float = 0.5, cycles: float = 4.0, sample_hz: float = 60.0) -> Series:
    """A kinematic snake: every point slides along one fixed serpenoid curve, curvature (A / L) sin(k sigma), at the
    wave speed f lambda (no slip): the body's shape is the commanded travelling wave, each point follows the head."""
    lam = wavelength_bl * length
    k, v = 2 * math.pi / lam, frequency * lam
    t = np.arange(0.0, cycles / frequency + 1e-9, 1.0 / sample_hz)
    ds = length / n / 40.0
    sigma = np.arange(-length - 0.1, v * t[-1] + 0.1, ds)
    heading = -(amplitude / length) / k * np.cos(k * sigma)
    x = np.concatenate([[0.0], np.cumsum(0.5 * (np.cos(heading[1:]) + np.cos(heading[:-1])) * ds)])
    z = np.concatenate([[0.0], np.cumsum(0.5 * (np.sin(heading[1:]) + np.sin(heading[:-1])) * ds)])
    s = (0.5 + np.arange(n)) * length / n
    at = v * t[:, None] - s[None, :]  # (T, n): each point's place on the curve
    xz = np.stack([np.interp(at, sigma, x), np.interp(at, sigma, z)], axis=2)
    return series_of(t, xz)


def test_a_spline_following_snake_swings_its_tail_like_its_middle_and_does_not_slip():
    ref = spline_follower()
    i1 = len(ref.t) - 1
    i0 = int(np.searchsorted(ref.t, 2.0))  # whole cycles: 2 s to 8 s at 0.5 Hz
    assert tail_swing_ratio(ref, i0, i1) == pytest.approx(1.0, abs=0.05)
    assert sideways_slip_ratio(ref, i0, i1, pitch_m=0.05) < 0.03


def test_a_body_moving_straight_across_itself_slips_fully_and_one_swinging_its_tail_reads_above_one():
    t = np.arange(0.0, 8.0, 1 / 60)
    d = np.linspace(-1.25, 1.25, 50)  # offsets along the body from its middle, head first at -1.25
    a, w = 0.05, 2 * math.pi * 0.5
    side = a * np.sin(w * t)[:, None] * np.ones_like(d)[None, :]
    across = series_of(t, np.stack([-d[None, :] * np.ones_like(side), side], axis=2))
    assert sideways_slip_ratio(across, 0, len(t) - 1) == pytest.approx(1.0, abs=1e-9)
    assert tail_swing_ratio(across, 0, len(t) - 1) == pytest.approx(1.0, abs=1e-9)
    # the same sideways swing plus a small rotation about the middle in phase with it: the tail swings
    # a + (L / 2) theta0 and the middle a (its median over the middle third)
    theta0 = 0.05
    rot = theta0 * np.sin(w * t)[:, None]
    swing = np.stack([-d[None, :] * np.cos(rot), side + d[None, :] * np.sin(rot)], axis=2)
    expected = (a + 1.25 * theta0) / a
    assert tail_swing_ratio(series_of(t, swing), 0, len(t) - 1) == pytest.approx(expected, rel=0.02)
    assert 0.1 < sideways_slip_ratio(series_of(t, swing), 0, len(t) - 1) < 1.0


def test_the_tracked_lattice_snake_departs_from_a_spline_following_snake_of_its_commanded_shape():
    """The default snake (curvature 10, two waves per body, 0.5 Hz, mu_t / mu_f = 5) in the default closed loop on the
    lattice against the kinematic snake of the same commanded shape: the dynamic body's tail does not swing like its
    middle and its segments slide sideways; a tracker that pinned every segment to a spline-following wave would
    read 1 and 0 like the reference."""
    r = run_case(resolve_case("snake", "massspring", "flat", "lateral-undulation", duration=12.0))
    assert r.status == "ok" and r.metrics["shape_not_achieved"] == 0.0  # it does track the commanded shape
    ref = spline_follower(cycles=6.0)
    i0, i1 = int(np.searchsorted(ref.t, 4.0)), len(ref.t) - 1  # the run's steady window: 2 warm-up cycles
    kin = spline_departure_metrics(ref, i0, i1, pitch_m=0.05)
    dyn = r.metrics
    print("departures", {k: (round(kin[k], 3), round(dyn[k], 3)) for k in kin})
    assert abs(dyn["tail_swing_ratio"] - kin["tail_swing_ratio"]) > 0.2
    assert dyn["sideways_slip_ratio"] > kin["sideways_slip_ratio"] + 0.1
