"""The Targeter of the myriapod paper (Fang, Jiang & Terzopoulos 2013, Sec. 4.1,
footnote 2, Sec. 4.3 and Sec. 6): desired poses of the rigid segments.

Each rigid segment i has a pose (centre ``c_i`` (3,) [m], rotation ``R_i``
(3, 3), segment -> world; segment frame x forward, y up, z right).  Every step
its target pose is initialized to the current one and then modified:

* Balancer (footnote 2): turn the segment's y axis toward the ground normal n
  below the centre by rotations about the segment's own z and x axes,
  ``R_T *= R([0, 0, +-1], w dt) R([+-1, 0, 0], w dt)``, the signs from the
  projection of n on the segment's x and z axes; and move the centre along n
  toward the target height: ``c_T += k2 (h_T - h) n dt``.  The paper prints
  (h - h_T), which with the upward normal would push a segment that is too high
  further up (PAPER-NOTES.md); we use the restoring sign.
* Follower (footnote 2): with the link vector l = c_ahead - c_i to the segment
  ahead (i - 1; the dragon dance of Sec. 4 -- each segment follows the one
  ahead of it), ``c_T += k1 (|l| - l0) l dt`` keeps the link length at l0, and
  ``R_T *= R([0, +-1, 0], w dt)`` turns the x axis toward l, the sign from the
  projection of l on the segment's z axis: l to the right (+z) needs a rotation
  about -y (a rotation about +y turns x toward -z).
* Follower speed feedforward (beyond the paper; the dynamic stance's default,
  ``controller.follower_feedforward``): ``c_T += v_head dt l / |l|`` as well, v_head the head's
  commanded speed, so a follower walks at the commanded speed by itself and the stretch term
  only corrects its spacing.  The paper's Follower alone needs a link stretched by
  v_head / (k1 |l|) to follow at v_head; a carried segment stretches its links for free, a
  segment pushed by its legs must hold that link's tension with its feet
  (docs/explanation/dynamic-stance.md, "Why the paper's Follower crawls").  Off (0) in the
  paper's kinematic stance: the same doubles as without it.
* Head (Sec. 4.3): the Balancer, then the motion (Sec. 6, step 2): the centre
  moves along the head's own x axis at the commanded speed and the head turns
  about its y axis at the commanded rate, ``turn_dir`` = +1 left (a positive
  rotation about y, x toward -z), -1 right, 0 straight.

Every rotation is limited so it cannot overshoot: it turns by
min(w dt, remaining angle), and not at all once the remaining angle is within
``ALIGN_TOL`` -- so an aligned segment stays exactly still instead of
chattering by +-w dt.  Rotations multiply on the right: they are about the
segment's own axes.  After the updates R_T is re-orthonormalized (Gram-Schmidt),
so a body that copies R_T back every step does not drift off SO(3).

Sec. 6 order: the head first, then the segments tail-ward, each Balancer before
its Follower; a segment follows the *updated* pose of the segment ahead (the
ahead segment's target when it is kinematic, its current pose otherwise).

Parameter vector ``params`` (float64, N_TARGETER_PARAMS), ``targeter_params``:

=============  ===========  ========================================
K1             [1/(m s)]    Follower gain; stable for k1 |l|^2 dt < 2
K2             [1/s]        Balancer height gain; stable for k2 dt < 2
OMEGA_FOLLOW   [rad/s]      Follower turn rate
OMEGA_BALANCE  [rad/s]      Balancer turn rate
ALIGN_TOL      [rad]        an axis this close to its goal is not turned
FOLLOW_FF      [-]          1: the Follower's speed feedforward, 0: none
=============  ===========  ========================================

Walls (``keep_clear_of_walls``).  A supported segment is carried by its legs and has no collision of its
own, and the Targeter's Follower pulls it toward the segment ahead, cutting the head's turns toward their
inside: past a tall obstacle (a wall the Balancer does not stand on, ``controller.walkable_terrain``) the
cut can carry a box into it, which a rigid box integrated by the body would never enter (its corner
contact holds it at the surface).  So after the poses are set, a carried segment whose box reaches into a
wall is moved out of it along the wall's outward normal, the kinematic counterpart of that contact.  A
segment clear of every wall is left exactly as it was.

Per-segment arrays: ``link_rest`` (n_segments,) [m], rest length l0 of the link
from segment i to segment i - 1 (entry 0 unused); ``height_target``
(n_segments,) [m], target height h_T of the centre above the terrain.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from bench_myriapoda.controllers.myriapod.switcher import STANCE
from bench_myriapoda.world.terrain_kernels import H_NOBST, distance_and_normal, obstacle_normal, obstacles_below

K1, K2, OMEGA_FOLLOW, OMEGA_BALANCE, ALIGN_TOL, FOLLOW_FF = 0, 1, 2, 3, 4, 5
N_TARGETER_PARAMS = 6

TURN_LEFT, TURN_STRAIGHT, TURN_RIGHT = 1, 0, -1


def targeter_params(k1: float = 20.0, k2: float = 10.0, omega_follow: float = 2.0,
                    omega_balance: float = 2.0, align_tol: float = 1e-6, follow_feedforward: bool = False) -> np.ndarray:
    """The Targeter parameter vector (units in the module docstring).

    The paper gives no values; these defaults settle a unit-length link in
    about 1/k1 s and a height error in about 1/k2 s.  follow_feedforward: the
    Follower's speed feedforward (module docstring; off: the paper's Follower).
    """
    values = np.empty(N_TARGETER_PARAMS)
    values[K1], values[K2] = k1, k2
    values[OMEGA_FOLLOW], values[OMEGA_BALANCE], values[ALIGN_TOL] = omega_follow, omega_balance, align_tol
    values[FOLLOW_FF] = 1.0 if follow_feedforward else 0.0
    if not (np.all(np.isfinite(values)) and np.all(values >= 0.0)):
        raise ValueError(f"targeter parameters must be finite and >= 0, got {values}")
    return values


@njit(cache=True)
def rotate_about_own_axis(R, axis, angle):
    """R <- R @ Rot(e_axis, angle): rotate a frame about its own axis (0 x, 1 y, 2 z).

    R: (3, 3), columns are the frame's axes in the world; overwritten.  Only
    the two other columns mix: with (i, j) the cyclic successors of ``axis``,
    col_i <- col_i cos + col_j sin and col_j <- col_j cos - col_i sin.
    """
    if angle == 0.0:
        return
    i = (axis + 1) % 3
    j = (axis + 2) % 3
    cs = math.cos(angle)
    sn = math.sin(angle)
    for r in range(3):
        a = R[r, i]
        b = R[r, j]
        R[r, i] = a * cs + b * sn
        R[r, j] = b * cs - a * sn


@njit(cache=True)
def orthonormalize(R):
    """Gram-Schmidt on the columns of R (3, 3) in place: x normalized, y made
    orthogonal to x and normalized, z = x cross y."""
    n = math.sqrt(R[0, 0] ** 2 + R[1, 0] ** 2 + R[2, 0] ** 2)
    for r in range(3):
        R[r, 0] /= n
    d = R[0, 0] * R[0, 1] + R[1, 0] * R[1, 1] + R[2, 0] * R[2, 1]
    for r in range(3):
        R[r, 1] -= d * R[r, 0]
    n = math.sqrt(R[0, 1] ** 2 + R[1, 1] ** 2 + R[2, 1] ** 2)
    for r in range(3):
        R[r, 1] /= n
    R[0, 2] = R[1, 0] * R[2, 1] - R[2, 0] * R[1, 1]
    R[1, 2] = R[2, 0] * R[0, 1] - R[0, 0] * R[2, 1]
    R[2, 2] = R[0, 0] * R[1, 1] - R[1, 0] * R[0, 1]


@njit(cache=True)
def limited_turn(remaining, max_step, tol):
    """Signed turn [rad] toward a goal ``remaining`` [rad] away: 0 within tol,
    else sign(remaining) min(|remaining|, max_step)."""
    if abs(remaining) <= tol:
        return 0.0
    return math.copysign(min(abs(remaining), max_step), remaining)


@njit(cache=True)
def turn_toward(y, x, max_step, tol):
    """``limited_turn(atan2(y, x), max_step, tol)`` [rad], without the atan2 where its answer is surely 0.

    For x > 0, |atan2(y, x)| <= |y| / x; with |y| <= tol x / 2 the angle is within tol even after the
    roundings of the test and of atan2 (a few ulps), so the turn is 0 -- the same double the full form
    returns.  An aligned segment (the common case: the Balancer's two axes every step) skips two atan2.
    """
    if x > 0.0 and abs(y) <= 0.5 * tol * x:
        return 0.0
    return limited_turn(math.atan2(y, x), max_step, tol)


@njit(cache=True)
def balance(c_T, R_T, h, nx, ny, nz, h_target, k2, omega, tol, dt):
    """Balancer (footnote 2) on a target pose, in place.

    c_T: (3,) [m]; R_T: (3, 3); h [m] current height above the terrain; n =
    (nx, ny, nz) unit ground normal below the segment; h_target [m]; k2 [1/s];
    omega [rad/s]; tol [rad]; dt [s].
    """
    # restoring sign (PAPER-NOTES.md): too high -> move against n, i.e. down
    g = k2 * (h_target - h) * dt
    c_T[0] += g * nx
    c_T[1] += g * ny
    c_T[2] += g * nz
    # n in the segment frame; y leans toward +x by a rotation about -z, toward +z about +x
    lx = R_T[0, 0] * nx + R_T[1, 0] * ny + R_T[2, 0] * nz
    ly = R_T[0, 1] * nx + R_T[1, 1] * ny + R_T[2, 1] * nz
    lz = R_T[0, 2] * nx + R_T[1, 2] * ny + R_T[2, 2] * nz
    step = omega * dt
    turn_z = -turn_toward(lx, ly, step, tol)
    turn_x = turn_toward(lz, ly, step, tol)
    rotate_about_own_axis(R_T, np.int64(2), turn_z)
    rotate_about_own_axis(R_T, np.int64(0), turn_x)


@njit(cache=True)
def follow(c_T, R_T, c_self, c_ahead, l0, k1, omega, tol, dt):
    """Follower (footnote 2) on a target pose, in place.

    c_T: (3,) [m]; R_T: (3, 3); c_self: (3,) [m] the segment's current centre;
    c_ahead: (3,) [m] the (updated) centre of the segment ahead; l0 [m] rest
    link length; k1 [1/(m s)]; omega [rad/s]; tol [rad]; dt [s].
    """
    _follow_centre(c_T, c_self, c_ahead, l0, k1, dt)
    _follow_turn(R_T, c_self, c_ahead, omega, tol, dt)


@njit(cache=True, inline="always")
def _follow_centre(c_T, c_self, c_ahead, l0, k1, dt):
    """The Follower's move of the centre: c_T += k1 (|l| - l0) l dt, l = c_ahead - c_self."""
    lx = c_ahead[0] - c_self[0]
    ly = c_ahead[1] - c_self[1]
    lz = c_ahead[2] - c_self[2]
    length = math.sqrt(lx * lx + ly * ly + lz * lz)
    g = k1 * (length - l0) * dt
    c_T[0] += g * lx
    c_T[1] += g * ly
    c_T[2] += g * lz


@njit(cache=True, inline="always")
def _follow_speed(c_T, c_self, c_ahead, speed, dt):
    """The Follower's speed feedforward: c_T += speed dt l / |l|, l = c_ahead - c_self; speed [m/s] the
    head's commanded speed (module docstring)."""
    lx = c_ahead[0] - c_self[0]
    ly = c_ahead[1] - c_self[1]
    lz = c_ahead[2] - c_self[2]
    length = math.sqrt(lx * lx + ly * ly + lz * lz)
    if length > 0.0:
        g = speed * dt / length
        c_T[0] += g * lx
        c_T[1] += g * ly
        c_T[2] += g * lz


@njit(cache=True, inline="always")
def _follow_turn(R_T, c_self, c_ahead, omega, tol, dt):
    """The Follower's turn of the x axis toward l = c_ahead - c_self about the segment's own y axis."""
    lx = c_ahead[0] - c_self[0]
    ly = c_ahead[1] - c_self[1]
    lz = c_ahead[2] - c_self[2]
    # angle from the x axis to l in the segment's x-z plane, positive toward +z
    px = R_T[0, 0] * lx + R_T[1, 0] * ly + R_T[2, 0] * lz
    pz = R_T[0, 2] * lx + R_T[1, 2] * ly + R_T[2, 2] * lz
    if px == 0.0 and pz == 0.0:
        return
    rotate_about_own_axis(R_T, np.int64(1), -turn_toward(pz, px, omega * dt, tol))


@njit(cache=True)
def head_motion(c_T, R_T, speed, turn_rate, turn_dir, dt):
    """The head's commanded motion (Sec. 4.3), in place: c_T += speed dt x_axis,
    then a turn by turn_dir turn_rate dt about the head's own y axis.

    speed [m/s]; turn_rate [rad/s] >= 0; turn_dir: +1 left, -1 right, 0 none.
    """
    d = speed * dt
    c_T[0] += d * R_T[0, 0]
    c_T[1] += d * R_T[1, 0]
    c_T[2] += d * R_T[2, 0]
    rotate_about_own_axis(R_T, np.int64(1), turn_dir * turn_rate * dt)


@njit(cache=True)
def targeter_step(c, R, kinematic, kind, f, params, link_rest, height_target,
                  head_speed, head_turn_rate, head_turn_dir, dt, c_T, R_T):
    """Target poses of all rigid segments for one step (Sec. 6, steps 2-3).

    c: (n_segments, 3) [m], R: (n_segments, 3, 3) current poses;
    kinematic: (n_segments,) bool -- for the head, "not in the brain's
    ADJUSTMENT mode"; for the others, "supported" (``segments_supported``).
    A segment that is not kinematic gets its current pose as target (the body
    dynamics moves it).  kind, f: terrain (``terrain_kernels``), queried at each
    centre for h (signed distance) and n.  params: (N_TARGETER_PARAMS,);
    link_rest, height_target: (n_segments,) [m]; head_speed [m/s];
    head_turn_rate [rad/s]; head_turn_dir (+1 left, -1 right, 0); dt [s].
    c_T: (n_segments, 3) [m], R_T: (n_segments, 3, 3): overwritten (must not
    alias c, R).
    """
    # Two passes over the segments, each segment's operations in the order of Sec. 6 (Balancer, then the
    # head's motion or the Follower, then Gram-Schmidt), so the same doubles as one pass: the centres first,
    # head to tail (a Follower needs the final centre of the segment ahead: a chain of dependent steps), then
    # the Followers' turns and the re-orthonormalization, which depend on that chain but not on each other,
    # so the processor overlaps their atan2, sin, cos and square roots across segments (issue 13).
    n = c.shape[0]
    for i in range(n):
        for a in range(3):
            c_T[i, a] = c[i, a]
            for b in range(3):
                R_T[i, a, b] = R[i, a, b]
        if not kinematic[i]:
            continue
        x, y, z = c[i, 0], c[i, 1], c[i, 2]
        h, nx, ny, nz = distance_and_normal(kind, f, x, y, z)  # signed_distance, surface_normal: one search
        balance(c_T[i], R_T[i], h, nx, ny, nz, height_target[i], params[K2], params[OMEGA_BALANCE],
                params[ALIGN_TOL], dt)
        if i == 0:
            head_motion(c_T[0], R_T[0], head_speed, head_turn_rate, head_turn_dir, dt)
        else:
            _follow_centre(c_T[i], c[i], c_T[i - 1], link_rest[i], params[K1], dt)
            if params[FOLLOW_FF] != 0.0:  # the paper's Follower (0) takes no branch: the same doubles
                _follow_speed(c_T[i], c[i], c_T[i - 1], head_speed, dt)
    for i in range(n):
        if not kinematic[i]:
            continue
        if i > 0:
            _follow_turn(R_T[i], c[i], c_T[i - 1], params[OMEGA_FOLLOW], params[ALIGN_TOL], dt)
        orthonormalize(R_T[i])


@njit(cache=True)
def segments_supported(states, min_stance_legs, out):
    """out[i] = segment i has at least ``min_stance_legs`` (1 or 2) legs in STANCE.

    Sec. 4.1: a supported segment is carried kinematically by its legs.  The
    paper does not say how many; its left/right synchronization "maximizes the
    duration that a rigid segment stays in the ... supported state" (Sec. 4.2),
    which holds only if support needs both legs -- with one leg enough,
    alternating the sides would maximize it instead.  So 2 is the reading of
    the paper, 1 a looser option.  states: (2 n_segments,) int64; out:
    (n_segments,) bool, overwritten.
    """
    for i in range(out.shape[0]):
        n = 0
        if states[2 * i] == STANCE:
            n += 1
        if states[2 * i + 1] == STANCE:
            n += 1
        out[i] = n >= min_stance_legs


# the points of a segment's box tested against the walls, in half extents: the 8 corners and the midpoints
# of the 4 edges along the segment's length (x), so a wall thinner than the box's length is caught too
WALL_PROBES = ((-1.0, -1.0, -1.0), (1.0, -1.0, -1.0), (-1.0, 1.0, -1.0), (1.0, 1.0, -1.0),
               (-1.0, -1.0, 1.0), (1.0, -1.0, 1.0), (-1.0, 1.0, 1.0), (1.0, 1.0, 1.0),
               (0.0, -1.0, -1.0), (0.0, 1.0, -1.0), (0.0, -1.0, 1.0), (0.0, 1.0, 1.0))
WALL_PASSES = 4  # push-outs per segment and step: a box against two walls at once, or a corner after a push


@njit(cache=True, error_model="numpy")
def keep_clear_of_walls(c_T, R_T, kinematic, walls, half):
    """Move every carried segment's target centre out of the walls (module docstring); return the pushes made.

    c_T: (n_segments, 3) [m], R_T: (n_segments, 3, 3): the targets, c_T UPDATED in place (R_T read); kinematic:
    (n_segments,) bool, the carried segments; walls: a terrain array holding only the wall obstacles (its
    base surface is not used; ``controller.wall_terrain``); half: (n_segments, 3) [m] the boxes' half extents.
    A pass finds the deepest of the box's ``WALL_PROBES`` inside a wall (signed distance phi < 0) and moves the
    centre by -phi along that wall's outward normal there; up to ``WALL_PASSES`` passes, ending at the first
    with no probe inside.  A segment with no probe inside is not touched (the same doubles as without walls).
    """
    if walls[H_NOBST] <= 0.0:
        return 0
    pushes = 0
    for i in range(c_T.shape[0]):
        if not kinematic[i]:
            continue
        for _ in range(WALL_PASSES):
            deepest = 0.0
            jw = np.int64(-1)  # not a literal -1: numba would compile obstacle_normal for Literal[int](-1) too
            qx = qy = qz = 0.0
            for sx, sy, sz in WALL_PROBES:
                ax, ay, az = sx * half[i, 0], sy * half[i, 1], sz * half[i, 2]
                px = c_T[i, 0] + R_T[i, 0, 0] * ax + R_T[i, 0, 1] * ay + R_T[i, 0, 2] * az
                py = c_T[i, 1] + R_T[i, 1, 0] * ax + R_T[i, 1, 1] * ay + R_T[i, 1, 2] * az
                pz = c_T[i, 2] + R_T[i, 2, 0] * ax + R_T[i, 2, 1] * ay + R_T[i, 2, 2] * az
                phi, j = obstacles_below(walls, px, py, pz, deepest)
                if j >= 0 and phi < deepest:
                    deepest, jw, qx, qy, qz = phi, j, px, py, pz
            if jw < 0:
                break
            nx, ny, nz = obstacle_normal(walls, jw, qx, qy, qz)
            c_T[i, 0] -= deepest * nx
            c_T[i, 1] -= deepest * ny
            c_T[i, 2] -= deepest * nz
            pushes += 1
    return pushes
