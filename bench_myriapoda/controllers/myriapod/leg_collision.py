"""Legs that collide with the terrain and its obstacles (issue 16; paper Sec. 5.1's inside test on the legs).

The paper's legs are kinematic: outside STANCE the Switcher moves their angles
toward a target pose by forward kinematics (Sec. 4.2), and nothing stops a
swinging leg that meets an obstacle -- a tip could reach 0.45 m into a Fig. 13
cylinder.  Here every leg outside STANCE (SF1, SF2, SB1, SB2, ADJUST) is
checked after the Switcher's move, at its segment's new target pose: when its
tip or knee would be inside the terrain (signed distance phi < 0, the full
terrain with every obstacle), the move is cut where the leg meets the surface --
the largest fraction s of the straight step in (theta, alpha, beta) from the
previous angles that keeps both points outside, by bisection to
``BISECTION_STEPS`` halvings.  The stopped tip then lies on the surface, within
the contact distance, so rule 2 of the Switcher (touch-down -> STANCE) acts on
whatever surface it met: the ground, a cylinder's top, a box.

A leg already inside at s = 0 was pushed in by its segment's own motion (the
previous angles at the new pose); it escapes along the straight path toward the
tucked pose (theta, pi/2, pi - gamma) -- femur straight up, tibia straight down,
the tip just below the root, inside the body's own clearance -- and stops at
the first outside pose of that path.

A tip touches down where the Switcher saw it within the contact distance,
at the previous step's pose; on this step's pose it may have moved inside
(a segment left to the dynamics can move more than its target did): such a
tip is put back on the surface along the normal before it is fixed
(``surface_touchdown_tips``).  A STANCE leg's tip is fixed where it touched down, outside; its IK knee can be
carried into an obstacle by the body's motion: that leg is reported as an IK
failure, so rule 3 lifts it on the next step (App. B's "cannot resolve").

Knee and tip only: the femur and tibia between them are not tested (an
obstacle thinner than a leg could slip between the two points).
"""
from __future__ import annotations

import math

from numba import njit

from bench_myriapoda.kinematics.legs import ALPHA, BETA, FEMUR, GAMMA, ROOT_X, ROOT_Y, ROOT_Z, THETA, TIBIA, \
    leg_plane_points, side_sign
from bench_myriapoda.kinematics.rotations import matvec as _matvec
from bench_myriapoda.world.terrain_kernels import (clearance, clearance_cell, clearance_view, distance_at_least,
                                                   flat_ground, signed_distance, surface_normal)

from .switcher import STANCE

BISECTION_STEPS = 40   # 2^-40 of one step's angle change: the stopped tip is on the surface to ~1e-12 m
KNEE_CLEAR_M = 5e-324  # the smallest positive double: phi >= it means phi > 0
PROJECTION_STEPS = 4   # p -= phi n: exact in one step on planes, cylinder sides and tops, box faces


@njit(cache=True, inline="always")
def _knee_tip_points(c, R, g, side, theta, alpha, beta):
    """(knee x, y, z, tip x, y, z) [m] of one leg at angles (theta, alpha, beta) on pose (c, R)."""
    mu, mv, pu, pv = leg_plane_points(alpha, beta, g[FEMUR], g[TIBIA], g[GAMMA])
    ux, uz = math.sin(theta), side * math.cos(theta)
    mx, my, mz = _matvec(R, g[ROOT_X] + mu * ux, g[ROOT_Y] + mv, g[ROOT_Z] + mu * uz)
    px, py, pz = _matvec(R, g[ROOT_X] + pu * ux, g[ROOT_Y] + pv, g[ROOT_Z] + pu * uz)
    return c[0] + mx, c[1] + my, c[2] + mz, c[0] + px, c[1] + py, c[2] + pz


@njit(cache=True)
def knee_tip_phi(kind, f, c, R, g, side, theta, alpha, beta):
    """(phi of the knee, phi of the tip) [m] of one leg at angles (theta, alpha, beta) on pose (c, R)."""
    mx, my, mz, px, py, pz = _knee_tip_points(c, R, g, side, theta, alpha, beta)
    return signed_distance(kind, f, mx, my, mz), signed_distance(kind, f, px, py, pz)


