"""One rigid segment chain: rigid boxes joined by deformable links, the boxes' step and contacts.

The hybrid body (FEM links, ``hybrid.kernels``) and the legged mass-spring body (spring-cube links,
``massspring.myriapod``) are the same chain of rigid exoskeletal segments (paper Sec. 3) with a
different link element.  Each step of either is the paper's staggered scheme:

1. the link element's step (its own kernel): the links' forces on their free nodes, which advance
   with the suite's ground contact (``contact_kernels``), and their forces on the attached nodes
   f_att at x_att, and where eq. 15 would take each attached node (x_pred, for the residual);
2. ``rigid_segments_step``: those forces act on the boxes as force and torque, plus gravity; one
   rigid step with terrain contact and friction (``rigid_kernels._step_body``) for every box that
   is not kinematic;
3. still in ``rigid_segments_step``: the attached nodes are put back on their boxes
   (``follow_boxes``), the coupling residual accumulated, and the boxes' blow-up checks.

The legs hold the same boxes the same way in both (``carried_boxes``).  This module is what the two
share: the scalar parameters' layout (``phys``), the statistics (``acc``), the attachment kernels
and the rigid step; a link element is whatever computes step 1 into these arrays.
"""
from __future__ import annotations

import math

from collections import namedtuple

import numpy as np
from numba import njit
from numba.core import types
from numba.extending import overload

from ..world.terrain_kernels import (clearance, clearance_cell, clearance_view, distance_at_least, flat_ground,
                                    signed_distance)
from . import rigid_kernels as rk
from . import step_status as S
from .case_scalars import contact_scalars
from .friction_kernels import CONTACT_DISTANCE, spine_between
from .step_status import ACC_CONTACT_SUM, ACC_MAX_PEN, ACC_STEPS, DEEP_PENETRATION, NONFINITE, OK, RUNAWAY_SPEED

# The chain's arguments, named records (numba compiles a namedtuple of arrays as a struct of them; kernels read
# the fields by name, which costs nothing in compiled code).  Python builds them by field name (``boxes_of``,
# ``coupling_of``, a body's ``_chain_args``) and hands them over as plain tuples (``core.kernel_records``: numba's
# dispatcher types a namedtuple argument several times slower), which a link element's entry kernel names again
# with the same classes (``hybrid.kernels.advance``).  So each link element's module has its own entry kernel, a
# few lines alike by design (``hybrid.kernels.advance``, ``massspring.myriapod.advance_spring_chain``).
# the boxes (``rigid_kernels`` conventions; c, q, vr, w, impulse_cache UPDATED; mass (n_rigid,) [kg], inertia_body
# (n_rigid, 3) [kg m^2], half_extents (n_rigid, 3) [m], kinematic (n_rigid,) bool; force, torque (n_rigid, 3) scratch)
Boxes = namedtuple("Boxes", "c q vr w mass inertia_body half_extents kinematic impulse_cache force torque")
# the attached nodes: fixed (n_fixed,) node ids, att_body (n_fixed,) the box of each, att_local (n_fixed, 3) [m] its
# body-frame position, grouped by box
Attachment = namedtuple("Attachment", "fixed att_body att_local")
# the chain's constant contact parameters: fric_model, fric (``friction_kernels``) for the free nodes; phys (N_PHYS,)
# the scalars below.  The world (gravity, terrain: ``world.world.StepWorld``) and the time step dt are not here: they
# are plain arguments of the step (``advance_chain``), given by whoever runs it.
ChainParams = namedtuple("ChainParams", "fric_model fric phys")
# the coupling's scratch (``segment_chain.CouplingScratch``, less qtmp): f_att, x_att, x_pred (n_fixed, 3), residual
# (n_fixed,), spine (n_links, 3), Rb (n_rigid, 3, 3), and ``rigid_kernels._solve_contacts``'s
Coupling = namedtuple("Coupling", "f_att x_att x_pred residual spine Rb R Iw corner_of lin ang resp kn kt target lam")


