"""Numba kernels for rigid boxes: quaternions, one dynamics step, terrain contact.

The myriapod paper (Sec. 3) moves its rigid exoskeletal segments with rigid-body
dynamics with collision and friction [Baraff 1997].  These kernels are the
numerical core; ``bench_myriapoda.bodies.rigid.RigidBoxes`` owns the arrays.

Conventions (PAPER-NOTES.md): world frame with y up, gravity along -y, SI units,
float64 C-contiguous arrays.  Quaternions are stored (w, x, y, z), unit length,
and map body coordinates to world coordinates: p_world = c + R(q) p_body.
Angular velocities are in the world frame.

State of n boxes (each a row):

* ``c``            (n, 3) [m]       centre of mass (the box centre)
* ``q``            (n, 4) [-]       orientation quaternion (w, x, y, z)
* ``v``            (n, 3) [m/s]     linear velocity
* ``w``            (n, 3) [rad/s]   angular velocity, world frame
* ``mass``         (n,)   [kg]
* ``inertia_body`` (n, 3) [kg m^2]  principal moments, body frame (box axes)
* ``half_extents`` (n, 3) [m]
* ``force``        (n, 3) [N]       external force accumulator (not gravity)
* ``torque``       (n, 3) [N m]     external torque accumulator about c, world frame
* ``kinematic``    (n,)   bool      True: pose and velocities are set by the
                                    caller; the integrator leaves the body alone.

One step (``advance`` runs many), for every dynamic body:

1. kick: v += dt (g + F/m), w += dt I_world^-1 tau.  In angular-momentum form
   (Baraff 1997 I, Sec. 2.9 and 2.11: dL/dt = tau, w = I(t)^-1 L) the kick has no
   gyroscopic term; the gyroscopic effect comes entirely from the drift below.
2. contact: the 8 corners against the terrain signed distance; sequential
   impulses (projected Gauss-Seidel, warm-started from the previous step) for
   the normal impulse with restitution and a 2D Coulomb friction impulse in the
   friction disk (static if it can stop the slip, else kinetic with maximum
   dissipation).
3. drift: c += dt v (symplectic Euler with the new velocity); the orientation
   follows the torque-free flow with the post-contact angular momentum L held
   fixed, approximated by the symmetric splitting of the free rigid body into
   three exact rotations about the body axes (McLachlan 1993; Dullweber,
   Leimkuhler & McLachlan 1997).  That flow keeps L exactly (to round-off) and is
   symplectic and time-reversible, so the kinetic energy error stays bounded
   over long runs instead of drifting, as explicit Euler on dw/dt = I^-1
   (tau - w x I w) does.
4. position projection: corners deeper than ``slop`` are pushed out along the
   terrain normal by non-linear Gauss-Seidel on the pose alone (the "position
   solver" of Box2D), so a resting box does not sink and the correction adds no
   velocity, hence no bounce or jitter.

No kernel allocates inside its per-step loop; ``advance`` allocates a few
(8, k) scratch arrays once per call.  No fastmath: results are deterministic.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from ..kinematics.rotations import mat_t_vec as _matTvec, matvec as _matvec  # noqa: F401 (fem kernels use them from here)

from bench_myriapoda.world.terrain_kernels import (clearance, clearance_cell, clearance_view, distance_and_normal,
                                                   distance_at_least, surface_normal)

STATUS_OK = 0
STATUS_NONFINITE = 1
STATUS_RUNAWAY = 2

N_CORNERS = 8
# Anisotropic box friction (``_solve_contacts``'s ``aniso``): [on, mu_forward, mu_backward,
# mu_transverse] along the box's own x axis (forward, toward the head) and across it.  Off: the
# isotropic ``mu``.  NO_ANISO is the all-zero vector of the plain rigid bodies.
ANISO_ON, ANISO_MU_F, ANISO_MU_B, ANISO_MU_T = range(4)
N_ANISO = 4
NO_ANISO = np.zeros(N_ANISO)
_MU_FLOOR = 1e-9  # a zero coefficient in the scaled disk problem: no friction along that axis

# ``_step_body``'s arguments, named records (numba compiles a namedtuple as a struct of its fields, read by name;
# building one in compiled code, as ``rigid_chain.rigid_segments_step`` does, costs nothing).
# The boxes' arrays (module docstring): c (n, 3) [m], q (n, 4), v (n, 3) [m/s], w (n, 3) [rad/s], impulse_cache
# (n, 8, 3) [N s] UPDATED; mass (n,) [kg], inertia_body (n, 3) [kg m^2], half_extents (n, 3) [m]; force (n, 3) [N],
# torque (n, 3) [N m] read
BoxArrays = namedtuple("BoxArrays", "c q v w mass inertia_body half_extents force torque impulse_cache")
# the contact's scalars (``advance``): mu, restitution, bounce_threshold [m/s], n_velocity_iterations,
# velocity_tolerance [m/s], n_position_iterations, beta (``advance``'s position_beta), slop [m]
ContactParams = namedtuple("ContactParams", "mu restitution bounce_threshold n_velocity_iterations "
                                            "velocity_tolerance n_position_iterations beta slop")
# the step's scratch, overwritten: R, Iw (3, 3) and ``_solve_contacts``' corner_of ... lam
ContactScratch = namedtuple("ContactScratch", "R Iw corner_of lin ang resp kn kt target lam")

# Below this rotation angle [rad] sin(a/2)/a is replaced by its Taylor series
# 1/2 - a^2/48; the neglected a^4/3840 term is far below round-off there.
_SMALL_ANGLE = 1e-4


# --------------------------------------------------------------------------
# Scalar quaternion and matrix helpers (tuples: no heap allocation)
# --------------------------------------------------------------------------

@njit(cache=True)
def _qmul(aw, ax, ay, az, bw, bx, by, bz):
    """Hamilton product a b of two quaternions given as scalars; returns (w, x, y, z)."""
    return (aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw)


@njit(cache=True)
def _qnormalize(qw, qx, qy, qz):
    """Unit quaternion along (qw, qx, qy, qz); the zero quaternion maps to identity."""
    n = math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz)
    if n == 0.0:
        return 1.0, 0.0, 0.0, 0.0
    return qw / n, qx / n, qy / n, qz / n


@njit(cache=True)
def _q_from_rotvec(rx, ry, rz):
    """Unit quaternion of the rotation by |r| [rad] about r / |r| (exp map)."""
    angle = math.sqrt(rx * rx + ry * ry + rz * rz)
    if angle < _SMALL_ANGLE:
        s = 0.5 - angle * angle / 48.0
    else:
        s = math.sin(0.5 * angle) / angle
    return math.cos(0.5 * angle), s * rx, s * ry, s * rz


@njit(cache=True)
def _rotation_matrix(qw, qx, qy, qz, R):
    """Overwrite R (3, 3) with the rotation matrix of the unit quaternion q."""
    R[0, 0] = 1.0 - 2.0 * (qy * qy + qz * qz)
    R[0, 1] = 2.0 * (qx * qy - qw * qz)
    R[0, 2] = 2.0 * (qx * qz + qw * qy)
    R[1, 0] = 2.0 * (qx * qy + qw * qz)
    R[1, 1] = 1.0 - 2.0 * (qx * qx + qz * qz)
    R[1, 2] = 2.0 * (qy * qz - qw * qx)
    R[2, 0] = 2.0 * (qx * qz - qw * qy)
    R[2, 1] = 2.0 * (qy * qz + qw * qx)
    R[2, 2] = 1.0 - 2.0 * (qx * qx + qy * qy)


@njit(cache=True)
def _world_inverse_inertia(R, i0, i1, i2, Iw):
    """Overwrite Iw (3, 3) with I_world^-1 = R diag(1/I_body) R^T (Baraff 1997 I, Sec. 2.10)."""
    for a in range(3):
        for b in range(3):
            Iw[a, b] = R[a, 0] * R[b, 0] / i0 + R[a, 1] * R[b, 1] / i1 + R[a, 2] * R[b, 2] / i2


@njit(cache=True)
def _cross(ax, ay, az, bx, by, bz):
    return ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx


@njit(cache=True)
def _tangent_basis(nx, ny, nz):
    """Two unit tangents (t1, t2) with t1, t2, n right-handed-orthonormal; deterministic in n.

    t1 is the world x axis (or z when n is nearly along x) projected onto the
    tangent plane, so that on a plane or slope the basis is the same every step.
    """
    if abs(nx) < 0.9:
        ax, ay, az = 1.0, 0.0, 0.0
    else:
        ax, ay, az = 0.0, 0.0, 1.0
    d = ax * nx + ay * ny + az * nz
    tx, ty, tz = ax - d * nx, ay - d * ny, az - d * nz
    tn = math.sqrt(tx * tx + ty * ty + tz * tz)
    tx, ty, tz = tx / tn, ty / tn, tz / tn
    sx, sy, sz = _cross(nx, ny, nz, tx, ty, tz)
    return tx, ty, tz, sx, sy, sz


# --------------------------------------------------------------------------
# Public quaternion kernels (arrays in, arrays out)
# --------------------------------------------------------------------------

@njit(cache=True)
def quat_multiply(a, b, out):
    """Hamilton product out[k] = a[k] b[k].

    a, b, out: (n, 4) quaternions (w, x, y, z).  Overwrites out; out may alias a or b.
    """
    for k in range(a.shape[0]):
        r = _qmul(a[k, 0], a[k, 1], a[k, 2], a[k, 3], b[k, 0], b[k, 1], b[k, 2], b[k, 3])
        out[k, 0], out[k, 1], out[k, 2], out[k, 3] = r


@njit(cache=True)
def quat_normalize(q, out):
    """out[k] = q[k] / |q[k]| (the zero quaternion becomes the identity).

    q, out: (n, 4).  Overwrites out; out may alias q.
    """
    for k in range(q.shape[0]):
        r = _qnormalize(q[k, 0], q[k, 1], q[k, 2], q[k, 3])
        out[k, 0], out[k, 1], out[k, 2], out[k, 3] = r


@njit(cache=True)
def quat_to_matrix(q, out):
    """Rotation matrices of unit quaternions: p_world = out[k] @ p_body.

    q: (n, 4) unit quaternions (w, x, y, z); out: (n, 3, 3), overwritten.
    """
    for k in range(q.shape[0]):
        _rotation_matrix(q[k, 0], q[k, 1], q[k, 2], q[k, 3], out[k])


@njit(cache=True)
def quat_from_axis_angle(axis, angle, out):
    """Unit quaternions of rotations by angle[k] [rad] about axis[k].

    axis: (n, 3) [-], need not be unit (a zero axis gives the identity);
    angle: (n,) [rad]; out: (n, 4), overwritten.
    """
    for k in range(axis.shape[0]):
        ax, ay, az = axis[k, 0], axis[k, 1], axis[k, 2]
        na = math.sqrt(ax * ax + ay * ay + az * az)
        if na == 0.0:
            out[k, 0], out[k, 1], out[k, 2], out[k, 3] = 1.0, 0.0, 0.0, 0.0
            continue
        s = math.sin(0.5 * angle[k]) / na
        out[k, 0] = math.cos(0.5 * angle[k])
        out[k, 1], out[k, 2], out[k, 3] = s * ax, s * ay, s * az


@njit(cache=True)
def quat_integrate(q, w, dt, out):
    """Orientation after dt at constant world-frame angular velocity w.

    Integrates dq/dt = 1/2 (0, w) q (Baraff 1997 I, Sec. 4) exactly for constant
    w: out = exp(dt w / 2) q, renormalized.  q, out: (n, 4); w: (n, 3) [rad/s];
    dt [s].  Overwrites out; out may alias q.
    """
    for k in range(q.shape[0]):
        dw, dx, dy, dz = _q_from_rotvec(dt * w[k, 0], dt * w[k, 1], dt * w[k, 2])
        r = _qmul(dw, dx, dy, dz, q[k, 0], q[k, 1], q[k, 2], q[k, 3])
        out[k, 0], out[k, 1], out[k, 2], out[k, 3] = _qnormalize(r[0], r[1], r[2], r[3])


# --------------------------------------------------------------------------
# Bodies: inertia, forces at points, attached points, energy
# --------------------------------------------------------------------------

@njit(cache=True)
def box_inertia(mass, half_extents, out):
    """Principal moments of inertia of solid uniform boxes about their centre.

    Baraff 1997 I, Sec. 2.10 (block of sides x0, y0, z0): Ixx = M (y0^2 + z0^2) / 12;
    with half-extents h = side / 2 this is M (hy^2 + hz^2) / 3.
    mass: (n,) [kg]; half_extents: (n, 3) [m]; out: (n, 3) [kg m^2], overwritten.
    """
    for k in range(mass.shape[0]):
        hx2 = half_extents[k, 0] ** 2
        hy2 = half_extents[k, 1] ** 2
        hz2 = half_extents[k, 2] ** 2
        out[k, 0] = mass[k] * (hy2 + hz2) / 3.0
        out[k, 1] = mass[k] * (hx2 + hz2) / 3.0
        out[k, 2] = mass[k] * (hx2 + hy2) / 3.0


@njit(cache=True)
def accumulate_point_forces(body, points, forces, c, force_acc, torque_acc):
    """Add forces applied at world points to the bodies' force and torque accumulators.

    Baraff 1997 I, Sec. 2.7: F = sum f_k, tau = sum (p_k - c) x f_k.  This is how
    the FEM coupling pushes on rigid segments (myriapod paper Sec. 3, step 2).
    body: (k,) int body index of each force; points: (k, 3) [m] world application
    points; forces: (k, 3) [N]; c: (n, 3) [m].  ACCUMULATES into force_acc (n, 3) [N]
    and torque_acc (n, 3) [N m] (torque about each body's centre of mass).

    A run of consecutive points on the same body (the attached nodes come sorted by body) is
    summed in registers and stored once: the same additions in the same order as adding each
    point into the accumulators in memory, so the same doubles, without a chain of dependent
    loads and stores through memory from one point to the next.
    """
    n = body.shape[0]
    k = 0
    while k < n:
        i = body[k]
        cx, cy, cz = c[i, 0], c[i, 1], c[i, 2]
        sfx, sfy, sfz = force_acc[i, 0], force_acc[i, 1], force_acc[i, 2]
        stx, sty, stz = torque_acc[i, 0], torque_acc[i, 1], torque_acc[i, 2]
        while k < n and body[k] == i:
            fx, fy, fz = forces[k, 0], forces[k, 1], forces[k, 2]
            tx, ty, tz = _cross(points[k, 0] - cx, points[k, 1] - cy, points[k, 2] - cz, fx, fy, fz)
            sfx += fx
            sfy += fy
            sfz += fz
            stx += tx
            sty += ty
            stz += tz
            k += 1
        force_acc[i, 0], force_acc[i, 1], force_acc[i, 2] = sfx, sfy, sfz
        torque_acc[i, 0], torque_acc[i, 1], torque_acc[i, 2] = stx, sty, stz


@njit(cache=True)
def body_points_to_world(body, local, c, q, out):
    """World positions of points fixed in bodies: out[k] = c[b] + R(q[b]) local[k], b = body[k].

    Moves FEM nodes attached to a rigid segment with it (myriapod paper Sec. 3, step 3).
    body: (k,) int; local: (k, 3) [m] body-frame coordinates; c: (n, 3) [m];
    q: (n, 4); out: (k, 3) [m], overwritten.
    """
    R = np.empty((3, 3))
    for k in range(body.shape[0]):
        i = body[k]
        _rotation_matrix(q[i, 0], q[i, 1], q[i, 2], q[i, 3], R)
        px, py, pz = _matvec(R, local[k, 0], local[k, 1], local[k, 2])
        out[k, 0] = c[i, 0] + px
        out[k, 1] = c[i, 1] + py
        out[k, 2] = c[i, 2] + pz


@njit(cache=True)
def point_velocities(body, points, c, v, w, out):
    """Velocities of world points moving with bodies: out[k] = v[b] + w[b] x (points[k] - c[b]).

    Baraff 1997 I, Sec. 2.5.  body: (k,) int; points: (k, 3) [m] world; c: (n, 3) [m];
    v: (n, 3) [m/s]; w: (n, 3) [rad/s]; out: (k, 3) [m/s], overwritten.
    """
    for k in range(body.shape[0]):
        i = body[k]
        ux, uy, uz = _cross(w[i, 0], w[i, 1], w[i, 2], points[k, 0] - c[i, 0],
                            points[k, 1] - c[i, 1], points[k, 2] - c[i, 2])
        out[k, 0] = v[i, 0] + ux
        out[k, 1] = v[i, 1] + uy
        out[k, 2] = v[i, 2] + uz


@njit(cache=True)
def energy(c, q, v, w, mass, inertia_body, gravity, out):
    """Mechanical energy per body [J].

    out[:, 0] = 1/2 m |v|^2 (linear kinetic), out[:, 1] = 1/2 w . I_world w
    (rotational kinetic, Baraff 1997 I, Sec. 2.10), out[:, 2] = -m g . c
    (gravitational potential, zero at the origin; m g y for g = (0, -g, 0)).
    gravity: (3,) [m/s^2]; out: (n, 3) [J], overwritten.
    """
    R = np.empty((3, 3))
    for i in range(c.shape[0]):
        m = mass[i]
        out[i, 0] = 0.5 * m * (v[i, 0] ** 2 + v[i, 1] ** 2 + v[i, 2] ** 2)
        _rotation_matrix(q[i, 0], q[i, 1], q[i, 2], q[i, 3], R)
        bx, by, bz = _matTvec(R, w[i, 0], w[i, 1], w[i, 2])
        out[i, 1] = 0.5 * (inertia_body[i, 0] * bx * bx + inertia_body[i, 1] * by * by
                           + inertia_body[i, 2] * bz * bz)
        out[i, 2] = -m * (gravity[0] * c[i, 0] + gravity[1] * c[i, 1] + gravity[2] * c[i, 2])


# --------------------------------------------------------------------------
# Torque-free rotation (drift)
# --------------------------------------------------------------------------

@njit(cache=True)
def _axis_flow(axis, h, qw, qx, qy, qz, l0, l1, l2, i0, i1, i2):
    """Exact flow of the free rigid body restricted to T_k = L_k^2 / (2 I_k) for time h.

    The body spins about its own axis k by theta = h L_k / I_k: q <- q exp(theta e_k / 2)
    (a body-frame rotation, so it multiplies on the right); the world angular
    momentum is fixed, so its body components turn the other way, by -theta.
    """
    if axis == 0:
        theta = h * l0 / i0
    elif axis == 1:
        theta = h * l1 / i1
    else:
        theta = h * l2 / i2
    ch = math.cos(0.5 * theta)
    sh = math.sin(0.5 * theta)
    ct = math.cos(theta)
    st = math.sin(theta)
    if axis == 0:
        q = _qmul(qw, qx, qy, qz, ch, sh, 0.0, 0.0)
        l1, l2 = ct * l1 + st * l2, -st * l1 + ct * l2
    elif axis == 1:
        q = _qmul(qw, qx, qy, qz, ch, 0.0, sh, 0.0)
        l0, l2 = ct * l0 - st * l2, st * l0 + ct * l2
    else:
        q = _qmul(qw, qx, qy, qz, ch, 0.0, 0.0, sh)
        l0, l1 = ct * l0 + st * l1, -st * l0 + ct * l1
    return q[0], q[1], q[2], q[3], l0, l1, l2


@njit(cache=True)
def _free_rotation(h, qw, qx, qy, qz, l0, l1, l2, i0, i1, i2):
    """Torque-free rotation over h by Strang splitting x(h/2) y(h/2) z(h) y(h/2) x(h/2).

    Second order, symplectic and time-reversible (McLachlan 1993); each sub-flow
    is a rotation, so |L| and the world vector L are kept to round-off.
    (l0, l1, l2): body-frame angular momentum [kg m^2/s].  Returns (q, L_body).
    """
    # np.int64 axes, not the literals: a Literal[int] argument compiles one signature of _axis_flow per axis
    qw, qx, qy, qz, l0, l1, l2 = _axis_flow(np.int64(0), 0.5 * h, qw, qx, qy, qz, l0, l1, l2, i0, i1, i2)
    qw, qx, qy, qz, l0, l1, l2 = _axis_flow(np.int64(1), 0.5 * h, qw, qx, qy, qz, l0, l1, l2, i0, i1, i2)
    qw, qx, qy, qz, l0, l1, l2 = _axis_flow(np.int64(2), h, qw, qx, qy, qz, l0, l1, l2, i0, i1, i2)
    qw, qx, qy, qz, l0, l1, l2 = _axis_flow(np.int64(1), 0.5 * h, qw, qx, qy, qz, l0, l1, l2, i0, i1, i2)
    qw, qx, qy, qz, l0, l1, l2 = _axis_flow(np.int64(0), 0.5 * h, qw, qx, qy, qz, l0, l1, l2, i0, i1, i2)
    return qw, qx, qy, qz, l0, l1, l2


# --------------------------------------------------------------------------
# Contact with the terrain
# --------------------------------------------------------------------------

@njit(cache=True)
def _inv_mass_along(inv_m, Iw, rx, ry, rz, ax, ay, az, bx, by, bz):
    """Entry a^T K b of the point's inverse effective mass K = 1/m - [r]x I_w^-1 [r]x [1/kg].

    The denominator of Baraff's collision impulse (Rigid Body Simulation II, Sec. 8):
    1/m + a . ((I_w^-1 (r x b)) x r) = 1/m a.b + (r x a) . I_w^-1 (r x b).
    """
    ux, uy, uz = _cross(rx, ry, rz, ax, ay, az)
    sx, sy, sz = _cross(rx, ry, rz, bx, by, bz)
    tx, ty, tz = _matvec(Iw, sx, sy, sz)
    return inv_m * (ax * bx + ay * by + az * bz) + ux * tx + uy * ty + uz * tz


@njit(cache=True)
def _coulomb_friction_impulse(a, b, d, ia, ib, id_, u1, u2, limit):
    """Friction impulse (l1, l2) [N s] of one contact, with maximum dissipation.

    u = (u1, u2) [m/s]: tangential slip velocity without this impulse; after it
    the slip is u + K l, with K = [[a, b], [b, d]] [1/kg] the tangential inverse
    effective mass and (ia, ib, id_) the entries of K^-1.  limit = mu lam_n [N s].

    Static: l = -K^-1 u (zero slip) when |l| <= limit.  Kinetic otherwise: l on
    the rim |l| = limit opposing the resulting slip, u + K l = -alpha l with
    alpha > 0 (Coulomb's law with maximum dissipation), i.e. l = -(K + alpha I)^-1 u.
    |l(alpha)| decreases monotonically, and 1/|l(alpha)| is concave in alpha, so
    Newton on 1/|l| - 1/limit from alpha = 0 converges monotonically (the secular
    equation of trust-region methods, More & Sorensen 1983).  Taking the K-metric
    projection instead of the Euclidean one matters: K of a box corner is
    anisotropic, and scaling -K^-1 u radially onto the disk tilts the friction
    away from the slip and under-brakes a sliding box by about 6 %; using -u/|u|
    instead is discontinuous at the stick/slip switch and makes a box creep on
    a slope it should stick to.
    """
    l1 = -(ia * u1 + ib * u2)
    l2 = -(ib * u1 + id_ * u2)
    if l1 * l1 + l2 * l2 <= limit * limit:
        return l1, l2
    if limit <= 0.0:
        return 0.0, 0.0
    alpha = 0.0
    for _ in range(30):
        # (K + alpha I)^-1 by its adjugate.
        pa, pd = a + alpha, d + alpha
        det = pa * pd - b * b
        m00, m01, m11 = pd / det, -b / det, pa / det
        l1 = -(m00 * u1 + m01 * u2)
        l2 = -(m01 * u1 + m11 * u2)
        nl = math.sqrt(l1 * l1 + l2 * l2)
        if nl <= limit * (1.0 + 1e-12):
            break
        # d(1/|l|)/d alpha = l^T (K + alpha I)^-1 l / |l|^3
        slope = (l1 * (m00 * l1 + m01 * l2) + l2 * (m01 * l1 + m11 * l2)) / (nl * nl * nl)
        alpha += (1.0 / limit - 1.0 / nl) / slope
    # Newton approaches the rim from outside; land on it exactly.
    scale = limit / math.sqrt(l1 * l1 + l2 * l2)
    return l1 * scale, l2 * scale


@njit(cache=True)
def _hu_friction_impulse(a, b, d, u1, u2, m1, m2, lam_n):
    """Anisotropic friction impulse (l1, l2) [N s] of one contact by Hu et al.'s law (PNAS 2009).

    Axis 1 is the box's forward axis on the surface, axis 2 across it; m1 = mu_f or mu_b, m2 = mu_t
    (> 0); lam_n [N s] the normal impulse; u = (u1, u2) [m/s] the slip without this impulse and
    K = [[a, b], [b, d]] [1/kg] the tangential inverse effective mass (slip after: u + K l).
    Static: l = -K^-1 u when it lies in the ellipse (l1 / m1)^2 + (l2 / m2)^2 <= lam_n^2.
    Kinetic: Hu et al.'s friction l = -lam_n (m1 s1, m2 s2) with s the unit direction of the
    resulting slip u + K l, the law the point nodes (``friction_kernels``, COULOMB) and the
    kinematic reference (``reference.slithering``) use.  (The maximum-dissipation point of the
    same ellipse, -lam_n (m1^2 s1, m2^2 s2) / |M s|, resists a small sideways slip mu_t / mu_f
    times harder, so the hybrid snake's boxes barely slipped sideways and it slithered 62 %
    faster than the reference at mu_t / mu_f = 5; issue 11.)
    With l = M l', M = diag(m1, m2): u + K M l' = -alpha l' for some alpha > 0 and |l'| = lam_n,
    i.e. l' = -(K M + alpha I)^-1 u; 1 / |l'(alpha)| - 1 / lam_n is solved for alpha by Newton,
    kept inside a bisection bracket.
    """
    det0 = a * d - b * b
    l1 = -(d * u1 - b * u2) / det0
    l2 = -(-b * u1 + a * u2) / det0
    if (l1 / m1) ** 2 + (l2 / m2) ** 2 <= lam_n * lam_n:
        return l1, l2
    if lam_n <= 0.0:
        return 0.0, 0.0
    lo, hi = 0.0, -1.0  # |l'(lo)| > lam_n; hi: first alpha found with |l'| < lam_n
    alpha = 0.0
    p1 = p2 = 0.0
    for _ in range(60):
        a11, a12, a21, a22 = a * m1 + alpha, b * m2, b * m1, d * m2 + alpha
        det = a11 * a22 - a12 * a21
        p1 = -(a22 * u1 - a12 * u2) / det
        p2 = -(-a21 * u1 + a11 * u2) / det
        nl = math.sqrt(p1 * p1 + p2 * p2)
        if abs(nl - lam_n) <= 1e-10 * lam_n:
            break
        if nl > lam_n:
            lo = alpha
        else:
            hi = alpha
        # Newton on 1/|l'| - 1/lam_n: d l'/d alpha = -A^-1 l', so d(1/|l'|)/d alpha = l'.A^-1 l' / |l'|^3
        q1 = (a22 * p1 - a12 * p2) / det
        q2 = (-a21 * p1 + a11 * p2) / det
        slope = (p1 * q1 + p2 * q2) / (nl * nl * nl)
        nxt = alpha + (1.0 / lam_n - 1.0 / nl) / slope if slope > 0.0 else -1.0
        if hi < 0.0:
            if nxt <= lo:
                nxt = 2.0 * lo + (a * m1 + d * m2)
        elif nxt <= lo or nxt >= hi:
            nxt = 0.5 * (lo + hi)
        alpha = nxt
    scale = lam_n / math.sqrt(p1 * p1 + p2 * p2)
    return m1 * p1 * scale, m2 * p2 * scale


@njit(cache=True, error_model="numpy", inline="always")
def _corner(R, c, i, corner, hx, hy, hz):
    """(r, p): corner ``corner`` (0-7; bits 0, 1, 2 set: +x, +y, +z) of box i, with half extents (hx, hy, hz)
    [m] and rotation matrix R, relative to its centre c[i] (r) and in the world (p = c[i] + r) [m]; the
    contact loop's and the position projection's corners."""
    sx = 1.0 if (corner & 1) else -1.0
    sy = 1.0 if (corner & 2) else -1.0
    sz = 1.0 if (corner & 4) else -1.0
    rx, ry, rz = _matvec(R, sx * hx, sy * hy, sz * hz)
    return rx, ry, rz, c[i, 0] + rx, c[i, 1] + ry, c[i, 2] + rz


# inlined into its one caller, _step_body: as a kernel of its own numba would optimize and emit its
# machine code twice (once alone, once linked into _step_body), seconds of compile (README Development notes)
@njit(cache=True, inline="always")
def _solve_contacts(i, boxes, kind, f, contact, scratch, aniso=NO_ANISO):
    """Velocity-level contact of body i's 8 corners with the terrain; updates v[i], w[i].  boxes: a
    ``BoxArrays``, contact: a ``ContactParams``, scratch: a ``ContactScratch`` (named records);
    R, Iw: body i's rotation and world inverse inertia.

    Contacts are the corners with phi < 0.  Each gets a normal impulse lam_n >= 0
    whose target is a separating normal velocity of -e v_n^- when the approach
    speed exceeds ``bounce_threshold`` (Newton's restitution law, Baraff II Sec. 8)
    and 0 otherwise, so that the small approach speed a resting box gains from
    gravity in one step does not make it hop.

    Friction is a 2D tangential impulse lam_t in the Coulomb disk
    |lam_t| <= mu lam_n, found by ``_coulomb_friction_impulse`` from the slip
    velocity u the contact would have without its own friction impulse: static
    when the impulse that stops the slip is inside the disk, kinetic (on the
    rim, opposing the resulting slip) otherwise.

    Anisotropic friction (``aniso[ANISO_ON]`` set: a body segment with scales, Hu et al. 2009):
    the tangent basis is the box's x axis (forward) projected on the surface and its normal
    cross product, and the friction set is the ellipse |l_1 / mu_1|^2 + |l_2 / mu_2|^2 <=
    lam_n^2 with mu_1 = mu_f or mu_b by the sign of the forward slip and mu_2 = mu_t; a sliding
    contact takes Hu et al.'s point of it, -lam_n (mu_1 s_1, mu_2 s_2) for the unit slip s
    (``_hu_friction_impulse``), as the point nodes do.

    Projected Gauss-Seidel over the contacts on accumulated impulses
    (sequential impulses; Catto 2005), warm-started with the impulses the same
    corners took in the previous step (``impulse_cache`` (n, 8, 3) [N s],
    normal, t1, t2; read, then OVERWRITTEN for body i, zero for corners out of
    contact), and stopped after ``n_iterations`` sweeps or as soon as no impulse
    of a sweep changes the body's velocity by more than ``tolerance`` [m/s].
    Warm starting makes a resting box converge in a sweep or two and leaves no
    residual creep on a slope it sticks to.

    Each contact has three rows k (normal, tangent 1, tangent 2) with direction
    d_k: the velocity along a row is d_k . v + (r x d_k) . w, and an impulse p
    along it changes v by p d_k / m and w by p I_w^-1 (r x d_k).
    Scratch (overwritten): corner_of (8,) int; lin, ang, resp (8, 3, 3) holding
    d_k, r x d_k and I_w^-1 (r x d_k) per contact and row; kn, target (8,);
    kt (8, 6) the 2x2 tangential inverse effective mass K_t (a, b, d) and its
    inverse; lam (8, 3) accumulated impulses.  Returns the contact count.
    """
    c, v, w, mass, half_extents, impulse_cache = (boxes.c, boxes.v, boxes.w, boxes.mass, boxes.half_extents,
                                                  boxes.impulse_cache)
    mu, restitution, bounce_threshold = contact.mu, contact.restitution, contact.bounce_threshold
    n_iterations, tolerance = contact.n_velocity_iterations, contact.velocity_tolerance
    R, Iw, corner_of, lin, ang = scratch.R, scratch.Iw, scratch.corner_of, scratch.lin, scratch.ang
    resp, kn, kt, target, lam = scratch.resp, scratch.kn, scratch.kt, scratch.target, scratch.lam
    inv_m = 1.0 / mass[i]
    aniso_on = aniso[ANISO_ON] != 0.0
    hx, hy, hz = half_extents[i, 0], half_extents[i, 1], half_extents[i, 2]
    vx, vy, vz = v[i, 0], v[i, 1], v[i, 2]
    wx, wy, wz = w[i, 0], w[i, 1], w[i, 2]
    nc = 0
    V = clearance_view(kind, f)  # the terrain's scalars for the corners' tests
    for corner in range(N_CORNERS):
        rx, ry, rz, px, py, pz = _corner(R, c, i, corner, hx, hy, hz)
        # signed_distance >= 0, without an obstacle search above them (``clearance``, else ``distance_at_least``)
        kc = clearance_cell(V, px, pz, 0.0)
        cl = clearance(V, f[kc] if kc >= 0 else 0.0, py, 0.0, kc)
        if (cl > 0) if cl >= 0 else distance_at_least(kind, f, px, py, pz, 0.0):
            continue
        nx, ny, nz = surface_normal(kind, f, px, py, pz)
        t1x, t1y, t1z, t2x, t2y, t2z = _tangent_basis(nx, ny, nz)
        if aniso_on:
            # the box's forward axis (first column of R) on the tangent plane
            ex, ey, ez = R[0, 0], R[1, 0], R[2, 0]
            dn = ex * nx + ey * ny + ez * nz
            ex, ey, ez = ex - dn * nx, ey - dn * ny, ez - dn * nz
            el = math.sqrt(ex * ex + ey * ey + ez * ez)
            if el > 1e-9:
                t1x, t1y, t1z = ex / el, ey / el, ez / el
                t2x, t2y, t2z = _cross(nx, ny, nz, t1x, t1y, t1z)
        lin[nc, 0, 0], lin[nc, 0, 1], lin[nc, 0, 2] = nx, ny, nz
        lin[nc, 1, 0], lin[nc, 1, 1], lin[nc, 1, 2] = t1x, t1y, t1z
        lin[nc, 2, 0], lin[nc, 2, 1], lin[nc, 2, 2] = t2x, t2y, t2z
        for k in range(3):
            ax, ay, az = _cross(rx, ry, rz, lin[nc, k, 0], lin[nc, k, 1], lin[nc, k, 2])
            ang[nc, k, 0], ang[nc, k, 1], ang[nc, k, 2] = ax, ay, az
            resp[nc, k, 0], resp[nc, k, 1], resp[nc, k, 2] = _matvec(Iw, ax, ay, az)
        kn[nc] = 1.0 / _inv_mass_along(inv_m, Iw, rx, ry, rz, nx, ny, nz, nx, ny, nz)
        a = _inv_mass_along(inv_m, Iw, rx, ry, rz, t1x, t1y, t1z, t1x, t1y, t1z)
        b = _inv_mass_along(inv_m, Iw, rx, ry, rz, t1x, t1y, t1z, t2x, t2y, t2z)
        d = _inv_mass_along(inv_m, Iw, rx, ry, rz, t2x, t2y, t2z, t2x, t2y, t2z)
        det = a * d - b * b
        kt[nc, 0], kt[nc, 1], kt[nc, 2] = a, b, d
        kt[nc, 3], kt[nc, 4], kt[nc, 5] = d / det, -b / det, a / det
        vn = (nx * vx + ny * vy + nz * vz
              + ang[nc, 0, 0] * wx + ang[nc, 0, 1] * wy + ang[nc, 0, 2] * wz)
        target[nc] = -restitution * vn if vn < -bounce_threshold else 0.0
        corner_of[nc] = corner
        for k in range(3):
            lam[nc, k] = impulse_cache[i, corner, k]
        nc += 1

    # Warm start: apply last step's impulses of the corners still in contact.
    for j in range(nc):
        for k in range(3):
            p = lam[j, k]
            vx += p * inv_m * lin[j, k, 0]
            vy += p * inv_m * lin[j, k, 1]
            vz += p * inv_m * lin[j, k, 2]
            wx += p * resp[j, k, 0]
            wy += p * resp[j, k, 1]
            wz += p * resp[j, k, 2]

    for _ in range(n_iterations):
        change = 0.0
        for j in range(nc):
            # Normal: drive v_n to its target, keeping the accumulated impulse >= 0.
            vn = (lin[j, 0, 0] * vx + lin[j, 0, 1] * vy + lin[j, 0, 2] * vz
                  + ang[j, 0, 0] * wx + ang[j, 0, 1] * wy + ang[j, 0, 2] * wz)
            new = max(lam[j, 0] + kn[j] * (target[j] - vn), 0.0)
            p = new - lam[j, 0]
            lam[j, 0] = new
            vx += p * inv_m * lin[j, 0, 0]
            vy += p * inv_m * lin[j, 0, 1]
            vz += p * inv_m * lin[j, 0, 2]
            wx += p * resp[j, 0, 0]
            wy += p * resp[j, 0, 1]
            wz += p * resp[j, 0, 2]
            # Friction: slip velocity u without this contact's own friction impulse.
            v1 = (lin[j, 1, 0] * vx + lin[j, 1, 1] * vy + lin[j, 1, 2] * vz
                  + ang[j, 1, 0] * wx + ang[j, 1, 1] * wy + ang[j, 1, 2] * wz)
            v2 = (lin[j, 2, 0] * vx + lin[j, 2, 1] * vy + lin[j, 2, 2] * vz
                  + ang[j, 2, 0] * wx + ang[j, 2, 1] * wy + ang[j, 2, 2] * wz)
            u1 = v1 - (kt[j, 0] * lam[j, 1] + kt[j, 1] * lam[j, 2])
            u2 = v2 - (kt[j, 1] * lam[j, 1] + kt[j, 2] * lam[j, 2])
            if aniso_on:
                m1 = max(aniso[ANISO_MU_F] if u1 > 0.0 else aniso[ANISO_MU_B], _MU_FLOOR)
                m2 = max(aniso[ANISO_MU_T], _MU_FLOOR)
                l1, l2 = _hu_friction_impulse(kt[j, 0], kt[j, 1], kt[j, 2], u1, u2, m1, m2, lam[j, 0])
            else:
                l1, l2 = _coulomb_friction_impulse(kt[j, 0], kt[j, 1], kt[j, 2], kt[j, 3],
                                                   kt[j, 4], kt[j, 5], u1, u2, mu * lam[j, 0])
            p1 = l1 - lam[j, 1]
            p2 = l2 - lam[j, 2]
            lam[j, 1] = l1
            lam[j, 2] = l2
            vx += inv_m * (p1 * lin[j, 1, 0] + p2 * lin[j, 2, 0])
            vy += inv_m * (p1 * lin[j, 1, 1] + p2 * lin[j, 2, 1])
            vz += inv_m * (p1 * lin[j, 1, 2] + p2 * lin[j, 2, 2])
            wx += p1 * resp[j, 1, 0] + p2 * resp[j, 2, 0]
            wy += p1 * resp[j, 1, 1] + p2 * resp[j, 2, 1]
            wz += p1 * resp[j, 1, 2] + p2 * resp[j, 2, 2]
            change = max(change, inv_m * (abs(p) + math.sqrt(p1 * p1 + p2 * p2)))
        if change <= tolerance:
            break
    v[i, 0], v[i, 1], v[i, 2] = vx, vy, vz
    w[i, 0], w[i, 1], w[i, 2] = wx, wy, wz
    for corner in range(N_CORNERS):
        for k in range(3):
            impulse_cache[i, corner, k] = 0.0
    for j in range(nc):
        for k in range(3):
            impulse_cache[i, corner_of[j], k] = lam[j, k]
    return nc


# inlined into its one caller, _step_body: as a kernel of its own numba would optimize and emit its
# machine code twice (once alone, once linked into _step_body), seconds of compile (README Development notes)
@njit(cache=True, inline="always")
def _project_positions(i, c, q, mass, inertia_body, half_extents, R, Iw, kind, f,
                       n_iterations, beta, slop):
    """Push body i's corners out of the terrain by moving its pose (not its velocity).

    Non-linear Gauss-Seidel over corners deeper than ``slop``: the correction
    impulse P = -beta (phi + slop) / K along the normal (K as in the collision
    impulse) moves c by P n / m and turns the body by I_w^-1 (r x n) P.  The slop
    keeps resting corners slightly inside, so the contact set does not flicker.
    Overwrites c[i], q[i], and the scratch R, Iw (left at the final pose).
    """
    inv_m = 1.0 / mass[i]
    i0, i1, i2 = inertia_body[i, 0], inertia_body[i, 1], inertia_body[i, 2]
    hx, hy, hz = half_extents[i, 0], half_extents[i, 1], half_extents[i, 2]
    V = clearance_view(kind, f)
    for _ in range(n_iterations):
        moved = False
        for corner in range(N_CORNERS):
            rx, ry, rz, px, py, pz = _corner(R, c, i, corner, hx, hy, hz)
            kc = clearance_cell(V, px, pz, -slop)
            cl = clearance(V, f[kc] if kc >= 0 else 0.0, py, -slop, kc)
            if (cl > 0) if cl >= 0 else distance_at_least(kind, f, px, py, pz, -slop):  # phi >= -slop (as above)
                continue
            phi, nx, ny, nz = distance_and_normal(kind, f, px, py, pz)  # signed_distance, surface_normal
            k = _inv_mass_along(inv_m, Iw, rx, ry, rz, nx, ny, nz, nx, ny, nz)
            p = -beta * (phi + slop) / k
            c[i, 0] += p * nx * inv_m
            c[i, 1] += p * ny * inv_m
            c[i, 2] += p * nz * inv_m
            ax, ay, az = _cross(rx, ry, rz, nx, ny, nz)
            dx, dy, dz = _matvec(Iw, p * ax, p * ay, p * az)
            ew, ex, ey, ez = _q_from_rotvec(dx, dy, dz)
            r = _qmul(ew, ex, ey, ez, q[i, 0], q[i, 1], q[i, 2], q[i, 3])
            q[i, 0], q[i, 1], q[i, 2], q[i, 3] = _qnormalize(r[0], r[1], r[2], r[3])
            _rotation_matrix(q[i, 0], q[i, 1], q[i, 2], q[i, 3], R)
            _world_inverse_inertia(R, i0, i1, i2, Iw)
            moved = True
        if not moved:
            break


# --------------------------------------------------------------------------
# Time stepping
# --------------------------------------------------------------------------

@njit(cache=True)
def _step_body(i, boxes, dt, gravity, kind, f, contact, scratch, aniso=NO_ANISO):
    """Advance dynamic body i by one step dt (kick, contact, drift, projection); boxes: a ``BoxArrays``,
    contact: a ``ContactParams``, scratch: a ``ContactScratch`` (named records); ``aniso``: see
    ``_solve_contacts``."""
    c, q, v, w, mass = boxes.c, boxes.q, boxes.v, boxes.w, boxes.mass
    inertia_body, half_extents, force, torque = boxes.inertia_body, boxes.half_extents, boxes.force, boxes.torque
    n_position_iterations, beta, slop = contact.n_position_iterations, contact.beta, contact.slop
    R, Iw = scratch.R, scratch.Iw
    m = mass[i]
    i0, i1, i2 = inertia_body[i, 0], inertia_body[i, 1], inertia_body[i, 2]
    _rotation_matrix(q[i, 0], q[i, 1], q[i, 2], q[i, 3], R)
    _world_inverse_inertia(R, i0, i1, i2, Iw)

    # Kick (Baraff I, Sec. 2.11): dP/dt = F, dL/dt = tau at the current pose.
    v[i, 0] += dt * (gravity[0] + force[i, 0] / m)
    v[i, 1] += dt * (gravity[1] + force[i, 1] / m)
    v[i, 2] += dt * (gravity[2] + force[i, 2] / m)
    ax, ay, az = _matvec(Iw, torque[i, 0], torque[i, 1], torque[i, 2])
    w[i, 0] += dt * ax
    w[i, 1] += dt * ay
    w[i, 2] += dt * az

    _solve_contacts(i, boxes, kind, f, contact, scratch, aniso)

    # Drift: position with the new velocity; orientation by the torque-free flow
    # at the post-contact angular momentum L = R I_body R^T w.
    c[i, 0] += dt * v[i, 0]
    c[i, 1] += dt * v[i, 1]
    c[i, 2] += dt * v[i, 2]
    bx, by, bz = _matTvec(R, w[i, 0], w[i, 1], w[i, 2])
    qw, qx, qy, qz, l0, l1, l2 = _free_rotation(dt, q[i, 0], q[i, 1], q[i, 2], q[i, 3],
                                                i0 * bx, i1 * by, i2 * bz, i0, i1, i2)
    qw, qx, qy, qz = _qnormalize(qw, qx, qy, qz)
    q[i, 0], q[i, 1], q[i, 2], q[i, 3] = qw, qx, qy, qz
    _rotation_matrix(qw, qx, qy, qz, R)
    w[i, 0], w[i, 1], w[i, 2] = _matvec(R, l0 / i0, l1 / i1, l2 / i2)

    if n_position_iterations > 0:
        _world_inverse_inertia(R, i0, i1, i2, Iw)
        _project_positions(i, c, q, mass, inertia_body, half_extents, R, Iw, kind, f,
                           n_position_iterations, beta, slop)


@njit(cache=True)
def _check_state(c, q, v, w, half_extents, max_speed):
    """Status of the state: non-finite values, or a point moving faster than max_speed."""
    for i in range(c.shape[0]):
        s = 0.0
        for a in range(3):
            s += c[i, a] + v[i, a] + w[i, a]
        s += q[i, 0] + q[i, 1] + q[i, 2] + q[i, 3]
        if not math.isfinite(s):
            return STATUS_NONFINITE
        speed = math.sqrt(v[i, 0] ** 2 + v[i, 1] ** 2 + v[i, 2] ** 2)
        spin = math.sqrt(w[i, 0] ** 2 + w[i, 1] ** 2 + w[i, 2] ** 2)
        radius = math.sqrt(half_extents[i, 0] ** 2 + half_extents[i, 1] ** 2
                           + half_extents[i, 2] ** 2)
        # |v| + |w| r bounds the speed of every point of the box.
        if speed + spin * radius > max_speed:
            return STATUS_RUNAWAY
    return STATUS_OK


@njit(cache=True)
def advance(box_arrays, kinematic, n_steps, dt, gravity, terrain_kind, terrain_params, contact_params, max_speed):
    """Advance all boxes by up to n_steps steps of dt [s]; stop early when unstable.

    box_arrays: a ``BoxArrays`` (c, q, v, w, mass, inertia_body, half_extents, force, torque, impulse_cache)
    and contact_params a ``ContactParams`` (mu, restitution, bounce_threshold, n_velocity_iterations,
    velocity_tolerance, n_position_iterations, beta, slop), as plain tuples (``core.kernel_records``: the
    call's cost), named here.
    State arrays (module docstring) are OVERWRITTEN in place for dynamic bodies;
    kinematic bodies are left untouched.  force (n, 3) [N] and torque (n, 3) [N m]
    are read, not cleared: they act as constant loads over the whole call.
    impulse_cache: (n, 8, 3) [N s] contact impulses (normal, t1, t2) of each
    corner in the last step, used to warm-start the next; updated in place
    (zeros: cold start).
    gravity: (3,) [m/s^2]; terrain_kind, terrain_params: see terrain_kernels.
    mu [-]: Coulomb friction coefficient; restitution [-]: e in [0, 1];
    bounce_threshold [m/s]: approach speeds below it get no bounce;
    n_velocity_iterations: most contact sweeps per step, fewer once a sweep
    changes the velocity by at most velocity_tolerance [m/s];
    n_position_iterations: most penetration-projection sweeps per step;
    position_beta [-] in (0, 1]: fraction of the penetration beyond ``slop`` [m]
    removed per sweep; max_speed [m/s]: a point of a box faster than this is a
    runaway.

    Returns (n_done, status): status STATUS_OK (0) after all n_steps; otherwise
    STATUS_NONFINITE (1) or STATUS_RUNAWAY (2) and n_done counts the steps taken
    including the one that produced the bad state (left in the arrays), so the
    failure time is t0 + n_done dt.
    """
    boxes, contact = BoxArrays(*box_arrays), ContactParams(*contact_params)
    c, q, v, w, half_extents = boxes.c, boxes.q, boxes.v, boxes.w, boxes.half_extents
    corner_of = np.empty(N_CORNERS, dtype=np.int64)
    lin = np.empty((N_CORNERS, 3, 3))
    ang = np.empty((N_CORNERS, 3, 3))
    resp = np.empty((N_CORNERS, 3, 3))
    kt = np.empty((N_CORNERS, 6))
    lam = np.empty((N_CORNERS, 3))
    kn = np.empty(N_CORNERS)
    target = np.empty(N_CORNERS)
    R = np.empty((3, 3))
    Iw = np.empty((3, 3))
    scratch = ContactScratch(R=R, Iw=Iw, corner_of=corner_of, lin=lin, ang=ang, resp=resp, kn=kn, kt=kt,
                             target=target, lam=lam)
    for step in range(n_steps):
        for i in range(c.shape[0]):
            if kinematic[i]:
                continue
            _step_body(i, boxes, dt, gravity, terrain_kind, terrain_params, contact, scratch)
        status = _check_state(c, q, v, w, half_extents, max_speed)
        if status != STATUS_OK:
            return step + 1, status
    return n_steps, STATUS_OK
