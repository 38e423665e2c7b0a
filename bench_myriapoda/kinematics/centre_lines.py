"""Curvature of a body's centre line on the ground.

Here, in the kinematics layer, because both a body's calibration (``bodies.curvature_calibration``, which
identifies the open loop's response) and the shape metrics (``metrics.body_shape``, which re-exports it) measure
the same curvature, and the bodies sit below the metrics."""
from __future__ import annotations

import math

import numpy as np
from numba import njit


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


@njit(cache=True)
def ground_bend(centers, scale, out):
    """``scale`` x :func:`ground_curvature` of one centre line, into ``out`` (n - 2,), in one compiled call.

    centers: (n, 3) [m], head first; scale: e.g. [strain per 1/m].  The same operations in the same order as
    ``ground_curvature`` (to an ulp: numpy's array arctan2 may be a SIMD one); for the shape tracker's guard, which reads the bend every control
    tick, where the numpy version's call overhead cost 13 % of the lattice snake's throughput (``regress``)."""
    for i in range(centers.shape[0] - 2):
        ax = centers[i + 1, 0] - centers[i, 0]
        az = centers[i + 1, 2] - centers[i, 2]
        bx = centers[i + 2, 0] - centers[i + 1, 0]
        bz = centers[i + 2, 2] - centers[i + 1, 2]
        cross = -(ax * bz - az * bx)
        dot = 0.0 + ax * bx + az * bz  # numpy's sum starts at +0.0: the same sign of a zero dot (atan2's branch)
        mean_len = 0.5 * (math.sqrt(ax * ax + az * az) + math.sqrt(bx * bx + bz * bz))
        kappa = math.atan2(cross, dot) / mean_len if mean_len > 0 else 0.0
        out[i] = scale * kappa
