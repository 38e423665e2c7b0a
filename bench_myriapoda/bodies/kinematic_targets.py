"""Moving supported rigid segments to their target poses (paper Sec. 4.1).

A supported segment is "kinematically transported to the desired position and
orientation by the legs": its pose becomes the Targeter's target and its
velocities the finite differences that take it there in one step, so that
whatever is attached to it (FEM nodes, springs) sees a consistent motion.
"""
from __future__ import annotations

import math

from numba import njit


@njit(cache=True, error_model="numpy")
def matrix_to_quaternion(R, q):
    """Overwrite q (4,) (w, x, y, z) with the unit quaternion of rotation matrix R (3, 3) (Shepperd's method)."""
    tr = R[0, 0] + R[1, 1] + R[2, 2]
    if tr > 0.0:
        s = 2.0 * math.sqrt(tr + 1.0)
        q[0], q[1], q[2], q[3] = 0.25 * s, (R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s
    elif R[0, 0] > R[1, 1] and R[0, 0] > R[2, 2]:
        s = 2.0 * math.sqrt(1.0 + R[0, 0] - R[1, 1] - R[2, 2])
        q[0], q[1], q[2], q[3] = (R[2, 1] - R[1, 2]) / s, 0.25 * s, (R[0, 1] + R[1, 0]) / s, (R[0, 2] + R[2, 0]) / s
    elif R[1, 1] > R[2, 2]:
        s = 2.0 * math.sqrt(1.0 + R[1, 1] - R[0, 0] - R[2, 2])
        q[0], q[1], q[2], q[3] = (R[0, 2] - R[2, 0]) / s, (R[0, 1] + R[1, 0]) / s, 0.25 * s, (R[1, 2] + R[2, 1]) / s
    else:
        s = 2.0 * math.sqrt(1.0 + R[2, 2] - R[0, 0] - R[1, 1])
        q[0], q[1], q[2], q[3] = (R[1, 0] - R[0, 1]) / s, (R[0, 2] + R[2, 0]) / s, (R[1, 2] + R[2, 1]) / s, 0.25 * s
    n = math.sqrt(q[0] ** 2 + q[1] ** 2 + q[2] ** 2 + q[3] ** 2)
    if q[0] < 0.0:
        n = -n  # keep w >= 0 so consecutive poses do not flip sign
    for k in range(4):
        q[k] /= n


@njit(cache=True, error_model="numpy")
def drive_to_targets(c, q, v, w, R, kinematic, c_T, R_T, dt, qtmp):
    """For kinematic segments: pose <- target, v = (c_T - c) / dt, w = log(R_T R^T) / dt.

    c (n, 3) [m], q (n, 4), v (n, 3) [m/s], w (n, 3) [rad/s]: rigid state, updated
    in place for kinematic segments only; R (n, 3, 3): their current rotations;
    c_T, R_T: targets; qtmp (4,) scratch.
    """
    for i in range(c.shape[0]):
        if not kinematic[i]:
            continue
        # relative rotation D = R_T R^T, its axis-angle / dt is the angular velocity (world frame)
        d00 = d01 = d02 = d10 = d11 = d12 = d20 = d21 = d22 = 0.0
        for k in range(3):
            d00 += R_T[i, 0, k] * R[i, 0, k]
            d01 += R_T[i, 0, k] * R[i, 1, k]
            d02 += R_T[i, 0, k] * R[i, 2, k]
            d10 += R_T[i, 1, k] * R[i, 0, k]
            d11 += R_T[i, 1, k] * R[i, 1, k]
            d12 += R_T[i, 1, k] * R[i, 2, k]
            d20 += R_T[i, 2, k] * R[i, 0, k]
            d21 += R_T[i, 2, k] * R[i, 1, k]
            d22 += R_T[i, 2, k] * R[i, 2, k]
        cos_a = max(-1.0, min(1.0, 0.5 * (d00 + d11 + d22 - 1.0)))
        angle = math.acos(cos_a)
        ax, ay, az = d21 - d12, d02 - d20, d10 - d01
        sin2 = math.sqrt(ax * ax + ay * ay + az * az)  # = 2 sin(angle)
        scale = angle / (sin2 * dt) if sin2 > 1e-12 else 0.5 / dt
        w[i, 0], w[i, 1], w[i, 2] = ax * scale, ay * scale, az * scale
        for k in range(3):
            v[i, k] = (c_T[i, k] - c[i, k]) / dt
            c[i, k] = c_T[i, k]
        matrix_to_quaternion(R_T[i], qtmp)
        for k in range(4):
            q[i, k] = qtmp[k]
