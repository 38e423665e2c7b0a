"""Numba kernels of the hybrid body: rigid exoskeletal segments joined by FEM links.

The myriapod paper (Fang, Jiang & Terzopoulos 2013, Sec. 3) couples its rigid
segments and its fixed-corotational deformable segments (App. A) with a
staggered scheme of three steps.  ``advance`` runs many time steps of it inside
one call; one step, with n the state at the start of the step:

1. FEM step with the attached ("fixed") nodes prescribed by the rigid bodies at
   state n: positions on the bodies, velocities v_c + w x r (set at the end of
   the previous step, or at set-up).  Free nodes: elastic force f_E(x^n) plus
   gravity M g (eq. 14, PAPER-NOTES), the semi-implicit velocity solve of eq. 14
   with the prescribed fixed-node velocities entering through D_fp, then the
   suite's ground contact of a point mass (``contact_kernels``: friction, then
   Miller's path collision), which also performs x += dt v (eq. 15).  The force
   the mesh exerts on each attached node is f_E(x^n)_p - (D v^{n+1})_p with the
   same prescribed v_p used in the solve.  Because D has zero row and column
   sums and the elastic forces of every tet sum to zero (eq. 10), the internal
   forces of mesh and attachments cancel exactly: the coupling neither creates
   nor destroys linear momentum.
2. Those forces act on the rigid bodies, as force and torque about their
   centres applied at the attached nodes' positions at state n (Sec. 3 step 2,
   ``rigid_kernels.accumulate_point_forces``), plus gravity; one rigid step
   with terrain contact and Coulomb friction (``rigid_kernels._step_body``:
   kick, sequential-impulse corner contact, drift, position projection).
   Kinematic bodies (a held head) are not integrated; forces on them are lost
   to whatever holds them.
3. The attached nodes are moved onto the rigid bodies' new state n+1 (Sec. 3
   step 3), with velocities v_c + w x r.  The coupling residual of a node is the
   distance between where step 1 would have moved it, x_p + dt v_p, and where
   its rigid body puts it; its maximum and mean over all nodes and steps are
   accumulated in ``acc``.

Kinematic boxes (carried by their legs, or held) are not integrated, so the mesh's forces on
their attached nodes have no use: those nodes' elastic sums, damping reactions and point forces
are not computed, and their nodes are not rewritten in step 3, where their box has not moved
(``follow_boxes``).  Every other number is computed as before, in the same order: the results
are the same doubles.  (On the walking centipede 16 of 18 boxes are kinematic in a typical step.)

Order.  Sec. 6 lists the rigid segments' update before the deformable
segments'; here the FEM step comes first within a step because the rigid step
needs the mesh's reactions at state n, and those are only exact (cancelling)
when computed with the velocities the FEM solve prescribed.  Over many steps
it is the same cycle (FEM, rigid, attach, FEM, ...), started at the FEM step.

The lumped masses of the attached nodes (eq. 12) are never used: the rigid body
carries that material, its configured mass includes it, and momenta and
energies count rigid bodies and free nodes only.

Blow-ups are returned as status codes (non-finite state, a point faster than a
limit, a node or box corner deeper inside the terrain than a limit), never
raised.  Nothing is allocated inside the step loop: all scratch comes from the
caller.  ``error_model="numpy"`` everywhere (a division by zero gives inf/nan,
caught by the checks).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ...world.terrain_kernels import flat_ground, signed_distance
from .. import rigid_kernels as rk
from ..contact_kernels import advance_point
from ..fem.kernels import element_forces, gather_node_force, semi_implicit_velocity
from ..friction_kernels import CONTACT_DISTANCE
from ..step_status import (ACC_CONTACT_SUM, ACC_MAX_PEN, ACC_STEPS, DEEP_PENETRATION, NONFINITE, OK,  # noqa: F401
                           RUNAWAY_SPEED, STATUS_TEXT)
from .. import step_status as S
from ..fem.body_kernels import active_coefficients

# Scalar parameter vector layout (``phys``, float64).
(DT, R_N, R_T, MAX_SPEED, MAX_PEN, RIGID_MU, RIGID_RESTITUTION, BOUNCE_THRESHOLD,
 VEL_ITERATIONS, VEL_TOLERANCE, POS_ITERATIONS, POS_BETA, SLOP,
 MUSCLES_ON, MUSCLE_GAIN, VOLUME) = range(16)
# the boxes' anisotropic friction, rigid_kernels' ``aniso`` layout (on, mu_f, mu_b, mu_t)
RIGID_ANISO = 16
N_PHYS = 16 + rk.N_ANISO

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
    support (``fused.legged_walk._place_attached``, without it); inlined, so both compile the
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
        sx = c[k, 0] - c[k + 1, 0]
        sy = c[k, 1] - c[k + 1, 1]
        sz = c[k, 2] - c[k + 1, 2]
        n = math.sqrt(sx * sx + sy * sy + sz * sz)
        if n > 0.0:
            spine[k, 0], spine[k, 1], spine[k, 2] = sx / n, sy / n, sz / n
        else:
            spine[k, 0], spine[k, 1], spine[k, 2] = 1.0, 0.0, 0.0


@njit(cache=True, error_model="numpy")
def rigid_segments_step(fixed, att_body, att_local, f_att, x_att, x, v, x_pred, residual,
                        c, q, vr, w, rmass, inertia_body, half_extents, kinematic, impulse_cache,
                        gravity, terr_kind, terr, fric, phys, force, torque, Rb,
                        R, Iw, corner_of, lin, ang, resp, kn, kt, target, lam, acc):
    """Sec. 3 steps 2 and 3 for rigid segments joined by deformable links; return (status, box corners touching).

    Step 2: the links' forces on the attached nodes f_att (n_fixed, 3) [N], at
    x_att (n_fixed, 3) [m], act on the boxes as force and torque, plus gravity;
    one rigid step for every box that is not kinematic (f_att and x_att are read only for the
    nodes of those boxes).  Step 3: the attached
    nodes are moved onto the boxes (x, v updated for ``fixed`` on boxes that are not
    kinematic, ``follow_boxes``) and the coupling residual accumulated.  Then the rigid checks: finite state, the
    speed of any box point, corner depth after the position projection.
    Shared by the hybrid (FEM links) and the legged mass-spring chain (spring links).
    """
    n_fixed = fixed.shape[0]
    n_rigid = c.shape[0]
    dt = phys[DT]
    max_pen = phys[MAX_PEN]
    vmax = phys[MAX_SPEED]
    mu_r = phys[RIGID_MU]
    e_r = phys[RIGID_RESTITUTION]
    bounce = phys[BOUNCE_THRESHOLD]
    n_vel = int(phys[VEL_ITERATIONS])
    vel_tol = phys[VEL_TOLERANCE]
    n_pos = int(phys[POS_ITERATIONS])
    beta = phys[POS_BETA]
    slop = phys[SLOP]
    contact_dist = fric[CONTACT_DISTANCE]
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
    for i in range(n_rigid):
        if kinematic[i]:
            continue
        rk._step_body(i, c, q, vr, w, rmass, inertia_body, half_extents, force, torque,
                      impulse_cache, dt, gravity, terr_kind, terr, mu_r, e_r, bounce,
                      n_vel, vel_tol, n_pos, beta, slop, R, Iw, corner_of, lin, ang, resp,
                      kn, kt, target, lam, phys[RIGID_ANISO:RIGID_ANISO + rk.N_ANISO])

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
            phi = py - ground if flat else signed_distance(terr_kind, terr, px, py, pz)
            if phi < contact_dist:
                n_contact += 1
            if -phi > deepest:
                deepest = -phi
            if -phi > max_pen:
                status = DEEP_PENETRATION
    acc[ACC_MAX_PEN] = deepest
    return status, n_contact


@njit(cache=True, error_model="numpy")
def advance(x, v, tets, Dm_inv, coef, muscle, mass, q_ws, F_work, H_work, inc_ptr, inc_off,
            perm, sky_first, sky_ptr, sky_L, fp_ptr, fp_col, fp_val,
            fixed, pf_ptr, pf_col, pf_val, node_link, att_body, att_local,
            c, q, vr, w, rmass, inertia_body, half_extents, kinematic, impulse_cache,
            gravity, terr_kind, terr, fric_model, fric, phys, n_steps,
            f_work, b_work, f_att, x_att, x_pred, residual, spine, force, torque, Rb,
            R, Iw, corner_of, lin, ang, resp, kn, kt, target, lam, acc):
    """Advance the coupled body ``n_steps`` staggered steps (module docstring); return (steps, status).

    FEM (App. A), from ``FEMSystem`` and its ``solver(dt)`` for the mask of
    attached nodes: x, v (n_nodes, 3) [m], [m/s], UPDATED in place (attached
    rows are rewritten from the rigid bodies every step); tets, Dm_inv, coef,
    q_ws, F_work, H_work as in ``fem.kernels.elastic_forces`` (q_ws UPDATED);
    inc_ptr, inc_off: ``fem.kernels.node_incidence`` of tets (``FEMSystem._inc_ptr``, ``_inc_off``),
    for ``elastic_forces_gathered``;
    muscle: the active links (paper Sec. 7's "actively contractile deformable segments"), a
    tuple (Dm_inv_rest (n_tets, 3, 3), vol, mu, lam (n_tets,), tet_link, tet_y, tet_z (n_tets,),
    act_buf (n_rows, n_links, 3)): when phys[MUSCLES_ON] is set, step k rescales the links' rest
    shapes by row k of act_buf times phys[MUSCLE_GAIN] (``fem.body_kernels.active_coefficients``,
    which OVERWRITES Dm_inv and coef);
    mass (n_nodes,) [kg] lumped; perm, sky_*, fp_* as in
    ``semi_implicit_velocity``; fixed (n_fixed,) attached node ids and pf_*
    the CSR of D's rows of those nodes [N s/m]; node_link (n_nodes,) link of
    each node; att_body (n_fixed,), att_local (n_fixed, 3) [m] body and
    body-frame position of each attached node (in ``fixed`` order).
    Rigid boxes (``rigid_kernels`` conventions): c, q, vr, w, impulse_cache
    UPDATED; rmass (n_rigid,) [kg], inertia_body (n_rigid, 3) [kg m^2],
    half_extents (n_rigid, 3) [m], kinematic (n_rigid,) bool.
    World: gravity (3,) [m/s^2]; terr_kind, terr (``terrain_kernels``);
    fric_model, fric (``friction_kernels.friction_params``) for the free nodes;
    phys (N_PHYS,) scalars (layout at the top of this module: dt [s], Miller's
    r_n, r_t, blow-up limits [m/s] and [m], the boxes' Coulomb mu,
    restitution and contact-solver settings as in ``rigid_kernels.advance``).
    Scratch (overwritten): f_work (n_nodes, 3) (its free rows), b_work (n_free, 3), f_att,
    x_att (n_fixed, 3) (the rows of nodes on boxes that are not kinematic), x_pred (n_fixed, 3),
    residual (n_fixed,), spine (n_links, 3), force,
    torque (n_rigid, 3) (zero on kinematic boxes), Rb (n_rigid, 3, 3), and the contact scratch of
    ``rigid_kernels._solve_contacts`` (R, Iw (3, 3); corner_of (8,) int64;
    lin, ang, resp (8, 3, 3); kn, target (8,); kt (8, 6); lam (8, 3)).
    acc (N_ACC,) ACCUMULATES the statistics (residual max / sum / count,
    deepest penetration, contact fraction sum, steps, slow-path tets).
    On a blow-up the step that produced it is completed and its status code
    returned with the number of steps including it.
    """
    n_fixed = fixed.shape[0]
    n_free = perm.shape[0]
    n_rigid = c.shape[0]
    dt = phys[DT]
    r_n = phys[R_N]
    r_t = phys[R_T]
    max_pen = phys[MAX_PEN]
    vmax = phys[MAX_SPEED]
    vmax2 = vmax * vmax
    phys[RIGID_MU]
    phys[RIGID_RESTITUTION]
    phys[BOUNCE_THRESHOLD]
    int(phys[VEL_ITERATIONS])
    phys[VEL_TOLERANCE]
    int(phys[POS_ITERATIONS])
    phys[POS_BETA]
    phys[SLOP]
    contact_dist = fric[CONTACT_DISTANCE]
    gx, gy, gz = gravity[0], gravity[1], gravity[2]
    n_points = n_free + N_CORNERS * n_rigid
    muscles_on = phys[MUSCLES_ON] != 0.0
    act_buf = muscle[7]
    n_rows = act_buf.shape[0]
    # on the plane without obstacles the free nodes' distances are y - ground (``flat_ground``: what
    # ``signed_distance`` computes there, without its reference-count updates per call)
    flat, ground = flat_ground(terr_kind, terr)
    for step in range(n_steps):
        status = OK
        if muscles_on:
            active_coefficients(muscle[0], muscle[1], muscle[2], muscle[3], muscle[4], muscle[5], muscle[6],
                                act_buf[min(step, n_rows - 1)], phys[MUSCLE_GAIN], phys[VOLUME] != 0.0, Dm_inv, coef)
        # ---------------- (1) FEM step, attached nodes prescribed at rigid state n
        # Every tet's nodal forces (eqs. 7-11), then each node's sum, gathered in the scatter's order
        # (bit for bit ``elastic_forces``), for the nodes that use it: the free nodes, and the attached
        # nodes of the boxes that take a rigid step.  A kinematic box is not integrated (the forces on
        # it are lost to whatever holds it), so its nodes' forces are not summed: on the walking
        # centipede, 16 of 18 boxes are carried by their legs in a step.
        acc[ACC_SLOW_TETS] += element_forces(x, tets, coef, q_ws, F_work, H_work)
        Hf = H_work.reshape(H_work.size)
        for k in range(n_free):
            i = perm[k]
            # plus gravity M g (eq. 14: g is a force, PAPER-NOTES), after the elastic sum as before
            s0, s1, s2 = gather_node_force(Hf, inc_ptr, inc_off, i, 0.0, 0.0, 0.0)
            m = mass[i]
            f_work[i, 0] = s0 + m * gx
            f_work[i, 1] = s1 + m * gy
            f_work[i, 2] = s2 + m * gz
        for a in range(n_fixed):
            p = fixed[a]
            # Where eq. 15 would take the node if it were simulated (for the residual).
            x_pred[a, 0] = x[p, 0] + dt * v[p, 0]
            x_pred[a, 1] = x[p, 1] + dt * v[p, 1]
            x_pred[a, 2] = x[p, 2] + dt * v[p, 2]
            if kinematic[att_body[a]]:
                continue
            f_att[a, 0], f_att[a, 1], f_att[a, 2] = gather_node_force(Hf, inc_ptr, inc_off, p, 0.0, 0.0, 0.0)
            x_att[a, 0] = x[p, 0]
            x_att[a, 1] = x[p, 1]
            x_att[a, 2] = x[p, 2]
        semi_implicit_velocity(v, mass, f_work, dt, perm, sky_first, sky_ptr, sky_L,
                               fp_ptr, fp_col, fp_val, b_work)
        # Damping reaction on the attached nodes, -(D v^{n+1})_p, with the same
        # prescribed v_p the solve used: total internal force exactly zero.
        # (each row summed in registers, in the order of its entries: the same doubles as in memory;
        # the nodes of kinematic boxes skipped, as above)
        for a in range(n_fixed):
            if kinematic[att_body[a]]:
                continue
            s0, s1, s2 = f_att[a, 0], f_att[a, 1], f_att[a, 2]
            for e in range(pf_ptr[a], pf_ptr[a + 1]):
                j = np.uint64(pf_col[e])  # node ids are >= 0: no wrap-around test per index
                d = pf_val[e]
                s0 -= d * v[j, 0]
                s1 -= d * v[j, 1]
                s2 -= d * v[j, 2]
            f_att[a, 0], f_att[a, 1], f_att[a, 2] = s0, s1, s2
        # Ground contact of the free nodes (the suite's point-mass contact) and eq. 15.
        link_spines(c, spine)
        n_contact = 0
        for k in range(n_free):
            i = perm[k]
            # A node clear of the terrain at both ends of its step (phi >= the contact distance now,
            # phi >= 0 after x += dt v) is what ``advance_point`` reduces to for it: no friction, no
            # collision, x += dt v and the blow-up checks, done here with the same arithmetic (bit
            # for bit), as the fem bodies do; any other node (also a NaN distance) goes through
            # ``advance_point``.  Written out rather than a call of
            # ``contact_kernels.advance_point_if_clear`` (the same doubles; it also rewrites v with
            # itself), with an unsigned node id (no wrap-around test per index): 3.0 -> 1.9 us per
            # step for the walking centipede's 153 free nodes, all in the air (kernel timed in a loop).
            u = np.uint64(i)
            px, py, pz = x[u, 0], x[u, 1], x[u, 2]
            vx, vy, vz = v[u, 0], v[u, 1], v[u, 2]
            phi = py - ground if flat else signed_distance(terr_kind, terr, px, py, pz)
            if phi >= contact_dist:
                qx, qy, qz = px + dt * vx, py + dt * vy, pz + dt * vz
                phi = qy - ground if flat else signed_distance(terr_kind, terr, qx, qy, qz)
                if phi >= 0.0:
                    x[u, 0], x[u, 1], x[u, 2] = qx, qy, qz
                    if not math.isfinite(qx + qy + qz + vx + vy + vz):
                        status = NONFINITE
                    elif vx * vx + vy * vy + vz * vz > vmax2:
                        status = RUNAWAY_SPEED
                    continue
            s = node_link[i]
            touching, st = advance_point(x, v, i, vx, vy, vz, spine[s, 0], spine[s, 1],
                                         spine[s, 2], dt, terr_kind, terr, fric_model, fric, r_n, r_t,
                                         contact_dist, max_pen, vmax2, acc, False, 0.0, 0.0, 0.0)
            n_contact += touching
            if st != OK:
                status = st

        # ---------------- (2) rigid step under the mesh's forces, (3) attached nodes follow (Sec. 3)
        st, nc = rigid_segments_step(fixed, att_body, att_local, f_att, x_att, x, v, x_pred, residual,
                                     c, q, vr, w, rmass, inertia_body, half_extents, kinematic, impulse_cache,
                                     gravity, terr_kind, terr, fric, phys, force, torque, Rb,
                                     R, Iw, corner_of, lin, ang, resp, kn, kt, target, lam, acc)
        n_contact += nc
        if st != OK:
            status = st
        acc[ACC_CONTACT_SUM] += n_contact / n_points
        acc[ACC_STEPS] += 1.0
        if status != OK:
            return step + 1, status
    return n_steps, OK


@njit(cache=True, error_model="numpy")
def momenta(x, v, mass, free, c, vr, w, rmass, inertia_body, Rb, origin, out):
    """Linear and angular momentum of the simulated masses (rigid boxes and free nodes).

    x, v (n_nodes, 3) [m], [m/s]; mass (n_nodes,) [kg]; free (n_free,) node ids
    (attached nodes are carried by the rigid bodies and not counted); rigid
    c, vr, w (n_rigid, 3), rmass (n_rigid,), inertia_body (n_rigid, 3), Rb
    (n_rigid, 3, 3) the current rotation matrices; origin (3,) [m] the point
    the angular momentum is taken about.  OVERWRITES out (6,): P [kg m/s]
    then L [kg m^2/s] = sum (x - o) x m v + sum R I_body R^T w.
    """
    for k in range(6):
        out[k] = 0.0
    ox, oy, oz = origin[0], origin[1], origin[2]
    for k in range(free.shape[0]):
        i = free[k]
        m = mass[i]
        px, py, pz = m * v[i, 0], m * v[i, 1], m * v[i, 2]
        rx, ry, rz = x[i, 0] - ox, x[i, 1] - oy, x[i, 2] - oz
        out[0] += px
        out[1] += py
        out[2] += pz
        out[3] += ry * pz - rz * py
        out[4] += rz * px - rx * pz
        out[5] += rx * py - ry * px
    for i in range(c.shape[0]):
        m = rmass[i]
        px, py, pz = m * vr[i, 0], m * vr[i, 1], m * vr[i, 2]
        rx, ry, rz = c[i, 0] - ox, c[i, 1] - oy, c[i, 2] - oz
        out[0] += px
        out[1] += py
        out[2] += pz
        out[3] += ry * pz - rz * py
        out[4] += rz * px - rx * pz
        out[5] += rx * py - ry * px
        # spin: R I_body R^T w
        b0 = Rb[i, 0, 0] * w[i, 0] + Rb[i, 1, 0] * w[i, 1] + Rb[i, 2, 0] * w[i, 2]
        b1 = Rb[i, 0, 1] * w[i, 0] + Rb[i, 1, 1] * w[i, 1] + Rb[i, 2, 1] * w[i, 2]
        b2 = Rb[i, 0, 2] * w[i, 0] + Rb[i, 1, 2] * w[i, 1] + Rb[i, 2, 2] * w[i, 2]
        b0 *= inertia_body[i, 0]
        b1 *= inertia_body[i, 1]
        b2 *= inertia_body[i, 2]
        out[3] += Rb[i, 0, 0] * b0 + Rb[i, 0, 1] * b1 + Rb[i, 0, 2] * b2
        out[4] += Rb[i, 1, 0] * b0 + Rb[i, 1, 1] * b1 + Rb[i, 1, 2] * b2
        out[5] += Rb[i, 2, 0] * b0 + Rb[i, 2, 1] * b1 + Rb[i, 2, 2] * b2
