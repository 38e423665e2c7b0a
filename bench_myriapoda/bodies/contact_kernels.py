"""Ground contact of one point mass, shared by every body backend's numba step loop.

A step of a mass in contact has two parts, in this order:

1. ``contact_friction``: if the mass is within the contact distance of the
   terrain, the friction model (``friction_kernels``) changes its velocity
   after the step's forces.  The normal impulse per unit mass is the one the
   collision of step 2 delivers: (1 + r_n) times the velocity into the surface
   when the step's path reaches the surface, and zero when it does not.  (A mass
   hovering inside the contact distance while it moves down feels no normal
   force, so it gets no friction: counting its approach velocity as a normal
   impulse gave, at dt = 1/12000 s, 8.8 times mu m g of friction on a vibrating
   FEM snake, and a slithering speed that fell with dt; issue 11.)
2. ``collide_path``: Miller 1988 Sec. 3, Fig. 1: the mass's path over the step
   (p -> q) is intersected with the terrain; the part of the path beyond the
   surface is reflected with r_n along the normal and kept with r_t along the
   tangent, and the velocity likewise.  A curved surface can leave the
   reflected point inside: it is then pushed out along the normal, and the
   depth before that correction is returned as the penetration.

``advance_point`` does both, plus the position update and the blow-up checks,
for one free mass: every backend's step loop calls it for its free nodes.
"""
from __future__ import annotations

import math

from numba import njit

from ..world.terrain_kernels import distance_at_least, path_surface_fraction, signed_distance, surface_normal
from .friction_kernels import STICK, ground_friction
from .step_status import ACC_MAX_PEN, DEEP_PENETRATION, NONFINITE, OK, RUNAWAY_SPEED


@njit(cache=True, error_model="numpy", inline="always")
def contact_friction(terr_kind, terr, fric_model, fric, r_n, p, vel, s, phi, d):
    """Return (vx, vy, vz) for a mass at p, touching the terrain, with velocity v after forces.

    p = (px, py, pz) [m], vel = (vx, vy, vz) [m/s], s = (sx, sy, sz), d = (dx, dy, dz) [m]: tuples of
    scalars (inlined, they stay in registers).
    The caller tests contact (signed distance of p below ``fric[CONTACT_DISTANCE]``)
    inline, so the common no-contact path costs no call.  s: unit spine vector
    toward the head at the mass; phi: signed distance of p [m]; d: the mass's travel over the
    step [m] with this velocity (dt v, or dt (v_old + v) / 2 for Miller's Euler).
    The normal impulse per unit mass is -(1 + r_n) v.n when the path reaches the surface
    (phi + d.n < 0, the first-order test of ``collide_path``'s crossing; exact on planes) and
    v.n < 0, else 0: friction never exceeds mu times the normal impulse the step delivers.
    The STICK model holds every mass within the contact distance that moves toward the surface.
    """
    px, py, pz = p
    vx, vy, vz = vel
    sx, sy, sz = s
    dx, dy, dz = d
    nx, ny, nz = surface_normal(terr_kind, terr, px, py, pz)
    vn = vx * nx + vy * ny + vz * nz
    # Miller's caterpillar rule (STICK) is kinematic, not a force law: a mass within the contact
    # distance that presses toward the surface is held, whether or not this step reaches it.  (With
    # the reaching test the vibrating fem caterpillar slid off the 45 degree descent, and the
    # lattice one held on: tests/test_miller_images.py; issue 11.)
    reaches = fric_model == STICK or phi + dx * nx + dy * ny + dz * nz < 0.0
    jn = -(1.0 + r_n) * vn if (vn < 0.0 and reaches) else 0.0
    return ground_friction(fric_model, fric, vx, vy, vz, nx, ny, nz, sx, sy, sz, jn)


