"""Numba step loop of a creature whose every segment is a fixed-corotational FEM block.

One step (paper App. A with the suite's muscles and ground contact):

1. the step's muscle activation: row k of the actuation buffer written by the
   controller (``core.protocols.Actuation``; the kernel knows no gait);
2. active strain (``active_coefficients``): each tet's rest shape is scaled by
   A = diag(l_axial, l_c, l_c) in the body's rest frame, with l_axial the
   fibre stretch 1 + axial + lateral z_s + dorsal y_s at the tet's centroid
   (z_s, y_s in [-1, 1] across the section, as at the lattice's corners) and
   l_c = 1 / sqrt(1 + axial) when volume-conserving (Miller Sec. 4);
3. elastic forces f_E (eqs. 7-11) plus gravity M g (eq. 14);
4. semi-implicit velocity solve (M + dt D) v^{n+1} = M v^n + dt f (eq. 14),
   with held nodes (a suspended head) prescribed at rest;
5. per free node: ground friction then Miller's path collision
   (``contact_kernels``), x^{n+1} = x^n + dt v^{n+1} (eq. 15);
6. blow-up checks (``step_status``).
"""
from __future__ import annotations

import math
from collections import namedtuple

from numba import njit

from ...world.terrain_kernels import distance_at_least, flat_ground
from ...world.world import StepWorld
from ..contact_kernels import advance_point
from ..friction_kernels import CONTACT_DISTANCE, spine_between
from ..step_status import ACC_CONTACT_SUM, ACC_STEPS, NONFINITE, OK, RUNAWAY_SPEED
from .kernels import COEF_DM_INV, COEF_LAM, COEF_TWO_MU, LANES, elastic_forces_gathered, semi_implicit_velocity

# scalar parameter vector layout (``phys``): the body's own constants.  Gravity and the time step are not here: the
# world (``world.world.StepWorld``) and dt are plain arguments of the step (``advance``).
RAMP_S, VOLUME, R_N, R_T, MAX_SPEED, MAX_PEN, MUSCLES = range(7)
N_PHYS = 8
MIN_STRETCH = 0.1  # as in the lattice: a fibre never shortens below 10 % of its rest length


@njit(cache=True, error_model="numpy")
def active_coefficients(Dm_inv, vol, mu, lam, tet_seg, tet_y, tet_z, act, gain, volume_conserving, Dm_inv_eff, coef):
    """Overwrite Dm_inv_eff (n_tets, 3, 3) [1/m] and the blocked ``coef`` for activation ``act`` (n_seg, 3).

    gain [-] scales every strain (1 for a body whose segments are all muscle; the hybrid body's
    links, a fraction of the body's length, take the strain of the whole pitch).  A tet with
    tet_seg < 0 is passive (rest shape kept).
    F_e = F A^-1 with A diagonal in the rest frame, so Dm_inv_eff = Dm^-1 A^-1
    scales the columns of Dm^-1; ``coef`` packs -V Dm_inv_eff, 2 mu, lambda and Dm_inv_eff
    (layout of ``fem.kernels.pack_tet_coefficients``).  tet_y, tet_z: (n_tets,)
    centroid position across the section, scaled to [-1, 1].
    """
    for e in range(Dm_inv.shape[0]):
        i = tet_seg[e]
        if i < 0:
            continue
        axial = max(1.0 + gain * act[i, 0], MIN_STRETCH)
        la = max(1.0 + gain * (act[i, 0] + act[i, 1] * tet_z[e] + act[i, 2] * tet_y[e]), MIN_STRETCH)
        lc = 1.0 / math.sqrt(axial) if volume_conserving else 1.0
        inv = (1.0 / la, 1.0 / lc, 1.0 / lc)
        b = e // LANES
        ln = e - b * LANES
        for r in range(3):
            for c in range(3):
                d = Dm_inv[e, r, c] * inv[c]
                Dm_inv_eff[e, r, c] = d
                coef[b, (3 * r + c) * LANES + ln] = -vol[e] * d
                coef[b, (COEF_DM_INV + 3 * r + c) * LANES + ln] = d
        coef[b, COEF_TWO_MU * LANES + ln] = 2.0 * mu[e]
        coef[b, COEF_LAM * LANES + ln] = lam[e]


@njit(cache=True, error_model="numpy")
def segment_spines(x, seg_ptr, seg_nodes, centers, spine):
    """Overwrite centers (n_seg, 3) [m] with the mean node position of each segment and
    spine (n_seg, 3) with the unit vector from the segment behind to the one ahead (Miller Sec. 4)."""
    n_seg = centers.shape[0]
    for i in range(n_seg):
        cx = cy = cz = 0.0
        for a in range(seg_ptr[i], seg_ptr[i + 1]):
            k = seg_nodes[a]
            cx += x[k, 0]
            cy += x[k, 1]
            cz += x[k, 2]
        m = seg_ptr[i + 1] - seg_ptr[i]
        centers[i, 0], centers[i, 1], centers[i, 2] = cx / m, cy / m, cz / m
    for i in range(n_seg):
        spine_between(centers, i - 1 if i > 0 else 0, i + 1 if i < n_seg - 1 else n_seg - 1, spine, i)


