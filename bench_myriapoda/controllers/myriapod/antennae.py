"""The myriapod's antennae (Fang, Jiang & Terzopoulos 2013, Sec. 5.2, Fig. 11; Sec. 6 step 1).

Two antennae (0 left, 1 right) on the head segment, each a chain of N short
links of length l.  Link i has two joint angles (theta_i, phi_i) relative to
the previous link (the root link, i = 0, relative to the head frame):

* theta -- yaw about the previous link's y axis, positive **outward** (away from
  the midline): the left antenna (at -z; z is the creature's right) turns by
  +theta about y (a positive rotation about +y turns x toward -z), the right one
  by -theta, so the two are mirror images for equal angles;
* phi -- pitch about the (yawed) z axis, positive up.

Forward kinematics: F_base = R_head; F_i = F_(i-1) Ry(s theta_i) Rz(phi_i) with
s = +1 left, -1 right; p_0 = c_head + R_head (root_x, root_y, -+root_z) and
p_(i+1) = p_i + l F_i e_x.  Every link keeps its length by construction.

Motion (Sec. 5.2):

* root link: [theta_0, phi_0] moves toward a random target [theta_T, phi_T] at
  the constant angular speed omega0 (along the straight line in angle space,
  landing exactly on it); when it arrives, a new target is drawn (uniform in
  the configured ranges, from the controller's seeded generator) -- the
  kernel reports ``arrived`` and the Python side draws;
* links i >= 1: [theta_i, phi_i] = A sin(omega t - lambda i) + B (an outward
  travelling wave for lambda > 0).

Contact and retraction (Sec. 5.2 "the theta_T, phi_T and omega0 will be
adjusted to retract the antenna in the direction of the obstacle's surface
normal"): each link is sampled at its middle and its end; a sample with
``obstacles_phi < margin`` (obstacles only, not the ground; the margin is
small, 2 cm by default) is a contact: inside the obstacle, or touching it --
a retracted antenna is held ``margin`` outside, so one pressed against an
obstacle keeps touching it.  Contact ends when every sample is more than
``release`` (twice the margin) outside.
On contact the antenna is retracted in two ways:

1. the paper's: the root's target moves by ``retract_angle`` in the direction
   (in (theta_0, phi_0) space) that moves the deepest contact point along the
   obstacle's outward normal n -- the gradient (n . dp/dtheta_0, n . dp/dphi_0)
   -- and the root turns there at ``retract_speed`` instead of omega0 (the
   target may leave the random ranges by up to ``retract_angle``); when it
   arrives, omega0 and random targets resume;
2. the touching links are pulled out within the same step: going from the root
   to the tip, a link whose samples are inside (or closer than ``margin``) is
   turned about its own start point, its end pushed along the normal until every
   sample is ``margin`` outside (a few fixed-point iterations), and the links
   beyond it keep their joint angles.  The change of a link's joint angles is
   kept as a retraction offset that relaxes back to zero with time constant
   ``relax_tau`` (so a retracted antenna stays out while the obstacle is there
   and resumes its wave when it is gone).

A link whose start is itself inside an obstacle (the head inside it) cannot be
pulled out by turning; it is left as it is.

Parameter vector ``params`` (``antenna_params``), angles in radians:
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from ...world.terrain_kernels import (
    H_NOBST,
    _obstacle_normal,
    _obstacle_phi,
    obstacles_within,
)

LEFT, RIGHT = 0, 1
THETA, PHI = 0, 1

(P_NLINKS, P_LINK, P_RX, P_RY, P_RZ, P_OMEGA0, P_ATH, P_APH, P_BTH, P_BPH, P_OMEGA_W, P_LAMBDA, P_MARGIN,
 P_RELEASE, P_RETRACT_SPEED, P_RETRACT_ANGLE, P_RELAX_TAU, P_TH_LO, P_TH_HI, P_PH_LO, P_PH_HI) = range(21)
N_ANTENNA_PARAMS = 21
PROJECTION_ITERATIONS = 12
SAMPLES = (0.5, 1.0)  # where along a link its contact samples sit (fractions of its length)

__doc__ += """
==================  =====  ===============================================
P_NLINKS            [-]    links per antenna N
P_LINK              [m]    link length l
P_RX, P_RY, P_RZ    [m]    root joint in the head frame (left at -P_RZ)
P_OMEGA0            rad/s  root turn speed toward random targets
P_ATH, P_APH        rad    wave amplitudes A_theta, A_phi
P_BTH, P_BPH        rad    wave bases B_theta, B_phi
P_OMEGA_W           rad/s  wave angular frequency omega
P_LAMBDA            rad    wave phase lag per link lambda
P_MARGIN            [m]    retracted samples are held this far outside
P_RELEASE           [m]    contact ends beyond this distance (2 margin)
P_RETRACT_SPEED     rad/s  root turn speed while retracting
P_RETRACT_ANGLE     rad    how far the root target moves on contact
P_RELAX_TAU         [s]    relaxation time of the retraction offsets
P_TH_LO .. P_PH_HI  rad    ranges of the random root targets
==================  =====  ===============================================
"""


def antenna_params(cfg) -> np.ndarray:
    """The parameter vector of an ``AntennaeConfig`` (degrees and hertz converted to radians)."""
    d = math.radians
    p = np.zeros(N_ANTENNA_PARAMS)
    p[P_NLINKS], p[P_LINK] = cfg.n_links, cfg.link_length_m
    p[P_RX], p[P_RY], p[P_RZ] = cfg.root_x_m, cfg.root_y_m, cfg.root_z_m
    p[P_OMEGA0] = d(cfg.omega0_deg_s)
    p[P_ATH], p[P_APH] = d(cfg.wave_amplitude_theta_deg), d(cfg.wave_amplitude_phi_deg)
    p[P_BTH], p[P_BPH] = d(cfg.wave_base_theta_deg), d(cfg.wave_base_phi_deg)
    p[P_OMEGA_W] = 2.0 * math.pi * cfg.wave_frequency_hz
    p[P_LAMBDA] = d(cfg.wave_lambda_deg)
    p[P_MARGIN] = cfg.contact_margin_m
    p[P_RELEASE] = 2.0 * cfg.contact_margin_m
    p[P_RETRACT_SPEED], p[P_RETRACT_ANGLE] = d(cfg.retract_speed_deg_s), d(cfg.retract_angle_deg)
    p[P_RELAX_TAU] = cfg.retract_relax_s
    p[P_TH_LO], p[P_TH_HI] = d(cfg.root_theta_range_deg[0]), d(cfg.root_theta_range_deg[1])
    p[P_PH_LO], p[P_PH_HI] = d(cfg.root_phi_range_deg[0]), d(cfg.root_phi_range_deg[1])
    return p


# --------------------------------------------------------------------------- small 3x3 helpers

@njit(cache=True)
def _yaw_pitch_frame(F_prev, a, phi, out):
    """out = F_prev Ry(a) Rz(phi) (3x3); Ry(a) turns x toward -z for a > 0, Rz(phi) x toward +y."""
    ca, sa = math.cos(a), math.sin(a)
    cp, sp = math.cos(phi), math.sin(phi)
    # M = Ry(a) Rz(phi); columns: x = (ca cp, sp, -sa cp), y = (-ca sp, cp, sa sp), z = (sa, 0, ca)
    m00, m01, m02 = ca * cp, -ca * sp, sa
    m10, m11, m12 = sp, cp, 0.0
    m20, m21, m22 = -sa * cp, sa * sp, ca
    for r in range(3):
        f0, f1, f2 = F_prev[r, 0], F_prev[r, 1], F_prev[r, 2]
        out[r, 0] = f0 * m00 + f1 * m10 + f2 * m20
        out[r, 1] = f0 * m01 + f1 * m11 + f2 * m21
        out[r, 2] = f0 * m02 + f1 * m12 + f2 * m22


@njit(cache=True)
def _angles_of_direction(F_prev, dx, dy, dz):
    """(a, phi) with F_prev Ry(a) Rz(phi) e_x = d (unit): d in F_prev's frame is
    (cos phi cos a, sin phi, -cos phi sin a)."""
    lx = F_prev[0, 0] * dx + F_prev[1, 0] * dy + F_prev[2, 0] * dz
    ly = F_prev[0, 1] * dx + F_prev[1, 1] * dy + F_prev[2, 1] * dz
    lz = F_prev[0, 2] * dx + F_prev[1, 2] * dy + F_prev[2, 2] * dz
    return math.atan2(-lz, lx), math.asin(min(1.0, max(-1.0, ly)))


@njit(cache=True)
def _root_toward_target(ang, target, omega, dt):
    """Move (theta, phi) toward target by omega dt along the straight line; True when it lands."""
    d0 = target[0] - ang[0]
    d1 = target[1] - ang[1]
    dist = math.sqrt(d0 * d0 + d1 * d1)
    step = omega * dt
    if dist <= step:
        ang[0] = target[0]
        ang[1] = target[1]
        return True
    s = step / dist
    ang[0] += s * d0
    ang[1] += s * d1
    return False


@njit(cache=True)
def _near_obstacles(f, x, y, z, radius, out):
    """Record indices (into f) of the obstacles closer than ``radius`` to (x, y, z), written to out; how many.

    Through the terrain's obstacle grid (``terrain_kernels.obstacles_within``): the cells
    near the root, in record order, as a loop over every obstacle would give them.
    """
    return obstacles_within(f, x, y, z, radius, out)


@njit(cache=True)
def _phi_near(f, near, n_near, x, y, z):
    """(phi, record index) of the nearest of the ``near`` obstacles; (inf, -1) without any."""
    best = np.inf
    arg = -1
    for k in range(n_near):
        d = _obstacle_phi(f, near[k], x, y, z)
        if d < best:
            best = d
            arg = near[k]
    return best, arg


# --------------------------------------------------------------------------- the kernels

@njit(cache=True)
def wave_angles(params, t, nominal_a):
    """The wave of the links after the root at time t [s]: nominal_a (N, 2) [rad] of one antenna, rows 1..N-1
    written in place (row 0, the root, follows its own target dynamics)."""
    for i in range(1, nominal_a.shape[0]):
        ph = params[P_OMEGA_W] * t - params[P_LAMBDA] * i
        nominal_a[i, THETA] = params[P_ATH] * math.sin(ph) + params[P_BTH]
        nominal_a[i, PHI] = params[P_APH] * math.sin(ph) + params[P_BPH]


@njit(cache=True)
def antennae_forward_kinematics(c, R, params, angles, points, frames):
    """Link points of both antennae from joint angles, no contact handling.

    c: (3,) [m], R: (3, 3) head pose; angles: (2, N, 2) [rad] joint angles
    (theta, phi) used as they are; points: (2, N + 1, 3) [m] out (point 0 the root
    joint, point N the tip); frames: (2, N + 1, 3, 3) out: frames[:, 0] the head
    frame, frames[:, i + 1] link i's frame (x along the link).
    """
    n = angles.shape[1]
    for a in range(2):
        s = 1.0 if a == LEFT else -1.0
        rz = -params[P_RZ] if a == LEFT else params[P_RZ]
        for k in range(3):
            points[a, 0, k] = c[k] + R[k, 0] * params[P_RX] + R[k, 1] * params[P_RY] + R[k, 2] * rz
            for m in range(3):
                frames[a, 0, k, m] = R[k, m]
        for i in range(n):
            _yaw_pitch_frame(frames[a, i], s * angles[a, i, THETA], angles[a, i, PHI], frames[a, i + 1])
            for k in range(3):
                points[a, i + 1, k] = points[a, i, k] + params[P_LINK] * frames[a, i + 1, k, 0]


# ``antennae_step``'s state, packed (numba compiles a namedtuple of arrays as a struct of them).  Callers hand
# them over as plain tuples in these fields' order (``Antennae.step_packs``; ``compiled.controller_step``
# builds them in compiled code): numba types a plain tuple of arrays in its C dispatcher, a namedtuple in
# Python (``bodies.rigid_chain``).  The fields are described in ``antennae_step``.
AntennaMotion = namedtuple("AntennaMotion", "nominal offsets root_target root_omega retracting")
AntennaContact = namedtuple("AntennaContact", "contact rising contact_point contact_normal contact_depth arrived")
AntennaShape = namedtuple("AntennaShape", "points frames")


@njit(cache=True)
def antennae_step(c, R, t, dt, params, f, motion, touch, shape, links):
    """One antenna update (Sec. 6, step 1) from the head pose (c (3,) [m], R (3, 3)) at time t [s].

    f: terrain parameter vector (its obstacle block is queried; the ground is not).
    motion = ``AntennaMotion`` (nominal, offsets, root_target, root_omega, retracting), touch =
    ``AntennaContact`` (contact, rising, contact_point, contact_normal, contact_depth, arrived), shape =
    ``AntennaShape`` (points, frames), each a tuple of these arrays:
    State, updated in place: nominal (2, N, 2) [rad] joint angles of the motion
    (root dynamics and wave); offsets (2, N, 2) [rad] retraction offsets (the
    antenna's joints are nominal + offsets); root_target (2, 2) [rad];
    root_omega (2,) [rad/s] current root speed; retracting (2,) bool; contact (2,)
    bool (in: last step's contact, for the release hysteresis; out: this step's);
    rising (2,) bool out: contact began this step.
    Out: contact_point, contact_normal (2, 3) the deepest sample of a touching
    antenna before its retraction and the obstacle's outward normal there;
    contact_depth (2,) [m] its depth (-phi, > 0 inside; 0 without contact);
    arrived (2,) bool: the root reached a random target (draw a new one);
    points (2, N + 1, 3) [m]; frames (2, N + 1, 3, 3) (0: the head frame, i + 1: link i).
    links: False lets a caller that steps many times in a row (``compiled.controller_step`` inside a fused
    chunk) skip, on a terrain WITHOUT obstacles, the links' wave angles (nominal rows 1..N-1), frames and
    points beyond the roots: there no sample can touch anything, so nothing in this step reads them (the
    contact stays off, the retraction never starts); the roots (points[:, 0], frames[:, 0]), the root
    dynamics, the offsets' relaxation and the contact signals are updated as always, and
    ``antennae_links`` with this step's t computes the skipped rows later -- the same doubles, since they
    depend only on t, the roots and the joint angles this step leaves.  With obstacles ``links`` is ignored.
    Returns (rising edges this step, True when a root arrived at its target).
    """
    nominal, offsets, root_target, root_omega, retracting = motion
    contact, rising, contact_point, contact_normal, contact_depth, arrived = touch
    points, frames = shape
    n_rising = 0
    any_arrived = False
    n = nominal.shape[1]
    link = params[P_LINK]
    margin = params[P_MARGIN]
    has_obst = f[H_NOBST] > 0.0
    relax = math.exp(-dt / params[P_RELAX_TAU])
    near = np.empty(int(f[H_NOBST]), dtype=np.int64)
    reach = n * link + 2.0 * params[P_RELEASE]  # no sample of an antenna is farther from its root
    full = links or has_obst
    for a in range(2):
        s = 1.0 if a == LEFT else -1.0
        # 1. the root link toward its target at constant speed; the other links' wave
        arrived[a] = False
        if _root_toward_target(nominal[a, 0], root_target[a], root_omega[a], dt):
            if retracting[a]:
                retracting[a] = False
                root_omega[a] = params[P_OMEGA0]
            arrived[a] = True
            any_arrived = True
        if full:
            wave_angles(params, t, nominal[a])
        for i in range(n):
            offsets[a, i, THETA] *= relax
            offsets[a, i, PHI] *= relax
        # 2. forward kinematics with contact detection and the pull-out, root to tip
        rz = -params[P_RZ] if a == LEFT else params[P_RZ]
        for k in range(3):
            points[a, 0, k] = c[k] + R[k, 0] * params[P_RX] + R[k, 1] * params[P_RY] + R[k, 2] * rz
            for m in range(3):
                frames[a, 0, k, m] = R[k, m]
        min_phi = np.inf
        # only the obstacles within the antenna's reach are queried below
        n_near = _near_obstacles(f, points[a, 0, 0], points[a, 0, 1], points[a, 0, 2], reach, near) if has_obst else 0
        for i in range(n if full else 0):
            F_prev = frames[a, i]
            F = frames[a, i + 1]
            th = nominal[a, i, THETA] + offsets[a, i, THETA]
            pp = nominal[a, i, PHI] + offsets[a, i, PHI]
            _yaw_pitch_frame(F_prev, s * th, pp, F)
            p0x, p0y, p0z = points[a, i, 0], points[a, i, 1], points[a, i, 2]
            dx, dy, dz = F[0, 0], F[1, 0], F[2, 0]
            if n_near > 0:
                worst = np.inf
                for sf in SAMPLES:
                    x, y, z = p0x + sf * link * dx, p0y + sf * link * dy, p0z + sf * link * dz
                    ph_s, j = _phi_near(f, near, n_near, x, y, z)
                    if ph_s < min_phi:
                        min_phi = ph_s
                        if ph_s < margin:
                            nx, ny, nz = _obstacle_normal(f, j, x, y, z)
                            contact_point[a, 0], contact_point[a, 1], contact_point[a, 2] = x, y, z
                            contact_normal[a, 0], contact_normal[a, 1], contact_normal[a, 2] = nx, ny, nz
                    worst = min(worst, ph_s)
                start_phi, _ = _phi_near(f, near, n_near, p0x, p0y, p0z)
                if worst < margin and start_phi > 0.0:
                    # pull this link out: turn it about its start until its samples are margin outside
                    for _ in range(PROJECTION_ITERATIONS):
                        worst = np.inf
                        bx = by = bz = 0.0
                        push = 0.0
                        for sf in SAMPLES:
                            x, y, z = p0x + sf * link * dx, p0y + sf * link * dy, p0z + sf * link * dz
                            ph_s, j = _phi_near(f, near, n_near, x, y, z)
                            if ph_s < worst:
                                worst = ph_s
                                bx, by, bz = _obstacle_normal(f, j, x, y, z)
                                push = (margin - ph_s) / sf  # the end moves 1/sf times as far as the sample
                        if worst >= margin - 1e-9:
                            break
                        ex = p0x + link * dx + push * bx
                        ey = p0y + link * dy + push * by
                        ez = p0z + link * dz + push * bz
                        nrm = math.sqrt((ex - p0x) ** 2 + (ey - p0y) ** 2 + (ez - p0z) ** 2)
                        if nrm <= 0.0:
                            break
                        dx, dy, dz = (ex - p0x) / nrm, (ey - p0y) / nrm, (ez - p0z) / nrm
                    ang_a, ang_phi = _angles_of_direction(F_prev, dx, dy, dz)
                    offsets[a, i, THETA] = s * ang_a - nominal[a, i, THETA]
                    offsets[a, i, PHI] = ang_phi - nominal[a, i, PHI]
                    _yaw_pitch_frame(F_prev, ang_a, ang_phi, F)
                    dx, dy, dz = F[0, 0], F[1, 0], F[2, 0]
            points[a, i + 1, 0] = p0x + link * dx
            points[a, i + 1, 1] = p0y + link * dy
            points[a, i + 1, 2] = p0z + link * dz
        # 3. the contact signal, with release hysteresis: it starts where the pull-out engages (closer than
        # the margin: a retracted antenna pressed against the obstacle keeps touching it) and ends beyond
        # twice the margin
        was = contact[a]
        contact[a] = min_phi < margin or (was and min_phi < params[P_RELEASE])
        rising[a] = contact[a] and not was
        if rising[a]:
            n_rising += 1
        contact_depth[a] = -min_phi if min_phi < 0.0 else 0.0
        # 4. the paper's retraction: the root's target moves along the normal in (theta_0, phi_0)
        if min_phi < margin and not retracting[a]:
            px = contact_point[a, 0] - points[a, 0, 0]
            py = contact_point[a, 1] - points[a, 0, 1]
            pz = contact_point[a, 2] - points[a, 0, 2]
            nx, ny, nz = contact_normal[a, 0], contact_normal[a, 1], contact_normal[a, 2]
            # d p / d theta_0 = s y_head x (p - p0)
            yx, yy, yz = R[0, 1], R[1, 1], R[2, 1]
            jtx, jty, jtz = s * (yy * pz - yz * py), s * (yz * px - yx * pz), s * (yx * py - yy * px)
            # d p / d phi_0 = z' x (p - p0), z' the root frame's z axis (after the yaw)
            zx, zy, zz = frames[a, 1, 0, 2], frames[a, 1, 1, 2], frames[a, 1, 2, 2]
            jpx, jpy, jpz = zy * pz - zz * py, zz * px - zx * pz, zx * py - zy * px
            g_t = nx * jtx + ny * jty + nz * jtz
            g_p = nx * jpx + ny * jpy + nz * jpz
            g = math.sqrt(g_t * g_t + g_p * g_p)
            if g < 1e-12:
                g_t, g_p, g = 0.0, 1.0, 1.0  # no lever: lift
            th0 = nominal[a, 0, THETA] + offsets[a, 0, THETA]
            ph0 = nominal[a, 0, PHI] + offsets[a, 0, PHI]
            nominal[a, 0, THETA] = th0
            nominal[a, 0, PHI] = ph0
            offsets[a, 0, THETA] = 0.0
            offsets[a, 0, PHI] = 0.0
            # the retraction may carry the root beyond its random-target ranges by up to retract_angle
            ra = params[P_RETRACT_ANGLE]
            root_target[a, 0] = min(max(th0 + ra * g_t / g, params[P_TH_LO] - ra), params[P_TH_HI] + ra)
            root_target[a, 1] = min(max(ph0 + ra * g_p / g, params[P_PH_LO] - ra), params[P_PH_HI] + ra)
            root_omega[a] = params[P_RETRACT_SPEED]
            retracting[a] = True
    return n_rising, any_arrived


@njit(cache=True)
def antennae_links(params, t, nominal, offsets, points, frames):
    """The rows ``antennae_step(..., links=False)`` skipped, for its step at time t [s]: the wave angles
    (nominal (2, N, 2) [rad], rows 1..N-1), the links' frames (frames (2, N + 1, 3, 3), entries 1..N) and
    points (points (2, N + 1, 3) [m], entries 1..N) from the roots points[:, 0], frames[:, 0] and the joint
    angles nominal + offsets; the arithmetic of ``antennae_step``'s link loop without obstacles."""
    n = nominal.shape[1]
    link = params[P_LINK]
    for a in range(2):
        s = 1.0 if a == LEFT else -1.0
        wave_angles(params, t, nominal[a])
        for i in range(n):
            F = frames[a, i + 1]
            th = nominal[a, i, THETA] + offsets[a, i, THETA]
            pp = nominal[a, i, PHI] + offsets[a, i, PHI]
            _yaw_pitch_frame(frames[a, i], s * th, pp, F)
            points[a, i + 1, 0] = points[a, i, 0] + link * F[0, 0]
            points[a, i + 1, 1] = points[a, i, 1] + link * F[1, 0]
            points[a, i + 1, 2] = points[a, i, 2] + link * F[2, 0]


class Antennae:
    """State and update of the two antennae of one head (see the module docstring).

    ``contact`` (2,) bool: left/right antenna touching an obstacle this step;
    ``rising`` (2,) bool: contact began this step; ``contact_events`` counts
    rising edges; ``contact_point`` (2, 3) [m]; ``points`` (2, N + 1, 3) [m]
    (``tips`` = points[:, -1]).  Random root targets come from ``rng`` (a numpy
    Generator).
    """

    def __init__(self, cfg, dt: float, rng: np.random.Generator, terrain_f: np.ndarray):
        self.cfg = cfg
        self.dt = dt
        self.rng = rng
        self.f = np.ascontiguousarray(terrain_f, dtype=np.float64)
        self.params = antenna_params(cfg)
        n = int(cfg.n_links)
        self.n_links = n
        self.nominal = np.zeros((2, n, 2))
        self.offsets = np.zeros((2, n, 2))
        self.root_target = np.zeros((2, 2))
        self.root_omega = np.full(2, self.params[P_OMEGA0])
        self.retracting = np.zeros(2, dtype=np.bool_)
        self.contact = np.zeros(2, dtype=np.bool_)
        self.rising = np.zeros(2, dtype=np.bool_)
        self.contact_point = np.zeros((2, 3))
        self.contact_normal = np.zeros((2, 3))
        self.contact_depth = np.zeros(2)
        self.arrived = np.zeros(2, dtype=np.bool_)
        self.points = np.zeros((2, n + 1, 3))
        self.frames = np.zeros((2, n + 1, 3, 3))
        self.contact_events = 0
        self.targets_drawn = 0
        for a in range(2):  # start at a random pose, heading for a random target
            self.nominal[a, 0] = self._draw()
            self.root_target[a] = self._draw()

    def _draw(self) -> np.ndarray:
        p = self.params
        self.targets_drawn += 1
        return np.array([self.rng.uniform(p[P_TH_LO], p[P_TH_HI]), self.rng.uniform(p[P_PH_LO], p[P_PH_HI])])

    def place(self, c: np.ndarray, R: np.ndarray, t: float = 0.0) -> None:
        """Put the antennae on the head pose (c (3,) [m], R (3, 3)) at time t [s] without advancing them.

        Before the first ``step`` the link points would otherwise be all zero, so a scene of the starting
        pose (frame 0 of an animation or of an exported frame sequence) would show antennae of zero
        length at the origin.  Only ``points``, ``frames`` and the wave rows of ``nominal`` (which every
        ``step`` recomputes from t) are written: the run's dynamics do not change.
        """
        for a in (LEFT, RIGHT):
            wave_angles(self.params, t, self.nominal[a])
        antennae_forward_kinematics(np.ascontiguousarray(c, dtype=np.float64),
                                    np.ascontiguousarray(R, dtype=np.float64), self.params,
                                    self.nominal + self.offsets, self.points, self.frames)

    def step(self, c: np.ndarray, R: np.ndarray, t: float) -> None:
        """Update the antennae on the head pose (c (3,) [m], R (3, 3)) at time t [s]."""
        n_rising, arrived = antennae_step(c, R, t, self.dt, self.params, self.f, *self.step_packs(), True)
        self.contact_events += n_rising
        if arrived:
            for a in (LEFT, RIGHT):
                if self.arrived[a]:
                    self.root_target[a] = self._draw()

    def step_packs(self) -> tuple[tuple, tuple, tuple]:
        """``antennae_step``'s (motion, touch, shape) packs of this state's arrays, plain tuples in the fields'
        order of ``AntennaMotion``, ``AntennaContact`` and ``AntennaShape``."""
        return ((self.nominal, self.offsets, self.root_target, self.root_omega, self.retracting),
                (self.contact, self.rising, self.contact_point, self.contact_normal, self.contact_depth, self.arrived),
                (self.points, self.frames))

    @property
    def tips(self) -> np.ndarray:
        """(2, 3) [m] tip positions, left then right."""
        return self.points[:, -1]

    def joint_angles(self) -> np.ndarray:
        """(2, N, 2) [rad] current joint angles (theta, phi): nominal + retraction offsets."""
        return self.nominal + self.offsets