def boxes_of(rb) -> Boxes:
    """The ``Boxes`` record of a ``rigid.RigidBoxes`` rb (its own arrays, no copy)."""
    return Boxes(c=rb.c, q=rb.q, vr=rb.v, w=rb.w, mass=rb.mass, inertia_body=rb.inertia_body,
                 half_extents=rb.half_extents, kinematic=rb.kinematic, impulse_cache=rb.impulse_cache,
                 force=rb.force, torque=rb.torque)


def coupling_of(sc) -> Coupling:
    """The ``Coupling`` record of a ``segment_chain.CouplingScratch`` sc (its own arrays, no copy)."""
    return Coupling(f_att=sc.f_att, x_att=sc.x_att, x_pred=sc.x_pred, residual=sc.residual, spine=sc.spine,
                    Rb=sc.Rb, R=sc.R, Iw=sc.Iw, corner_of=sc.corner_of, lin=sc.lin, ang=sc.ang, resp=sc.resp,
                    kn=sc.kn, kt=sc.kt, target=sc.target, lam=sc.lam)

# Scalar parameter vector layout (``phys``, float64); MUSCLES_ON, MUSCLE_GAIN and VOLUME are the hybrid's
# active FEM links' (a spring link has no muscles and leaves them 0).  No time step: dt is the step's argument.
(R_N, R_T, MAX_SPEED, MAX_PEN, RIGID_MU, RIGID_RESTITUTION, BOUNCE_THRESHOLD,
 VEL_ITERATIONS, VEL_TOLERANCE, POS_ITERATIONS, POS_BETA, SLOP,
 MUSCLES_ON, MUSCLE_GAIN, VOLUME) = range(15)
# the boxes' anisotropic friction, rigid_kernels' ``aniso`` layout (on, mu_f, mu_b, mu_t)
RIGID_ANISO = 15
N_PHYS = 15 + rk.N_ANISO


def chain_phys(case, contact) -> np.ndarray:
    """(N_PHYS,) the chain's scalars for the boxes' contact (``rigid.ContactSettings``); the link element's own
    (MUSCLES_ON, MUSCLE_GAIN, VOLUME) and the boxes' RIGID_ANISO are left 0 for its body to set."""
    phys = np.zeros(N_PHYS)
    contact_scalars(phys, (R_N, R_T, MAX_SPEED, MAX_PEN), case)
    phys[RIGID_MU] = contact.friction
    phys[RIGID_RESTITUTION] = contact.restitution
    phys[BOUNCE_THRESHOLD] = contact.bounce_threshold
    phys[VEL_ITERATIONS] = contact.velocity_iterations
    phys[VEL_TOLERANCE] = contact.velocity_tolerance
    phys[POS_ITERATIONS] = contact.position_iterations
    phys[POS_BETA] = contact.position_beta
    phys[SLOP] = contact.slop
    return phys

# Status codes and the shared statistics (contact fraction sum, steps, deepest
# penetration) as every body's kernel; the hybrid's own statistics follow them.
(ACC_RES_MAX, ACC_RES_SUM, ACC_RES_COUNT, ACC_SLOW_TETS) = range(S.N_ACC, S.N_ACC + 4)
N_ACC = S.N_ACC + 4

N_CORNERS = rk.N_CORNERS


@njit(cache=True, error_model="numpy")
def place_attached_nodes(fixed, att_body, att_local, c, q, vr, w, Rb, x, v, x_pred, residual):
    """Put the attached nodes on their rigid bodies (Sec. 3 step 3).

    fixed: (n_fixed,) node ids; att_body: (n_fixed,) rigid body of each;
    att_local: (n_fixed, 3) [m] body-frame coordinates; c (n_rigid, 3) [m],
    q (n_rigid, 4), vr (n_rigid, 3) [m/s], w (n_rigid, 3) [rad/s]: rigid state.
    Rb: (n_rigid, 3, 3) scratch, OVERWRITTEN with the bodies' rotation matrices.
    OVERWRITES x[fixed] (n_nodes, 3) [m] with c + R local and v[fixed] [m/s] with
    v_c + w x (x - c) (``rigid_kernels.point_velocities``), and residual
    (n_fixed,) [m] with |x_new - x_pred| for the predicted positions x_pred
    (n_fixed, 3) [m].
    (Same as ``rigid_kernels.body_points_to_world``, with each body's rotation
    built once and without its per-call scratch allocation.)
    """
    rk.quat_to_matrix(q, Rb)
    for a in range(fixed.shape[0]):
        _place_node(a, att_body[a], fixed[a], att_local, c, vr, w, Rb, x, v, x_pred, residual)


