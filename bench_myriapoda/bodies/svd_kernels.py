"""Numba kernels of the signed 3x3 singular value decomposition and the polar rotation, shared by the bodies.

The FEM's corotational elements (``fem.kernels``) take the rotation of each tet's deformation gradient
from it, and ``segment_frames`` the best-fit rotation of a deformable segment's nodes; neither body owns
it, so it lives here (issue 42: a shared ``bodies/`` module imports no specific body).

``svd3_core`` is a 3x3 SVD in scalar registers: cyclic Jacobi on the symmetric
F^T F (exact rotations, run to convergence), columns sorted by singular value with
det V = +1 kept, then U from a Gram-Schmidt QR of F V with u3 = u1 x u2 (McAdams
et al. 2011, Sec. 2, with exact Givens in float64 instead of approximate ones).
U and V are proper rotations and the smallest singular value carries the sign of
det F (Irving et al. 2004, Stomakhin et al. 2012), so R = U V^T is the rotation of
the fixed corotational model, also for flat and inverted elements.

All kernels use ``error_model="numpy"`` (as ``fem.kernels``): a division by zero gives inf/nan instead of a
Python exception.  Matrices are float64; ``Mat3`` and ``SVD3`` are the named records (issue 42: no
positional packs) that the inlined helpers pass in registers inside compiled code.
"""
from __future__ import annotations

import math
from collections import namedtuple

from numba import njit

# Jacobi sweeps: a pair (p, q) is rotated while |a_pq| exceeds both a relative
# bound (gives relative accuracy of the eigenvalues, Demmel-Veselic) and an absolute
# floor relative to trace(F^T F) (stops rotating on round-off in flat elements).
_JACOBI_REL_TOL = 1e-15
_JACOBI_ABS_FLOOR = 1e-30
_JACOBI_MAX_SWEEPS = 12
# Gram-Schmidt: a column shorter than this fraction of the first is treated as
# zero (rank-deficient F); its direction is then chosen, not computed.
_QR_REL_TINY = 1e-14
_QR_ABS_TINY = 1e-150

# A 3x3 matrix, row-major (m01: row 0, column 1).
Mat3 = namedtuple("Mat3", "m00 m01 m02 m10 m11 m12 m20 m21 m22")
# ``svd3_core``'s signed SVD F = U diag(s0, s1, s2) V^T: U, V Mat3 proper rotations, s0 >= s1 >= |s2|.
SVD3 = namedtuple("SVD3", "U s0 s1 s2 V")

@njit(cache=True, inline="always", error_model="numpy")
def _jacobi_cs(app, aqq, apq):
    """Rotation (c, s, t) that zeroes a_pq of a symmetric matrix (Numerical Recipes 11.1)."""
    theta = (aqq - app) / (2.0 * apq)
    if abs(theta) > 1e150:
        t = 0.5 / theta
    else:
        t = 1.0 / (abs(theta) + math.sqrt(theta * theta + 1.0))
        if theta < 0.0:
            t = -t
    c = 1.0 / math.sqrt(t * t + 1.0)
    return c, t * c, t


@njit(cache=True, inline="always", error_model="numpy")
def _needs_rotation(app, aqq, apq, floor):
    g = abs(apq)
    return g > floor and g > _JACOBI_REL_TOL * math.sqrt(abs(app * aqq))


