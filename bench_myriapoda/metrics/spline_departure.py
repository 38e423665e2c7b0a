"""How a bending body departs from a spline-following kinematic snake: ``tail_swing_ratio``, ``sideways_slip_ratio``.

Miller (1988, Sec. 4) describes his dynamic snake by what it adds over a kinematic one whose every segment follows
the path of the head (a spline): the tail, not laterally constrained, swishes from side to side, and segments slide
sideways when grip is poor or the coil's amplitude changes.  A kinematic snake moves every point of its centre line
along the same curve, tangentially.  Two figures measure the departures, on the recorded centre line projected on
the ground (x, z; y up) over the steady window (``locomotion.measurement_window``):

* ``tail_swing_ratio`` [-]: the RMS lateral excursion of the tail (the last recorded centre) over that of the
  mid-body (the median over the middle third of the centres).  The lateral coordinate of a point is its position across the mean body axis of the window
  (``body_shape.axis_angle``, averaged), less a straight line fitted over the window (the travel and a slow
  drift).  On a kinematic snake every point traces the same curve, so over whole cycles the ratio is 1; a tail
  that swishes wider than the body reads above 1, a tail dragged straight below 1.
* ``sideways_slip_ratio`` [-]: RMS over the window and the interior centre-line points (one segment pitch apart,
  ``body_shape.pitch_stride``) of the ground velocity across the local centre line, over the RMS ground speed of
  the same points.  The velocity is the centred difference of successive samples, the tangent the chord between
  the point's neighbours.  0 for a body that moves along itself (a kinematic snake, a train on a track); 1 for
  one that moves straight across itself.

Both are NaN with fewer than 3 samples or 5 points in the window, or a mid-body that does not move laterally.
"""
from __future__ import annotations

import numpy as np

from ..core.series import Series
from .body_shape import axis_angle, pitch_stride


def _lateral_rms(points: np.ndarray, t: np.ndarray, across: np.ndarray) -> np.ndarray:
    """RMS over time [m] of each point's coordinate along ``across`` (2,), less a line fitted in time.
    points: (T, n, 2) ground positions [m]; t: (T,) [s]."""
    y = points @ across  # (T, n)
    basis = np.column_stack([np.ones_like(t), t - t.mean()])
    coef, *_ = np.linalg.lstsq(basis, y, rcond=None)
    return np.sqrt(np.mean((y - basis @ coef) ** 2, axis=0))


def tail_swing_ratio(series: Series, i0: int, i1: int) -> float:
    """RMS lateral excursion of the tail over the mid-body's (the median over the middle third of the centres) over
    samples [i0, i1] (module docstring) [-]."""
    c = series.segment_centers
    if c is None or c.shape[1] < 5 or i1 - i0 < 2:
        return float("nan")
    win = c[i0:i1 + 1]
    ang = float(np.mean(axis_angle(win)))
    # the axis angle is right-handed about +y from +x: axis (cos, -sin) in (x, z); across it: (sin, cos)
    across = np.array([np.sin(ang), np.cos(ang)])
    n = c.shape[1]
    rms = _lateral_rms(win[..., [0, 2]], series.t[i0:i1 + 1], across)
    mid = float(np.median(rms[n // 3:n - n // 3]))  # the middle third: one centre may sit at a node of the wave
    return float(rms[-1] / mid) if mid > 0 else float("nan")


def sideways_slip_ratio(series: Series, i0: int, i1: int, pitch_m: float | None = None) -> float:
    """RMS ground velocity across the local centre line over the RMS ground speed, over the interior points one
    pitch apart and samples [i0, i1] (module docstring) [-].  pitch_m: the segment pitch [m] (None: every centre)."""
    c = series.segment_centers
    if c is None or i1 - i0 < 2:
        return float("nan")
    if pitch_m is not None and pitch_m > 0:
        c = c[:, ::pitch_stride(c[0], pitch_m)]
    if c.shape[1] < 5:
        return float("nan")
    p = c[i0:i1 + 1][..., [0, 2]]
    t = series.t[i0:i1 + 1]
    v = (p[2:] - p[:-2]) / (t[2:] - t[:-2])[:, None, None]  # (T - 2, n, 2) at the middle samples
    tangent = p[1:-1, :-2] - p[1:-1, 2:]  # at the interior points, head-ward
    norm = np.linalg.norm(tangent, axis=2, keepdims=True)
    tangent = tangent / np.where(norm > 0, norm, 1.0)
    vi = v[:, 1:-1]
    v_across = vi[..., 0] * tangent[..., 1] - vi[..., 1] * tangent[..., 0]
    speed2 = float(np.mean(np.sum(vi * vi, axis=2)))
    return float(np.sqrt(np.mean(v_across ** 2) / speed2)) if speed2 > 0 else float("nan")


def spline_departure_metrics(series: Series, i0: int, i1: int, pitch_m: float | None = None) -> dict[str, float]:
    """tail_swing_ratio and sideways_slip_ratio over samples [i0, i1] (module docstring)."""
    return {"tail_swing_ratio": tail_swing_ratio(series, i0, i1),
            "sideways_slip_ratio": sideways_slip_ratio(series, i0, i1, pitch_m)}
