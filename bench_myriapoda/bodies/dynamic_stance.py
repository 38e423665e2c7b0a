"""The dynamic stance (issue 43, docs/explanation/dynamic-stance.md): STANCE legs push their segments
through friction-limited feet instead of carrying them kinematically (paper Sec. 3's shortcut).

Per supported segment, per step (``push_segments``):

1. the spring-damper toward the Targeter's pose, integrated implicitly over the step with the links' force
   F_o and moment tau_o on the segment in its last step, gives the velocities
   v' = (v + a v_T + dt F_o / m) / (1 + a), w' = (w + a w_T + dt I_w^-1 tau_o) / (1 + a),
   a = omega^2 dt^2 + 2 zeta omega dt, with v_T = (c_T - c) / dt and w_T = log(R_T R^T) / dt the kinematic
   stance's; the legs, which also carry the weight, ask for F_d = m (v' - v) / dt - F_o - m g [N] and
   tau_d = I_w (w' - w) / dt - tau_o [N m];
2. ``foot_forces``: that wrench shared by the STANCE feet, each foot's force cut to its friction
   cone (Coulomb, coefficient mu) and to the leg's maximum force; what the feet transmit acts on the
   segment as an impulse (v += dt F / m, w += dt I_w^-1 tau);
3. a foot that slid moves (``slide_fraction`` of the stroke the ground did not resist).

The kernels work on plain arrays; the record types below name their parameters
(``StanceParams``) and a body's per-run data (``StanceArrays``).
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from ..core.leg_timeline import STANCE
from ..world.terrain_kernels import distance_and_normal

STANCES = ("kinematic", "dynamic")

# dynamic: 1.0 dynamic stance, 0.0 the paper's kinematic stance; omega [rad/s] the legs' natural frequency;
# zeta [-] their damping ratio; mu [-] the feet's Coulomb coefficient (inf: feet never slide); max_force [N] a
# foot's largest force (<= 0: unbounded)
StanceParams = namedtuple("StanceParams", "dynamic omega zeta mu max_force")

# What a body with rigid segments keeps for the dynamic stance: params a ``StanceParams``; mass (n_seg,) [kg],
# inertia_body (n_seg, 3) [kg m^2] of the segments; gravity (3,) [m/s^2]; force, torque (n_seg, 3) [N], [N m]: the
# other forces on each segment in its last step (the links', about its centre; the body's own accumulators, read
# only); terr_kind, terr the terrain (``terrain_kernels``, for the normal under a foot); acc (N_STANCE_ACC,)
# ACCUMULATES the statistics below; feet scratch: r, nrm, f (2, 3), slide (2,)
StanceArrays = namedtuple("StanceArrays", "params mass inertia_body gravity force torque terr_kind terr acc r nrm f "
                                          "slide")

# statistics (``acc``): foot-steps in STANCE that pushed, those that slid, summed sliding distance [m], summed and
# largest foot force [N], positive mechanical work of the legs on the segments [J], sum of foot force^2 [N^2]
(ACC_FOOT_STEPS, ACC_SLID_STEPS, ACC_SLIP_M, ACC_FORCE_SUM, ACC_FORCE_MAX, ACC_WORK_POS, ACC_FORCE_SQ) = range(7)
N_STANCE_ACC = 7


def stance_params(legs, friction) -> StanceParams:
    """The ``StanceParams`` of a case's ``legs`` and ``friction`` sections (docs/explanation/dynamic-stance.md):
    mu is ``legs.foot_mu``, or at -1 the boxes' ground friction ``friction.mu_transverse`` (inf for the
    ``stick`` model)."""
    if legs.foot_mu >= 0.0:
        mu = float(legs.foot_mu)
    elif friction.model == "stick":
        mu = math.inf
    else:
        mu = float(friction.mu_transverse)
    return StanceParams(1.0 if legs.stance == "dynamic" else 0.0, 2.0 * math.pi * float(legs.stance_frequency_hz),
                        float(legs.stance_damping_ratio), mu, float(legs.max_leg_force_n))


def stance_arrays(params: StanceParams, mass, inertia_body, gravity, force, torque, terr_kind, terr) -> StanceArrays:
    """A body's ``StanceArrays`` (fresh statistics and scratch; force and torque are the body's own arrays)."""
    return StanceArrays(params, np.ascontiguousarray(mass, dtype=np.float64),
                        np.ascontiguousarray(inertia_body, dtype=np.float64),
                        np.ascontiguousarray(gravity, dtype=np.float64), force, torque, terr_kind, terr,
                        np.zeros(N_STANCE_ACC),
                        np.zeros((2, 3)), np.zeros((2, 3)), np.zeros((2, 3)), np.zeros(2))


def stance_statistics(acc: np.ndarray) -> dict[str, float]:
    """The body's dynamic-stance metrics (docs/explanation/dynamic-stance.md, "Measures") from its statistics
    acc (N_STANCE_ACC,): summed slip of the STANCE feet [m], fraction of STANCE foot-steps that slid, mean and
    largest foot force [N], positive work of the legs on the segments [J]."""
    steps = acc[ACC_FOOT_STEPS]
    return {"stance_foot_slip_m": float(acc[ACC_SLIP_M]),
            "stance_slide_fraction": float(acc[ACC_SLID_STEPS] / steps) if steps > 0 else 0.0,
            "leg_force_mean_n": float(acc[ACC_FORCE_SUM] / steps) if steps > 0 else 0.0,
            "leg_force_max_n": float(acc[ACC_FORCE_MAX]),
            "leg_work_positive_j": float(acc[ACC_WORK_POS])}


def per_stride_and_cost(stats: dict, weight_n: float, distance_m: float, strides: float) -> dict[str, float]:
    """``stance_slip_per_stride_m`` (summed foot slip [m] / strides, strides = stride frequency x duration x
    legs) and ``cost_of_transport`` (positive leg work / (weight [N] x net distance of the centre of mass [m]),
    dimensionless) from ``stance_statistics``'s stats; NaN where undefined (no stride, no progress)."""
    slip, work = stats["stance_foot_slip_m"], stats["leg_work_positive_j"]
    return {"stance_slip_per_stride_m": slip / strides if strides > 0 else math.nan,
            "cost_of_transport": work / (weight_n * distance_m) if weight_n * distance_m > 0 else math.nan}