@njit(cache=True, error_model="numpy")
def svd3_core(f00, f01, f02, f10, f11, f12, f20, f21, f22):
    """Signed SVD F = U diag(s) V^T of a 3x3 matrix held in scalars.

    Returns an ``SVD3`` record: U, V (``Mat3``) proper rotations, s0 >= s1 >= |s2|, s2 < 0 iff det F < 0.
    """
    # S = F^T F
    a00 = f00 * f00 + f10 * f10 + f20 * f20
    a01 = f00 * f01 + f10 * f11 + f20 * f21
    a02 = f00 * f02 + f10 * f12 + f20 * f22
    a11 = f01 * f01 + f11 * f11 + f21 * f21
    a12 = f01 * f02 + f11 * f12 + f21 * f22
    a22 = f02 * f02 + f12 * f12 + f22 * f22
    v00, v01, v02 = 1.0, 0.0, 0.0
    v10, v11, v12 = 0.0, 1.0, 0.0
    v20, v21, v22 = 0.0, 0.0, 1.0

    floor = _JACOBI_ABS_FLOOR * (a00 + a11 + a22)
    for _sweep in range(_JACOBI_MAX_SWEEPS):
        rotated = False
        # Deliberately unrolled: the three pairs' rotations are written out one after another on scalars in
        # registers (``duplicates`` pairs their alike blocks; a loop over the pairs would index arrays).
        # pair (0, 1); the third index r = 2
        if _needs_rotation(a00, a11, a01, floor):
            c, s, t = _jacobi_cs(a00, a11, a01)
            a00 -= t * a01
            a11 += t * a01
            a01 = 0.0
            r0 = c * a02 - s * a12
            r1 = s * a02 + c * a12
            a02 = r0
            a12 = r1
            r0 = c * v00 - s * v01
            v01 = s * v00 + c * v01
            v00 = r0
            r0 = c * v10 - s * v11
            v11 = s * v10 + c * v11
            v10 = r0
            r0 = c * v20 - s * v21
            v21 = s * v20 + c * v21
            v20 = r0
            rotated = True
        # pair (0, 2); r = 1 (unrolled, as pair (0, 1))
        if _needs_rotation(a00, a22, a02, floor):
            c, s, t = _jacobi_cs(a00, a22, a02)
            a00 -= t * a02
            a22 += t * a02
            a02 = 0.0
            r0 = c * a01 - s * a12
            r1 = s * a01 + c * a12
            a01 = r0
            a12 = r1
            r0 = c * v00 - s * v02
            v02 = s * v00 + c * v02
            v00 = r0
            r0 = c * v10 - s * v12
            v12 = s * v10 + c * v12
            v10 = r0
            r0 = c * v20 - s * v22
            v22 = s * v20 + c * v22
            v20 = r0
            rotated = True
        # pair (1, 2); r = 0 (unrolled, as pair (0, 1))
        if _needs_rotation(a11, a22, a12, floor):
            c, s, t = _jacobi_cs(a11, a22, a12)
            a11 -= t * a12
            a22 += t * a12
            a12 = 0.0
            r0 = c * a01 - s * a02
            r1 = s * a01 + c * a02
            a01 = r0
            a02 = r1
            r0 = c * v01 - s * v02
            v02 = s * v01 + c * v02
            v01 = r0
            r0 = c * v11 - s * v12
            v12 = s * v11 + c * v12
            v11 = r0
            r0 = c * v21 - s * v22
            v22 = s * v21 + c * v22
            v21 = r0
            rotated = True
        if not rotated:
            break

    # Sort eigenvalues of F^T F descending; a column swap is paired with a sign
    # flip of one column so that det V stays +1.
    if a00 < a11:
        a00, a11 = a11, a00
        v00, v01 = -v01, v00
        v10, v11 = -v11, v10
        v20, v21 = -v21, v20
    if a00 < a22:
        a00, a22 = a22, a00
        v00, v02 = -v02, v00
        v10, v12 = -v12, v10
        v20, v22 = -v22, v20
    if a11 < a22:
        a11, a22 = a22, a11
        v01, v02 = -v02, v01
        v11, v12 = -v12, v11
        v21, v22 = -v22, v21

    # B = F V; its columns are orthogonal with norms sigma_i.
    b00 = f00 * v00 + f01 * v10 + f02 * v20
    b10 = f10 * v00 + f11 * v10 + f12 * v20
    b20 = f20 * v00 + f21 * v10 + f22 * v20
    b01 = f00 * v01 + f01 * v11 + f02 * v21
    b11 = f10 * v01 + f11 * v11 + f12 * v21
    b21 = f20 * v01 + f21 * v11 + f22 * v21
    b02 = f00 * v02 + f01 * v12 + f02 * v22
    b12 = f10 * v02 + f11 * v12 + f12 * v22
    b22 = f20 * v02 + f21 * v12 + f22 * v22

    # QR of B by Gram-Schmidt with u2 = u0 x u1 (so det U = +1 and the sign of
    # det F lands on the smallest singular value).
    n0 = math.sqrt(b00 * b00 + b10 * b10 + b20 * b20)
    if n0 > _QR_ABS_TINY:
        u00 = b00 / n0
        u10 = b10 / n0
        u20 = b20 / n0
    else:
        u00 = 1.0
        u10 = 0.0
        u20 = 0.0
    d = u00 * b01 + u10 * b11 + u20 * b21
    w0 = b01 - d * u00
    w1 = b11 - d * u10
    w2 = b21 - d * u20
    n1 = math.sqrt(w0 * w0 + w1 * w1 + w2 * w2)
    if n1 > _QR_REL_TINY * n0 and n1 > _QR_ABS_TINY:
        u01 = w0 / n1
        u11 = w1 / n1
        u21 = w2 / n1
    else:
        # Rank <= 1: any unit vector orthogonal to u0 will do; take u0 x e_k with
        # e_k the axis least aligned with u0.
        ax = abs(u00)
        ay = abs(u10)
        az = abs(u20)
        if ax <= ay and ax <= az:
            w0, w1, w2 = 0.0, u20, -u10
        elif ay <= az:
            w0, w1, w2 = -u20, 0.0, u00
        else:
            w0, w1, w2 = u10, -u00, 0.0
        nw = math.sqrt(w0 * w0 + w1 * w1 + w2 * w2)
        u01 = w0 / nw
        u11 = w1 / nw
        u21 = w2 / nw
        if u01 * b01 + u11 * b11 + u21 * b21 < 0.0:
            u01 = -u01
            u11 = -u11
            u21 = -u21
    u02 = u10 * u21 - u20 * u11
    u12 = u20 * u01 - u00 * u21
    u22 = u00 * u11 - u10 * u01
    sg0 = u00 * b00 + u10 * b10 + u20 * b20
    sg1 = u01 * b01 + u11 * b11 + u21 * b21
    sg2 = u02 * b02 + u12 * b12 + u22 * b22
    return SVD3(U=Mat3(u00, u01, u02, u10, u11, u12, u20, u21, u22), s0=sg0, s1=sg1, s2=sg2,
                V=Mat3(v00, v01, v02, v10, v11, v12, v20, v21, v22))