# ``advance``'s arguments, named records (numba compiles a namedtuple as a struct of its fields, read by name;
# ``bodies.rigid_chain``'s note on the call's cost).  The fields are described in ``advance``.
BodyMesh = namedtuple("BodyMesh", "mass tets Dm_inv vol mu lam tet_seg tet_y tet_z")
BodyFactor = namedtuple("BodyFactor", "perm sky_first sky_ptr sky_L fp_ptr fp_col fp_val")
NodeFrames = namedtuple("NodeFrames", "node_seg node_seg_b node_w seg_ptr seg_nodes")
BodyWork = namedtuple("BodyWork", "Dm_inv_eff coef q_ws F_work H_work inc_ptr inc_off force b_work centers spine")


@njit(cache=True, error_model="numpy")
def advance(x, v, body_mesh, act_buf, body_factor, node_frames, fric_model, fric, phys, body_work, act, acc, world,
            dt, n_steps):
    """Advance the FEM creature ``n_steps`` steps of dt [s] in world (the run's ``world.world.StepWorld`` as a plain
    tuple: gravity, terrain); return (steps done, status).  The legless FEM body's one step function
    (``BodySpec.legless_step``); dt must be the one the factor of (M + dt D) was built for (the body's ``dt``).

    mesh = ``BodyMesh`` (mass, tets, Dm_inv, vol, mu, lam, tet_seg, tet_y, tet_z), factor = ``BodyFactor`` (perm,
    sky_first, sky_ptr, sky_L, fp_ptr, fp_col, fp_val), frames = ``NodeFrames`` (node_seg, node_seg_b, node_w,
    seg_ptr, seg_nodes), work = ``BodyWork`` (Dm_inv_eff, coef, q_ws, F_work, H_work, inc_ptr, inc_off, force,
    b_work, centers, spine): the records as plain tuples (``core.kernel_records``: the call's cost), named
    here.

    act_buf (n_rows, n_seg, 3): the muscle strains of step k in row k (rows past the last repeat
    it); read only when phys[MUSCLES] is set (the actuation drives muscles at all).
    x, v: (n_nodes, 3) [m], [m/s], updated in place; mass (n_nodes,) [kg];
    tets, Dm_inv (rest), vol, mu, lam: the mesh; tet_seg, tet_y, tet_z: each
    tet's segment and section position; perm, sky_*, fp_*: the factorization of
    (M + dt D)_ff over the free nodes ``perm`` (``FEMSystem.solver``); nodes not
    in ``perm`` are held (v = 0).  node_seg, node_seg_b, node_w (n_nodes,): a node's friction
    frame is the spine (1 - w) spine[a] + w spine[b], normalized (``body.spine_interpolation``:
    the tangent at the node's own place on the body); seg_ptr/seg_nodes: CSR of each segment's nodes.
    inc_ptr, inc_off: ``fem.kernels.node_incidence`` of tets.  Work arrays are
    overwritten; ``acc`` accumulates statistics (``step_status``).
    """
    mesh, factor, frames = BodyMesh(*body_mesh), BodyFactor(*body_factor), NodeFrames(*node_frames)
    work = BodyWork(*body_work)
    mass, tets, Dm_inv, vol, mu, lam = mesh.mass, mesh.tets, mesh.Dm_inv, mesh.vol, mesh.mu, mesh.lam
    tet_seg, tet_y, tet_z = mesh.tet_seg, mesh.tet_y, mesh.tet_z
    perm, sky_first, sky_ptr, sky_L = factor.perm, factor.sky_first, factor.sky_ptr, factor.sky_L
    fp_ptr, fp_col, fp_val = factor.fp_ptr, factor.fp_col, factor.fp_val
    node_seg, node_seg_b, node_w, seg_ptr, seg_nodes = (frames.node_seg, frames.node_seg_b, frames.node_w,
                                                        frames.seg_ptr, frames.seg_nodes)
    Dm_inv_eff, coef, q_ws, F_work, H_work = work.Dm_inv_eff, work.coef, work.q_ws, work.F_work, work.H_work
    inc_ptr, inc_off, force, b_work = work.inc_ptr, work.inc_off, work.force, work.b_work
    centers, spine = work.centers, work.spine
    W = StepWorld(*world)
    terr_kind, terr = W.terr_kind, W.terr
    g = -W.gravity[1]  # the world's gravity is (0, -g, 0) [m/s^2]
    r_n = phys[R_N]
    r_t = phys[R_T]
    muscles = phys[MUSCLES] != 0.0
    volume = phys[VOLUME] != 0.0
    max_speed2 = phys[MAX_SPEED] * phys[MAX_SPEED]
    contact_dist = fric[CONTACT_DISTANCE]
    n_free = perm.shape[0]
    n_rows = act_buf.shape[0]
    # on the plane without obstacles the free nodes' distances are y - ground (``flat_ground``: what
    # ``signed_distance`` computes there, without its reference-count updates per call)
    flat, ground = flat_ground(terr_kind, terr)
    for step in range(n_steps):
        if muscles:
            row = act_buf[min(step, n_rows - 1)]
            for i in range(act.shape[0]):  # element-wise: a slice copy compiles numba's shape-error formatting
                for j in range(act.shape[1]):
                    act[i, j] = row[i, j]
            active_coefficients(Dm_inv, vol, mu, lam, tet_seg, tet_y, tet_z, row, 1.0, volume, Dm_inv_eff, coef)
        force[:, :] = 0.0
        elastic_forces_gathered(x, tets, coef, q_ws, F_work, H_work, inc_ptr, inc_off, force)
        for k in range(n_free):
            i = perm[k]
            force[i, 1] -= mass[i] * g  # eq. 14: the gravity force M g (PAPER-NOTES)
        semi_implicit_velocity(v, mass, force, dt, perm, sky_first, sky_ptr, sky_L, fp_ptr, fp_col, fp_val, b_work)
        segment_spines(x, seg_ptr, seg_nodes, centers, spine)
        status = OK
        n_contact = 0
        for k in range(n_free):
            i = perm[k]
            # a node clear of the terrain at both ends of its step: ``advance_point``'s no-contact case
            # with its arithmetic, bit for bit (as in ``fem.myriapod.advance_chain``).  Deliberately unrolled,
            # not a call of ``contact_kernels.advance_point_if_clear`` (the same doubles): that call measured -4 %
            # on `fem-worm` and -9 % on `fem-centipede` (regress, 4 alternating rounds, 2026-11-24)
            px, py, pz = x[i, 0], x[i, 1], x[i, 2]
            vx, vy, vz = v[i, 0], v[i, 1], v[i, 2]
            # (``distance_at_least``: the same tests as phi >= ..., answered among obstacles without their search
            # for the nodes high above them)
            if (py - ground >= contact_dist) if flat else distance_at_least(terr_kind, terr, px, py, pz, contact_dist):
                qx, qy, qz = px + dt * vx, py + dt * vy, pz + dt * vz
                if (qy - ground >= 0.0) if flat else distance_at_least(terr_kind, terr, qx, qy, qz, 0.0):
                    x[i, 0], x[i, 1], x[i, 2] = qx, qy, qz
                    if not math.isfinite(qx + qy + qz + vx + vy + vz):
                        status = NONFINITE
                    elif vx * vx + vy * vy + vz * vz > max_speed2:
                        status = RUNAWAY_SPEED
                    continue
            sa = node_seg[i]
            sb = node_seg_b[i]
            w = node_w[i]
            sx = (1.0 - w) * spine[sa, 0] + w * spine[sb, 0]
            sy = (1.0 - w) * spine[sa, 1] + w * spine[sb, 1]
            sz = (1.0 - w) * spine[sa, 2] + w * spine[sb, 2]
            nrm = math.sqrt(sx * sx + sy * sy + sz * sz)
            if nrm > 0.0:
                sx, sy, sz = sx / nrm, sy / nrm, sz / nrm
            touching, st = advance_point(x, v, i, (vx, vy, vz), (sx, sy, sz), terr_kind, terr, fric_model, fric,
                                         (dt, r_n, r_t, contact_dist, phys[MAX_PEN], max_speed2), acc, False,
                                         (0.0, 0.0, 0.0))
            n_contact += touching
            if st != OK:
                status = st
        acc[ACC_CONTACT_SUM] += n_contact / x.shape[0]
        acc[ACC_STEPS] += 1.0
        if status != OK:
            return step + 1, status
    return n_steps, OK


@njit(cache=True, error_model="numpy")
def kinetic_and_gravity(x, v, mass, g):
    """(kinetic [J], gravitational [J] from y = 0) of the nodes."""
    ke = 0.0
    pg = 0.0
    for i in range(x.shape[0]):
        ke += 0.5 * mass[i] * (v[i, 0] ** 2 + v[i, 1] ** 2 + v[i, 2] ** 2)
        pg += mass[i] * g * x[i, 1]
    return ke, pg