@njit(cache=True, error_model="numpy", inline="always")
def reflect_beyond(ix, iy, iz, qx, qy, qz, nx, ny, nz, r_n, r_t):
    """Miller's reflection of the part of a path beyond its crossing point i: q [m] moved to i plus the part's
    normal component times -r_n and its tangential component times r_t (unit normal n); ``collide_path``'s,
    and the flat lattice's select form of it (``massspring.kernels._positions_flat``)."""
    dx, dy, dz = qx - ix, qy - iy, qz - iz
    dn = dx * nx + dy * ny + dz * nz
    tx, ty, tz = dx - dn * nx, dy - dn * ny, dz - dn * nz
    return ix - r_n * dn * nx + r_t * tx, iy - r_n * dn * ny + r_t * ty, iz - r_n * dn * nz + r_t * tz


@njit(cache=True, error_model="numpy", inline="always")
def reflect_velocity(vx, vy, vz, vn, nx, ny, nz, r_n, r_t):
    """The velocity after a collision with the surface of unit normal n: its normal part vn (< 0, into the
    surface) times -r_n, its tangential part times r_t [m/s]."""
    wx, wy, wz = vx - vn * nx, vy - vn * ny, vz - vn * nz
    return r_t * wx - r_n * vn * nx, r_t * wy - r_n * vn * ny, r_t * wz - r_n * vn * nz


@njit(cache=True, error_model="numpy", inline="always")
def collide_path(terr_kind, terr, r_n, r_t, px, py, pz, phi_p, qx, qy, qz, phi_q, vx, vy, vz):
    """Return (qx, qy, qz, vx, vy, vz, penetration) after Miller's collision of the path p -> q.

    The caller tests the crossing (phi_q < 0) inline.  phi_p, phi_q: signed
    distances of p and q [m]; penetration: depth left inside after the
    reflection, before the push-out [m].
    """
    s = path_surface_fraction(terr_kind, terr, px, py, pz, qx, qy, qz, phi_p, phi_q)
    ix, iy, iz = px + s * (qx - px), py + s * (qy - py), pz + s * (qz - pz)
    nx, ny, nz = surface_normal(terr_kind, terr, ix, iy, iz)
    qx, qy, qz = reflect_beyond(ix, iy, iz, qx, qy, qz, nx, ny, nz, r_n, r_t)
    vn = vx * nx + vy * ny + vz * nz
    if vn < 0.0:
        vx, vy, vz = reflect_velocity(vx, vy, vz, vn, nx, ny, nz, r_n, r_t)
    phi_r = signed_distance(terr_kind, terr, qx, qy, qz)
    if phi_r < 0.0:
        mx, my, mz = surface_normal(terr_kind, terr, qx, qy, qz)
        qx, qy, qz = qx - phi_r * mx, qy - phi_r * my, qz - phi_r * mz
        return qx, qy, qz, vx, vy, vz, -phi_r
    return qx, qy, qz, vx, vy, vz, 0.0