@njit(cache=True, inline="always", error_model="numpy")
def place_on_box(a, i, p, att_local, c, vr, w, Rb, x, v):
    """Attached node a (node id p) onto box i; returns its new position (px, py, pz) [m].

    OVERWRITES x[p] with c_i + R_i local_a and v[p] with v_c + w x r (r = R_i local_a), for
    att_local (n_fixed, 3) [m], c (n_rigid, 3) [m], vr (n_rigid, 3) [m/s], w (n_rigid, 3) [rad/s]
    and Rb (n_rigid, 3, 3) the boxes' rotation matrices.  The placement arithmetic shared by
    ``place_attached_nodes`` (with the coupling residual, ``_place_node``) and the fused legged
    support (``carried_boxes.carry_boxes``, without it); inlined, so both compile the
    same operations in the same order.
    """
    lx, ly, lz = att_local[a, 0], att_local[a, 1], att_local[a, 2]
    rx = Rb[i, 0, 0] * lx + Rb[i, 0, 1] * ly + Rb[i, 0, 2] * lz
    ry = Rb[i, 1, 0] * lx + Rb[i, 1, 1] * ly + Rb[i, 1, 2] * lz
    rz = Rb[i, 2, 0] * lx + Rb[i, 2, 1] * ly + Rb[i, 2, 2] * lz
    px, py, pz = c[i, 0] + rx, c[i, 1] + ry, c[i, 2] + rz
    x[p, 0], x[p, 1], x[p, 2] = px, py, pz
    # v_c + w x r (Baraff 1997 I, Sec. 2.5)
    v[p, 0] = vr[i, 0] + w[i, 1] * rz - w[i, 2] * ry
    v[p, 1] = vr[i, 1] + w[i, 2] * rx - w[i, 0] * rz
    v[p, 2] = vr[i, 2] + w[i, 0] * ry - w[i, 1] * rx
    return px, py, pz


@njit(cache=True, inline="always", error_model="numpy")
def _place_node(a, i, p, att_local, c, vr, w, Rb, x, v, x_pred, residual):
    """Attached node a (node id p) onto box i: ``place_attached_nodes`` for one node."""
    px, py, pz = place_on_box(a, i, p, att_local, c, vr, w, Rb, x, v)
    dx, dy, dz = px - x_pred[a, 0], py - x_pred[a, 1], pz - x_pred[a, 2]
    residual[a] = math.sqrt(dx * dx + dy * dy + dz * dz)


@njit(cache=True, inline="always", error_model="numpy")
def follow_boxes(fixed, att_body, att_local, c, q, vr, w, kinematic, Rb, x, v, x_pred, residual):
    """Sec. 3 step 3: ``place_attached_nodes`` after a rigid step in which the kinematic boxes did not move.

    Arguments as ``place_attached_nodes``, plus kinematic (n_rigid,) bool.  The nodes of a kinematic
    box are not rewritten: the step started with every attached node on its box (put there by
    ``place_attached_nodes``: at set-up, by the support or by the previous step; the FEM step
    prescribes them so), and a kinematic box's state is the same at the end, so ``place_attached_nodes``
    would write the same doubles.  Their residual |x - x_pred| is computed from x as it stands.
    Rb (n_rigid, 3, 3) is OVERWRITTEN with every box's rotation matrix.
    """
    rk.quat_to_matrix(q, Rb)
    for a in range(fixed.shape[0]):
        i = att_body[a]
        p = fixed[a]
        if kinematic[i]:
            dx, dy, dz = x[p, 0] - x_pred[a, 0], x[p, 1] - x_pred[a, 1], x[p, 2] - x_pred[a, 2]
            residual[a] = math.sqrt(dx * dx + dy * dy + dz * dz)
            continue
        _place_node(a, i, p, att_local, c, vr, w, Rb, x, v, x_pred, residual)


