"""Lateral undulation measures (``metrics.undulation``) on constructed travelling and standing waves."""
import math

import numpy as np
import pytest

from bench_myriapoda.metrics.undulation import undulation_metrics


def wave(n=18, T=600, f=1.2, amp=0.15, wavelength=9.0, direction=1.0, speed=0.5, pitch=1.5, yaw_amp=0.0, dur=5.0):
    """Centres (T, n, 3) of a body along +x moving at `speed`, each segment displaced sideways (z) by
    amp sin(2 pi f t - direction 2 pi s / wavelength), s its distance from the head [m]."""
    t = np.linspace(0.0, dur, T)
    s = np.arange(n) * pitch
    c = np.zeros((T, n, 3))
    c[:, :, 0] = -s[None, :] + speed * t[:, None]
    c[:, :, 2] = amp * np.sin(2 * math.pi * f * t[:, None] - direction * 2 * math.pi * s[None, :] / wavelength)
    return t, c, s[-1]


@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_a_travelling_wave_gives_its_amplitude_wavelength_direction_and_frequency(direction):
    t, c, length = wave(direction=direction, wavelength=12.0)
    m = undulation_metrics(t, c, length)
    assert m["undulation_frequency_hz"] == pytest.approx(1.2, rel=0.05)
    assert m["undulation_wavelength_bl"] == pytest.approx(12.0 / length, rel=0.05)
    assert m["undulation_direction"] == direction
    assert m["undulation_amplitude_bl"] == pytest.approx(0.15 / length, rel=0.03)


def test_amplitude_grows_with_the_wave_and_a_straight_walk_has_none():
    t, c, length = wave(amp=0.0)
    m0 = undulation_metrics(t, c, length)
    assert m0["undulation_amplitude_bl"] == pytest.approx(0.0, abs=1e-12)
    assert math.isnan(m0["undulation_wavelength_bl"])
    amps = [undulation_metrics(*wave(amp=a, wavelength=12.0)[:2], length)["undulation_amplitude_bl"]
            for a in (0.05, 0.1, 0.2)]
    assert amps[0] < amps[1] < amps[2]
    assert amps[2] == pytest.approx(4 * amps[0], rel=1e-9)   # linear in the amplitude


def test_head_yaw_oscillation_of_a_wagging_head():
    t = np.linspace(0.0, 4.0, 400)
    n = 5
    c = np.zeros((len(t), n, 3))
    c[:, :, 0] = -np.arange(n)[None, :] * 1.0
    yaw = math.radians(10.0) * np.sin(2 * math.pi * 1.0 * t) + 0.05 * t   # 10 deg wag on a slow turn
    c[:, 0, 0] = c[:, 1, 0] + np.cos(yaw)
    c[:, 0, 2] = c[:, 1, 2] - np.sin(yaw)        # heading about +y: x toward -z
    m = undulation_metrics(t, c, 4.0)
    assert m["head_yaw_osc_deg"] == pytest.approx(10.0, rel=0.03)


def test_the_leg_phase_is_where_the_head_wave_stands_at_stance_onsets():
    f = 1.0
    t, c, length = wave(f=f, wavelength=40.0, dur=6.0, T=1200)
    # the head's z is amp sin(2 pi f t), to the right of +x travel: y (to the left) = amp sin(2 pi f t + pi);
    # onsets at t = k / f + 0.25 / f sit at theta = pi / 2 + pi
    onsets = np.arange(6) / f + 0.25 / f
    m = undulation_metrics(t, c, length, onsets)
    assert m["undulation_leg_phase_rad"] == pytest.approx(1.5 * math.pi, abs=0.05)


def test_too_few_samples_give_nan():
    t, c, length = wave(T=5)
    assert all(math.isnan(v) for v in undulation_metrics(t, c, length).values())