@njit(cache=True)
def _clear_at(kind, f, c, R, g, side, a0, b0, s):
    """True when the leg at a0 + s (b0 - a0) (angles as 3-tuples) has knee and tip outside: ``knee_tip_phi``'s
    two distances >= 0, asked as ``distance_at_least`` (the same answer, without an obstacle search for a
    point above the obstacles)."""
    mx, my, mz, px, py, pz = _knee_tip_points(c, R, g, side, a0[0] + s * (b0[0] - a0[0]), a0[1] + s * (b0[1] - a0[1]),
                                              a0[2] + s * (b0[2] - a0[2]))
    # ``clearance``, else ``distance_at_least``: the same answers, with the grid read once and no reference counts
    V = clearance_view(kind, f)
    kc = clearance_cell(V, mx, mz, 0.0)
    cl = clearance(V, f[kc] if kc >= 0 else 0.0, my, 0.0, kc)
    if not ((cl > 0) if cl >= 0 else distance_at_least(kind, f, mx, my, mz, 0.0)):
        return False
    kc = clearance_cell(V, px, pz, 0.0)
    cl = clearance(V, f[kc] if kc >= 0 else 0.0, py, 0.0, kc)
    return (cl > 0) if cl >= 0 else distance_at_least(kind, f, px, py, pz, 0.0)


@njit(cache=True)
def _clear_edge(kind, f, c, R, g, side, a0, b0):
    """(lo, hi): ``BISECTION_STEPS`` halvings of [0, 1] toward the fraction s where the leg at a0 + s (b0 - a0)
    (``_clear_at``) changes from its state at s = 0 (outside or inside) to the other: lo keeps the state at 0,
    hi the other.  Both moves of ``stop_swinging_legs`` bisect here (no flag argument: a constant passed to a
    kernel would compile it for a literal type as well, tests/kernel_signatures.py)."""
    start = _clear_at(kind, f, c, R, g, side, a0, b0, 0.0)
    lo, hi = 0.0, 1.0
    for _ in range(BISECTION_STEPS):
        mid = 0.5 * (lo + hi)
        if _clear_at(kind, f, c, R, g, side, a0, b0, mid) == start:
            lo = mid
        else:
            hi = mid
    return lo, hi


@njit(cache=True)
def stop_swinging_legs(states, prev_angles, angles, seg_c, seg_R, geom, kind, f, stopped):
    """Cut the Switcher's move of every leg outside STANCE at the terrain surface (module docstring).

    states: (n_legs,) int64; prev_angles: (n_legs, 3) [rad] the angles before this
    step's ``switcher_step``; angles: (n_legs, 3) [rad] after it, rows of blocked
    legs overwritten; seg_c (n_segments, 3) [m], seg_R (n_segments, 3, 3): the
    segments' target poses the legs are placed on; kind, f: the terrain
    (``terrain_kernels``).  stopped: (n_legs,) bool, overwritten: True where the
    move was cut or the leg escaped.  Returns the number of legs left inside
    (no outside pose on the escape path either).
    """
    stuck = 0
    for k in range(states.shape[0]):
        stopped[k] = False
        if states[k] == STANCE:
            continue
        i = k // 2
        c, R, g, side = seg_c[i], seg_R[i], geom[k], side_sign(k)
        new = (angles[k, THETA], angles[k, ALPHA], angles[k, BETA])
        if _clear_at(kind, f, c, R, g, side, new, new, 0.0):
            continue
        old = (prev_angles[k, THETA], prev_angles[k, ALPHA], prev_angles[k, BETA])
        stopped[k] = True
        if _clear_at(kind, f, c, R, g, side, old, new, 0.0):
            # the move from outside (s = 0) to inside (s = 1): keep the last outside fraction
            s, a, b = _clear_edge(kind, f, c, R, g, side, old, new)[0], old, new
        else:
            # pushed in by the segment's motion: the first outside pose toward the tucked pose
            tuck = (old[0], 0.5 * math.pi, math.pi - g[GAMMA])
            if not _clear_at(kind, f, c, R, g, side, old, tuck, 1.0):
                stuck += 1
                continue
            s, a, b = _clear_edge(kind, f, c, R, g, side, old, tuck)[1], old, tuck
        angles[k, THETA] = a[0] + s * (b[0] - a[0])
        angles[k, ALPHA] = a[1] + s * (b[1] - a[1])
        angles[k, BETA] = a[2] + s * (b[2] - a[2])
    return stuck