@njit(cache=True, error_model="numpy")
def foot_forces(Fx, Fy, Fz, tx, ty, tz, r, nrm, n_feet, mu, max_force, f, slide):
    """The wrench the STANCE feet of one segment transmit (docs/explanation/dynamic-stance.md, "The feet").

    (Fx, Fy, Fz) [N], (tx, ty, tz) [N m]: the force and the moment about the segment's centre the legs ask
    for; r (>= n_feet, 3) [m]: each foot's position from the centre; nrm (>= n_feet, 3): the unit surface
    normal under each foot; mu [-] the Coulomb coefficient; max_force [N] a foot's largest force (<= 0:
    unbounded).  OVERWRITES f (n_feet, 3) [N] the force the ground gives each foot and slide (n_feet,) the
    fraction of its stroke each foot slides (0: it sticks).  Returns the transmitted (F, tau), 6 floats.
    """
    # the feet's mean normal N: the yaw moment is the moment about it
    Nx = Ny = Nz = 0.0
    for j in range(n_feet):
        Nx += nrm[j, 0]
        Ny += nrm[j, 1]
        Nz += nrm[j, 2]
    nn = math.sqrt(Nx * Nx + Ny * Ny + Nz * Nz)
    Nx, Ny, Nz = Nx / nn, Ny / nn, Nz / nn
    # equal shares of the force, then the yaw moment they leave unmet, by a couple of forces perpendicular to
    # the feet's arms d_j = r_j - mean r (they sum to zero; their moment about N is g sum |d_j perp|^2)
    yaw_need = tx * Nx + ty * Ny + tz * Nz
    inv = 1.0 / n_feet
    mx_ = my_ = mz_ = 0.0
    for j in range(n_feet):
        f[j, 0], f[j, 1], f[j, 2] = Fx * inv, Fy * inv, Fz * inv
        rx, ry, rz = r[j, 0], r[j, 1], r[j, 2]
        yaw_need -= ((ry * f[j, 2] - rz * f[j, 1]) * Nx + (rz * f[j, 0] - rx * f[j, 2]) * Ny
                     + (rx * f[j, 1] - ry * f[j, 0]) * Nz)
        mx_ += rx * inv
        my_ += ry * inv
        mz_ += rz * inv
    lever2 = 0.0
    for j in range(n_feet):
        dx, dy, dz = r[j, 0] - mx_, r[j, 1] - my_, r[j, 2] - mz_
        dn = dx * Nx + dy * Ny + dz * Nz
        px, py, pz = dx - dn * Nx, dy - dn * Ny, dz - dn * Nz
        lever2 += px * px + py * py + pz * pz
    if lever2 > 1e-12:
        g = yaw_need / lever2
        for j in range(n_feet):
            dx, dy, dz = r[j, 0] - mx_, r[j, 1] - my_, r[j, 2] - mz_
            dn = dx * Nx + dy * Ny + dz * Nz
            px, py, pz = dx - dn * Nx, dy - dn * Ny, dz - dn * Nz
            # N x d_perp
            f[j, 0] += g * (Ny * pz - Nz * py)
            f[j, 1] += g * (Nz * px - Nx * pz)
            f[j, 2] += g * (Nx * py - Ny * px)
    # each foot: no pull, the friction cone, the actuator's bound
    loaded = False
    Sx = Sy = Sz = 0.0
    Mx = My = Mz = 0.0
    for j in range(n_feet):
        nx, ny, nz = nrm[j, 0], nrm[j, 1], nrm[j, 2]
        fn = f[j, 0] * nx + f[j, 1] * ny + f[j, 2] * nz
        ftx, fty, ftz = f[j, 0] - fn * nx, f[j, 1] - fn * ny, f[j, 2] - fn * nz
        ft = math.sqrt(ftx * ftx + fty * fty + ftz * ftz)
        slide[j] = 0.0
        if fn <= 0.0:
            f[j, 0] = f[j, 1] = f[j, 2] = 0.0
            slide[j] = 1.0 if ft > 0.0 else 0.0
            continue
        loaded = True
        if ft > mu * fn:
            cut = mu * fn / ft
            slide[j] = 1.0 - cut
            ftx, fty, ftz = ftx * cut, fty * cut, ftz * cut
        fx, fy, fz = fn * nx + ftx, fn * ny + fty, fn * nz + ftz
        if max_force > 0.0:
            mag = math.sqrt(fx * fx + fy * fy + fz * fz)
            if mag > max_force:
                s = max_force / mag
                fx, fy, fz = fx * s, fy * s, fz * s
        f[j, 0], f[j, 1], f[j, 2] = fx, fy, fz
        Sx += fx
        Sy += fy
        Sz += fz
        rx, ry, rz = r[j, 0], r[j, 1], r[j, 2]
        Mx += ry * fz - rz * fy
        My += rz * fx - rx * fz
        Mz += rx * fy - ry * fx
    if not loaded:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    # the tilting moment passes (normal forces, joints); the yaw moment is what the feet give
    yaw = Mx * Nx + My * Ny + Mz * Nz
    td = tx * Nx + ty * Ny + tz * Nz
    return (Sx, Sy, Sz, tx - td * Nx + yaw * Nx, ty - td * Ny + yaw * Ny, tz - td * Nz + yaw * Nz)


