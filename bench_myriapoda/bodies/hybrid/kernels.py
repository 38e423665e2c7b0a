"""Numba kernels of the hybrid body: rigid exoskeletal segments joined by FEM links.

The myriapod paper (Fang, Jiang & Terzopoulos 2013, Sec. 3) couples its rigid
segments and its fixed-corotational deformable segments (App. A) with a
staggered scheme of three steps.  The rigid segment chain's ``rigid_chain.advance_chain``, with
this module's FEM links (``FEMLinks``) as its link element, runs many time steps of it inside
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
from collections import namedtuple

import numpy as np
from numba import njit

from ...world.terrain_kernels import clearance, clearance_cell, clearance_view, distance_at_least
from ...world.world import StepWorld
from ..contact_kernels import advance_point
from ..fem.kernels import element_forces, gather_node_force, semi_implicit_velocity
from ..step_status import (ACC_CONTACT_SUM, ACC_MAX_PEN, ACC_STEPS, DEEP_PENETRATION, NONFINITE, OK,  # noqa: F401
                           RUNAWAY_SPEED, STATUS_TEXT)
from ..fem.body_kernels import active_coefficients
# the phys layout, the statistics and the rigid segments' step are the rigid segment chain's (``bodies.rigid_chain``,
# shared with the legged mass-spring body), this kernel's link element being FEM; imported here as its own
from ..rigid_chain import (ACC_RES_COUNT, ACC_RES_MAX, ACC_RES_SUM, ACC_SLOW_TETS, BOUNCE_THRESHOLD,  # noqa: F401
                           MAX_PEN, MAX_SPEED, MUSCLE_GAIN, MUSCLES_ON, N_ACC, N_CORNERS, N_PHYS, POS_BETA,
                           POS_ITERATIONS, R_N, R_T, RIGID_ANISO, RIGID_MU, RIGID_RESTITUTION, SLOP, VEL_ITERATIONS,
                           VEL_TOLERANCE, VOLUME, Attachment, Boxes, ChainParams, Coupling, advance_chain,
                           chain_scalars,
                           follow_boxes,
                           link_spines, place_attached_nodes, place_on_box, register_link, rigid_segments_step)


# The FEM link element of the rigid segment chain (``rigid_chain.link_step``), a named record: x, v (n_nodes, 3)
# [m], [m/s] UPDATED (attached rows are rewritten from the boxes every step); n_free the free nodes; tets
# (n_tets, 4), Dm_inv (n_tets, 3, 3) [1/m], coef, q_ws (UPDATED), F_work, H_work as in ``fem.kernels.elastic_forces``;
# muscle: the active links, an ``ActiveLinks`` as a plain tuple (named where read); mass (n_nodes,) [kg] lumped;
# inc_ptr, inc_off: ``fem.kernels.node_incidence`` of tets, for ``gather_node_force``; perm, sky_first, sky_ptr,
# sky_L, fp_ptr, fp_col, fp_val as in ``semi_implicit_velocity`` for the mask of attached nodes
# (``FEMSystem.solver``); pf_ptr, pf_col, pf_val the CSR of D's rows of the attached nodes [N s/m] (``fixed``
# order); node_link (n_nodes,) the link of each node; scratch f_work (n_nodes, 3) (its free rows), b_work (n_free, 3).
FEMLinks = namedtuple("FEMLinks", "x v n_free tets Dm_inv coef muscle mass q_ws F_work H_work inc_ptr inc_off "
                                  "perm sky_first sky_ptr sky_L fp_ptr fp_col fp_val pf_ptr pf_col pf_val node_link "
                                  "f_work b_work")
# The active links (paper Sec. 7's "actively contractile deformable segments"): Dm_inv_rest (n_tets, 3, 3) [1/m],
# vol [m^3], mu, lam [Pa] (n_tets,), tet_link (n_tets,) int, tet_y, tet_z (n_tets,) [-], act_buf (n_rows, n_links, 3)
# [-]: when phys[MUSCLES_ON] is set, step k rescales the links' rest shapes by row k of act_buf times
# phys[MUSCLE_GAIN] (``fem.body_kernels.active_coefficients``, which OVERWRITES FEMLinks.Dm_inv and coef).
ActiveLinks = namedtuple("ActiveLinks", "Dm_inv_rest vol mu lam tet_link tet_y tet_z act_buf")


def _fem_links_step(L, A, B, M, W, C, acc, dt, step, flat, ground):
    """``rigid_chain.link_step`` of the FEM links: step 1 of the module docstring."""
    x, v, n_free, tets, coef, mass, q_ws = L.x, L.v, L.n_free, L.tets, L.coef, L.mass, L.q_ws
    inc_ptr, inc_off, perm, pf_ptr, pf_col, pf_val = L.inc_ptr, L.inc_off, L.perm, L.pf_ptr, L.pf_col, L.pf_val
    node_link, f_work, b_work, F_work, H_work = L.node_link, L.f_work, L.b_work, L.F_work, L.H_work
    fixed, att_body = A.fixed, A.att_body
    kinematic = B.kinematic
    gravity, terr_kind, terr, fric_model, fric, phys = W.gravity, W.terr_kind, W.terr, M.fric_model, M.fric, M.phys
    f_att, x_att, x_pred, spine = C.f_att, C.x_att, C.x_pred, C.spine
    n_fixed = fixed.shape[0]
    r_n, r_t, max_pen, vmax, contact_dist = chain_scalars(phys, fric)
    vmax2 = vmax * vmax
    gx, gy, gz = gravity[0], gravity[1], gravity[2]
    status = OK
    if phys[MUSCLES_ON] != 0.0:
        M = ActiveLinks(*L.muscle)
        act_buf = M.act_buf
        active_coefficients(M.Dm_inv_rest, M.vol, M.mu, M.lam, M.tet_link, M.tet_y, M.tet_z,
                            act_buf[min(step, act_buf.shape[0] - 1)], phys[MUSCLE_GAIN], phys[VOLUME] != 0.0,
                            L.Dm_inv, coef)
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
    semi_implicit_velocity(v, mass, f_work, dt, perm, L.sky_first, L.sky_ptr, L.sky_L,
                           L.fp_ptr, L.fp_col, L.fp_val, b_work)
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
    link_spines(B.c, spine)
    n_contact = 0
    V = clearance_view(terr_kind, terr)  # the terrain's scalars for the nodes' tests, read once per step
    for k in range(n_free):
        i = perm[k]
        # A node clear of the terrain at both ends of its step (phi >= the contact distance now,
        # phi >= 0 after x += dt v) is what ``advance_point`` reduces to for it: no friction, no
        # collision, x += dt v and the blow-up checks, done here with the same arithmetic (bit
        # for bit); any other node (also a NaN distance) goes through ``advance_point``.  Deliberately
        # unrolled, as in the FEM bodies (``fem.myriapod.advance_chain`` has the measurements of a call of
        # ``contact_kernels.advance_point_if_clear`` instead, the same doubles); an unsigned node id (no
        # wrap-around test per index): 3.0 -> 1.9 us per step for the walking centipede's 153 free nodes
        # (kernel timed in a loop).
        u = np.uint64(i)
        px, py, pz = x[u, 0], x[u, 1], x[u, 2]
        vx, vy, vz = v[u, 0], v[u, 1], v[u, 2]
        # (on the plane without obstacles y - ground; else ``clearance``, then ``distance_at_least`` where it cannot
        # tell: the same tests as phi >= ..., answered among obstacles without their search for the nodes high
        # above them)
        if flat:
            clear = py - ground >= contact_dist
        else:
            kc = clearance_cell(V, px, pz, contact_dist)
            c = clearance(V, terr[kc] if kc >= 0 else 0.0, py, contact_dist, kc)
            clear = (c > 0) if c >= 0 else distance_at_least(terr_kind, terr, px, py, pz, contact_dist)
        if clear:
            qx, qy, qz = px + dt * vx, py + dt * vy, pz + dt * vz
            if flat:
                clear = qy - ground >= 0.0
            else:
                kc = clearance_cell(V, qx, qz, 0.0)
                c = clearance(V, terr[kc] if kc >= 0 else 0.0, qy, 0.0, kc)
                clear = (c > 0) if c >= 0 else distance_at_least(terr_kind, terr, qx, qy, qz, 0.0)
            if clear:
                x[u, 0], x[u, 1], x[u, 2] = qx, qy, qz
                if not math.isfinite(qx + qy + qz + vx + vy + vz):
                    status = NONFINITE
                elif vx * vx + vy * vy + vz * vz > vmax2:
                    status = RUNAWAY_SPEED
                continue
        # a node not clear: ``advance_point`` on its link's spine.  This tail of the loop and the entry kernel
        # below are alike in each link element by design (``massspring.myriapod._spring_links_step`` and
        # ``advance_spring_chain``): the call is inlined into each link element's own loop (an inline wrapper
        # around it would bind its array arguments again at every contact node), and an entry kernel names
        # its link class, which numba must see as a global (a kernel shared through a closure over the class
        # would be cached under one name for every class)
        s = node_link[i]
        touching, st = advance_point(x, v, i, (vx, vy, vz), (spine[s, 0], spine[s, 1], spine[s, 2]), terr_kind,
                                     terr, fric_model, fric, (dt, r_n, r_t, contact_dist, max_pen, vmax2), acc,
                                     False, (0.0, 0.0, 0.0))
        n_contact += touching
        if st != OK:
            status = st
    return status, n_contact


register_link(FEMLinks, _fem_links_step)


# inline: the fused legged walk's step is this function with n = 1 (``legged_chunk.chain_step``), inlined into its
# chunk, so no kernel of its own sits between the chain and the chunk on a cold start
@njit(cache=True, error_model="numpy", inline="always")
def advance(links, att, boxes, params, coupling, acc, world, dt, n_steps):
    """The hybrid's one step function (its ``BodySpec.step``): n_steps of dt [s] of ``rigid_chain.advance_chain`` of
    the FEM-linked chain in world, from Python (``BodyHybrid.advance``) and in the fused legged walk: the body's
    records ``FEMLinks``, ``Attachment``, ``Boxes``, ``ChainParams`` and ``Coupling`` and the run's world
    (``world.world.StepWorld``) as plain tuples (``core.kernel_records``), named here; acc (N_ACC,) ACCUMULATES;
    returns (steps, status).  dt must be the one the links' factor of (M + dt D) was built for (the body's)."""
    return advance_chain(FEMLinks(*links), Attachment(*att), Boxes(*boxes), ChainParams(*params),
                         Coupling(*coupling), acc, StepWorld(*world), dt, n_steps)


@njit(cache=True, error_model="numpy", inline="always")
def _add_point_momentum(out, m, v, x, i, ox, oy, oz):
    """out[0:3] += m v[i] [kg m/s], out[3:6] += (x[i] - o) x m v[i] [kg m^2/s] (``momenta``)."""
    px, py, pz = m * v[i, 0], m * v[i, 1], m * v[i, 2]
    rx, ry, rz = x[i, 0] - ox, x[i, 1] - oy, x[i, 2] - oz
    out[0] += px
    out[1] += py
    out[2] += pz
    out[3] += ry * pz - rz * py
    out[4] += rz * px - rx * pz
    out[5] += rx * py - ry * px


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
        _add_point_momentum(out, mass[i], v, x, i, ox, oy, oz)
    for i in range(c.shape[0]):
        _add_point_momentum(out, rmass[i], vr, c, i, ox, oy, oz)
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
