r"""Leg kinematics of the myriapod paper (Fang, Jiang & Terzopoulos 2013).

Sec. 3 makes the legs massless rigid links; Sec. 4.2 / Fig. 9 define a pose by
three angles (theta, alpha, beta) with a fixed fourth angle gamma; App. B gives
the inverse kinematics.  These numba kernels are the numerical core; the leg
controller (``bench_myriapoda.controllers.myriapod``) and the scene drawing call them once
per time step for all legs at once, from inside their own @njit loops.

Frames and indexing (PAPER-NOTES.md)
------------------------------------
World frame: y up, gravity along -y, SI units.  Segment frame: x forward
(toward the head), y up (dorsal), z to the creature's right (z = x cross y).
A segment pose is its centre ``c`` (3,) [m] and rotation ``R`` (3, 3)
(segment -> world: p_world = c + R p_seg).  Segment 0 is the head; leg
``k = 2 * segment + side`` with ``side`` 0 = LEFT (-z), 1 = RIGHT (+z); its side
sign is s = -1 (left) or +1 (right).

Geometric model (our reading of Fig. 9's caption and App. B)
-------------------------------------------------------------
Seen in the leg plane (u outward, v = segment y, origin at the root O)::

            v (segment y, up)
            ^          M  knee
            |        .  \            alpha : elevation of the femur OM above the
            |      .     \                    segment's x-z plane (up > 0)
            |    . alpha  \  tibia   beta  : knee flexion (actuated), > 0 = convex
            |  .           \                 (the leg is an arch, knee above OP)
            O -- -- -- -- --\- --> u (outward, horizontal in the segment)
                              \    gamma : fixed built-in bend of the knee
                               P tip

    M = O + |OM| (cos alpha, sin alpha)
    P = M + |MP| (cos phi,   sin phi),   phi = alpha - (beta + gamma)

The distal link MP is straight; its direction is the femur direction turned
downward (clockwise in this picture) by ``beta + gamma``.  ``gamma`` is the
knee's fixed bend -- our reading of App. B's "segments PM (with gamma fixed)"
and "Fixing gamma for simplicity" (Fig. 9 itself is missing): at beta = 0, the
MUP and MDP poses of Sec. 4.2, the leg is already bent by gamma, as a resting
leg is, and beta is the actuated flexion beyond it.  The two IK solutions are
mirror images about the chord OP with total bends +b and -b; "convex"
(App. B: beta > 0) then means b > gamma, so a tip too close to full extension
(|OP| > sqrt(|OM|^2 + |MP|^2 + 2 |OM| |MP| cos gamma)) has only non-convex
solutions.
The femur and tibia lengths and gamma >= 0 are parameters.

The leg plane contains the segment's y axis through O and the outward unit
vector ``u = (sin theta, 0, s cos theta)`` (segment frame): theta rotates the
plane about the segment's y axis and **theta > 0 swings the leg forward (toward
+x) on both sides** -- a rotation by +theta about +y for a right leg and by
-theta for a left leg, so left and right legs are mirror images for equal
angles.  Seen from above (x up the page, z to the right)::

              +x (head)
        u_L    ^    u_R        theta > 0: both tips swing toward +x.
          \    |    /          theta is kept in [-pi/2, pi/2]: a leg plane
           O_L-+-O_R ---> +z   never swings through the body.
               |
          (left)  (right)

Array layouts
-------------
* ``angles`` (n_legs, 3) [rad]: columns THETA, ALPHA, BETA.
* ``geom``   (n_legs, N_LEG_GEOM): ROOT_X, ROOT_Y, ROOT_Z [m] -- the root O in
  its segment's frame (left legs have ROOT_Z < 0; ``leg_geometry`` mirrors it),
  FEMUR = |OM| [m], TIBIA = |MP| [m], GAMMA [rad] (fixed knee bend, >= 0).
* ``seg_c`` (n_segments, 3) [m], ``seg_R`` (n_segments, 3, 3): segment poses.
* points O, M, P, tips: (n_legs, 3) [m] world.

No kernel allocates; all float64, no fastmath.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .rotations import mat_t_vec as _matTvec, matvec as _matvec
from bench_myriapoda.world.terrain_kernels import signed_distance

LEFT, RIGHT = 0, 1

# columns of ``angles``
THETA, ALPHA, BETA = 0, 1, 2
N_ANGLES = 3

# columns of ``geom``
ROOT_X, ROOT_Y, ROOT_Z, FEMUR, TIBIA, GAMMA = 0, 1, 2, 3, 4, 5
N_LEG_GEOM = 6

_HALF_PI = 0.5 * math.pi
_TWO_PI = 2.0 * math.pi


def leg_geometry(n_segments: int, root_offset=(0.0, 0.0, 0.5), femur: float = 1.0,
                 tibia: float = 1.2, gamma: float = 0.5) -> np.ndarray:
    """The (2 n_segments, N_LEG_GEOM) geometry table of identical leg pairs.

    root_offset: (x, y, |z|) [m] of the right leg's root in the segment frame;
    the left root is its mirror image (z -> -z).  femur = |OM|, tibia = |MP| [m];
    gamma [rad] the fixed knee bend, 0 <= gamma < pi.
    """
    if not (femur > 0.0 and tibia > 0.0):
        raise ValueError(f"femur and tibia must be > 0 m, got {femur}, {tibia}")
    if not 0.0 <= gamma < math.pi:
        raise ValueError(f"gamma must be in [0, pi) rad, got {gamma}")
    geom = np.empty((2 * n_segments, N_LEG_GEOM))
    for k in range(2 * n_segments):
        s = -1.0 if k % 2 == LEFT else 1.0
        geom[k] = (root_offset[0], root_offset[1], s * abs(root_offset[2]), femur, tibia, gamma)
    return geom


@njit(cache=True)
def side_sign(leg):
    """-1.0 for a left leg (even index), +1.0 for a right leg (odd index)."""
    return -1.0 if leg % 2 == LEFT else 1.0


@njit(cache=True)
def _wrap(a):
    """Angle a [rad] wrapped into [-pi, pi)."""
    s = a + math.pi
    if 0.0 <= s < _TWO_PI:
        # then (a + pi) / 2 pi rounds below 1 (2 pi's ulp is over 2^-53 of it), the floor is 0 and the
        # general form gives a - 0.0 == a: the same double without the division, the common case
        return a
    return a - _TWO_PI * math.floor(s / _TWO_PI)


@njit(cache=True)
def leg_plane_points(alpha, beta, femur, tibia, gamma):
    """In-plane coordinates (mu, mv, pu, pv) [m] of the knee M and tip P relative to O."""
    mu = femur * math.cos(alpha)
    mv = femur * math.sin(alpha)
    phi = alpha - (beta + gamma)
    return mu, mv, mu + tibia * math.cos(phi), mv + tibia * math.sin(phi)


@njit(cache=True)
def leg_root(c, R, geom_row, O):
    """World position of a leg root: O = c + R root.  c: (3,); R: (3, 3); O: (3,) overwritten."""
    ox, oy, oz = _matvec(R, geom_row[ROOT_X], geom_row[ROOT_Y], geom_row[ROOT_Z])
    O[0] = c[0] + ox
    O[1] = c[1] + oy
    O[2] = c[2] + oz


@njit(cache=True)
def leg_tip(c, R, geom_row, side, theta, alpha, beta):
    """World tip position (x, y, z) [m] of one leg as a tuple (no allocation); see
    ``leg_forward_kinematics`` for the arguments."""
    _, _, pu, pv = leg_plane_points(alpha, beta, geom_row[FEMUR], geom_row[TIBIA], geom_row[GAMMA])
    ux, uz = math.sin(theta), side * math.cos(theta)
    wx, wy, wz = _matvec(R, geom_row[ROOT_X] + pu * ux, geom_row[ROOT_Y] + pv, geom_row[ROOT_Z] + pu * uz)
    return c[0] + wx, c[1] + wy, c[2] + wz


@njit(cache=True)
def leg_forward_kinematics(c, R, geom_row, side, theta, alpha, beta, O, M, P):
    """World positions of the root O, knee M and tip P of one leg.

    c: (3,) [m] segment centre; R: (3, 3) segment -> world; geom_row: (N_LEG_GEOM,);
    side: +-1.0 (``side_sign``); theta, alpha, beta [rad].  O, M, P: (3,) [m],
    overwritten.
    """
    leg_root(c, R, geom_row, O)
    mu, mv, pu, pv = leg_plane_points(alpha, beta, geom_row[FEMUR], geom_row[TIBIA], geom_row[GAMMA])
    # outward unit vector of the leg plane in the segment frame (theta > 0: forward)
    ux, uz = math.sin(theta), side * math.cos(theta)
    wx, wy, wz = _matvec(R, mu * ux, mv, mu * uz)
    M[0], M[1], M[2] = O[0] + wx, O[1] + wy, O[2] + wz
    wx, wy, wz = _matvec(R, pu * ux, pv, pu * uz)
    P[0], P[1], P[2] = O[0] + wx, O[1] + wy, O[2] + wz


@njit(cache=True)
def leg_inverse_kinematics(O, P, R, side, geom_row, theta_hint):
    """Joint angles that put the tip at P with the root at O (App. B).

    O, P: (3,) [m] world root and tip; R: (3, 3) segment -> world; side: +-1.0;
    geom_row: (N_LEG_GEOM,); theta_hint [rad]: returned as theta when P is
    straight above or below O, where the leg plane is undetermined.

    Returns ``(ok, theta, alpha, beta)``.  App. B step 1: the leg lies in one
    plane, so theta follows from O and P alone; it is chosen in [-pi/2, pi/2]
    (a tip inward of the root gets a negative in-plane distance rather than a
    plane swung through the body).  Step 2: the knee M is an intersection of the
    circle about O of radius |OM| with the circle about P of radius |MP|; of the
    two, the one above the chord OP (the arch) is the only candidate with
    beta > 0 for gamma >= 0.  ``ok`` is False when the circles do not meet (tip
    too far, or too close to the root) -- then alpha = beta = nan -- or when the
    arch still has beta <= 0 (the leg would have to straighten past its fixed
    bend: only a non-convex solution); then the non-convex angles are returned.
    """
    return _ik_vector(P[0] - O[0], P[1] - O[1], P[2] - O[2], R, side, geom_row, theta_hint)


@njit(cache=True)
def _ik_vector(wx, wy, wz, R, side, geom_row, theta_hint):
    """``leg_inverse_kinematics`` given the world vector P - O = (wx, wy, wz) [m]."""
    ok, theta, alpha, beta, _, _, _, _ = _ik_solve(wx, wy, wz, R, side, geom_row, theta_hint)
    return ok, theta, alpha, beta


@njit(cache=True)
def _ik_solve(wx, wy, wz, R, side, geom_row, theta_hint):
    """``_ik_vector`` that also returns what the forward kinematics of its solution needs:
    (ok, theta, alpha, beta, sin theta, cos theta, mu, mv) with (mu, mv) [m] the knee in the
    leg plane (``leg_plane_points``).  The last four are computed exactly as
    ``leg_forward_kinematics`` computes them from (theta, alpha), so a caller that reuses them
    gets the same doubles without evaluating the sines and cosines twice; they are nan when
    alpha is nan.  Its stages (``_ik_theta``, ``_ik_alpha``, ``_ik_knee``, ``_ik_bend``) are separate so that
    ``stance_ik_and_fk`` can interleave two legs; they are inlined at numba's IR level (as plain calls
    LLVM kept them out of line, and the stance pass ran 20 % slower than with one function)."""
    theta, u, v, st, ct = _ik_theta(wx, wy, wz, R, side, theta_hint)
    ok, alpha = _ik_alpha(u, v, geom_row[FEMUR], geom_row[TIBIA])
    if not ok:
        return False, theta, np.nan, np.nan, st, ct, np.nan, np.nan
    mu, mv = _ik_knee(alpha, geom_row[FEMUR])
    beta = _ik_bend(u, v, alpha, mu, mv, geom_row[GAMMA])
    return beta > 0.0, theta, alpha, beta, st, ct, mu, mv


@njit(cache=True, inline="always")
def _ik_theta(wx, wy, wz, R, side, theta_hint):
    """App. B step 1: the leg plane's angle theta [rad] from the world vector P - O = (wx, wy, wz) [m]
    (``leg_inverse_kinematics``), and the tip in the plane (u outward, v up) [m]; returns
    (theta, u, v, sin theta, cos theta)."""
    dx, dy, dz = _matTvec(R, wx, wy, wz)
    lateral = side * dz  # outward component
    if dx == 0.0 and lateral == 0.0:
        theta = theta_hint
    else:
        theta = math.atan2(dx, lateral)
        if theta > _HALF_PI:
            theta -= math.pi
        elif theta < -_HALF_PI:
            theta += math.pi
    st = math.sin(theta)
    ct = math.cos(theta)
    return theta, dx * st + lateral * ct, dy, st, ct


@njit(cache=True, inline="always")
def _ik_alpha(u, v, femur, tibia):
    """App. B step 2's femur elevation: (ok, alpha [rad]) for the tip (u, v) [m] in the leg plane, the knee
    above the chord OP; (False, nan) where the two circles do not meet."""
    d2 = u * u + v * v
    d = math.sqrt(d2)
    if d == 0.0:
        return False, np.nan
    # foot of the knee on the chord OP, and the knee's height above the chord
    a = (femur * femur - tibia * tibia + d2) / (2.0 * d)
    h2 = femur * femur - a * a
    if h2 < 0.0:
        return False, np.nan
    # atan2 forms keep full precision near straight and folded legs (acos would not)
    return True, _wrap(math.atan2(v, u) + math.atan2(math.sqrt(h2), a))


@njit(cache=True, inline="always")
def _ik_knee(alpha, femur):
    """The knee (mu, mv) [m] in the leg plane for the femur at alpha [rad], as ``leg_plane_points``."""
    return femur * math.cos(alpha), femur * math.sin(alpha)


@njit(cache=True, inline="always")
def _ik_bend(u, v, alpha, mu, mv, gamma):
    """App. B step 2's knee flexion beta [rad] for the tip (u, v) [m] and the femur at alpha with its knee
    (mu, mv) [m] (``_ik_knee``)."""
    return _wrap(alpha - math.atan2(v - mv, u - mu)) - gamma


# --------------------------------------------------------------------------
# All legs at once
# --------------------------------------------------------------------------

@njit(cache=True)
def legs_roots(seg_c, seg_R, geom, O):
    """World root positions of all legs.  O: (n_legs, 3) [m], overwritten."""
    for k in range(geom.shape[0]):
        i = k // 2
        leg_root(seg_c[i], seg_R[i], geom[k], O[k])


@njit(cache=True)
def legs_forward_kinematics(seg_c, seg_R, geom, angles, O, M, P):
    """O, M, P (n_legs, 3) [m] of all legs from angles (n_legs, 3) [rad]; outputs overwritten."""
    for k in range(geom.shape[0]):
        i = k // 2
        leg_forward_kinematics(seg_c[i], seg_R[i], geom[k], side_sign(k), angles[k, THETA],
                               angles[k, ALPHA], angles[k, BETA], O[k], M[k], P[k])


@njit(cache=True)
def legs_inverse_kinematics(seg_c, seg_R, geom, tips, angles, ok):
    """IK of all legs from their tips (n_legs, 3) [m] and their segments' poses.

    The root of leg k is computed from its segment's pose (the Targeter's output,
    Sec. 4.2 STANCE).  Where the IK succeeds, angles[k] (n_legs, 3) [rad] is
    overwritten; where it fails angles[k] is left as it was.  ``angles[k, THETA]``
    on entry is the hint for a tip straight below the root.  ok: (n_legs,) bool,
    overwritten.
    """
    for k in range(geom.shape[0]):
        ok[k] = leg_ik_from_segment(seg_c, seg_R, geom, tips, angles, k)


@njit(cache=True)
def leg_ik_from_segment(seg_c, seg_R, geom, tips, angles, k):
    """IK of leg k from its tip and its segment's pose; writes angles[k] on success.

    seg_c: (n_segments, 3) [m]; seg_R: (n_segments, 3, 3); geom: (n_legs, N_LEG_GEOM);
    tips: (n_legs, 3) [m]; angles: (n_legs, 3) [rad], row k overwritten only on
    success (angles[k, THETA] is the hint).  Returns success.  No allocation.
    """
    i = k // 2
    R = seg_R[i]
    ox, oy, oz = _matvec(R, geom[k, ROOT_X], geom[k, ROOT_Y], geom[k, ROOT_Z])
    success, theta, alpha, beta = _ik_vector(tips[k, 0] - seg_c[i, 0] - ox, tips[k, 1] - seg_c[i, 1] - oy,
                                             tips[k, 2] - seg_c[i, 2] - oz, R, side_sign(k), geom[k],
                                             angles[k, THETA])
    if success:
        angles[k, THETA] = theta
        angles[k, ALPHA] = alpha
        angles[k, BETA] = beta
    return success


@njit(cache=True)
def stance_ik_and_fk(states, stance, seg_c, seg_R, geom, tips, angles, ik_failed, theta_min, O, M):
    """The legs' IK and FK of one controller step in one pass (paper Sec. 4.2, App. B).

    The same doubles as ``switcher.stance_inverse_kinematics`` (the STANCE legs' angles from their
    fixed tips), then ik_failed |= STANCE and theta < theta_min, then ``legs_forward_kinematics``
    of all legs with the STANCE legs' tips kept where they touched down: a STANCE leg whose IK
    succeeded reuses the IK's sin theta, cos theta and knee (mu, mv) for its root and knee, instead
    of evaluating them again, and no leg in STANCE computes the tip it would not keep.

    The two legs of a segment that are both in STANCE (the common case while walking) run their IK
    stage by stage side by side (``_stance_pair``): each leg's IK is a chain of dependent libm calls
    (atan2, sin and cos, two atan2, sin and cos, atan2), and two independent chains issued together
    overlap in the processor (measured 4.1 -> 3.6 to 3.7 us per call on a walking 18-segment state with 28
    of 36 legs in STANCE; the same operations on each leg, so the same doubles).

    states: (n_legs,) int64; stance: the STANCE state code; seg_c (n_segments, 3) [m], seg_R
    (n_segments, 3, 3): the segments' (Targeter) poses; geom (n_legs, N_LEG_GEOM); tips (n_legs, 3)
    [m]: read for STANCE legs, overwritten with the FK tip for the others; angles (n_legs, 3) [rad]:
    STANCE rows overwritten where the IK succeeds (THETA on entry is the hint); ik_failed (n_legs,)
    bool, overwritten; theta_min [rad]; O, M (n_legs, 3) [m] roots and knees, overwritten.  n_legs is
    even (legs 2 i and 2 i + 1 on segment i).
    """
    for i in range(geom.shape[0] // 2):
        k0 = 2 * i
        if states[k0] == stance and states[k0 + 1] == stance:
            _stance_pair(k0, seg_c, seg_R, geom, tips, angles, ik_failed, theta_min, O, M)
            continue
        for k in (k0, k0 + 1):
            c = seg_c[i]
            R = seg_R[i]
            g = geom[k]
            side = side_sign(k)
            ox, oy, oz = _matvec(R, g[ROOT_X], g[ROOT_Y], g[ROOT_Z])
            O[k, 0], O[k, 1], O[k, 2] = c[0] + ox, c[1] + oy, c[2] + oz
            if states[k] == stance:
                ik = _ik_solve(tips[k, 0] - c[0] - ox, tips[k, 1] - c[1] - oy, tips[k, 2] - c[2] - oz, R, side, g,
                               angles[k, THETA])
                _stance_result(k, ik, R, side, g, angles, ik_failed, theta_min, O, M)
                continue
            ik_failed[k] = False
            mu, mv, pu, pv = leg_plane_points(angles[k, ALPHA], angles[k, BETA], g[FEMUR], g[TIBIA], g[GAMMA])
            theta = angles[k, THETA]
            ux, uz = math.sin(theta), side * math.cos(theta)
            wx, wy, wz = _matvec(R, mu * ux, mv, mu * uz)
            M[k, 0], M[k, 1], M[k, 2] = O[k, 0] + wx, O[k, 1] + wy, O[k, 2] + wz
            wx, wy, wz = _matvec(R, pu * ux, pv, pu * uz)
            tips[k, 0], tips[k, 1], tips[k, 2] = O[k, 0] + wx, O[k, 1] + wy, O[k, 2] + wz


@njit(cache=True, inline="always")
def _stance_pair(k0, seg_c, seg_R, geom, tips, angles, ik_failed, theta_min, O, M):
    """``stance_ik_and_fk`` on legs k0 (left) and k0 + 1 (right) of one segment, both in STANCE: each leg's
    ``_ik_solve`` stage by stage, the two legs side by side, then ``_stance_result``.  A leg whose circles
    do not meet gets alpha = nan from ``_ik_alpha``; its knee and bend on that nan are computed and not used."""
    k1 = k0 + 1
    i = k0 // 2
    c = seg_c[i]
    R = seg_R[i]
    g0, g1 = geom[k0], geom[k1]
    s0, s1 = -1.0, 1.0  # side_sign of a left (even) and a right (odd) leg
    ox0, oy0, oz0 = _matvec(R, g0[ROOT_X], g0[ROOT_Y], g0[ROOT_Z])
    ox1, oy1, oz1 = _matvec(R, g1[ROOT_X], g1[ROOT_Y], g1[ROOT_Z])
    O[k0, 0], O[k0, 1], O[k0, 2] = c[0] + ox0, c[1] + oy0, c[2] + oz0
    O[k1, 0], O[k1, 1], O[k1, 2] = c[0] + ox1, c[1] + oy1, c[2] + oz1
    th0, u0, v0, st0, ct0 = _ik_theta(tips[k0, 0] - c[0] - ox0, tips[k0, 1] - c[1] - oy0, tips[k0, 2] - c[2] - oz0,
                                      R, s0, angles[k0, THETA])
    th1, u1, v1, st1, ct1 = _ik_theta(tips[k1, 0] - c[0] - ox1, tips[k1, 1] - c[1] - oy1, tips[k1, 2] - c[2] - oz1,
                                      R, s1, angles[k1, THETA])
    ok0, al0 = _ik_alpha(u0, v0, g0[FEMUR], g0[TIBIA])
    ok1, al1 = _ik_alpha(u1, v1, g1[FEMUR], g1[TIBIA])
    mu0, mv0 = _ik_knee(al0, g0[FEMUR])
    mu1, mv1 = _ik_knee(al1, g1[FEMUR])
    be0 = _ik_bend(u0, v0, al0, mu0, mv0, g0[GAMMA])
    be1 = _ik_bend(u1, v1, al1, mu1, mv1, g1[GAMMA])
    _stance_result(k0, (ok0 and be0 > 0.0, th0, al0, be0, st0, ct0, mu0, mv0), R, s0, g0, angles, ik_failed,
                   theta_min, O, M)
    _stance_result(k1, (ok1 and be1 > 0.0, th1, al1, be1, st1, ct1, mu1, mv1), R, s1, g1, angles, ik_failed,
                   theta_min, O, M)


@njit(cache=True, inline="always")
def _stance_result(k, ik, R, side, g, angles, ik_failed, theta_min, O, M):
    """A STANCE leg k's IK result ik (``_ik_solve``'s tuple (ok, theta, alpha, beta, sin theta, cos theta, mu,
    mv), scalars that stay in registers once inlined) into angles, ik_failed (rule 3 and theta_min) and
    its knee M[k] from the root O[k]: from the IK's own sines, cosines and knee where it succeeded, else from
    the angles it keeps (``leg_forward_kinematics``' M)."""
    ok, theta, alpha, beta, st, ct, mu, mv = ik
    ik_failed[k] = not ok
    if ok:
        angles[k, THETA], angles[k, ALPHA], angles[k, BETA] = theta, alpha, beta
    if angles[k, THETA] < theta_min:
        ik_failed[k] = True
    if not ok:
        mu, mv, _, _ = leg_plane_points(angles[k, ALPHA], angles[k, BETA], g[FEMUR], g[TIBIA], g[GAMMA])
        th = angles[k, THETA]
        st, ct = math.sin(th), math.cos(th)
    wx, wy, wz = _matvec(R, mu * st, mv, mu * (side * ct))
    M[k, 0], M[k, 1], M[k, 2] = O[k, 0] + wx, O[k, 1] + wy, O[k, 2] + wz


@njit(cache=True)
def tips_touching(kind, f, tips, contact_distance, out):
    """Contact test of Sec. 5.1 (inside/outside) widened by a contact distance.

    out[k] = phi(tip_k) <= contact_distance, with phi the terrain signed distance
    [m] of ``terrain_kernels`` (kind, f).  tips: (n_legs, 3) [m]; out: (n_legs,)
    bool, overwritten.
    """
    for k in range(tips.shape[0]):
        out[k] = signed_distance(kind, f, tips[k, 0], tips[k, 1], tips[k, 2]) <= contact_distance
