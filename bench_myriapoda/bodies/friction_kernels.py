"""Ground friction models for point masses, callable from any backend's numba kernel.

All three models act on the velocity of one mass in contact, at velocity
level (an impulse per unit mass), after the other forces of the step:

* ``MILLER`` (Miller 1988 Sec. 4, read as in PAPER-NOTES.md): with s the
  unit spine vector pointing toward the head, if s.v < 0 then v -= s (s.v).
  Backward sliding is removed; the forward and sideways sliding left is
  resisted by Coulomb friction of coefficient ``MU_SLIDE`` (the impulse
  mu J_n opposes the remaining tangential velocity, down to rest; 0: free).
  J_n grows with dt, so the braking per unit time does not depend on dt.
* ``COULOMB``: anisotropic Coulomb friction after Hu et al. (PNAS 2009): the
  friction impulse opposes each tangential component u_a of the unit sliding
  direction with mu_a * J_n * |u_a|, where a is forward / backward (along the
  spine projected on the tangent plane) or transverse.  For equal
  coefficients this is ordinary isotropic Coulomb friction.  Static friction:
  the mass sticks when the tangential speed could be cancelled by the static
  coefficients' impulse.
* ``STICK`` (Miller's caterpillar, Sec. 4): a loaded mass in contact gets no
  tangential motion at all.

``jn`` is the normal impulse per unit mass [m/s] the surface delivers this
step (zero when the mass is not pressed into the surface).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

MILLER, COULOMB, STICK = 0, 1, 2
FRICTION_MODELS = {"miller": MILLER, "coulomb": COULOMB, "stick": STICK}
# what a body that applies ``ground_friction`` declares it can honour (``core.specs.BodySpec.capabilities``)
FRICTION_CAPABILITIES = frozenset(f"friction:{name}" for name in FRICTION_MODELS)

# friction parameter vector layout
CONTACT_DISTANCE, MU_F, MU_B, MU_T, MUS_F, MUS_B, MUS_T, MU_SLIDE = range(8)
N_FRICTION_PARAMS = 8


def friction_params(cfg) -> tuple[int, np.ndarray]:
    """(model code, parameter vector) from a ``FrictionConfig``; static -1 means 'same as kinetic'."""
    p = np.zeros(N_FRICTION_PARAMS)
    p[CONTACT_DISTANCE] = cfg.contact_distance_m
    p[MU_F], p[MU_B], p[MU_T] = cfg.mu_forward, cfg.mu_backward, cfg.mu_transverse
    p[MUS_F] = cfg.mu_forward if cfg.mu_static_forward < 0 else cfg.mu_static_forward
    p[MUS_B] = cfg.mu_backward if cfg.mu_static_backward < 0 else cfg.mu_static_backward
    p[MUS_T] = cfg.mu_transverse if cfg.mu_static_transverse < 0 else cfg.mu_static_transverse
    p[MU_SLIDE] = getattr(cfg, "miller_mu_slide", 0.0)
    return FRICTION_MODELS[cfg.model], p


@njit(cache=True, error_model="numpy", inline="always")
def spine_between(c, a, b, spine, k):
    """spine[k] = the unit vector from c[b] to c[a] [c (n, 3) [m], e.g. from a segment's centre to the one
    ahead], or (1, 0, 0) where they coincide: the direction toward the head that the friction models (Miller's
    rule, anisotropic Coulomb) read at a point.  OVERWRITES spine[k]."""
    sx = c[a, 0] - c[b, 0]
    sy = c[a, 1] - c[b, 1]
    sz = c[a, 2] - c[b, 2]
    n = math.sqrt(sx * sx + sy * sy + sz * sz)
    if n > 0.0:
        spine[k, 0], spine[k, 1], spine[k, 2] = sx / n, sy / n, sz / n
    else:
        spine[k, 0], spine[k, 1], spine[k, 2] = 1.0, 0.0, 0.0


@njit(cache=True, error_model="numpy")
def ground_friction(model, p, vx, vy, vz, nx, ny, nz, sx, sy, sz, jn):
    """New velocity (vx, vy, vz) [m/s] of a mass in contact.

    v: velocity after the step's forces; n: unit surface normal; s: unit spine
    vector toward the head; jn: normal impulse per unit mass [m/s] (>= 0).
    """
    if model == MILLER:
        sv = sx * vx + sy * vy + sz * vz
        if sv < 0.0:
            vx, vy, vz = vx - sx * sv, vy - sy * sv, vz - sz * sv
        mu = p[MU_SLIDE]
        if mu > 0.0 and jn > 0.0:
            vn = vx * nx + vy * ny + vz * nz
            tx, ty, tz = vx - vn * nx, vy - vn * ny, vz - vn * nz
            speed = math.sqrt(tx * tx + ty * ty + tz * tz)
            if speed <= mu * jn:
                return vn * nx, vn * ny, vn * nz
            k = 1.0 - mu * jn / speed
            return vn * nx + k * tx, vn * ny + k * ty, vn * nz + k * tz
        return vx, vy, vz
    vn = vx * nx + vy * ny + vz * nz
    tx, ty, tz = vx - vn * nx, vy - vn * ny, vz - vn * nz
    if jn <= 0.0:
        return vx, vy, vz
    if model == STICK:
        return vn * nx, vn * ny, vn * nz
    # Tangent frame: f = spine projected on the tangent plane, q = n x f.
    sn = sx * nx + sy * ny + sz * nz
    fx, fy, fz = sx - sn * nx, sy - sn * ny, sz - sn * nz
    fl = math.sqrt(fx * fx + fy * fy + fz * fz)
    if fl < 1e-12:
        # spine along the normal (body standing up): fall back to isotropic transverse friction
        fx, fy, fz = 0.0, 0.0, 0.0
    else:
        fx, fy, fz = fx / fl, fy / fl, fz / fl
    qx, qy, qz = ny * fz - nz * fy, nz * fx - nx * fz, nx * fy - ny * fx
    va = tx * fx + ty * fy + tz * fz
    vq = tx * qx + ty * qy + tz * qz
    if fl < 1e-12:
        vq = math.sqrt(tx * tx + ty * ty + tz * tz)
        va = 0.0
    speed = math.sqrt(va * va + vq * vq)
    if speed <= 0.0:
        return vn * nx, vn * ny, vn * nz
    ua, uq = va / speed, vq / speed
    mus_a = p[MUS_F] if va > 0.0 else p[MUS_B]
    mus = math.sqrt((mus_a * ua) ** 2 + (p[MUS_T] * uq) ** 2)
    if speed <= mus * jn:
        va, vq = 0.0, 0.0
    else:
        mu_a = p[MU_F] if va > 0.0 else p[MU_B]
        da = mu_a * jn * abs(ua)
        dq = p[MU_T] * jn * abs(uq)
        va = 0.0 if abs(va) <= da else va - math.copysign(da, va)
        vq = 0.0 if abs(vq) <= dq else vq - math.copysign(dq, vq)
    if fl < 1e-12:
        scale = vq / speed if speed > 0 else 0.0
        return vn * nx + tx * scale, vn * ny + ty * scale, vn * nz + tz * scale
    return (vn * nx + va * fx + vq * qx, vn * ny + va * fy + vq * qy, vn * nz + va * fz + vq * qz)


def ground_friction_numpy(model, p, v, n, s, jn):
    """Slow reference of :func:`ground_friction` for one mass (vectors as numpy arrays)."""
    v, n, s = (np.asarray(a, float) for a in (v, n, s))
    if model == MILLER:
        sv = s @ v
        v = v - s * sv if sv < 0 else v.copy()
        mu = p[MU_SLIDE]
        if mu > 0 and jn > 0:
            vt = v - (v @ n) * n
            speed = np.linalg.norm(vt)
            if speed <= mu * jn:
                return (v @ n) * n
            return (v @ n) * n + vt * (1.0 - mu * jn / speed)
        return v
    vn = v @ n
    vt = v - vn * n
    if jn <= 0:
        return v.copy()
    if model == STICK:
        return vn * n
    f = s - (s @ n) * n
    f /= np.linalg.norm(f)
    q = np.cross(n, f)
    va, vq = vt @ f, vt @ q
    speed = math.hypot(va, vq)
    if speed == 0:
        return vn * n
    ua, uq = va / speed, vq / speed
    mus = math.hypot((p[MUS_F] if va > 0 else p[MUS_B]) * ua, p[MUS_T] * uq)
    if speed <= mus * jn:
        return vn * n
    da = (p[MU_F] if va > 0 else p[MU_B]) * jn * abs(ua)
    dq = p[MU_T] * jn * abs(uq)
    va = 0.0 if abs(va) <= da else va - math.copysign(da, va)
    vq = 0.0 if abs(vq) <= dq else vq - math.copysign(dq, vq)
    return vn * n + va * f + vq * q