@njit(cache=True)
def surface_touchdown_tips(entered, tips, kind, f):
    """Tips (n_legs, 3) [m] of the legs that touched down (entered (n_legs,) bool) moved out onto the surface.

    A tip inside (phi < 0) moves by -phi along the surface normal, up to PROJECTION_STEPS
    times, until phi >= 0.  Call after ``switcher.fix_stance_tips``, before the IK.
    """
    for k in range(entered.shape[0]):
        if not entered[k]:
            continue
        for _ in range(PROJECTION_STEPS):
            d = signed_distance(kind, f, tips[k, 0], tips[k, 1], tips[k, 2])
            if d >= 0.0:
                break
            nx, ny, nz = surface_normal(kind, f, tips[k, 0], tips[k, 1], tips[k, 2])
            tips[k, 0] -= d * nx
            tips[k, 1] -= d * ny
            tips[k, 2] -= d * nz


@njit(cache=True)
def stance_knees_inside(states, knees, kind, f, ik_failed):
    """ik_failed[k] |= STANCE leg k's knee (knees (n_legs, 3) [m]) is inside the terrain (phi < 0)."""
    for k in range(states.shape[0]):
        if states[k] == STANCE and signed_distance(kind, f, knees[k, 0], knees[k, 1], knees[k, 2]) < 0.0:
            ik_failed[k] = True


@njit(cache=True)
def legs_penetration(kind, f, knees, tips):
    """Depth [m] of the deepest knee or tip (n_legs, 3) [m] inside the terrain; 0 when all are outside."""
    deepest = 0.0
    for k in range(tips.shape[0]):
        deepest = max(deepest, -signed_distance(kind, f, knees[k, 0], knees[k, 1], knees[k, 2]),
                      -signed_distance(kind, f, tips[k, 0], tips[k, 1], tips[k, 2]))
    return deepest


@njit(cache=True)
def knees_inside_and_penetration(states, knees, tips, kind, f, check_knees, ik_failed, tip_phi):
    """``stance_knees_inside`` (when check_knees) then ``legs_penetration`` in one pass, each knee's signed
    distance taken once: the same ik_failed and the same depth [m] (returned).  tip_phi (n_legs,) [m],
    overwritten: the tips' signed distances, for a caller that tests the same tips again before they move
    (the next controller step's ``legs.tips_touching``)."""
    deepest = 0.0
    # on the plane without obstacles phi = y - ground (``flat_ground``: the same doubles as
    # ``signed_distance``, without its two atomic reference-count updates per call)
    flat, ground = flat_ground(kind, f)
    V = clearance_view(kind, f)
    for k in range(tips.shape[0]):
        pt = tips[k, 1] - ground if flat else signed_distance(kind, f, tips[k, 0], tips[k, 1], tips[k, 2])
        tip_phi[k] = pt
        # a knee strictly outside (phi >= the smallest positive double) changes neither ik_failed nor the
        # depth (-phi < 0 <= deepest): among obstacles ``clearance`` (else ``distance_at_least``) tells so
        # without their search
        if not flat:
            kc = clearance_cell(V, knees[k, 0], knees[k, 2], KNEE_CLEAR_M)
            cl = clearance(V, f[kc] if kc >= 0 else 0.0, knees[k, 1], KNEE_CLEAR_M, kc)
            if (cl > 0) if cl >= 0 else distance_at_least(kind, f, knees[k, 0], knees[k, 1], knees[k, 2],
                                                          KNEE_CLEAR_M):
                deepest = max(deepest, -pt)
                continue
        pk = knees[k, 1] - ground if flat else signed_distance(kind, f, knees[k, 0], knees[k, 1], knees[k, 2])
        if check_knees and states[k] == STANCE and pk < 0.0:
            ik_failed[k] = True
        deepest = max(deepest, -pk, -pt)
    return deepest