@njit(cache=True, error_model="numpy", inline="always")
def advance_point(x, v, i, vel, s, terr_kind, terr, fric_model, fric, step, acc, euler, old):
    """Move free point mass i one step: friction, position, Miller's collision, checks.

    vel = (vx, vy, vz): its velocity after the step's forces [m/s]; s = (sx, sy, sz): unit spine
    vector at the mass (used by friction only when it touches); step = (dt [s], r_n, r_t [-],
    contact_dist [m], max_pen [m], max_speed2 [m^2/s^2]); the position
    update is x += dt v (semi-implicit), or x += dt (v_old + v) / 2 with
    v_old = old = (ox, oy, oz) when ``euler`` (Miller's Euler).  The tuples hold scalars: inlined, they
    stay in registers.  Writes x[i], v[i]
    (n, 3); raises acc[ACC_MAX_PEN] to the penetration left by a collision.
    Returns (touching, status) with status a ``step_status`` code.
    """
    vx, vy, vz = vel
    dt, r_n, r_t, contact_dist, max_pen, max_speed2 = step
    ox, oy, oz = old
    px, py, pz = x[i, 0], x[i, 1], x[i, 2]
    phi = signed_distance(terr_kind, terr, px, py, pz)
    touching = phi < contact_dist
    if touching:
        if euler:
            dx, dy, dz = 0.5 * dt * (ox + vx), 0.5 * dt * (oy + vy), 0.5 * dt * (oz + vz)
        else:
            dx, dy, dz = dt * vx, dt * vy, dt * vz
        vx, vy, vz = contact_friction(terr_kind, terr, fric_model, fric, r_n, (px, py, pz), (vx, vy, vz), s,
                                      phi, (dx, dy, dz))
    if euler:
        qx, qy, qz = px + 0.5 * dt * (ox + vx), py + 0.5 * dt * (oy + vy), pz + 0.5 * dt * (oz + vz)
    else:
        qx, qy, qz = px + dt * vx, py + dt * vy, pz + dt * vz
    status = OK
    # (the position update, the collision and the checks stand again, deliberately written out, in the
    # lattice's node loop ``massspring.kernels._nodes_general``: this call measured 13 % of its step)
    phi_q = signed_distance(terr_kind, terr, qx, qy, qz)
    if phi_q < 0.0:
        qx, qy, qz, vx, vy, vz, pen = collide_path(terr_kind, terr, r_n, r_t, px, py, pz, phi,
                                                   qx, qy, qz, phi_q, vx, vy, vz)
        if pen > acc[ACC_MAX_PEN]:
            acc[ACC_MAX_PEN] = pen
        if pen > max_pen:
            status = DEEP_PENETRATION
    x[i, 0], x[i, 1], x[i, 2] = qx, qy, qz
    v[i, 0], v[i, 1], v[i, 2] = vx, vy, vz
    if not math.isfinite(qx + qy + qz + vx + vy + vz):
        status = NONFINITE
    elif vx * vx + vy * vy + vz * vz > max_speed2:
        status = RUNAWAY_SPEED
    return touching, status


# ``advance_point_if_clear``'s answer for a point it did not move
NOT_CLEAR = -1


@njit(cache=True, error_model="numpy", inline="always")
def advance_point_if_clear(x, v, i, vx, vy, vz, dt, terr_kind, terr, flat, ground, contact_dist, max_speed2,
                           new_velocity):
    """``advance_point`` (semi-implicit, not Euler) for a point clear of the terrain at both ends of its
    step, else nothing: returns NOT_CLEAR, or the status code after moving it.

    Clear: phi >= contact_dist now and phi >= 0 after x += dt v.  For such a point ``advance_point``
    reduces to no friction, no collision, x += dt v, v = (vx, vy, vz) and the blow-up checks; this is
    that arithmetic (the same doubles), without the contact code around it -- the walking body's many
    points in the air.  A point not clear (also a NaN distance) is left to ``advance_point``.
    flat, ground: ``terrain_kernels.flat_ground`` of the terrain, taken once per step loop (where flat,
    phi is y - ground without a ``signed_distance`` call and its reference-count updates).
    new_velocity: False when v[i] already holds (vx, vy, vz), so it is not written again (pass a
    literal: inlined, the branch compiles away).  The legged mass-spring chain's loop calls it; the hybrid's
    and the FEM bodies' loops keep the same arithmetic written out, measured faster (``fem.myriapod.advance_chain``).
    """
    px, py, pz = x[i, 0], x[i, 1], x[i, 2]
    # (``distance_at_least``: the same tests as phi >= ..., answered among obstacles without their search
    # for the points high above them)
    if not ((py - ground >= contact_dist) if flat else distance_at_least(terr_kind, terr, px, py, pz, contact_dist)):
        return NOT_CLEAR
    qx, qy, qz = px + dt * vx, py + dt * vy, pz + dt * vz
    if not ((qy - ground >= 0.0) if flat else distance_at_least(terr_kind, terr, qx, qy, qz, 0.0)):
        return NOT_CLEAR
    x[i, 0], x[i, 1], x[i, 2] = qx, qy, qz
    if new_velocity:
        v[i, 0], v[i, 1], v[i, 2] = vx, vy, vz
    if not math.isfinite(qx + qy + qz + vx + vy + vz):
        return NONFINITE
    if vx * vx + vy * vy + vz * vz > max_speed2:
        return RUNAWAY_SPEED
    return OK