@njit(cache=True, error_model="numpy")
def link_spines(c, spine):
    """Unit spine vector of every link: from the rigid centre behind it to the one ahead.

    c: (n_rigid, 3) [m]; OVERWRITES spine (n_rigid - 1, 3).  The friction models
    (Miller's rule, anisotropic Coulomb) need the direction toward the head at a
    node; for the nodes of link k that is c[k] - c[k + 1] (PAPER-NOTES: index 0
    is the head).
    """
    for k in range(spine.shape[0]):
        spine_between(c, k, k + 1, spine, k)


@njit(cache=True, error_model="numpy", inline="always")
def chain_scalars(phys, fric):
    """(Miller's r_n, r_t, deepest penetration [m], fastest speed [m/s], contact distance [m]) of the chain's phys
    (N_PHYS,) and the free nodes' fric: what each part of a step reads."""
    return phys[R_N], phys[R_T], phys[MAX_PEN], phys[MAX_SPEED], fric[CONTACT_DISTANCE]


@njit(cache=True, error_model="numpy")
def rigid_segments_step(A, x, v, B, M, W, C, acc, dt):
    """Sec. 3 steps 2 and 3 for rigid segments joined by deformable links; return (status, box corners touching).

    A: the ``Attachment``; x, v (n_nodes, 3) [m], [m/s]: the link nodes, attached rows UPDATED; B: the
    ``Boxes``, UPDATED; M: the ``ChainParams``; W: the world (``world.world.StepWorld``); C: the ``Coupling``
    scratch; acc (N_ACC,) ACCUMULATES; dt [s] the time step.
    Step 2: the links' forces on the attached nodes C.f_att (n_fixed, 3) [N], at
    C.x_att (n_fixed, 3) [m], act on the boxes as force and torque, plus gravity;
    one rigid step for every box that is not kinematic (f_att and x_att are read only for the
    nodes of those boxes).  Step 3: the attached
    nodes are moved onto the boxes (x, v updated for ``fixed`` on boxes that are not
    kinematic, ``follow_boxes``) and the coupling residual accumulated.  Then the rigid checks: finite state, the
    speed of any box point, corner depth after the position projection.
    Shared by the hybrid (FEM links) and the legged mass-spring chain (spring links): steps 2 and 3 of the
    module docstring.
    """
    fixed, att_body, att_local = A.fixed, A.att_body, A.att_local
    c, q, vr, w, kinematic, half_extents = B.c, B.q, B.vr, B.w, B.kinematic, B.half_extents
    gravity, terr_kind, terr, fric, phys = W.gravity, W.terr_kind, W.terr, M.fric, M.phys
    f_att, x_att, x_pred, residual, Rb = C.f_att, C.x_att, C.x_pred, C.residual, C.Rb
    force, torque = B.force, B.torque
    n_fixed = fixed.shape[0]
    n_rigid = c.shape[0]
    _, _, max_pen, vmax, contact_dist = chain_scalars(phys, fric)
    mu_r = phys[RIGID_MU]
    e_r = phys[RIGID_RESTITUTION]
    bounce = phys[BOUNCE_THRESHOLD]
    n_vel = int(phys[VEL_ITERATIONS])
    vel_tol = phys[VEL_TOLERANCE]
    n_pos = int(phys[POS_ITERATIONS])
    beta = phys[POS_BETA]
    slop = phys[SLOP]
    status = OK
    n_contact = 0
    # (2) rigid step under the links' forces: each run of attached nodes on one box summed
    # (``accumulate_point_forces``, the same doubles as over all of them), on the boxes that step
    force[:, :] = 0.0
    torque[:, :] = 0.0
    a0 = 0
    while a0 < n_fixed:
        i = att_body[a0]
        a1 = a0 + 1
        while a1 < n_fixed and att_body[a1] == i:
            a1 += 1
        if not kinematic[i]:
            rk.accumulate_point_forces(att_body[a0:a1], x_att[a0:a1], f_att[a0:a1], c, force, torque)
        a0 = a1
    boxes = rk.BoxArrays(c=c, q=q, v=vr, w=w, mass=B.mass, inertia_body=B.inertia_body, half_extents=half_extents,
                         force=force, torque=torque, impulse_cache=B.impulse_cache)
    contact = rk.ContactParams(mu=mu_r, restitution=e_r, bounce_threshold=bounce, n_velocity_iterations=n_vel,
                               velocity_tolerance=vel_tol, n_position_iterations=n_pos, beta=beta, slop=slop)
    scratch = rk.ContactScratch(R=C.R, Iw=C.Iw, corner_of=C.corner_of, lin=C.lin, ang=C.ang, resp=C.resp, kn=C.kn,
                                kt=C.kt, target=C.target, lam=C.lam)
    for i in range(n_rigid):
        if kinematic[i]:
            continue
        rk._step_body(i, boxes, dt, gravity, terr_kind, terr, contact, scratch,
                      phys[RIGID_ANISO:RIGID_ANISO + rk.N_ANISO])

    # (3) attached nodes follow the rigid bodies; those of a kinematic box are already where its
    # unchanged state puts them (step 1's precondition), so only their residual is computed
    follow_boxes(fixed, att_body, att_local, c, q, vr, w, kinematic, Rb, x, v, x_pred, residual)
    # the statistics in registers, stored once: the same sum in the same order, the same maximum
    res_sum, res_max = acc[ACC_RES_SUM], acc[ACC_RES_MAX]
    for a in range(n_fixed):
        r = residual[a]
        res_sum += r
        if r > res_max:
            res_max = r
    acc[ACC_RES_SUM], acc[ACC_RES_MAX] = res_sum, res_max
    acc[ACC_RES_COUNT] += n_fixed

    # Rigid checks: finite state, speed bound |v| + |w| r of any box point,
    # corner depth (after the position projection) and contact count; on the plane without obstacles
    # a corner's distance is y - ground (``flat_ground``)
    flat, ground = flat_ground(terr_kind, terr)
    V = clearance_view(terr_kind, terr)
    deepest = acc[ACC_MAX_PEN]
    for i in range(n_rigid):
        hx, hy, hz = half_extents[i, 0], half_extents[i, 1], half_extents[i, 2]
        s = (c[i, 0] + c[i, 1] + c[i, 2] + vr[i, 0] + vr[i, 1] + vr[i, 2]
             + w[i, 0] + w[i, 1] + w[i, 2] + q[i, 0] + q[i, 1] + q[i, 2] + q[i, 3])
        if not math.isfinite(s):
            status = NONFINITE
            continue
        speed = math.sqrt(vr[i, 0] ** 2 + vr[i, 1] ** 2 + vr[i, 2] ** 2)
        spin = math.sqrt(w[i, 0] ** 2 + w[i, 1] ** 2 + w[i, 2] ** 2)
        if speed + spin * math.sqrt(hx * hx + hy * hy + hz * hz) > vmax:
            status = RUNAWAY_SPEED
        for corner in range(N_CORNERS):
            sx = hx if (corner & 1) else -hx
            sy = hy if (corner & 2) else -hy
            sz = hz if (corner & 4) else -hz
            px = c[i, 0] + Rb[i, 0, 0] * sx + Rb[i, 0, 1] * sy + Rb[i, 0, 2] * sz
            py = c[i, 1] + Rb[i, 1, 0] * sx + Rb[i, 1, 1] * sy + Rb[i, 1, 2] * sz
            pz = c[i, 2] + Rb[i, 2, 0] * sx + Rb[i, 2, 1] * sy + Rb[i, 2, 2] * sz
            # a corner at least the contact distance up changes nothing below (deepest and max_pen are >= 0
            # >= -contact_dist): ``clearance`` (else ``distance_at_least``) answers that among obstacles without
            # their search
            if not flat and -contact_dist <= deepest and -contact_dist <= max_pen:
                kc = clearance_cell(V, px, pz, contact_dist)
                cl = clearance(V, terr[kc] if kc >= 0 else 0.0, py, contact_dist, kc)
                if (cl > 0) if cl >= 0 else distance_at_least(terr_kind, terr, px, py, pz, contact_dist):
                    continue
            phi = py - ground if flat else signed_distance(terr_kind, terr, px, py, pz)
            if phi < contact_dist:
                n_contact += 1
            if -phi > deepest:
                deepest = -phi
            if -phi > max_pen:
                status = DEEP_PENETRATION
    acc[ACC_MAX_PEN] = deepest
    return status, n_contact


