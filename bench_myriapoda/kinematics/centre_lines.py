"""Curvature of a body's centre line on the ground.

Here, in the kinematics layer, because both a body's calibration (``bodies.curvature_calibration``, which
identifies the open loop's response) and the shape metrics (``metrics.body_shape``, which re-exports it) measure
the same curvature, and the bodies sit below the metrics."""
from __future__ import annotations

import numpy as np


def ground_curvature(centers: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Signed curvature [1/m] of the ground projection of centre lines.

    centers: (T, n, 3) [m], head first.  Returns (kappa (T, n - 2) at the interior points, positive
    when the line, walked from head to tail, turns left seen from above; chord lengths (T, n - 1) [m]).
    """
    p = centers[..., [0, 2]]
    c = np.diff(p, axis=1)  # head -> tail chords
    ln = np.linalg.norm(c, axis=2)
    a, b = c[:, :-1], c[:, 1:]
    # seen from above (from +y) with x right, the left turn is a negative x-z cross product
    cross = -(a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0])
    dot = (a * b).sum(axis=2)
    turn = np.arctan2(cross, dot)
    mean_len = 0.5 * (ln[:, :-1] + ln[:, 1:])
    return turn / np.where(mean_len > 0, mean_len, np.inf), ln
