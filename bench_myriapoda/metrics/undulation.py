"""Lateral undulation of a walking body, measured from its segment centres (issue 43's emergent measures).

A walking myriapod's body may sway from side to side (Anderson, Shultz and Jayne 1995: centipedes undulate
more at higher speeds).  On the legged timeline's segment centres c (T, n, 3) [m] (segment 0 the head, y up)
over the gait window:

* each segment's lateral displacement y_i(t) [m]: its position in the ground plane (x, z) across the
  window's travel direction (positive to the left), less its least-squares line in time (a drift or a slow
  turn is not undulation): a straight walk's measure (a turning walk adds its curvature to it);
* the undulation frequency f_u [Hz]: the peak of the displacements' power spectrum summed over segments
  (samples resampled to a uniform grid first);
* ``undulation_amplitude_bl`` [BL]: mean over segments of sqrt(2) x RMS of y_i, / body length (a sine's
  amplitude);
* the phases phi_i = arg sum_t y_i(t) exp(-2 pi i f_u t) along the body, unwrapped, fitted linearly against
  the segment's distance from the head s_i [BL] (the centres' mean spacing, summed): phi = phi_0 - k s.
  ``undulation_wavelength_bl`` = 2 pi / |k| [BL] (NaN for a standing sway, |k| < 1e-9);
  ``undulation_direction`` = +1 when the wave travels head to tail (k > 0), -1 tail to head;
* ``undulation_leg_phase_rad``: the undulation's phase theta at the head (y_0 = A sin theta, theta =
  2 pi f_u t + arg Y_0 + pi / 2) at the head's left leg's stance onsets, their circular mean in [0, 2 pi):
  where in the body wave the leg wave's stance begins (meaningful when f_u is the stride frequency;
  ``undulation_frequency_hz`` says);
* ``head_yaw_osc_deg`` [deg]: sqrt(2) x RMS of the head's heading (the direction from segment 1's centre
  to the head's in the ground plane, unwrapped), less its least-squares line over the window (turning).

All NaN with fewer than 8 samples or 3 segments.
"""
from __future__ import annotations

import math

import numpy as np

UNDULATION_METRICS = ("undulation_amplitude_bl", "undulation_frequency_hz", "undulation_wavelength_bl",
                      "undulation_direction", "undulation_leg_phase_rad", "head_yaw_osc_deg")


def lateral_displacements(t: np.ndarray, centres: np.ndarray) -> np.ndarray:
    """(T, n) [m] each segment's sideways position in the ground plane across the window's travel direction
    (the net displacement of the centres' mean; the first sample's tail-to-head direction when it did not
    move), positive to the left, less its least-squares line in time (a steady drift or slow turn is not
    undulation).  t (T,) [s], centres (T, n, 3) [m]."""
    g = np.asarray(centres, float)[:, :, [0, 2]]
    mean = g.mean(axis=1)
    d = mean[-1] - mean[0]
    if not np.linalg.norm(d) > 1e-9:
        d = g[0, 0] - g[0, -1]
    u = d / max(np.linalg.norm(d), 1e-300)
    # left of the travel direction in (x, z) with y up: (u_z, -u_x)
    y = g[:, :, 0] * u[1] - g[:, :, 1] * u[0]
    A = np.stack([t - t.mean(), np.ones_like(t)], axis=1)
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    return y - A @ coef


def _uniform(t: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """values (T, ...) at times t (T,) resampled linearly to T uniform times over [t_0, t_-1]."""
    tu = np.linspace(t[0], t[-1], len(t))
    flat = values.reshape(len(t), -1)
    out = np.stack([np.interp(tu, t, flat[:, k]) for k in range(flat.shape[1])], axis=1)
    return tu, out.reshape(values.shape)


def undulation_metrics(t: np.ndarray, centres: np.ndarray, body_length_m: float,
                       leg_stance_onsets_s: np.ndarray | None = None) -> dict[str, float]:
    """The module's measures (docstring) on samples t (T,) [s] and centres (T, n, 3) [m] of the gait window;
    leg_stance_onsets_s: times [s] at which the head's left leg entered STANCE (for the leg phase)."""
    out = dict.fromkeys(UNDULATION_METRICS, math.nan)
    t = np.asarray(t, float)
    centres = np.asarray(centres, float)
    if len(t) < 8 or centres.shape[1] < 3 or not t[-1] > t[0] or body_length_m <= 0:
        return out
    tu, y = _uniform(t, lateral_displacements(t, centres))
    dt = tu[1] - tu[0]
    amp = math.sqrt(2.0) * np.sqrt(np.mean(y ** 2, axis=0))
    out["undulation_amplitude_bl"] = float(amp.mean() / body_length_m)
    # heading of the head: unwrapped, less its linear trend
    g = centres[:, :, [0, 2]]
    d = g[:, 0] - g[:, 1]
    yaw = np.unwrap(np.arctan2(-d[:, 1], d[:, 0]))
    _, yaw_u = _uniform(t, yaw[:, None])
    yaw_u = yaw_u[:, 0]
    trend = np.polyval(np.polyfit(tu, yaw_u, 1), tu)
    out["head_yaw_osc_deg"] = float(math.degrees(math.sqrt(2.0) * np.sqrt(np.mean((yaw_u - trend) ** 2))))
    if not np.any(amp > 0):
        return out
    spec = np.abs(np.fft.rfft(y, axis=0)) ** 2
    power = spec.sum(axis=1)
    power[0] = 0.0
    k = int(np.argmax(power))
    if k == 0:
        return out
    f_u = k / (len(tu) * dt)
    out["undulation_frequency_hz"] = float(f_u)
    Y = (y * np.exp(-2j * math.pi * f_u * tu)[:, None]).sum(axis=0)
    phi = np.unwrap(np.angle(Y))
    # each segment's distance from the head along the body [BL]: the centres' spacing, averaged over the samples
    gaps = np.linalg.norm(np.diff(centres, axis=1), axis=2).mean(axis=0)
    s = np.concatenate([[0.0], np.cumsum(gaps)]) / body_length_m
    slope, phi0 = np.polyfit(s, phi, 1)
    kk = -slope
    if abs(kk) > 1e-9:
        out["undulation_wavelength_bl"] = float(2.0 * math.pi / abs(kk))
        out["undulation_direction"] = 1.0 if kk > 0 else -1.0
    if leg_stance_onsets_s is not None and len(leg_stance_onsets_s):
        th = 2.0 * math.pi * f_u * np.asarray(leg_stance_onsets_s, float) + phi[0] + 0.5 * math.pi
        out["undulation_leg_phase_rad"] = float(np.angle(np.mean(np.exp(1j * th))) % (2.0 * math.pi))
    return out