# ---------------------------------------------------------------- the link element (pluggable)

def link_step(L, A, B, M, W, C, acc, dt, step, flat, ground):
    """Step 1 of the module docstring for the link element L (a namedtuple with at least ``x``, ``v`` the
    nodes (n_nodes, 3) and ``n_free`` the number of free nodes): the links' forces on their free nodes, which
    it advances by dt [s], and C.f_att, C.x_att, C.x_pred of the attached nodes (rows of boxes that are not
    kinematic at least); step is the step's index in the call; flat, ground: ``terrain_kernels.flat_ground`` of
    the world W's terrain.  Returns (status, free nodes touching).  Compiled code only: a link element's module gives its
    implementation to ``register_link``."""
    raise NotImplementedError("rigid_chain.link_step runs in compiled code, on a registered link element")


# The link element's class -> its step, filled by ``register_link``.
_LINK_STEPS: dict[type, object] = {}


def register_link(cls, impl) -> None:
    """Make the plain function ``impl`` (the parameters of ``link_step``) the step of link elements of
    namedtuple class ``cls``; inlined into ``advance_chain``.  Only fills a table read by the one overload
    of ``link_step`` below, so importing a link element's module while a kernel is being typed cannot
    change numba's type of ``link_step`` (``legged_chunk.register`` has the failure that avoids)."""
    _LINK_STEPS[cls] = getattr(impl, "py_func", impl)


