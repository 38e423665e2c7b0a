"""Emergent measures of a legged walk (``metrics.walk``) and the commanded speed's label."""
from __future__ import annotations

import math

import numpy as np
import pytest

from bench_myriapoda.metrics.walk import EMERGENT_WALK_METRICS, commanded_metric, walk_emergent_metrics

G, MASS, L = 9.81, 2.0, 1.0


def synthetic_walk(speed: float, sway_m: float, stretch: float, bumps_j: float, duration: float = 6.0):
    """A body whose centre of mass moves along +x at ``speed`` [m/s] with a sideways sine of ``sway_m`` [m]
    (1 Hz), a head-to-tail span ``stretch`` longer than at t = 0 after the first second, and a total
    energy that rises by ``bumps_j`` [J] once per stride (1 Hz) and falls back."""
    t = np.linspace(0.0, duration, int(duration * 100) + 1)
    com = np.stack([speed * t, np.full_like(t, 0.1), sway_m * np.sin(2 * np.pi * t)], axis=1)
    span = L * (1.0 + stretch * (t > 1.0))
    head = com + np.stack([0.5 * span, 0 * t, 0 * t], axis=1)
    tail = com - np.stack([0.5 * span, 0 * t, 0 * t], axis=1)
    energy = np.stack([np.full_like(t, 1.0), bumps_j * (np.sin(2 * np.pi * t) > 0), np.zeros_like(t)], axis=1)
    return t, com, head, tail, energy


def measure(walk, head_speed=1.0, stride_hz=1.0, start=1.5, need=2.0):
    return walk_emergent_metrics(*walk, start, head_speed, stride_hz, L, MASS, G, need)


def test_the_emergent_measures_follow_their_definitions():
    m, why = measure(synthetic_walk(0.8, 0.05, 0.1, 0.5))
    assert why is None
    assert m["steady_cycles"] == pytest.approx(4.5)                   # 4.5 s window at 1 stride/s
    assert m["body_speed_ratio"] == pytest.approx(0.8, rel=1e-3)      # 0.8 m/s against the commanded 1 m/s
    assert m["lateral_sway_bl"] == pytest.approx(0.05 / math.sqrt(2), rel=0.02)  # RMS of a sine
    assert m["body_stretch_rel"] == pytest.approx(0.1)
    # 0.5 J put in at each stride's start (t = 2, 3, 4, 5 s in the window), over m g d = 2 * 9.81 * 3.6
    assert m["cost_of_transport_mech"] == pytest.approx(4 * 0.5 / (MASS * G * 3.6), rel=1e-9)


def test_two_walks_built_to_differ_differ_in_every_emergent_measure():
    stiff, _ = measure(synthetic_walk(1.0, 0.0, 0.0, 0.1))
    soft, _ = measure(synthetic_walk(0.9, 0.04, 0.15, 0.6))
    for k in EMERGENT_WALK_METRICS:
        assert math.isfinite(stiff[k]) and math.isfinite(soft[k]), k
        assert abs(stiff[k] - soft[k]) > 1e-3, k
    assert soft["body_speed_ratio"] < stiff["body_speed_ratio"]
    assert soft["lateral_sway_bl"] > stiff["lateral_sway_bl"]
    assert soft["cost_of_transport_mech"] > stiff["cost_of_transport_mech"]


def test_a_walk_under_two_strides_is_too_short_with_the_reason():
    m, why = measure(synthetic_walk(1.0, 0.0, 0.0, 0.1, duration=3.0), start=1.5, stride_hz=1.0)
    assert m["steady_cycles"] == pytest.approx(1.5)
    assert all(math.isnan(m[k]) for k in EMERGENT_WALK_METRICS)
    assert why.startswith("too short: 1.50 strides") and "run >= 3.5 s" in why
    m, why = measure(synthetic_walk(1.0, 0.0, 0.0, 0.1), stride_hz=math.nan)
    assert "no complete stride" in why


def test_only_a_legged_walks_speed_is_commanded():
    assert commanded_metric("speed_m_per_s", legged=True) == "controller.head_speed_m_s"
    assert commanded_metric("speed_m_per_s", legged=False) is None
    assert commanded_metric("body_speed_ratio", legged=True) is None


def test_impact_loss_and_integrator_drift_are_measured_apart():
    """A dropped body: energy drifts 1e-4 in free fall, then loses half at the impact (first contact at 1 s)."""
    from bench_myriapoda.core.series import Series
    from bench_myriapoda.metrics.locomotion import contact_energy_metrics, energy_metrics

    t = np.linspace(0.0, 2.0, 201)
    total = np.where(t < 1.0, 10.0 * (1.0 + 1e-4 * t), 5.0)  # [J]
    energy = np.stack([np.zeros_like(t), np.zeros_like(t), total], axis=1)
    zeros = np.zeros((len(t), 3))
    contact = np.repeat((t >= 1.0)[:, None], 4, axis=1)
    s = Series(t, zeros, zeros, zeros, np.zeros((len(t), 4, 3)), energy, None, segment_contact=contact)
    m = contact_energy_metrics(s)
    assert m["energy_drift_free_rel"] == pytest.approx(1e-4 * t[t < 1.0][-1], rel=1e-9)
    assert m["impact_energy_loss_rel"] == pytest.approx((5.0 - 10.0 * (1 + 1e-4 * t[t < 1.0][-1])) / 10.0, rel=1e-9)
    assert energy_metrics(s)["energy_drift_rel"] == pytest.approx(-0.5)  # the whole run: impact and drift mixed
    # in contact from the start: no free-flight window; never in contact: no impact
    s.segment_contact = np.ones_like(contact)
    assert all(math.isnan(v) for v in contact_energy_metrics(s).values())
    s.segment_contact = np.zeros_like(contact)
    assert all(math.isnan(v) for v in contact_energy_metrics(s).values())