@njit(cache=True, error_model="numpy", inline="always")
def _rotation_rate(R, R_T, i, dt):
    """w [rad/s] (3 floats, world frame) that turns R[i] into R_T[i] in dt: log(R_T R^T) / dt (as
    ``kinematic_targets.drive_to_targets`` computes it)."""
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
    sin2 = math.sqrt(ax * ax + ay * ay + az * az)
    scale = angle / (sin2 * dt) if sin2 > 1e-12 else 0.5 / dt
    return ax * scale, ay * scale, az * scale


@njit(cache=True, error_model="numpy", inline="always")
def _world_inertia_times(R, i, I, x, y, z):
    """R[i] diag(I[i]) R[i]^T (x, y, z)."""
    b0 = (R[i, 0, 0] * x + R[i, 1, 0] * y + R[i, 2, 0] * z) * I[i, 0]
    b1 = (R[i, 0, 1] * x + R[i, 1, 1] * y + R[i, 2, 1] * z) * I[i, 1]
    b2 = (R[i, 0, 2] * x + R[i, 1, 2] * y + R[i, 2, 2] * z) * I[i, 2]
    return (R[i, 0, 0] * b0 + R[i, 0, 1] * b1 + R[i, 0, 2] * b2,
            R[i, 1, 0] * b0 + R[i, 1, 1] * b1 + R[i, 1, 2] * b2,
            R[i, 2, 0] * b0 + R[i, 2, 1] * b1 + R[i, 2, 2] * b2)