@njit(cache=True, inline="always", error_model="numpy")
def u_vt(svd):
    """R = U V^T of an ``SVD3`` (``Mat3``): r_ij = u_i0 v_j0 + u_i1 v_j1 + u_i2 v_j2, summed left to right."""
    U, V = svd.U, svd.V
    return Mat3(U.m00 * V.m00 + U.m01 * V.m01 + U.m02 * V.m02,
                U.m00 * V.m10 + U.m01 * V.m11 + U.m02 * V.m12,
                U.m00 * V.m20 + U.m01 * V.m21 + U.m02 * V.m22,
                U.m10 * V.m00 + U.m11 * V.m01 + U.m12 * V.m02,
                U.m10 * V.m10 + U.m11 * V.m11 + U.m12 * V.m12,
                U.m10 * V.m20 + U.m11 * V.m21 + U.m12 * V.m22,
                U.m20 * V.m00 + U.m21 * V.m01 + U.m22 * V.m02,
                U.m20 * V.m10 + U.m21 * V.m11 + U.m22 * V.m12,
                U.m20 * V.m20 + U.m21 * V.m21 + U.m22 * V.m22)


@njit(cache=True, inline="always", error_model="numpy")
def mat3_of(A):
    """The (3, 3) array A as a ``Mat3``."""
    return Mat3(A[0, 0], A[0, 1], A[0, 2], A[1, 0], A[1, 1], A[1, 2], A[2, 0], A[2, 1], A[2, 2])


@njit(cache=True, inline="always", error_model="numpy")
def mat3_into(M, A):
    """Write the ``Mat3`` M into the (3, 3) array A (overwritten)."""
    A[0, 0] = M.m00
    A[0, 1] = M.m01
    A[0, 2] = M.m02
    A[1, 0] = M.m10
    A[1, 1] = M.m11
    A[1, 2] = M.m12
    A[2, 0] = M.m20
    A[2, 1] = M.m21
    A[2, 2] = M.m22


@njit(cache=True, error_model="numpy")
def svd3(F, U, sigma, V):
    """Signed SVD of one 3x3 matrix: F = U diag(sigma) V^T.

    F: (3, 3).  Overwrites U: (3, 3), sigma: (3,), V: (3, 3).  U and V are proper
    rotations; sigma[0] >= sigma[1] >= |sigma[2]| and sigma[2] < 0 iff det F < 0.
    """
    r = svd3_core(F[0, 0], F[0, 1], F[0, 2], F[1, 0], F[1, 1], F[1, 2], F[2, 0], F[2, 1], F[2, 2])
    mat3_into(r.U, U)
    mat3_into(r.V, V)
    sigma[0] = r.s0
    sigma[1] = r.s1
    sigma[2] = r.s2


@njit(cache=True, error_model="numpy")
def svd3_batch(F, U, sigma, V):
    """Signed SVD of many 3x3 matrices.  F: (k, 3, 3); overwrites U, V: (k, 3, 3), sigma: (k, 3)."""
    for e in range(F.shape[0]):
        svd3(F[e], U[e], sigma[e], V[e])


@njit(cache=True, error_model="numpy")
def polar_rotation(F, R):
    """Rotation of the signed polar decomposition, R = U V^T (det R = +1).

    F: (3, 3); overwrites R: (3, 3).  For det F > 0 this is the polar factor of
    F = R S; for inverted F it is the rotation closest to F (the inversion is
    carried by S, Irving et al. 2004).
    """
    mat3_into(u_vt(svd3_core(F[0, 0], F[0, 1], F[0, 2], F[1, 0], F[1, 1], F[1, 2], F[2, 0], F[2, 1], F[2, 2])), R)