@overload(link_step, inline="always")
def _link_step(L, A, B, M, W, C, acc, dt, step, flat, ground):
    if isinstance(L, types.BaseNamedTuple):
        return _LINK_STEPS.get(L.instance_class)


@njit(cache=True, error_model="numpy")
def advance_chain(L, A, B, M, C, acc, W, dt, n_steps):
    """Advance the chain ``n_steps`` staggered steps of dt [s] (module docstring) in the world W; return (steps,
    status).

    L: the link element (``link_step``), A: ``Attachment``, B: ``Boxes``, M: ``ChainParams``, C: ``Coupling``;
    W: the world, a ``world.world.StepWorld`` (gravity, terrain); dt [s] the time step; acc (N_ACC,) ACCUMULATES the statistics (residual max / sum / count, deepest penetration, contact
    fraction sum over the free nodes and the box corners, steps).  On a blow-up the step that produced it
    is completed and its status code returned with the number of steps including it.
    """
    n_points = L.n_free + N_CORNERS * B.c.shape[0]
    # on the plane without obstacles the free nodes' distances are y - ground (``flat_ground``: what
    # ``signed_distance`` computes there, without its reference-count updates per call)
    flat, ground = flat_ground(W.terr_kind, W.terr)
    for step in range(n_steps):
        # ---------------- (1) the link element's step
        status, n_contact = link_step(L, A, B, M, W, C, acc, dt, step, flat, ground)
        # ---------------- (2) rigid step under the links' forces, (3) attached nodes follow (Sec. 3)
        st, nc = rigid_segments_step(A, L.x, L.v, B, M, W, C, acc, dt)
        n_contact += nc
        if st != OK:
            status = st
        acc[ACC_CONTACT_SUM] += n_contact / n_points
        acc[ACC_STEPS] += 1.0
        if status != OK:
            return step + 1, status
    return n_steps, OK
