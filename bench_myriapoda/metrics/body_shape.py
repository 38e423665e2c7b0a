"""Measured shape kinematics of a legless body, from the recorded segment centres.

Every figure is measured on the centre line of ``Series.segment_centers`` (head first), projected
on the ground plane (x, z; y is up), over the steady window (``locomotion.measurement_window``):

* ``curvature_amplitude``: peak curvature x body length, read through centres one segment pitch apart
  (``pitch_stride``: the hybrid's boxes, not its links).  The signed discrete curvature at each
  interior centre is its turning angle over the mean of the two adjacent chords; its amplitude at
  one point is sqrt(2) x its RMS over the window (the peak of a sine of that RMS, robust to noise
  where a maximum is not); the figure is the median over the interior points (the ends of a free
  body bend less), times the body length.
* ``body_wavelength_bl``: wavelength of the curvature wave along the body, in body lengths: the
  phase of each point's curvature at the gait frequency (one Fourier coefficient over the
  window) grows by 2 pi per wavelength of rest arc length.  NaN when the curvature amplitude is
  below ``MIN_AMPLITUDE_FOR_WAVELENGTH`` (a straight body, e.g. a worm, has no bending wave).
* ``heading_drift_deg_per_cycle``: rotation of the mean body axis (mean of the unit chords,
  toward the head) per gait period, from a least-squares line through its unwrapped angle over
  the window (so the axis's oscillation within a cycle averages out).  Positive: turning left
  (counter-clockwise seen from above), as the slithering reference's angular velocity.
"""
from __future__ import annotations

import math

import numpy as np

from ..core.series import Series
from ..kinematics.centre_lines import ground_curvature  # noqa: F401 (this module's measure, defined below the bodies)

MIN_AMPLITUDE_FOR_WAVELENGTH = 0.5  # curvature x body length below which no wavelength is measured


def axis_angle(centers: np.ndarray) -> np.ndarray:
    """Unwrapped angle [rad] of the mean body axis on the ground, right-handed about +y (left turn
    positive): (T,) from centres (T, n, 3), head first."""
    c = centers[:, :-1] - centers[:, 1:]  # tail -> head chords
    ln = np.linalg.norm(c, axis=2, keepdims=True)
    d = (c / np.where(ln > 0, ln, 1.0)).mean(axis=1)
    return np.unwrap(np.arctan2(-d[:, 2], d[:, 0]))


def pitch_stride(centers0: np.ndarray, pitch_m: float) -> int:
    """Every how many recorded centres one segment pitch is: 1, or 2 for a body listing two centres per pitch
    (the hybrid: box, link, box, ...).  centers0: (n, 3) [m] at one instant; pitch_m: the segment pitch [m]."""
    chord = np.linalg.norm(np.diff(centers0, axis=0), axis=1)
    med = float(np.median(chord)) if len(chord) else 0.0
    return max(1, int(round(pitch_m / med))) if med > 0 else 1


def body_shape_metrics(series: Series, i0: int, i1: int, period_s: float, body_length_m: float,
                       pitch_m: float | None = None) -> dict[str, float]:
    """curvature_amplitude, body_wavelength_bl, heading_drift_deg_per_cycle over samples [i0, i1].

    pitch_m: the segment pitch [m]; given, the centre line is read through points one pitch apart
    (``pitch_stride``).  A body whose centres alternate between two kinds bends unevenly between them: the
    hybrid's links bend and its boxes do not, and the three-point curvature through all its centres
    alternated between 8.2 and 5.8 at a commanded 7 (mu_t / mu_f = 1.5), the median reading 8.1, where its
    boxes, one pitch apart, read 7.04 (issue 27).  None: every centre (a bare series of points)."""
    out = {"curvature_amplitude": float("nan"), "body_wavelength_bl": float("nan"),
           "heading_drift_deg_per_cycle": float("nan")}
    centers = series.segment_centers
    if centers is None or centers.shape[1] < 4 or i1 - i0 < 2:
        return out
    if pitch_m is not None and pitch_m > 0:
        centers = centers[:, ::pitch_stride(centers[0], pitch_m)]
        if centers.shape[1] < 4:
            return out
    win = centers[i0:i1 + 1]
    t = series.t[i0:i1 + 1]
    kappa, _ = ground_curvature(win)
    amp_pts = math.sqrt(2.0) * np.sqrt((kappa ** 2).mean(axis=0))
    amp = float(np.median(amp_pts) * body_length_m)
    out["curvature_amplitude"] = amp

    if amp >= MIN_AMPLITUDE_FOR_WAVELENGTH:
        # rest arc length of the interior points from the first sample's chords, in body lengths
        _, ln0 = ground_curvature(centers[:1])
        s = np.concatenate([[0.0], np.cumsum(ln0[0])])[1:-1] / body_length_m
        coef = (kappa * np.exp(2j * math.pi * t / period_s)[:, None]).mean(axis=0)
        strong = np.abs(coef) > 0.2 * np.abs(coef).max()
        # a body off the ground plane (hanging straight down) has zero-length ground chords: no wave to fit
        if (strong.sum() >= 3 and np.all(np.isfinite(s[strong])) and np.all(np.isfinite(coef[strong]))
                and np.ptp(s[strong]) > 1e-9):
            phase = np.unwrap(np.angle(coef[strong]))
            slope = np.polyfit(s[strong], phase, 1)[0]
            if abs(slope) > 1e-9:
                out["body_wavelength_bl"] = float(2.0 * math.pi / abs(slope))

    psi = axis_angle(win)
    if t[-1] > t[0] and np.all(np.isfinite(psi)):
        rate = np.polyfit(t - t[0], psi, 1)[0]  # rad/s
        out["heading_drift_deg_per_cycle"] = float(math.degrees(rate * period_s))
    return out
