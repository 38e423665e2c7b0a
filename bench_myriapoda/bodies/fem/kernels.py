"""Numba kernels of the tetrahedral FEM of the myriapod paper (Fang et al. 2013, App. A).

Every kernel is a pure function over arrays with explicit outputs; each docstring
says whether an output is overwritten or accumulated into.  Orchestration (building
the factorization, caching it per fixed-node mask, status bookkeeping) lives in
``system.py``.  All kernels use ``error_model="numpy"``: a division by zero gives
inf/nan (caught by the instability check) instead of a Python exception, and the
checks that the Python error model inserts would stop LLVM from vectorising.

Conventions
-----------
* Arrays are float64 (indices int64) and C-contiguous.  ``x``: (n_nodes, 3) [m],
  ``v``: (n_nodes, 3) [m/s], ``tets``: (n_tets, 4) node indices,
  ``Dm_inv``: (n_tets, 3, 3) [1/m], ``vol``: (n_tets,) rest volumes [m^3],
  ``mu``, ``lam``: (n_tets,) Lame parameters [Pa].
* Edge matrices use Dm = [X1 - X0, X2 - X0, X3 - X0] (columns).  Eq. 3 lists the
  same edges in the reverse column order; that only permutes the local node
  numbering.  Meshes are oriented so that det Dm > 0 (see ``mesh.py``).
* Forces are minus the energy gradient.  Eq. 9 of the paper writes the gradient
  V0 P Dm^-T; the force on the nodes is its negative.
* The hot element loop works on blocked structure-of-arrays scratch so that LLVM
  vectorises it: tets are grouped in blocks of ``LANES``; a per-tet quantity with
  k entries is stored as an array (n_blocks, k * LANES) where entry r of tet
  e = b * LANES + l sits at [b, r * LANES + l].  (With one row per entry and
  all tets in a row, the row offsets are run-time values and LLVM gives up:
  "too many memory checks needed"; inside a block they are constants.)  Arrays:
  ``coef`` (n_blocks, N_COEF LANES) packs -V Dm^-1 (entry (r, c) in row 3 r + c),
  2 mu (row 9), lam (row 10) and Dm^-1 itself (entry (r, c) in row 11 + 3 r + c),
  built by ``pack_tet_coefficients``; ``q_ws``
  (n_blocks, N_Q LANES) each tet's rotation as a quaternion (w, x, y, z) in rows
  0-3 and its last increment (rows 4-6, below), kept between steps; ``F_work``
  (n_blocks, 9 LANES) and ``H_work`` (n_blocks, N_H LANES) are scratch: H rows
  3 k + i hold component i of the force on local node k + 1, rows 10 + i that on
  local node 0 (eq. 10: minus the sum of the other three), row 9 whether the
  rotation was accepted (0) or needs the fallback (inf).
  ``new_tet_workspace`` allocates them, with the padding lanes of the last
  block set to an inert identity tet.  ``node_incidence`` lists each node's
  entries of H, for ``elastic_forces_gathered``.

Active strain (muscles)
-----------------------
A per-tet active deformation A (rest-shape scaling) makes the elastic part of the
deformation F_e = F A^-1 = Ds Dm^-1 A^-1.  We represent it by an *effective*
inverse edge matrix ``Dm_inv_eff = Dm^-1 A^-1`` (built by ``active_dm_inv``) that
replaces ``Dm_inv`` in every kernel (and in ``coef``), while ``vol`` stays the
rest volume: the energy is integrated over the rest volume, sum_e V_e Psi(F_e).
Passive tets use A = I, i.e. ``Dm_inv_eff = Dm_inv``.  This costs nothing per
step; the body layer rebuilds ``Dm_inv_eff`` and ``coef`` when the activation
changes.

Singular value decomposition and the corotational rotation
----------------------------------------------------------
The signed 3x3 SVD ``svd3_core`` and R = U V^T of the fixed corotational model, also for
flat and inverted elements, are shared with the segment frames: ``bodies.svd_kernels``.

That SVD costs a few hundred ns per element, and a warm start does not help it:
near rest F^T F ~ I, so its eigenvectors are ill-defined and jump from step to
step.  The time step therefore gets R another way.  R = U V^T is the maximiser of
tr(R^T F) over SO(3) (Procrustes with the det constraint); it is unique whenever
sigma_2 + sigma_3 > 0, even where the singular vectors are not.  ``_newton_step_h``
is one Newton step of that maximisation in exponential coordinates,
R <- R exp([w]), w = -(tr(M) I - sym(M))^-1 axial(M - M^T), M = R^T F, applied to
a quaternion (q <- q (1, w/2)).  Started near the maximum it converges
quadratically.  The element pass starts each tet from a predicted rotation: its
rotation of the previous step times that step's increment (q (1, d), d the
half-angle vector of the increment, kept in ``q_ws`` rows 4-6), i.e. constant
angular velocity, so the start is off by the change of the tet's angular
velocity over one step.  It runs one Newton step for every tet, branch-free and
vectorised, and accepts it when twice the rotation error it leaves, estimated
as -2 (h^T H h) H^-1 h from the half step h and the Hessian H (the leading term,
third order in the step: ``_newton_step_h``), is below ``NEWTON_ERR`` (1e-12 rad).
A block of LANES tets with one not accepted takes a second step for all its
lanes, accepted by the same test.  (Until issue 13's third round the estimate
was a |h|^2 + |h|^3, a the anisotropy of the stretch: thousands of times the
error, which sent three quarters of the walking hybrid centipede's tets, whose
predictions miss by some 1e-5 rad, through the second step; now about one
block in 400 takes it.  The results differ at round-off level.)  (Until issue 13 the pass ran two steps from
the unpredicted previous rotation and accepted when the second was below
``NEWTON_TOL``, an error of order its square; this does about 80 fewer
multiplications per tet where one step is enough, and the results differ at
round-off level.)  The few tets that fail (Hessian not positive definite, i.e.
far from the maximum or sigma_2 + sigma_3 <= 0; a step above
``_NEWTON_MAX_STEP``; not yet converged) go through ``_fcr_rotation`` from the
previous rotation: more Newton steps, then the SVD.  The tests compare both
paths with numpy's SVD, including inverted F.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from bench_myriapoda.world.terrain_kernels import flat_ground, signed_distance, surface_normal

# the shared SVD; svd3, svd3_batch and polar_rotation are re-exported: the FEM's callers and tests name them here
from bench_myriapoda.bodies.svd_kernels import (  # noqa: F401
    Mat3, mat3_into, mat3_of, polar_rotation, svd3, svd3_batch, svd3_core, u_vt)

# Tets per block of the structure-of-arrays layout (a multiple of the SIMD width).
LANES = 16
# Rows of the blocked per-tet constants ``coef`` (module docstring).
COEF_TWO_MU = 9
COEF_LAM = 10
COEF_DM_INV = 11
N_COEF = 20
# Rows of the per-tet rotation state ``q_ws``: the quaternion (w, x, y, z) and the half-angle
# vector d of the last step's increment, q_new ~ q_old (1, d) (module docstring).
Q_D = 4
N_Q = 7
# Rows of the blocked per-tet scratch ``H_work`` (module docstring).
H_HH = 9
H_NODE0 = 10
N_H = 13

# Status codes returned by ``advance``.
STATUS_OK = 0
STATUS_NONFINITE = 1
STATUS_RUNAWAY = 2

# Newton rotation: accept after a step smaller than NEWTON_TOL [rad] (the error left
# is of order its square); a step above _NEWTON_MAX_STEP [rad] is not trusted, and
# after _NEWTON_MAX_ITER steps without convergence the SVD decides.
NEWTON_TOL = 1e-6
_NEWTON_MAX_ITER = 6
_NEWTON_MAX_STEP = 0.5
# Squared half-angle bounds used on the quaternion increment h = w / 2.
_NEWTON_TOL_HH = 0.25 * NEWTON_TOL * NEWTON_TOL
# The element pass accepts a Newton step when twice the rotation error it leaves, estimated from the
# half step h and the Hessian (``_newton_step_h``), is below NEWTON_ERR [rad] (the error the
# NEWTON_TOL rule bounds, of order its square); compared squared (no sqrt).
NEWTON_ERR = 1e-12
_NEWTON_ERR2 = NEWTON_ERR * NEWTON_ERR
_NEWTON_MAX_HH = 0.25 * _NEWTON_MAX_STEP * _NEWTON_MAX_STEP

# Named records of the per-tet helpers' scalars (issue 42: no positional packs).  They are built and read inside
# compiled code only, where numba keeps a namedtuple's fields in registers as it keeps a plain tuple's or single
# scalars: the same instructions in the same order, so the results are bit for bit those of the scalars.
# A quaternion (w, x, y, z), w the scalar part.
Quat = namedtuple("Quat", "w x y z")
# ``_newton_step_h``'s step: the new (unnormalised) quaternion (w, x, y, z), hh = |h|^2, ok, the half step
# (hx, hy, hz) and small (flat, so that its fields unpack as the scalars they are).
NewtonStep = namedtuple("NewtonStep", "w x y z hh ok hx hy hz small")
# ``_fcr_rotation``'s result: R (Mat3), q (Quat, unit) and n_iter (Newton steps, -1: the SVD decided).
FCRRotation = namedtuple("FCRRotation", "R q n_iter")
# ``_fcr_stress``'s result: the first Piola-Kirchhoff stress P (Mat3) [Pa] and J = det F.
FCRStress = namedtuple("FCRStress", "P J")


# --------------------------------------------------------------------------------------
# Corotational rotation by warm-started Newton iteration
# --------------------------------------------------------------------------------------
@njit(cache=True, inline="always", error_model="numpy")
def _quat_to_rot(w, x, y, z):
    """Rotation matrix (``Mat3``) of the quaternion (w, x, y, z).

    Homogeneous form: exact for any non-zero quaternion, so |q| need not be 1.
    """
    s = 2.0 / (w * w + x * x + y * y + z * z)
    xs = x * s
    ys = y * s
    zs = z * s
    wx = w * xs
    wy = w * ys
    wz = w * zs
    xx = x * xs
    xy = x * ys
    xz = x * zs
    yy = y * ys
    yz = y * zs
    zz = z * zs
    return Mat3(1.0 - (yy + zz), xy - wz, xz + wy,
                xy + wz, 1.0 - (xx + zz), yz - wx,
                xz - wy, yz + wx, 1.0 - (xx + yy))


@njit(cache=True, error_model="numpy")
def _rot_to_quat(r00, r01, r02, r10, r11, r12, r20, r21, r22):
    """Unit quaternion (``Quat``) of a rotation matrix given row-major (Shepperd's method)."""
    tr = r00 + r11 + r22
    if tr > 0.0:
        s = 2.0 * math.sqrt(tr + 1.0)
        w, x, y, z = 0.25 * s, (r21 - r12) / s, (r02 - r20) / s, (r10 - r01) / s
    elif r00 > r11 and r00 > r22:
        s = 2.0 * math.sqrt(1.0 + r00 - r11 - r22)
        w, x, y, z = (r21 - r12) / s, 0.25 * s, (r01 + r10) / s, (r02 + r20) / s
    elif r11 > r22:
        s = 2.0 * math.sqrt(1.0 + r11 - r00 - r22)
        w, x, y, z = (r02 - r20) / s, (r01 + r10) / s, 0.25 * s, (r12 + r21) / s
    else:
        s = 2.0 * math.sqrt(1.0 + r22 - r00 - r11)
        w, x, y, z = (r10 - r01) / s, (r02 + r20) / s, (r12 + r21) / s, 0.25 * s
    n = 1.0 / math.sqrt(w * w + x * x + y * y + z * z)
    return Quat(w * n, x * n, y * n, z * n)


@njit(cache=True, inline="always", error_model="numpy")
def _newton_step_h(f00, f01, f02, f10, f11, f12, f20, f21, f22, qw, qx, qy, qz):
    """One Newton step towards argmax_R tr(R^T F) from the rotation of q (module docstring).

    Branch-free so that loops over tets vectorise.  Returns a ``NewtonStep`` (q', hh, ok, h, small):
    the updated (unnormalised) quaternion q (1, h), h = w/2 the half step (3
    scalars), hh = |h|^2, ok = the Newton Hessian is positive definite and the step
    is below _NEWTON_MAX_STEP, and small = ok and twice the rotation error left
    after the step, estimated as below, is below NEWTON_ERR.  When not ok, q' and h
    are meaningless.

    The estimate.  With R exp([phi]) about the current R, the objective is exactly
    (Rodrigues) f(phi) = tr(exp(-[phi]) M) = tr M + (sin r / r) l.phi
    - ((1 - cos r) / r^2) phi^T H phi, r = |phi|, l the gradient at 0.  At the
    Newton step w = H^-1 l the gradient left is -(r^2 / 12) H w - (w^T H w) w / 4
    + O(r^5), so the optimum lies at w + e0, e0 = -(r^2 / 12) w - (w^T H w) H^-1 w / 4
    (relative corrections O(r^2)); q (1, h), h = w / 2, turns by 2 atan(r / 2)
    = r - r^3 / 12, which cancels the first term: the rotation error left is
    e = -(w^T H w) H^-1 w / 4 = -2 (h^T H h) H^-1 h, third order in the step,
    whatever the anisotropy (for an isotropic stretch |e| = 2 |h|^3 = r^3 / 4).
    Measured on 398 steps of the walking hybrid centipede (816 tets, against numpy's
    SVD): |e| matched the error left within 0.4 % wherever it exceeded 1e-13 rad
    (within 14 % above 1e-14, where the reference's round-off counts).
    """
    R = _quat_to_rot(qw, qx, qy, qz)
    # M = R^T F
    m00 = R.m00 * f00 + R.m10 * f10 + R.m20 * f20
    m01 = R.m00 * f01 + R.m10 * f11 + R.m20 * f21
    m02 = R.m00 * f02 + R.m10 * f12 + R.m20 * f22
    m10 = R.m01 * f00 + R.m11 * f10 + R.m21 * f20
    m11 = R.m01 * f01 + R.m11 * f11 + R.m21 * f21
    m12 = R.m01 * f02 + R.m11 * f12 + R.m21 * f22
    m20 = R.m02 * f00 + R.m12 * f10 + R.m22 * f20
    m21 = R.m02 * f01 + R.m12 * f11 + R.m22 * f21
    m22 = R.m02 * f02 + R.m12 * f12 + R.m22 * f22
    # gradient axial(M - M^T) and Hessian H = tr(M) I - sym(M)
    g0 = m12 - m21
    g1 = m20 - m02
    g2 = m01 - m10
    tr = m00 + m11 + m22
    h00 = tr - m00
    h11 = tr - m11
    h22 = tr - m22
    h01 = -0.5 * (m01 + m10)
    h02 = -0.5 * (m02 + m20)
    h12 = -0.5 * (m12 + m21)
    c00 = h11 * h22 - h12 * h12
    c01 = h02 * h12 - h01 * h22
    c02 = h01 * h12 - h02 * h11
    c11 = h00 * h22 - h02 * h02
    c12 = h01 * h02 - h00 * h12
    c22 = h00 * h11 - h01 * h01
    det = h00 * c00 + h01 * c01 + h02 * c02
    # half step h = w / 2 = -H^-1 g / 2
    k = -0.5 / det
    hx = k * (c00 * g0 + c01 * g1 + c02 * g2)
    hy = k * (c01 * g0 + c11 * g1 + c12 * g2)
    hz = k * (c02 * g0 + c12 * g1 + c22 * g2)
    hh = hx * hx + hy * hy + hz * hz
    ok = (h00 > 0.0) & (c22 > 0.0) & (det > 0.0) & (hh < _NEWTON_MAX_HH)
    # the error the step leaves, |e| = 2 |h.H h| |H^-1 h| (docstring), with H h = -g / 2 and
    # H^-1 h = C h / det: |e| = |h.g| |C h| / det; accepted when 2 |e| < NEWTON_ERR (squared, no sqrt)
    hg = hx * g0 + hy * g1 + hz * g2
    ux = c00 * hx + c01 * hy + c02 * hz
    uy = c01 * hx + c11 * hy + c12 * hz
    uz = c02 * hx + c12 * hy + c22 * hz
    small = ok & (4.0 * hg * hg * (ux * ux + uy * uy + uz * uz) < _NEWTON_ERR2 * det * det)
    nw = qw - (qx * hx + qy * hy + qz * hz)
    nx = qx + qw * hx + (qy * hz - qz * hy)
    ny = qy + qw * hy + (qz * hx - qx * hz)
    nz = qz + qw * hz + (qx * hy - qy * hx)
    return NewtonStep(w=nw, x=nx, y=ny, z=nz, hh=hh, ok=ok, hx=hx, hy=hy, hz=hz, small=small)


@njit(cache=True, inline="always", error_model="numpy")
def _renormalize(qw, qx, qy, qz):
    """Scale q towards unit length by one Newton step for 1/|q| (no sqrt).

    |q| only has to stay bounded (``_quat_to_rot`` is homogeneous); each Newton
    step multiplies |q|^2 by 1 + hh, and this correction removes that drift.
    """
    c = 1.5 - 0.5 * (qw * qw + qx * qx + qy * qy + qz * qz)
    return qw * c, qx * c, qy * c, qz * c


@njit(cache=True, error_model="numpy")
def _fcr_rotation(f00, f01, f02, f10, f11, f12, f20, f21, f22, qw, qx, qy, qz):
    """Rotation R = U V^T of the signed SVD of F: Newton from q, SVD fallback.

    (qw, qx, qy, qz): starting rotation (any non-zero quaternion; the previous
    step's is best).  Returns an ``FCRRotation`` (R, q, n_iter) with n_iter = -1 when
    the SVD fallback was used.
    """
    for it in range(_NEWTON_MAX_ITER):
        s = _newton_step_h(f00, f01, f02, f10, f11, f12, f20, f21, f22, qw, qx, qy, qz)
        if not s.ok:
            break
        qw, qx, qy, qz = _renormalize(s.w, s.x, s.y, s.z)
        if s.hh < _NEWTON_TOL_HH:
            return FCRRotation(R=_quat_to_rot(qw, qx, qy, qz), q=Quat(qw, qx, qy, qz), n_iter=it + 1)
    R = u_vt(svd3_core(f00, f01, f02, f10, f11, f12, f20, f21, f22))
    return FCRRotation(R=R, q=_rot_to_quat(R.m00, R.m01, R.m02, R.m10, R.m11, R.m12, R.m20, R.m21, R.m22),
                       n_iter=-1)


@njit(cache=True, error_model="numpy")
def fcr_rotation(F, q, R):
    """Corotational rotation of one F by warm-started Newton with SVD fallback.

    F: (3, 3); q: (4,) quaternion (w, x, y, z), the starting guess, OVERWRITTEN
    with the result; R: (3, 3) OVERWRITTEN.  Returns the number of Newton steps,
    or -1 if the SVD fallback was used.
    """
    r = _fcr_rotation(F[0, 0], F[0, 1], F[0, 2], F[1, 0], F[1, 1], F[1, 2], F[2, 0], F[2, 1], F[2, 2],
                      q[0], q[1], q[2], q[3])
    mat3_into(r.R, R)
    q[0] = r.q.w
    q[1] = r.q.x
    q[2] = r.q.y
    q[3] = r.q.z
    return r.n_iter


# --------------------------------------------------------------------------------------
# Rest shape, deformation gradient, active strain
# --------------------------------------------------------------------------------------
@njit(cache=True, error_model="numpy")
def rest_shape(X, tets, Dm_inv, vol):
    """Inverse rest edge matrices and signed rest volumes.

    X: (n_nodes, 3) rest positions [m]; tets: (n_tets, 4).  Overwrites
    Dm_inv: (n_tets, 3, 3) [1/m] with (X1-X0, X2-X0, X3-X0)^-1 (eq. 3) and
    vol: (n_tets,) [m^3] with det(Dm) / 6 (negative for a badly oriented tet; a
    zero-volume tet gives non-finite Dm_inv; callers check).
    """
    for e in range(tets.shape[0]):
        i0, i1, i2, i3 = tets[e, 0], tets[e, 1], tets[e, 2], tets[e, 3]
        a00 = X[i1, 0] - X[i0, 0]
        a10 = X[i1, 1] - X[i0, 1]
        a20 = X[i1, 2] - X[i0, 2]
        a01 = X[i2, 0] - X[i0, 0]
        a11 = X[i2, 1] - X[i0, 1]
        a21 = X[i2, 2] - X[i0, 2]
        a02 = X[i3, 0] - X[i0, 0]
        a12 = X[i3, 1] - X[i0, 1]
        a22 = X[i3, 2] - X[i0, 2]
        c00 = a11 * a22 - a12 * a21
        c01 = a12 * a20 - a10 * a22
        c02 = a10 * a21 - a11 * a20
        det = a00 * c00 + a01 * c01 + a02 * c02
        inv = 1.0 / det
        Dm_inv[e, 0, 0] = c00 * inv
        Dm_inv[e, 1, 0] = c01 * inv
        Dm_inv[e, 2, 0] = c02 * inv
        Dm_inv[e, 0, 1] = (a02 * a21 - a01 * a22) * inv
        Dm_inv[e, 1, 1] = (a00 * a22 - a02 * a20) * inv
        Dm_inv[e, 2, 1] = (a01 * a20 - a00 * a21) * inv
        Dm_inv[e, 0, 2] = (a01 * a12 - a02 * a11) * inv
        Dm_inv[e, 1, 2] = (a02 * a10 - a00 * a12) * inv
        Dm_inv[e, 2, 2] = (a00 * a11 - a01 * a10) * inv
        vol[e] = det / 6.0


@njit(cache=True, inline="always", error_model="numpy")
def _tet_F(x, tets, Dm_inv, e):
    """F = Ds Dm^-1 of tet e (eqs. 2-4), a ``Mat3``."""
    i0, i1, i2, i3 = tets[e, 0], tets[e, 1], tets[e, 2], tets[e, 3]
    x0 = x[i0, 0]
    y0 = x[i0, 1]
    z0 = x[i0, 2]
    d00 = x[i1, 0] - x0
    d10 = x[i1, 1] - y0
    d20 = x[i1, 2] - z0
    d01 = x[i2, 0] - x0
    d11 = x[i2, 1] - y0
    d21 = x[i2, 2] - z0
    d02 = x[i3, 0] - x0
    d12 = x[i3, 1] - y0
    d22 = x[i3, 2] - z0
    m00, m01, m02 = Dm_inv[e, 0, 0], Dm_inv[e, 0, 1], Dm_inv[e, 0, 2]
    m10, m11, m12 = Dm_inv[e, 1, 0], Dm_inv[e, 1, 1], Dm_inv[e, 1, 2]
    m20, m21, m22 = Dm_inv[e, 2, 0], Dm_inv[e, 2, 1], Dm_inv[e, 2, 2]
    f00 = d00 * m00 + d01 * m10 + d02 * m20
    f01 = d00 * m01 + d01 * m11 + d02 * m21
    f02 = d00 * m02 + d01 * m12 + d02 * m22
    f10 = d10 * m00 + d11 * m10 + d12 * m20
    f11 = d10 * m01 + d11 * m11 + d12 * m21
    f12 = d10 * m02 + d11 * m12 + d12 * m22
    f20 = d20 * m00 + d21 * m10 + d22 * m20
    f21 = d20 * m01 + d21 * m11 + d22 * m21
    f22 = d20 * m02 + d21 * m12 + d22 * m22
    return Mat3(f00, f01, f02, f10, f11, f12, f20, f21, f22)


@njit(cache=True, error_model="numpy")
def deformation_gradients(x, tets, Dm_inv, F):
    """F_e = Ds Dm^-1 for every tet (eqs. 2-4).

    x: (n_nodes, 3) [m]; Dm_inv: (n_tets, 3, 3) [1/m] (rest or active-effective).
    Overwrites F: (n_tets, 3, 3) [-].
    """
    for e in range(tets.shape[0]):
        mat3_into(_tet_F(x, tets, Dm_inv, e), F[e])


@njit(cache=True, error_model="numpy")
def active_dm_inv(Dm_inv, A, Dm_inv_eff):
    """Effective inverse edge matrices for an active strain: Dm_inv_eff = Dm^-1 A^-1.

    Dm_inv: (n_tets, 3, 3) rest [1/m]; A: (n_tets, 3, 3) active deformation of the
    rest shape [-] (identity = passive; det A > 0).  Overwrites
    Dm_inv_eff: (n_tets, 3, 3) [1/m].  Then F_e = Ds Dm_inv_eff = F A^-1.
    """
    for e in range(Dm_inv.shape[0]):
        a = A[e]
        c00 = a[1, 1] * a[2, 2] - a[1, 2] * a[2, 1]
        c01 = a[1, 2] * a[2, 0] - a[1, 0] * a[2, 2]
        c02 = a[1, 0] * a[2, 1] - a[1, 1] * a[2, 0]
        inv = 1.0 / (a[0, 0] * c00 + a[0, 1] * c01 + a[0, 2] * c02)
        i00 = c00 * inv
        i10 = c01 * inv
        i20 = c02 * inv
        i01 = (a[0, 2] * a[2, 1] - a[0, 1] * a[2, 2]) * inv
        i11 = (a[0, 0] * a[2, 2] - a[0, 2] * a[2, 0]) * inv
        i21 = (a[0, 1] * a[2, 0] - a[0, 0] * a[2, 1]) * inv
        i02 = (a[0, 1] * a[1, 2] - a[0, 2] * a[1, 1]) * inv
        i12 = (a[0, 2] * a[1, 0] - a[0, 0] * a[1, 2]) * inv
        i22 = (a[0, 0] * a[1, 1] - a[0, 1] * a[1, 0]) * inv
        for r in range(3):
            m0, m1, m2 = Dm_inv[e, r, 0], Dm_inv[e, r, 1], Dm_inv[e, r, 2]
            Dm_inv_eff[e, r, 0] = m0 * i00 + m1 * i10 + m2 * i20
            Dm_inv_eff[e, r, 1] = m0 * i01 + m1 * i11 + m2 * i21
            Dm_inv_eff[e, r, 2] = m0 * i02 + m1 * i12 + m2 * i22


@njit(cache=True, error_model="numpy")
def axial_active_strain(axis, l_axial, l_cross, A):
    """Muscle active strain A = Q diag(l_axial, l_c, l_c) Q^T = l_c I + (l_axial - l_c) a a^T.

    axis: (n_tets, 3) unit fibre direction a in the rest frame (Q e_x); l_axial,
    l_cross: (n_tets,) rest-shape stretch along and across the fibre [-].
    Overwrites A: (n_tets, 3, 3).
    """
    for e in range(axis.shape[0]):
        d = l_axial[e] - l_cross[e]
        for i in range(3):
            for j in range(3):
                A[e, i, j] = d * axis[e, i] * axis[e, j]
            A[e, i, i] += l_cross[e]


def n_tet_blocks(n_tets):
    """Number of LANES-wide blocks holding n_tets tets."""
    return (int(n_tets) + LANES - 1) // LANES


def new_tet_workspace(n_tets):
    """Allocate (q_ws, F_work, H_work) for ``elastic_forces`` (blocked layout, module docstring).

    q_ws (n_blocks, N_Q LANES) starts at the identity rotation, at rest (increment 0); F_work
    (n_blocks, 9 LANES) at F = I, so that the padding lanes past n_tets stay an
    inert, converged identity tet (their ``coef`` is zero); H_work
    (n_blocks, N_H LANES) is zero.
    """
    nb = n_tet_blocks(n_tets)
    q_ws = np.zeros((nb, N_Q * LANES))
    q_ws[:, :LANES] = 1.0
    F_work = np.zeros((nb, 9 * LANES))
    for r in (0, 4, 8):
        F_work[:, r * LANES:(r + 1) * LANES] = 1.0
    H_work = np.zeros((nb, N_H * LANES))
    return q_ws, F_work, H_work


def node_incidence(tets, n_nodes):
    """Each node's force entries in ``H_work``, for ``elastic_forces_gathered``.

    tets: (n_tets, 4); returns (ptr (n_nodes + 1,), off (4 n_tets,)), uint64: node
    i's entries are off[ptr[i]:ptr[i + 1]], ascending in tet index, each the flat
    index into H_work of the x component of that tet's force on the node (y and
    z follow LANES and 2 LANES further on).  The tet order is the order in which
    ``_scatter_pass`` adds into the node, so the gathered sums are bit for bit
    the scattered ones.
    """
    tets = np.asarray(tets, dtype=np.int64)
    n_t = len(tets)
    e = np.repeat(np.arange(n_t, dtype=np.int64), 4)
    k = np.tile(np.arange(4, dtype=np.int64), n_t)
    node = tets.ravel()
    order = np.lexsort((e, node))  # by node, then tet
    ptr = np.zeros(n_nodes + 1, dtype=np.int64)
    np.add.at(ptr, node + 1, 1)
    ptr = np.cumsum(ptr)
    e, k = e[order], k[order]
    b = e // LANES
    row = np.where(k == 0, H_NODE0, 3 * (k - 1))
    off = b * (N_H * LANES) + row * LANES + (e - b * LANES)
    return ptr.astype(np.uint64), off.astype(np.uint64)


@njit(cache=True, error_model="numpy")
def pack_tet_coefficients(Dm_inv, vol, mu, lam, coef):
    """Pack the per-tet constants of the force pass into the blocked layout.

    Dm_inv: (n_tets, 3, 3) [1/m] (rest or active-effective); vol (n_tets,) [m^3];
    mu, lam (n_tets,) [Pa].  Overwrites coef: (n_blocks, N_COEF LANES): row 3 r + c
    holds -vol Dm_inv[:, r, c] [m^2], row 9 holds 2 mu, row 10 lam [Pa], row
    11 + 3 r + c Dm_inv[:, r, c] [1/m]; padding lanes are zero but for an identity
    Dm_inv (their F stays the identity of ``new_tet_workspace``).
    """
    coef[:, :] = 0.0
    nb = coef.shape[0]
    for l in range(LANES):
        for r in range(3):
            coef[nb - 1, (COEF_DM_INV + 4 * r) * LANES + l] = 1.0
    for e in range(Dm_inv.shape[0]):
        b = e // LANES
        l = e - b * LANES
        for r in range(3):
            for c in range(3):
                coef[b, (3 * r + c) * LANES + l] = -vol[e] * Dm_inv[e, r, c]
                coef[b, (COEF_DM_INV + 3 * r + c) * LANES + l] = Dm_inv[e, r, c]
        coef[b, COEF_TWO_MU * LANES + l] = 2.0 * mu[e]
        coef[b, COEF_LAM * LANES + l] = lam[e]


# --------------------------------------------------------------------------------------
# Constitutive model and elastic forces
# --------------------------------------------------------------------------------------
@njit(cache=True, inline="always", error_model="numpy")
def _fcr_stress(F, two_mu, lam, R):
    """First Piola-Kirchhoff stress of eq. 8 in cofactor form.

    P = 2 mu (F - R) + lam (J - 1) cof(F), using J F^-T = cof(F) so that P stays
    finite as J -> 0.  The columns of cof(F) are f1 x f2, f2 x f0, f0 x f1 (f_k the
    columns of F).  F, R: ``Mat3`` (inlined, scalars in registers).  Returns an ``FCRStress`` (P, J).
    """
    f00, f01, f02 = F.m00, F.m01, F.m02
    f10, f11, f12 = F.m10, F.m11, F.m12
    f20, f21, f22 = F.m20, F.m21, F.m22
    c00 = f11 * f22 - f21 * f12
    c10 = f21 * f02 - f01 * f22
    c20 = f01 * f12 - f11 * f02
    c01 = f12 * f20 - f22 * f10
    c11 = f22 * f00 - f02 * f20
    c21 = f02 * f10 - f12 * f00
    c02 = f10 * f21 - f20 * f11
    c12 = f20 * f01 - f00 * f21
    c22 = f00 * f11 - f10 * f01
    J = f00 * c00 + f10 * c10 + f20 * c20
    k = lam * (J - 1.0)
    return FCRStress(P=Mat3(two_mu * (f00 - R.m00) + k * c00, two_mu * (f01 - R.m01) + k * c01,
                            two_mu * (f02 - R.m02) + k * c02, two_mu * (f10 - R.m10) + k * c10,
                            two_mu * (f11 - R.m11) + k * c11, two_mu * (f12 - R.m12) + k * c12,
                            two_mu * (f20 - R.m20) + k * c20, two_mu * (f21 - R.m21) + k * c21,
                            two_mu * (f22 - R.m22) + k * c22),
                     J=J)


@njit(cache=True, error_model="numpy")
def first_piola(F, mu, lam, P):
    """Fixed-corotational first Piola-Kirchhoff stress (eq. 8) of one F, R from the SVD.

    F: (3, 3); mu, lam [Pa].  Overwrites P: (3, 3) [Pa].
    """
    R = u_vt(svd3_core(F[0, 0], F[0, 1], F[0, 2], F[1, 0], F[1, 1], F[1, 2], F[2, 0], F[2, 1], F[2, 2]))
    mat3_into(_fcr_stress(mat3_of(F), 2.0 * mu, lam, R).P, P)


@njit(cache=True, inline="always", error_model="numpy")
def _store_nodal_forces(F, R, coef, H, b, l):
    """H = -V P Dm^-T of the tet in block b, lane l (eq. 9 with the force sign); F, R: the tet's deformation
    gradient and rotation, ``Mat3`` (inlined, scalars in registers).

    Row 3 k + i of H holds component i of the force on local node k + 1, row
    H_NODE0 + i that on local node 0, minus the sum of the three (eq. 10).
    """
    L = LANES
    P = _fcr_stress(F, coef[b, COEF_TWO_MU * L + l], coef[b, COEF_LAM * L + l], R).P
    p00, p01, p02 = P.m00, P.m01, P.m02
    p10, p11, p12 = P.m10, P.m11, P.m12
    p20, p21, p22 = P.m20, P.m21, P.m22
    a00, a01, a02 = coef[b, l], coef[b, L + l], coef[b, 2 * L + l]
    a10, a11, a12 = coef[b, 3 * L + l], coef[b, 4 * L + l], coef[b, 5 * L + l]
    a20, a21, a22 = coef[b, 6 * L + l], coef[b, 7 * L + l], coef[b, 8 * L + l]
    H[b, l] = p00 * a00 + p01 * a01 + p02 * a02
    H[b, L + l] = p10 * a00 + p11 * a01 + p12 * a02
    H[b, 2 * L + l] = p20 * a00 + p21 * a01 + p22 * a02
    H[b, 3 * L + l] = p00 * a10 + p01 * a11 + p02 * a12
    H[b, 4 * L + l] = p10 * a10 + p11 * a11 + p12 * a12
    H[b, 5 * L + l] = p20 * a10 + p21 * a11 + p22 * a12
    H[b, 6 * L + l] = p00 * a20 + p01 * a21 + p02 * a22
    H[b, 7 * L + l] = p10 * a20 + p11 * a21 + p12 * a22
    H[b, 8 * L + l] = p20 * a20 + p21 * a21 + p22 * a22
    # eq. 10: the four forces of a tet sum to zero.  Stored negated, so that adding it is
    # subtracting the sum (x - y is x + (-y) in IEEE arithmetic): as ``_scatter_pass``
    H[b, H_NODE0 * L + l] = -(H[b, l] + H[b, 3 * L + l] + H[b, 6 * L + l])
    H[b, (H_NODE0 + 1) * L + l] = -(H[b, L + l] + H[b, 4 * L + l] + H[b, 7 * L + l])
    H[b, (H_NODE0 + 2) * L + l] = -(H[b, 2 * L + l] + H[b, 5 * L + l] + H[b, 8 * L + l])


@njit(cache=True, error_model="numpy")
def _edge_pass(x, tets, F):
    """Edge matrix Ds = [x1 - x0, x2 - x0, x3 - x0] of every tet (eq. 2) into the blocked
    scratch F (n_blocks, 9 LANES) (overwritten for tets < n_tets; ``_rotation_stress_pass``
    turns it into F = Ds Dm^-1 in place)."""
    L = LANES
    for e in range(tets.shape[0]):
        b = e // L
        l = e - b * L
        # unsigned node ids: numba tests every signed index for wrap-around (ids are >= 0)
        i0, i1, i2, i3 = np.uint64(tets[e, 0]), np.uint64(tets[e, 1]), np.uint64(tets[e, 2]), np.uint64(tets[e, 3])
        x0 = x[i0, 0]
        y0 = x[i0, 1]
        z0 = x[i0, 2]
        F[b, l] = x[i1, 0] - x0
        F[b, L + l] = x[i2, 0] - x0
        F[b, 2 * L + l] = x[i3, 0] - x0
        F[b, 3 * L + l] = x[i1, 1] - y0
        F[b, 4 * L + l] = x[i2, 1] - y0
        F[b, 5 * L + l] = x[i3, 1] - y0
        F[b, 6 * L + l] = x[i1, 2] - z0
        F[b, 7 * L + l] = x[i2, 2] - z0
        F[b, 8 * L + l] = x[i3, 2] - z0


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _rotation_stress_pass(F, coef, q, H):
    """F = Ds Dm^-1, Newton rotation steps from the predicted rotation and the nodal forces of
    every tet, branch-free within a block (vectorised).

    F holds the edge matrices Ds (``_edge_pass``) and is OVERWRITTEN with F, Dm^-1
    read from ``coef``.  q (n_blocks, N_Q LANES): each tet's rotation and last
    increment d; the first step starts from q (1, d) (module docstring).  A tet is
    accepted after the first step if it was valid and the error it leaves is
    estimated below NEWTON_ERR (``_newton_step_h``); a block with a tet that was
    not runs a second step for all its lanes, and accepts the others whose two
    steps were valid and whose second leaves an error estimated below NEWTON_ERR.
    An accepted tet's q is OVERWRITTEN with the new rotation (renormalised) and d
    with the increment q_old -> q_new: d + h1 after one step (h1 the Newton half
    step: the term of second order, |d| |h1|, is well below the prediction's own error),
    the exact product (1, d) (1, h1) (1, h2) scaled to w = 1 after two.  Overwrites H rows 0-8
    and 10-12 with the nodal forces and H row 9 with 0 where accepted, inf where
    not; those (H row 9 >= _NEWTON_TOL_HH) need ``_rotation_fixup``.

    Each block goes through short loops over its lanes (first step; the second
    step if needed; stress and forces) rather than one long one: one tet's whole
    chain is several hundred dependent vector instructions, more than the
    processor's reorder window, so in a single loop the next lanes could not start
    until the last ones were nearly done; each short loop's lanes overlap.  The
    first step's quaternion, half step and flag wait in H rows 0-7, which the last
    loop overwrites.
    """
    L = LANES
    M = COEF_DM_INV * L
    D = Q_D * L
    for b in range(F.shape[0]):
        n_retry = 0
        for l in range(L):
            # F = Ds Dm^-1 (eqs. 2-4), in place of Ds (``_edge_pass``)
            d00, d01, d02 = F[b, l], F[b, L + l], F[b, 2 * L + l]
            d10, d11, d12 = F[b, 3 * L + l], F[b, 4 * L + l], F[b, 5 * L + l]
            d20, d21, d22 = F[b, 6 * L + l], F[b, 7 * L + l], F[b, 8 * L + l]
            m00, m01, m02 = coef[b, M + l], coef[b, M + L + l], coef[b, M + 2 * L + l]
            m10, m11, m12 = coef[b, M + 3 * L + l], coef[b, M + 4 * L + l], coef[b, M + 5 * L + l]
            m20, m21, m22 = coef[b, M + 6 * L + l], coef[b, M + 7 * L + l], coef[b, M + 8 * L + l]
            f00 = d00 * m00 + d01 * m10 + d02 * m20
            f01 = d00 * m01 + d01 * m11 + d02 * m21
            f02 = d00 * m02 + d01 * m12 + d02 * m22
            f10 = d10 * m00 + d11 * m10 + d12 * m20
            f11 = d10 * m01 + d11 * m11 + d12 * m21
            f12 = d10 * m02 + d11 * m12 + d12 * m22
            f20 = d20 * m00 + d21 * m10 + d22 * m20
            f21 = d20 * m01 + d21 * m11 + d22 * m21
            f22 = d20 * m02 + d21 * m12 + d22 * m22
            F[b, l] = f00
            F[b, L + l] = f01
            F[b, 2 * L + l] = f02
            F[b, 3 * L + l] = f10
            F[b, 4 * L + l] = f11
            F[b, 5 * L + l] = f12
            F[b, 6 * L + l] = f20
            F[b, 7 * L + l] = f21
            F[b, 8 * L + l] = f22
            qw, qx, qy, qz = q[b, l], q[b, L + l], q[b, 2 * L + l], q[b, 3 * L + l]
            dx, dy, dz = q[b, D + l], q[b, D + L + l], q[b, D + 2 * L + l]
            # predicted rotation q (1, d): the last step's increment once more
            pw = qw - (qx * dx + qy * dy + qz * dz)
            px = qx + qw * dx + (qy * dz - qz * dy)
            py = qy + qw * dy + (qz * dx - qx * dz)
            pz = qz + qw * dz + (qx * dy - qy * dx)
            s = _newton_step_h(f00, f01, f02, f10, f11, f12, f20, f21, f22, pw, px, py, pz)
            aw, ax, ay, az = s.w, s.x, s.y, s.z
            hx, hy, hz = s.hx, s.hy, s.hz
            ok, acc = s.ok, s.small
            nw, nx, ny, nz = _renormalize(aw, ax, ay, az)
            q[b, l] = nw if acc else qw
            q[b, L + l] = nx if acc else qx
            q[b, 2 * L + l] = ny if acc else qy
            q[b, 3 * L + l] = nz if acc else qz
            q[b, D + l] = dx + hx if acc else dx
            q[b, D + L + l] = dy + hy if acc else dy
            q[b, D + 2 * L + l] = dz + hz if acc else dz
            H[b, H_HH * L + l] = 0.0 if acc else np.inf
            # for the second step: the first one's quaternion and half step, and whether to take it
            H[b, l] = aw
            H[b, L + l] = ax
            H[b, 2 * L + l] = ay
            H[b, 3 * L + l] = az
            H[b, 4 * L + l] = hx
            H[b, 5 * L + l] = hy
            H[b, 6 * L + l] = hz
            retry = ok & (acc == False)  # noqa: E712 (valid, not yet accepted; no branch)
            H[b, 7 * L + l] = 1.0 if retry else 0.0
            n_retry += 1 if retry else 0
        if n_retry > 0:
            for l in range(L):
                f00, f01, f02 = F[b, l], F[b, L + l], F[b, 2 * L + l]
                f10, f11, f12 = F[b, 3 * L + l], F[b, 4 * L + l], F[b, 5 * L + l]
                f20, f21, f22 = F[b, 6 * L + l], F[b, 7 * L + l], F[b, 8 * L + l]
                s2 = _newton_step_h(f00, f01, f02, f10, f11, f12, f20, f21, f22,
                                    H[b, l], H[b, L + l], H[b, 2 * L + l], H[b, 3 * L + l])
                bw, bx, by, bz = _renormalize(s2.w, s2.x, s2.y, s2.z)
                kx, ky, kz = s2.hx, s2.hy, s2.hz
                acc = (H[b, 7 * L + l] != 0.0) & s2.small
                q[b, l] = bw if acc else q[b, l]
                q[b, L + l] = bx if acc else q[b, L + l]
                q[b, 2 * L + l] = by if acc else q[b, 2 * L + l]
                q[b, 3 * L + l] = bz if acc else q[b, 3 * L + l]
                # the increment (1, d) (1, h1) (1, h2), scaled to w = 1: exact, as the steps may be large here
                dx, dy, dz = q[b, D + l], q[b, D + L + l], q[b, D + 2 * L + l]
                hx, hy, hz = H[b, 4 * L + l], H[b, 5 * L + l], H[b, 6 * L + l]
                cw = 1.0 - (dx * hx + dy * hy + dz * hz)
                cx = dx + hx + (dy * hz - dz * hy)
                cy = dy + hy + (dz * hx - dx * hz)
                cz = dz + hz + (dx * hy - dy * hx)
                ew = cw - (cx * kx + cy * ky + cz * kz)
                ex = cx + cw * kx + (cy * kz - cz * ky)
                ey = cy + cw * ky + (cz * kx - cx * kz)
                ez = cz + cw * kz + (cx * ky - cy * kx)
                q[b, D + l] = ex / ew if acc else dx
                q[b, D + L + l] = ey / ew if acc else dy
                q[b, D + 2 * L + l] = ez / ew if acc else dz
                H[b, H_HH * L + l] = 0.0 if acc else H[b, H_HH * L + l]
        for l in range(L):
            f00, f01, f02 = F[b, l], F[b, L + l], F[b, 2 * L + l]
            f10, f11, f12 = F[b, 3 * L + l], F[b, 4 * L + l], F[b, 5 * L + l]
            f20, f21, f22 = F[b, 6 * L + l], F[b, 7 * L + l], F[b, 8 * L + l]
            R = _quat_to_rot(q[b, l], q[b, L + l], q[b, 2 * L + l], q[b, 3 * L + l])
            _store_nodal_forces(Mat3(f00, f01, f02, f10, f11, f12, f20, f21, f22), R, coef, H, b, l)


@njit(cache=True, inline="always", error_model="numpy")
def _fixup_tet(F, coef, q, H, b, l):
    """``_rotation_fixup`` of the tet in block b, lane l: its rotation (``_fcr_rotation`` from its q), increment
    and forces."""
    L = LANES
    f00, f01, f02 = F[b, l], F[b, L + l], F[b, 2 * L + l]
    f10, f11, f12 = F[b, 3 * L + l], F[b, 4 * L + l], F[b, 5 * L + l]
    f20, f21, f22 = F[b, 6 * L + l], F[b, 7 * L + l], F[b, 8 * L + l]
    ow, ox, oy, oz = q[b, l], q[b, L + l], q[b, 2 * L + l], q[b, 3 * L + l]
    r = _fcr_rotation(f00, f01, f02, f10, f11, f12, f20, f21, f22, ow, ox, oy, oz)
    qw, qx, qy, qz = r.q.w, r.q.x, r.q.y, r.q.z
    q[b, l] = qw
    q[b, L + l] = qx
    q[b, 2 * L + l] = qy
    q[b, 3 * L + l] = qz
    # the increment for the next step's prediction: conj(q_old) q_new = (cw, c), d = c / cw (the same
    # for q_new and -q_new); none if it is not a small turn (the SVD's answer, or a flip)
    cw = ow * qw + ox * qx + oy * qy + oz * qz
    cx = ow * qx - qw * ox - (oy * qz - oz * qy)
    cy = ow * qy - qw * oy - (oz * qx - ox * qz)
    cz = ow * qz - qw * oz - (ox * qy - oy * qx)
    dx, dy, dz = cx / cw, cy / cw, cz / cw
    small = dx * dx + dy * dy + dz * dz < _NEWTON_MAX_HH
    q[b, Q_D * L + l] = dx if small else 0.0
    q[b, (Q_D + 1) * L + l] = dy if small else 0.0
    q[b, (Q_D + 2) * L + l] = dz if small else 0.0
    _store_nodal_forces(Mat3(f00, f01, f02, f10, f11, f12, f20, f21, f22), r.R, coef, H, b, l)


@njit(cache=True, error_model="numpy")
def _rotation_fixup(n_tets, F, coef, q, H):
    """Finish the tets the branch-free pass left unconverged; returns how many.

    For each tet e < n_tets with not (H row 9 < _NEWTON_TOL_HH) (also NaN):
    ``_fcr_rotation`` from its current q, the previous step's rotation (more Newton
    steps, then the SVD), and its forces recomputed.  Overwrites q (rotation and
    increment) and H rows 0-8, 10-12 of those tets.
    """
    L = LANES
    count = 0
    for b in range((n_tets + L - 1) // L):
        # a block whose lanes were all accepted (the common case) is skipped after one vector
        # compare; NaN counts as not accepted, as in the lane test below
        n_open = 0
        for l in range(L):
            n_open += 0 if H[b, H_HH * L + l] < _NEWTON_TOL_HH else 1
        if n_open == 0:
            continue
        for l in range(min(L, n_tets - b * L)):
            if H[b, H_HH * L + l] < _NEWTON_TOL_HH:
                continue
            count += 1
            _fixup_tet(F, coef, q, H, b, l)
    return count


@njit(cache=True, error_model="numpy")
def _scatter_pass(tets, H, f):
    """Accumulate the per-tet nodal forces H into f (n_nodes, 3); eqs. 10-11."""
    L = LANES
    for e in range(tets.shape[0]):
        b = e // L
        l = e - b * L
        # unsigned node ids: no wrap-around test per index (as in ``_edge_pass``)
        i0, i1, i2, i3 = np.uint64(tets[e, 0]), np.uint64(tets[e, 1]), np.uint64(tets[e, 2]), np.uint64(tets[e, 3])
        h00, h10, h20 = H[b, l], H[b, L + l], H[b, 2 * L + l]
        h01, h11, h21 = H[b, 3 * L + l], H[b, 4 * L + l], H[b, 5 * L + l]
        h02, h12, h22 = H[b, 6 * L + l], H[b, 7 * L + l], H[b, 8 * L + l]
        f[i1, 0] += h00
        f[i1, 1] += h10
        f[i1, 2] += h20
        f[i2, 0] += h01
        f[i2, 1] += h11
        f[i2, 2] += h21
        f[i3, 0] += h02
        f[i3, 1] += h12
        f[i3, 2] += h22
        # eq. 10: the four forces of a tet sum to zero
        f[i0, 0] -= h00 + h01 + h02
        f[i0, 1] -= h10 + h11 + h12
        f[i0, 2] -= h20 + h21 + h22


@njit(cache=True, error_model="numpy")
def elastic_forces(x, tets, Dm_inv, coef, q_ws, F_work, H_work, f):
    """Fixed-corotational elastic nodal forces f_i = -dE/dx_i (eqs. 7-11).

    x: (n_nodes, 3) [m]; tets: (n_tets, 4); Dm_inv: (n_tets, 3, 3) [1/m] (rest, or
    active-effective ``Dm^-1 A^-1``); coef: from ``pack_tet_coefficients`` with the
    same Dm_inv (the pass reads Dm^-1 from its blocked copy in ``coef``, rows
    COEF_DM_INV..; the argument stays so that the callers' signature does); q_ws:
    per-tet rotation warm start (any non-zero quaternions) and last increments,
    OVERWRITTEN with the current ones; F_work, H_work: scratch.  The three come from ``new_tet_workspace`` (blocked layout, module docstring).
    ACCUMULATES into f: (n_nodes, 3) [N].  Returns the number of tets that needed
    the slow path (``_rotation_fixup``).
    """
    _edge_pass(x, tets, F_work)
    _rotation_stress_pass(F_work, coef, q_ws, H_work)
    n_slow = _rotation_fixup(tets.shape[0], F_work, coef, q_ws, H_work)
    _scatter_pass(tets, H_work, f)
    return n_slow


@njit(cache=True, inline="always", error_model="numpy")
def gather_node_force(Hf, inc_ptr, inc_off, i, s0, s1, s2):
    """(s0, s1, s2) plus the element forces on node i, H_work's entries flat (Hf = H_work.reshape(H_work.size)).

    inc_ptr, inc_off: ``node_incidence``.  The sum runs in registers over the node's tets in
    ascending order, the order ``_scatter_pass`` adds them in memory: the same result, bit for
    bit, without the scatter's chain of dependent loads and stores through memory where
    consecutive tets share a node.
    """
    L1 = np.uint64(LANES)
    L2 = np.uint64(2 * LANES)
    for a in range(inc_ptr[i], inc_ptr[i + 1]):
        o = inc_off[a]
        s0 += Hf[o]
        s1 += Hf[o + L1]
        s2 += Hf[o + L2]
    return s0, s1, s2


@njit(cache=True, error_model="numpy")
def _gather_pass(inc_ptr, inc_off, H, f):
    """Accumulate the per-tet nodal forces H into f (n_nodes, 3) node by node (eqs. 10-11;
    ``gather_node_force``, inc_ptr, inc_off: ``node_incidence``)."""
    Hf = H.reshape(H.size)
    for i in range(f.shape[0]):
        s0, s1, s2 = gather_node_force(Hf, inc_ptr, inc_off, i, f[i, 0], f[i, 1], f[i, 2])
        f[i, 0] = s0
        f[i, 1] = s1
        f[i, 2] = s2


@njit(cache=True, inline="always", error_model="numpy")
def element_forces(x, tets, coef, q_ws, F_work, H_work):
    """The element pass of ``elastic_forces`` without the nodal sums: every tet's nodal forces into
    H_work (rows 0-8 and 10-12, module docstring), q_ws UPDATED; returns the number of slow-path tets.

    For a caller that sums only some nodes' forces (``gather_node_force``), as the hybrid body does.
    """
    _edge_pass(x, tets, F_work)
    _rotation_stress_pass(F_work, coef, q_ws, H_work)
    return _rotation_fixup(tets.shape[0], F_work, coef, q_ws, H_work)


@njit(cache=True, error_model="numpy")
def elastic_forces_gathered(x, tets, coef, q_ws, F_work, H_work, inc_ptr, inc_off, f):
    """``elastic_forces`` with the nodal sums gathered node by node (``node_incidence``
    of ``tets``: inc_ptr, inc_off); the same result bit for bit, faster.

    ACCUMULATES into f: (n_nodes, 3) [N].  Returns the number of slow-path tets.
    """
    n_slow = element_forces(x, tets, coef, q_ws, F_work, H_work)
    _gather_pass(inc_ptr, inc_off, H_work, f)
    return n_slow


@njit(cache=True, error_model="numpy")
def elastic_energy(x, tets, Dm_inv, vol, mu, lam):
    """Total elastic energy sum_e V_e [mu sum_i (sigma_i - 1)^2 + lam/2 (J - 1)^2] [J] (eq. 6).

    x: (n_nodes, 3) [m]; Dm_inv: (n_tets, 3, 3) (rest or active-effective);
    vol, mu, lam: (n_tets,).  Uses the SVD; returns a float.
    """
    E = 0.0
    for e in range(tets.shape[0]):
        F = _tet_F(x, tets, Dm_inv, e)
        s = svd3_core(F.m00, F.m01, F.m02, F.m10, F.m11, F.m12, F.m20, F.m21, F.m22)
        s0 = s.s0 - 1.0
        s1 = s.s1 - 1.0
        s2 = s.s2 - 1.0
        J = s.s0 * s.s1 * s.s2
        E += vol[e] * (mu[e] * (s0 * s0 + s1 * s1 + s2 * s2) + 0.5 * lam[e] * (J - 1.0) ** 2)
    return E


@njit(cache=True, error_model="numpy")
def tet_invariants(x, tets, Dm_inv, J, sigma):
    """Per-tet J = det F and signed singular values of F (for metrics).

    Overwrites J: (n_tets,) and sigma: (n_tets, 3) (descending, smallest signed).
    """
    for e in range(tets.shape[0]):
        F = _tet_F(x, tets, Dm_inv, e)
        s = svd3_core(F.m00, F.m01, F.m02, F.m10, F.m11, F.m12, F.m20, F.m21, F.m22)
        sigma[e, 0] = s.s0
        sigma[e, 1] = s.s1
        sigma[e, 2] = s.s2
        J[e] = (F.m00 * (F.m11 * F.m22 - F.m12 * F.m21) - F.m01 * (F.m10 * F.m22 - F.m12 * F.m20)
                + F.m02 * (F.m10 * F.m21 - F.m11 * F.m20))


# --------------------------------------------------------------------------------------
# Mass and damping
# --------------------------------------------------------------------------------------
@njit(cache=True, error_model="numpy")
def lumped_mass(tets, vol, rho, m):
    """Lumped nodal masses m_i = 1/4 sum_{e ∋ i} rho V_e (eq. 12).

    tets: (n_tets, 4); vol: (n_tets,) [m^3]; rho: (n_tets,) [kg/m^3].
    Overwrites m: (n_nodes,) [kg].
    """
    m[:] = 0.0
    for e in range(tets.shape[0]):
        q = 0.25 * rho[e] * vol[e]
        for k in range(4):
            m[tets[e, k]] += q


@njit(cache=True, error_model="numpy")
def damping_forces(v, tets, vol, gamma, f):
    """Damping forces f_i = -gamma sum_{e ∋ i} V_e (v_i - mean_k v_{e_k}) (eq. 13).

    v: (n_nodes, 3) [m/s]; vol: (n_tets,) [m^3]; gamma [N s/m^4].
    ACCUMULATES into f: (n_nodes, 3) [N].  (The step treats this force implicitly
    through the constant matrix D; this explicit form is its reference.)
    """
    for e in range(tets.shape[0]):
        c = gamma * vol[e]
        for d in range(3):
            mean = 0.25 * (v[tets[e, 0], d] + v[tets[e, 1], d] + v[tets[e, 2], d] + v[tets[e, 3], d])
            for k in range(4):
                f[tets[e, k], d] -= c * (v[tets[e, k], d] - mean)


# --------------------------------------------------------------------------------------
# Skyline (variable-band) Cholesky of the constant matrix (M + dt D)_ff
# --------------------------------------------------------------------------------------
@njit(cache=True, error_model="numpy")
def skyline_cholesky(first, ptr, val):
    """In-place Cholesky factorization A = L L^T in skyline (row envelope) storage.

    Row i of the lower triangle holds columns first[i] .. i in
    val[ptr[i] : ptr[i+1]] (diagonal last).  first: (n,), ptr: (n+1,) int64.
    Overwrites val with L.  Returns 0, or i+1 if the pivot of row i is not
    positive (matrix not positive definite).
    """
    n = first.shape[0]
    for i in range(n):
        fi = first[i]
        pi = ptr[i]
        for j in range(fi, i + 1):
            fj = first[j]
            pj = ptr[j]
            k0 = fi if fi > fj else fj
            s = val[pi + j - fi]
            for k in range(k0, j):
                s -= val[pi + k - fi] * val[pj + k - fj]
            if j < i:
                val[pi + j - fi] = s / val[pj + j - fj]
            else:
                if s <= 0.0:
                    return i + 1
                val[pi + i - fi] = math.sqrt(s)
    return 0


# Unsigned index constants for ``skyline_solve`` (numba gives unsigned indices no
# wrap-around test; mixing a signed literal in would promote the index to float).
_U1 = np.uint64(1)
_U2 = np.uint64(2)
_U3 = np.uint64(3)
_U4 = np.uint64(4)
_U5 = np.uint64(5)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def skyline_solve(first, ptr, L, b):
    """Solve L L^T y = b for three right-hand sides at once (x, y, z share the matrix).

    L: Cholesky factor from ``skyline_cholesky``; b: (n, 3) C-contiguous,
    overwritten with y.

    Both sweeps take two rows per pass, and every entry of b sees exactly the
    operations, in the order, of the one-row loops (forward: row i's sum over its
    columns k ascending; backward, a column sweep: b[k] takes row i's update and
    then row i - 1's), so the result is bit for bit theirs.  Two rows per pass
    give two independent chains of dependent subtractions to overlap, and the
    backward sweep reads and writes each b[k] once for both rows.  The inner
    loops index a flat view of b with unsigned integers: numba adds a
    negative-index wrap-around test to every signed index, which here cost as
    much as the arithmetic.  (All indices are >= 0: ptr[i] - first[i] >= 0.)
    """
    n = first.shape[0]
    bf = b.reshape(b.size)
    # forward: L z = b (row-oriented), rows i and i + 1
    i = 0
    while i + 1 < n:
        fa = first[i]
        fb = first[i + 1]
        oa = np.uint64(ptr[i] - fa)
        ob = np.uint64(ptr[i + 1] - fb)
        ri = np.uint64(3 * i)
        a0 = bf[ri]
        a1 = bf[ri + _U1]
        a2 = bf[ri + _U2]
        c0 = bf[ri + _U3]
        c1 = bf[ri + _U4]
        c2 = bf[ri + _U5]
        # the columns only one of the two rows has (at most one of these loops runs), then the shared ones
        for k in range(np.uint64(fa), np.uint64(min(fb, i))):
            l = L[oa + k]
            r = _U3 * k
            a0 -= l * bf[r]
            a1 -= l * bf[r + _U1]
            a2 -= l * bf[r + _U2]
        for k in range(np.uint64(fb), np.uint64(min(fa, i))):
            l = L[ob + k]
            r = _U3 * k
            c0 -= l * bf[r]
            c1 -= l * bf[r + _U1]
            c2 -= l * bf[r + _U2]
        for k in range(np.uint64(max(fa, fb)), np.uint64(i)):
            la = L[oa + k]
            lb = L[ob + k]
            r = _U3 * k
            z0 = bf[r]
            z1 = bf[r + _U1]
            z2 = bf[r + _U2]
            a0 -= la * z0
            a1 -= la * z1
            a2 -= la * z2
            c0 -= lb * z0
            c1 -= lb * z1
            c2 -= lb * z2
        ui = np.uint64(i)
        d = L[oa + ui]
        a0 = a0 * d
        a1 = a1 * d
        a2 = a2 * d
        bf[ri] = a0
        bf[ri + _U1] = a1
        bf[ri + _U2] = a2
        if fb <= i:
            l = L[ob + ui]
            c0 -= l * a0
            c1 -= l * a1
            c2 -= l * a2
        d = L[ob + ui + _U1]
        bf[ri + _U3] = c0 * d
        bf[ri + _U4] = c1 * d
        bf[ri + _U5] = c2 * d
        i += 2
    if i < n:  # odd n: the last row alone
        fa = first[i]
        oa = np.uint64(ptr[i] - fa)
        ri = np.uint64(3 * i)
        a0 = bf[ri]
        a1 = bf[ri + _U1]
        a2 = bf[ri + _U2]
        for k in range(np.uint64(fa), np.uint64(i)):
            l = L[oa + k]
            r = _U3 * k
            a0 -= l * bf[r]
            a1 -= l * bf[r + _U1]
            a2 -= l * bf[r + _U2]
        d = L[oa + np.uint64(i)]
        bf[ri] = a0 * d
        bf[ri + _U1] = a1 * d
        bf[ri + _U2] = a2 * d
    # backward: L^T y = z (column sweep over the rows of L), rows i and j = i - 1
    i = n - 1
    while i >= 1:
        j = i - 1
        fa = first[i]
        fb = first[j]
        oa = np.uint64(ptr[i] - fa)
        ob = np.uint64(ptr[j] - fb)
        ui = np.uint64(i)
        uj = np.uint64(j)
        ri = _U3 * ui
        rj = _U3 * uj
        d = L[oa + ui]
        ya0 = bf[ri] * d
        ya1 = bf[ri + _U1] * d
        ya2 = bf[ri + _U2] * d
        bf[ri] = ya0
        bf[ri + _U1] = ya1
        bf[ri + _U2] = ya2
        if fa <= j:
            l = L[oa + uj]
            bf[rj] -= l * ya0
            bf[rj + _U1] -= l * ya1
            bf[rj + _U2] -= l * ya2
        d = L[ob + uj]
        yb0 = bf[rj] * d
        yb1 = bf[rj + _U1] * d
        yb2 = bf[rj + _U2] * d
        bf[rj] = yb0
        bf[rj + _U1] = yb1
        bf[rj + _U2] = yb2
        for k in range(np.uint64(fa), np.uint64(min(fb, j))):
            l = L[oa + k]
            r = _U3 * k
            bf[r] -= l * ya0
            bf[r + _U1] -= l * ya1
            bf[r + _U2] -= l * ya2
        for k in range(np.uint64(fb), np.uint64(min(fa, j))):
            l = L[ob + k]
            r = _U3 * k
            bf[r] -= l * yb0
            bf[r + _U1] -= l * yb1
            bf[r + _U2] -= l * yb2
        for k in range(np.uint64(max(fa, fb)), uj):
            la = L[oa + k]
            lb = L[ob + k]
            r = _U3 * k
            bf[r] = (bf[r] - la * ya0) - lb * yb0
            bf[r + _U1] = (bf[r + _U1] - la * ya1) - lb * yb1
            bf[r + _U2] = (bf[r + _U2] - la * ya2) - lb * yb2
        i -= 2
    if i == 0:  # odd n: row 0 alone (it has no column left of the diagonal)
        d = L[ptr[0]]
        b[0, 0] = b[0, 0] * d
        b[0, 1] = b[0, 1] * d
        b[0, 2] = b[0, 2] * d


# --------------------------------------------------------------------------------------
# Ground contact
# --------------------------------------------------------------------------------------
@njit(cache=True, error_model="numpy")
def ground_contact_coulomb(x, v, nodes, terrain_kind, terrain_params, mu_friction):
    """Project penetrating nodes onto the terrain with velocity-level Coulomb friction.

    For each node i in ``nodes`` (int64 indices) with terrain signed distance
    phi(x_i) < 0: x_i -= phi n (back onto the surface, n the outward unit normal);
    if the normal velocity v_n = v_i . n is negative it is removed, and the
    tangential velocity is reduced by mu_friction |v_n| (set to zero if smaller):
    kinetic friction whose impulse is at most mu times the normal impulse.
    x, v: (n_nodes, 3) [m], [m/s], OVERWRITTEN in place for contacting nodes.
    Separate from the step so a body can substitute its own friction model.
    """
    # on the plane without obstacles phi is y - ground (``flat_ground``: what ``signed_distance``
    # computes there, without its reference-count updates per call)
    flat, ground = flat_ground(terrain_kind, terrain_params)
    for a in range(nodes.shape[0]):
        i = nodes[a]
        phi = x[i, 1] - ground if flat else signed_distance(terrain_kind, terrain_params, x[i, 0], x[i, 1], x[i, 2])
        if phi < 0.0:
            nx, ny, nz = surface_normal(terrain_kind, terrain_params, x[i, 0], x[i, 1], x[i, 2])
            x[i, 0] -= phi * nx
            x[i, 1] -= phi * ny
            x[i, 2] -= phi * nz
            vn = v[i, 0] * nx + v[i, 1] * ny + v[i, 2] * nz
            if vn < 0.0:
                tx = v[i, 0] - vn * nx
                ty = v[i, 1] - vn * ny
                tz = v[i, 2] - vn * nz
                vt = math.sqrt(tx * tx + ty * ty + tz * tz)
                dv = -mu_friction * vn
                scale = 0.0
                if vt > dv:
                    scale = (vt - dv) / vt
                v[i, 0] = scale * tx
                v[i, 1] = scale * ty
                v[i, 2] = scale * tz


# --------------------------------------------------------------------------------------
# Semi-implicit step (eqs. 14-15) and the many-step driver
# --------------------------------------------------------------------------------------
@njit(cache=True, error_model="numpy")
def semi_implicit_velocity(v, mass, f, dt, perm, sky_first, sky_ptr, sky_L,
                           fp_ptr, fp_col, fp_val, b):
    """Velocity solve of eq. 14 for the free nodes, multiplied through by M.

    (M + dt D)_ff v_f^{n+1} = M_f v_f^n + dt f_f - dt D_fp v_p^{n+1}, where f is the
    total force (elastic + gravity M g + external) at x^n and v_p are the
    prescribed velocities of the fixed nodes.
    v: (n_nodes, 3) [m/s], free rows OVERWRITTEN with v^{n+1}; mass: (n_nodes,) [kg];
    f: (n_nodes, 3) [N]; perm: (n_free,) node of each solve row; sky_*: the
    factor of (M + dt D)_ff in that order; fp_*: CSR (rows = solve rows, cols =
    fixed node ids) of D_fp [N s/m]; b: (n_free, 3) scratch.
    """
    for k in range(perm.shape[0]):
        i = np.uint64(perm[k])  # node ids are >= 0: no wrap-around tests (``skyline_solve``)
        m = mass[i]
        b0 = m * v[i, 0] + dt * f[i, 0]
        b1 = m * v[i, 1] + dt * f[i, 1]
        b2 = m * v[i, 2] + dt * f[i, 2]
        for a in range(fp_ptr[k], fp_ptr[k + 1]):
            j = np.uint64(fp_col[a])  # (as i)
            c = dt * fp_val[a]
            b0 -= c * v[j, 0]
            b1 -= c * v[j, 1]
            b2 -= c * v[j, 2]
        b[k, 0] = b0
        b[k, 1] = b1
        b[k, 2] = b2
    skyline_solve(sky_first, sky_ptr, sky_L, b)
    for k in range(perm.shape[0]):
        i = np.uint64(perm[k])
        v[i, 0] = b[k, 0]
        v[i, 1] = b[k, 1]
        v[i, 2] = b[k, 2]


@njit(cache=True, error_model="numpy", fastmath={"reassoc"})
def _maybe_unstable(x, v, vmax2):
    """False only if every node's x and v (n_nodes, 3) are finite and its speed^2 is at most vmax2.

    A screen for ``advance``'s instability check, which runs its exact node loop (the
    free nodes in solve order, first problem wins) only when this returns True.  The
    sum of |x| and |v| over all nodes is non-finite iff one entry is (or it overflows:
    then True, and the node loop decides); as a sum of non-negative terms it may be
    reassociated, which lets LLVM vectorise it (NaN and inf tests stay: no nnan/ninf).
    """
    tot = 0.0
    n_fast = 0
    for i in range(x.shape[0]):
        tot += abs(x[i, 0]) + abs(x[i, 1]) + abs(x[i, 2]) + abs(v[i, 0]) + abs(v[i, 1]) + abs(v[i, 2])
        n_fast += 1 if v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1] + v[i, 2] * v[i, 2] > vmax2 else 0
    return n_fast > 0 or not math.isfinite(tot)


# ``advance``'s arguments, named records (numba compiles a namedtuple as a struct of its fields, read by name;
# ``bodies.rigid_chain``'s note on the call's cost).  The fields are described in ``advance``.
FEMMesh = namedtuple("FEMMesh", "tets inc_ptr inc_off coef mass")
FEMSolve = namedtuple("FEMSolve", "perm sky_first sky_ptr sky_L fp_ptr fp_col fp_val fixed pf_ptr pf_col pf_val")
FEMGround = namedtuple("FEMGround", "contact terrain_kind terrain_params mu_friction v_limit")
FEMWork = namedtuple("FEMWork", "q_ws f_fixed f_work b_work F_work H_work")


@njit(cache=True, error_model="numpy")
def advance(x, v, fem_mesh, gravity, f_ext, dt, n_steps, fem_solve, fem_ground, fem_work):
    """Run up to n_steps semi-implicit steps (eqs. 14-15) in one call.

    Per step: f = f_E(x^n) + M g + f_ext on the free nodes; solve
    (M + dt D)_ff v_f = M v_f + dt f_f - dt D_fp v_p (``semi_implicit_velocity``);
    fixed nodes keep their prescribed velocity v_p and move x_p += dt v_p; free
    nodes x_f += dt v_f; then, if ``contact``, ``ground_contact_coulomb`` on the
    free nodes; then the instability check (a non-finite x or v, or a free-node
    speed above v_limit).

    mesh = ``FEMMesh`` (tets, inc_ptr, inc_off, coef, mass), solve = ``FEMSolve`` (perm, sky_first, sky_ptr,
    sky_L, fp_ptr, fp_col, fp_val, fixed, pf_ptr, pf_col, pf_val), ground = ``FEMGround`` (contact,
    terrain_kind, terrain_params, mu_friction, v_limit), work = ``FEMWork`` (q_ws, f_fixed, f_work, b_work,
    F_work, H_work): the records as plain tuples (``core.kernel_records``: the call's cost), named here.
    Inputs: x, v (n_nodes, 3) [m], [m/s], OVERWRITTEN with the new state; tets,
    inc_ptr, inc_off (``node_incidence``), coef, q_ws as in
    ``elastic_forces_gathered``;
    mass (n_nodes,) [kg]; gravity (3,) [m/s^2] (the force is M g, PAPER-NOTES);
    f_ext (n_nodes, 3) [N], constant over the call; dt [s];
    perm/sky_*/fp_*: see ``semi_implicit_velocity`` (built for this dt);
    fixed (n_fixed,) node ids; pf_*: CSR (rows = fixed nodes in ``fixed`` order,
    cols = all nodes) of D [N s/m]; contact (bool), terrain_kind, terrain_params:
    see ``terrain_kernels``; mu_friction [-]; v_limit [m/s].
    Scratch: f_work (n_nodes, 3), b_work (n_free, 3), F_work, H_work (from
    ``new_tet_workspace``).
    Output f_fixed (n_fixed, 3) [N], OVERWRITTEN with the elastic + damping force
    the mesh exerts on each fixed node, f_E(x^n) - (D v^{n+1})_p, averaged over
    the steps of the call (the nodes' own weight is not included).
    Returns (steps_completed, status): status 0 ok, 1 non-finite, 2 runaway
    speed; on failure x, v hold the state of the failed step and f_fixed is
    undefined.
    """
    mesh, solve, ground, work = FEMMesh(*fem_mesh), FEMSolve(*fem_solve), FEMGround(*fem_ground), FEMWork(*fem_work)
    tets, inc_ptr, inc_off, coef, mass = mesh.tets, mesh.inc_ptr, mesh.inc_off, mesh.coef, mesh.mass
    perm, sky_first, sky_ptr, sky_L = solve.perm, solve.sky_first, solve.sky_ptr, solve.sky_L
    fp_ptr, fp_col, fp_val, fixed = solve.fp_ptr, solve.fp_col, solve.fp_val, solve.fixed
    pf_ptr, pf_col, pf_val = solve.pf_ptr, solve.pf_col, solve.pf_val
    contact, terrain_kind, terrain_params = ground.contact, ground.terrain_kind, ground.terrain_params
    mu_friction, v_limit = ground.mu_friction, ground.v_limit
    q_ws, f_fixed, f_work, b_work = work.q_ws, work.f_fixed, work.f_work, work.b_work
    F_work, H_work = work.F_work, work.H_work
    n_nodes = x.shape[0]
    n_fixed = fixed.shape[0]
    vmax2 = v_limit * v_limit
    f_fixed[:, :] = 0.0
    gx, gy, gz = gravity[0], gravity[1], gravity[2]
    for step in range(n_steps):
        f_work[:, :] = 0.0
        elastic_forces_gathered(x, tets, coef, q_ws, F_work, H_work, inc_ptr, inc_off, f_work)
        for a in range(n_fixed):
            p = fixed[a]
            f_fixed[a, 0] += f_work[p, 0]
            f_fixed[a, 1] += f_work[p, 1]
            f_fixed[a, 2] += f_work[p, 2]
        # Gravity force M g (eq. 14, PAPER-NOTES) and external forces, free nodes only.
        for k in range(perm.shape[0]):
            i = perm[k]
            m = mass[i]
            f_work[i, 0] += f_ext[i, 0] + m * gx
            f_work[i, 1] += f_ext[i, 1] + m * gy
            f_work[i, 2] += f_ext[i, 2] + m * gz
        semi_implicit_velocity(v, mass, f_work, dt, perm, sky_first, sky_ptr, sky_L,
                               fp_ptr, fp_col, fp_val, b_work)
        # Damping force on the fixed nodes, -(D v^{n+1})_p.
        for a in range(n_fixed):
            for c in range(pf_ptr[a], pf_ptr[a + 1]):
                j = pf_col[c]
                d = pf_val[c]
                f_fixed[a, 0] -= d * v[j, 0]
                f_fixed[a, 1] -= d * v[j, 1]
                f_fixed[a, 2] -= d * v[j, 2]
        # eq. 15 for every node (fixed nodes move with their prescribed velocity).
        for i in range(n_nodes):
            x[i, 0] += dt * v[i, 0]
            x[i, 1] += dt * v[i, 1]
            x[i, 2] += dt * v[i, 2]
        if contact:
            ground_contact_coulomb(x, v, perm, terrain_kind, terrain_params, mu_friction)
        status = STATUS_OK
        if _maybe_unstable(x, v, vmax2):  # a vectorised screen; the node loop decides
            for k in range(perm.shape[0]):
                i = perm[k]
                s = (abs(x[i, 0]) + abs(x[i, 1]) + abs(x[i, 2])
                     + abs(v[i, 0]) + abs(v[i, 1]) + abs(v[i, 2]))
                if not math.isfinite(s):
                    status = STATUS_NONFINITE
                    break
                if v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1] + v[i, 2] * v[i, 2] > vmax2:
                    status = STATUS_RUNAWAY
                    break
        if status != STATUS_OK:
            return step, status
    if n_steps > 0:
        f_fixed[:, :] *= 1.0 / n_steps
    return n_steps, STATUS_OK