@njit(cache=True, error_model="numpy", inline="always")
def _world_inertia_inverse_times(R, i, I, x, y, z):
    """R[i] diag(1 / I[i]) R[i]^T (x, y, z)."""
    b0 = (R[i, 0, 0] * x + R[i, 1, 0] * y + R[i, 2, 0] * z) / I[i, 0]
    b1 = (R[i, 0, 1] * x + R[i, 1, 1] * y + R[i, 2, 1] * z) / I[i, 1]
    b2 = (R[i, 0, 2] * x + R[i, 1, 2] * y + R[i, 2, 2] * z) / I[i, 2]
    return (R[i, 0, 0] * b0 + R[i, 0, 1] * b1 + R[i, 0, 2] * b2,
            R[i, 1, 0] * b0 + R[i, 1, 1] * b1 + R[i, 1, 2] * b2,
            R[i, 2, 0] * b0 + R[i, 2, 1] * b1 + R[i, 2, 2] * b2)


@njit(cache=True, error_model="numpy")
def push_segments(c, v, w, R, supported, held, c_T, R_T, states, tips, S, dt):
    """Steps 1-3 of the module docstring for every segment that is ``supported`` (n_seg,) bool and not
    ``held`` (n_seg,) bool and has a leg (2 i, 2 i + 1) in STANCE in ``states`` (n_legs,).

    c (n_seg, 3) [m], R (n_seg, 3, 3): the segments' poses; v, w (n_seg, 3) [m/s], [rad/s] UPDATED by the
    legs' impulse; c_T, R_T: the Targeter's targets; tips (n_legs, 3) [m] the feet, UPDATED where a foot
    slides; S a ``StanceArrays`` (its acc ACCUMULATES); dt [s].
    """
    P = S.params
    a = P.omega * P.omega * dt * dt + 2.0 * P.zeta * P.omega * dt
    gx, gy, gz = S.gravity[0], S.gravity[1], S.gravity[2]
    acc, r, nrm, f, slide = S.acc, S.r, S.nrm, S.f, S.slide
    I = S.inertia_body
    for i in range(c.shape[0]):
        if not supported[i] or held[i]:
            continue
        n_feet = 0
        for j in range(2 * i, 2 * i + 2):
            if states[j] == STANCE:
                r[n_feet, 0] = tips[j, 0] - c[i, 0]
                r[n_feet, 1] = tips[j, 1] - c[i, 1]
                r[n_feet, 2] = tips[j, 2] - c[i, 2]
                _, nx, ny, nz = distance_and_normal(S.terr_kind, S.terr, tips[j, 0], tips[j, 1], tips[j, 2])
                nrm[n_feet, 0], nrm[n_feet, 1], nrm[n_feet, 2] = nx, ny, nz
                n_feet += 1
        if n_feet == 0:
            continue
        m = S.mass[i]
        # 1. the kinematic stance's velocities; the implicit spring-damper's pull toward them, solved with the
        # links' force of the segment's last step (staggered as the body's coupling), while the legs carry its
        # weight: m (v' - v) / dt = F_spring-damper + F_links, F_legs = F_spring-damper - m g; so the stiff limit
        # holds the segment against both
        vTx, vTy, vTz = (c_T[i, 0] - c[i, 0]) / dt, (c_T[i, 1] - c[i, 1]) / dt, (c_T[i, 2] - c[i, 2]) / dt
        wTx, wTy, wTz = _rotation_rate(R, R_T, i, dt)
        Ox, Oy, Oz = S.force[i, 0], S.force[i, 1], S.force[i, 2]
        ax_, ay_, az_ = _world_inertia_inverse_times(R, i, I, S.torque[i, 0], S.torque[i, 1], S.torque[i, 2])
        dvx = (a * (vTx - v[i, 0]) + dt * Ox / m) / (1.0 + a)
        dvy = (a * (vTy - v[i, 1]) + dt * Oy / m) / (1.0 + a)
        dvz = (a * (vTz - v[i, 2]) + dt * Oz / m) / (1.0 + a)
        dwx = (a * (wTx - w[i, 0]) + dt * ax_) / (1.0 + a)
        dwy = (a * (wTy - w[i, 1]) + dt * ay_) / (1.0 + a)
        dwz = (a * (wTz - w[i, 2]) + dt * az_) / (1.0 + a)
        Fx, Fy, Fz = m * dvx / dt - Ox - m * gx, m * dvy / dt - Oy - m * gy, m * dvz / dt - Oz - m * gz
        tx, ty, tz = _world_inertia_times(R, i, I, dwx / dt, dwy / dt, dwz / dt)
        tx, ty, tz = tx - S.torque[i, 0], ty - S.torque[i, 1], tz - S.torque[i, 2]
        # 2. what the feet transmit, as an impulse
        # np.int64: numba types a count that no loop of a group's typing increments as Literal[int](0), which
        # would give foot_forces a second signature (tests/test_compiled_signatures.py: one signature per kernel)
        Sx, Sy, Sz, Tx, Ty, Tz = foot_forces(Fx, Fy, Fz, tx, ty, tz, r, nrm, np.int64(n_feet), P.mu, P.max_force,
                                             f, slide)
        v[i, 0] += dt * Sx / m
        v[i, 1] += dt * Sy / m
        v[i, 2] += dt * Sz / m
        ax_, ay_, az_ = _world_inertia_inverse_times(R, i, I, Tx, Ty, Tz)
        w[i, 0] += dt * ax_
        w[i, 1] += dt * ay_
        w[i, 2] += dt * az_
        # the legs' power on the segment (velocities after the impulse and gravity's kick)
        ux, uy, uz = v[i, 0] + dt * gx, v[i, 1] + dt * gy, v[i, 2] + dt * gz
        power = Sx * ux + Sy * uy + Sz * uz + Tx * w[i, 0] + Ty * w[i, 1] + Tz * w[i, 2]
        if power > 0.0:
            acc[ACC_WORK_POS] += power * dt
        # 3. the feet: statistics, and a sliding foot moves by its fraction of the unresisted stroke
        k = 0
        for j in range(2 * i, 2 * i + 2):
            if states[j] != STANCE:
                continue
            fm = math.sqrt(f[k, 0] ** 2 + f[k, 1] ** 2 + f[k, 2] ** 2)
            acc[ACC_FOOT_STEPS] += 1.0
            acc[ACC_FORCE_SUM] += fm
            acc[ACC_FORCE_SQ] += fm * fm
            if fm > acc[ACC_FORCE_MAX]:
                acc[ACC_FORCE_MAX] = fm
            s = slide[k]
            if s > 0.0:
                rx, ry, rz = r[k, 0], r[k, 1], r[k, 2]
                # velocity of the segment's point at the foot: now, and in the kinematic stance
                px = ux + w[i, 1] * rz - w[i, 2] * ry - (vTx + wTy * rz - wTz * ry)
                py = uy + w[i, 2] * rx - w[i, 0] * rz - (vTy + wTz * rx - wTx * rz)
                pz = uz + w[i, 0] * ry - w[i, 1] * rx - (vTz + wTx * ry - wTy * rx)
                nx, ny, nz = nrm[k, 0], nrm[k, 1], nrm[k, 2]
                pn = px * nx + py * ny + pz * nz
                dx, dy, dz = s * dt * (px - pn * nx), s * dt * (py - pn * ny), s * dt * (pz - pn * nz)
                tips[j, 0] += dx
                tips[j, 1] += dy
                tips[j, 2] += dz
                acc[ACC_SLID_STEPS] += 1.0
                acc[ACC_SLIP_M] += math.sqrt(dx * dx + dy * dy + dz * dz)
            k += 1
