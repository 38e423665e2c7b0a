"""A legged myriapod in one compiled call per chunk: leg controller, support and body step.

The reference is the Python path of ``harness.runner.Stepper`` for a closed-loop controller
ticking every step: ``body.sense`` -> ``MyriapodController.step`` -> ``body.apply_support``
-> ``LeggedMonitor.after_control`` -> ``body.advance(t, 1)``, a few dozen compiled calls
sequenced from Python per time step.  ``hybrid_chunk`` and ``massspring_chunk`` run k such
steps inside one numba call (``fem_chunk`` likewise, its steps 1 and 3 below are the FEM body's),
with the same kernels in the same order on the same arrays:

1. sense: the boxes' rotations from their quaternions (``rigid_kernels.quat_to_matrix``);
2. the controller's step (``controllers.myriapod.compiled.controller_step``);
3. the support (the bodies' ``set_support``): kinematic = supported | held, the supported
   boxes driven to their targets (``kinematic_targets.drive_to_targets``, paper Sec. 4.1),
   the attached link nodes put back on the boxes (``_place_attached``: ``hybrid.kernels.place_on_box``,
   the arithmetic of ``hybrid.kernels.place_attached_nodes`` without the coupling residual, which the body's
   step overwrites before reading it);
4. a timeline sample every ``record_every`` steps: the controller's record (states, tips,
   brain mode, antenna contact, segment centres before the support) and the monitor's
   (box poses and link centres after the support), into buffers;
5. one body step (``hybrid.kernels.advance``, ``massspring.myriapod.advance_chain`` or
   ``fem.myriapod.advance_chain``, n = 1).

After the last step (or a step that blew up) ``compiled.finish_chunk`` computes the antennae's
links that the chunk's steps left to it on a terrain without obstacles (``compiled.I_ANT_DEFER``).

Python is entered once per chunk (the runner's sample rate): ``FusedLeggedWalk.advance``
packs the controller's scalars, pre-draws its random numbers, calls the kernel, and
replays the buffered timeline samples into the controller's lists and the monitor, so
observations, metrics and series are those of the Python path.  The state after every step
equals the Python path's bit for bit (tests/test_fused_walk.py; numpy's summation order is
reproduced where a sum feeds a metric).

Fused: the three legged bodies -- ``hybrid`` and ``massspring`` (rigid boxes joined by FEM or
spring links; ``hybrid_chunk``, ``massspring_chunk``) and ``fem`` (stiff blocks in one mesh, their
poses sensed from the nodes and their support a penalty target, ``fem_chunk``) -- driven by
``MyriapodController`` every time step, on any terrain of ``world.terrain_kernels`` (plane,
slopes, heightfields, obstacles), antennae on or off, leg collisions on or off, brain modes
ADJUSTMENT, AVOIDANCE, RANDOM-WALK and CONTROL, the suspended scenario (held head).  Not fused
(``unsupported_reason``; the runner keeps the Python path): food (TROPHOTROPISM, eating), the
lateral body wave (``body_wave_amplitude`` > 0), muscle actuation of the hybrid's links, a
controller ticking slower than every step, a controller of another class, any other body.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ..bodies import rigid_kernels as rk
from ..bodies.hybrid import kernels as K
from ..bodies.hybrid.body import BodyHybrid
from ..bodies.kinematic_targets import drive_to_targets
from ..bodies.fem import myriapod as FM
from ..bodies.fem.myriapod import BodyFEMChain
from ..bodies.massspring import myriapod as MS
from ..bodies.massspring.myriapod import BodyRigidSpringChain
from ..controllers.myriapod import compiled as CC
from ..controllers.myriapod.controller import MyriapodController


def unsupported_reason(body, controller, steps_per_tick: int, act) -> str | None:
    """Why this body and controller run on the Python path (None: ``FusedLeggedWalk`` runs them)."""
    if type(body) not in BODY_KERNELS:
        return f"body {type(body).__name__} has no fused legged path"
    if type(controller) is not MyriapodController:
        return f"controller {type(controller).__name__} has no compiled step"
    if steps_per_tick != 1:
        return "the controller ticks slower than every step"
    if act.muscles_on:
        return "muscle actuation of the links is not fused"
    return CC.unsupported_reason(controller)


# The timeline rows are copied element-wise, not as rec[n] = a: an array assigned to a slice compiles numba's
# shape-mismatch message (string formatting, seconds of compile per process; README Development notes).
@njit(cache=True, error_model="numpy", inline="always")
def _copy_rows(a, out):
    """out[i, k] = a[i, k] for a, out (n, 3)."""
    for i in range(a.shape[0]):
        out[i, 0], out[i, 1], out[i, 2] = a[i, 0], a[i, 1], a[i, 2]


@njit(cache=True, error_model="numpy", inline="always")
def _copy_frames(R, out):
    """out[i] = R[i] for R, out (n, 3, 3)."""
    for i in range(R.shape[0]):
        for r in range(3):
            out[i, r, 0], out[i, r, 1], out[i, r, 2] = R[i, r, 0], R[i, r, 1], R[i, r, 2]


@njit(cache=True, error_model="numpy", inline="always")
def _place_attached(fixed, att_body, att_local, c, q, vr, w, Rb, x, v):
    """``hybrid.kernels.place_attached_nodes`` without its coupling residual: x[fixed], v[fixed] (the same
    doubles) and Rb (n_seg, 3, 3), the boxes' rotations.  The support's residual (the Python path's
    ``apply_support`` computes it) is never read: the body's step overwrites it before its statistics, so the
    fused support skips it and the copy of the positions it is measured from."""
    rk.quat_to_matrix(q, Rb)
    for a in range(fixed.shape[0]):
        K.place_on_box(a, att_body[a], fixed[a], att_local, c, vr, w, Rb, x, v)


# _control and _control_and_support are inlined into the chunks (numba IR inlining): as kernels of their own, numba
# would optimize and emit the whole controller's machine code once per layer (each compiled function links its
# callees' code and compiles it again), about 10 s of a cold start (README Development notes).
@njit(cache=True, error_model="numpy", inline="always")
def _control(t, C, c, R, REC, n_rec):
    """Step 2 of the module docstring on the segment poses c (n_seg, 3) [m], R (n_seg, 3, 3) for the step
    starting at t [s], and the controller's half of step 4 (row n_rec of REC); returns whether recorded.

    C = (fs, ints, A, rnd, ant_rnd, err_scratch): the controller (``compiled.controller_step``).
    REC: the timeline buffers (``hybrid_chunk``).
    """
    fs, ints, A, rnd, ant_rnd, err_scratch = C
    rec_t, rec_states, rec_tips, rec_brain, rec_contact, rec_centres, rec_c, rec_R, rec_links = REC
    states, tips, contact = A[CC.A_STATES], A[CC.A_TIPS], A[CC.A_CONTACT]
    recorded = CC.controller_step(c, R, t, fs, ints, A, rnd, ant_rnd, err_scratch)
    if recorded:
        rec_t[n_rec] = t
        for j in range(states.shape[0]):
            rec_states[n_rec, j] = states[j]
            for a in range(3):
                rec_tips[n_rec, j, a] = tips[j, a]
        rec_brain[n_rec] = ints[CC.I_BRAIN]
        rec_contact[n_rec, 0] = ints[CC.I_HAS_ANTENNAE] != 0 and contact[0]
        rec_contact[n_rec, 1] = ints[CC.I_HAS_ANTENNAE] != 0 and contact[1]
        _copy_rows(c, rec_centres[n_rec])
    return recorded


@njit(cache=True, error_model="numpy", inline="always")
def _control_and_support(t, C, c, q, vr, w, kinematic, x, v, fixed, att_body, att_local, Rb, dt, S, REC, n_rec):
    """Steps 1-4 of the module docstring on a body of rigid boxes for the step starting at t [s]; returns
    the rows recorded so far.

    C: the controller (``_control``).  c, q, vr, w, kinematic: the boxes (``rigid_kernels``), UPDATED by
    the support; x, v (n_nodes, 3): the link nodes, attached rows UPDATED; fixed, att_body, att_local: the
    attachment; Rb (n_seg, 3, 3): scratch the body shares (``_place_attached``).  S = (held (n_seg,) bool,
    link_nodes (n_links, m), Rseg (n_seg, 3, 3), qtmp (4,)).  REC: the timeline buffers (``hybrid_chunk``).
    """
    A = C[2]
    held, link_nodes, Rseg, qtmp = S
    rec_c, rec_R, rec_links = REC[6], REC[7], REC[8]
    seg_kin, c_T, R_T = A[CC.A_KINEMATIC], A[CC.A_C_T], A[CC.A_R_T]
    n_seg = c.shape[0]
    # 1. sense
    rk.quat_to_matrix(q, Rseg)
    # 2. controller
    recorded = _control(t, C, c, Rseg, REC, n_rec)
    # 3. support (the bodies' set_support); q has not changed since the sense, so Rseg is R
    for i in range(n_seg):
        kinematic[i] = seg_kin[i] or held[i]
    drive_to_targets(c, q, vr, w, Rseg, kinematic, c_T, R_T, dt, qtmp)
    _place_attached(fixed, att_body, att_local, c, q, vr, w, Rb, x, v)
    # 4. the monitor's sample: poses after the support, link centres as the mean of their nodes
    if recorded:
        _copy_rows(c, rec_c[n_rec])
        _copy_frames(Rb, rec_R[n_rec])   # place_attached_nodes left the new rotations there
        n_links, per_link = link_nodes.shape[0], link_nodes.shape[1]
        for li in range(n_links):
            for a in range(3):
                s = 0.0
                for j in range(per_link):
                    s += x[link_nodes[li, j], a]
                rec_links[n_rec, li, a] = s / per_link
        n_rec += 1
    return n_rec


@njit(cache=True, error_model="numpy")
def hybrid_chunk(t0, n_steps, C, BA, S, REC):
    """n_steps of the module docstring's steps 1-5 on the hybrid body from t0 [s].

    C, S, REC: as ``_control_and_support``; BA: ``hybrid.kernels.advance``'s arguments without
    n_steps (``FusedLeggedWalk``).  Timeline buffers REC = (rec_t [s], rec_states (int8), rec_tips [m],
    rec_brain, rec_contact (bool, 2), rec_centres (n_seg, 3) [m] before the support, rec_c (n_seg, 3) [m],
    rec_R (n_seg, 3, 3), rec_links (n_links, 3) [m] after it), capacity n_steps // record_every + 1 rows.
    Returns (steps done, status code, rows recorded); a blow-up ends the chunk after its step.
    """
    (x, v, tets, Dm_inv, coef, muscle, mass, q_ws, F_work, H_work, inc_ptr, inc_off,
     perm, sky_first, sky_ptr, sky_L, fp_ptr, fp_col, fp_val,
     fixed, pf_ptr, pf_col, pf_val, node_link, att_body, att_local,
     c, q, vr, w, rmass, inertia_body, half_extents, kinematic, impulse_cache,
     gravity, terr_kind, terr, fric_model, fric, phys,
     f_work, b_work, f_att, x_att, x_pred_adv, residual, spine, force, torque, Rb,
     R, Iw, corner_of, lin, ang, resp, kn, kt, target, lam, acc) = BA
    dt = phys[K.DT]
    # np.int64, not the literals 0 and 1: a Literal[int] argument compiles a second signature of the callee
    n_rec, one_step = np.int64(0), np.int64(1)
    for k in range(n_steps):
        n_rec = _control_and_support(t0 + k * dt, C, c, q, vr, w, kinematic, x, v, fixed, att_body, att_local, Rb,
                                     dt, S, REC, n_rec)
        done, status = K.advance(x, v, tets, Dm_inv, coef, muscle, mass, q_ws, F_work, H_work, inc_ptr, inc_off,
                                 perm, sky_first, sky_ptr, sky_L, fp_ptr, fp_col, fp_val,
                                 fixed, pf_ptr, pf_col, pf_val, node_link, att_body, att_local,
                                 c, q, vr, w, rmass, inertia_body, half_extents, kinematic, impulse_cache,
                                 gravity, terr_kind, terr, fric_model, fric, phys, one_step,
                                 f_work, b_work, f_att, x_att, x_pred_adv, residual, spine, force, torque, Rb,
                                 R, Iw, corner_of, lin, ang, resp, kn, kt, target, lam, acc)
        if status != K.OK:
            CC.finish_chunk(C[0], C[1], C[2])
            return k + 1, status, n_rec
    CC.finish_chunk(C[0], C[1], C[2])
    return n_steps, K.OK, n_rec


@njit(cache=True, error_model="numpy")
def massspring_chunk(t0, n_steps, C, BA, S, REC):
    """``hybrid_chunk`` on the legged mass-spring body (``massspring.myriapod.advance_chain``'s arguments
    without n_steps in BA)."""
    (x, v, mass, free, fixed, att_body, att_local, node_link, springs, stiffness, damping, rest,
     c, q, vr, w, rmass, inertia_body, half_extents, kinematic, impulse_cache,
     gravity, terr_kind, terr, fric_model, fric, phys,
     f_work, f_att, x_att, x_pred_adv, residual, spine, force, torque, Rb,
     R, Iw, corner_of, lin, ang, resp, kn, kt, target, lam, acc) = BA
    dt = phys[K.DT]
    # np.int64, not the literals 0 and 1: a Literal[int] argument compiles a second signature of the callee
    n_rec, one_step = np.int64(0), np.int64(1)
    for k in range(n_steps):
        n_rec = _control_and_support(t0 + k * dt, C, c, q, vr, w, kinematic, x, v, fixed, att_body, att_local, Rb,
                                     dt, S, REC, n_rec)
        done, status = MS.advance_chain(x, v, mass, free, fixed, att_body, att_local, node_link, springs, stiffness,
                                        damping, rest, c, q, vr, w, rmass, inertia_body, half_extents, kinematic,
                                        impulse_cache, gravity, terr_kind, terr, fric_model, fric, phys, one_step,
                                        f_work, f_att, x_att, x_pred_adv, residual, spine, force, torque, Rb,
                                        R, Iw, corner_of, lin, ang, resp, kn, kt, target, lam, acc)
        if status != K.OK:
            CC.finish_chunk(C[0], C[1], C[2])
            return k + 1, status, n_rec
    CC.finish_chunk(C[0], C[1], C[2])
    return n_steps, K.OK, n_rec


@njit(cache=True, error_model="numpy")
def fem_chunk(t0, n_steps, C, BA, S, REC):
    """``hybrid_chunk`` on the legged FEM body (``fem.myriapod.advance_chain``'s arguments without n_steps
    in BA; S = (held (n_seg,) bool, block_nodes, rest_offsets, cseg (n_seg, 3), A_scratch, Rseg (n_seg, 3, 3))).

    Sense: the blocks' best-fit poses (``fem.myriapod.block_poses``).  Support (``BodyFEMChain.set_support``):
    support = kinematic | held; every leg-attachment node of a supported, not held block gets the target
    x_T = c_T + R_T R^T (x_p - c), its current offset transported rigidly, which the body's implicit
    penalty pulls it to during its step.  The nodes do not move before the step, so the monitor's poses
    are the sensed ones, and a link's centre is the mean of its two blocks' centroids.
    """
    (x, v, mass, tets, inc_ptr, inc_off, coef, q_ws, F_work, H_work,
     perm, sky_first, sky_ptr, sky_L, fp_ptr, fp_col, fp_val,
     block_nodes, node_spine, att_nodes, att_block, att_target, support,
     gravity, terr_kind, terr, fric_model, fric, phys,
     f_work, b_work, cent, spine, acc) = BA
    held, block_nodes_s, rest_offsets, cseg, A_scr, Rseg = S
    A = C[2]
    seg_kin, c_T, R_T = A[CC.A_KINEMATIC], A[CC.A_C_T], A[CC.A_R_T]
    rec_c, rec_R, rec_links = REC[6], REC[7], REC[8]
    dt = phys[FM.DT]
    n_seg = cseg.shape[0]
    # np.int64, not the literals 0 and 1: a Literal[int] argument compiles a second signature of the callee
    n_rec, one_step = np.int64(0), np.int64(1)
    for k in range(n_steps):
        FM.block_poses(x, block_nodes_s, rest_offsets, cseg, A_scr, Rseg)
        recorded = _control(t0 + k * dt, C, cseg, Rseg, REC, n_rec)
        for i in range(n_seg):
            support[i] = seg_kin[i] or held[i]
        for e in range(att_nodes.shape[0]):
            b = att_block[e]
            if not seg_kin[b] or held[b]:
                continue
            p = att_nodes[e]
            d0, d1, d2 = x[p, 0] - cseg[b, 0], x[p, 1] - cseg[b, 1], x[p, 2] - cseg[b, 2]
            r0 = Rseg[b, 0, 0] * d0 + Rseg[b, 1, 0] * d1 + Rseg[b, 2, 0] * d2
            r1 = Rseg[b, 0, 1] * d0 + Rseg[b, 1, 1] * d1 + Rseg[b, 2, 1] * d2
            r2 = Rseg[b, 0, 2] * d0 + Rseg[b, 1, 2] * d1 + Rseg[b, 2, 2] * d2
            # numpy's einsum "nij,nj->ni" (the Python path) adds the three products as (j=0 + j=2) + j=1 and
            # "nji,nj->ni" above in order (checked on this numpy by tests/test_fused_walk.py): kept so, bit for bit
            for i in range(3):
                att_target[e, i] = c_T[b, i] + ((R_T[b, i, 0] * r0 + R_T[b, i, 2] * r2) + R_T[b, i, 1] * r1)
        if recorded:
            _copy_rows(cseg, rec_c[n_rec])
            _copy_frames(Rseg, rec_R[n_rec])
            for li in range(n_seg - 1):
                for i in range(3):
                    rec_links[n_rec, li, i] = 0.5 * (cseg[li, i] + cseg[li + 1, i])
            n_rec += 1
        done, status = FM.advance_chain(x, v, mass, tets, inc_ptr, inc_off, coef, q_ws, F_work, H_work,
                                        perm, sky_first, sky_ptr, sky_L, fp_ptr, fp_col, fp_val,
                                        block_nodes, node_spine, att_nodes, att_block, att_target, support,
                                        gravity, terr_kind, terr, fric_model, fric, phys, one_step,
                                        f_work, b_work, cent, spine, acc)
        if status != K.OK:
            CC.finish_chunk(C[0], C[1], C[2])
            return k + 1, status, n_rec
    CC.finish_chunk(C[0], C[1], C[2])
    return n_steps, K.OK, n_rec


def _fem_args(b: BodyFEMChain) -> tuple:
    """``fem.myriapod.advance_chain``'s arguments but n_steps, as ``BodyFEMChain.advance`` passes them."""
    f, s = b.fem, b.solver
    return (b.x, b.v, f.mass, f.tets, f._inc_ptr, f._inc_off, f.coef, f._q_ws, f._F_work, f._H_work,
            s.perm, s.sky_first, s.sky_ptr, s.sky_L, s.fp_ptr, s.fp_col, s.fp_val,
            b.block_nodes, b.node_spine, b.att_nodes, b.att_block, b.att_target, b.support,
            b.gravity, b.terr_kind, b.terr, b.fric_model, b.fric, b.phys,
            b._f_work, b._b_work, b._cent, b._spine, b.acc)


def _hybrid_args(b: BodyHybrid) -> tuple:
    """``hybrid.kernels.advance``'s arguments but n_steps, as ``BodyHybrid.advance`` passes them (no muscles)."""
    fem, s, rb, sc = b.fem, b.solver, b.rigid, b.scratch
    b.phys[K.MUSCLES_ON] = 0.0
    return (fem.x, fem.v, fem.tets, fem.Dm_inv_eff, fem.coef, b._muscle_static + (b._no_muscle,),
            fem.mass, fem._q_ws, fem._F_work, fem._H_work, fem._inc_ptr, fem._inc_off,
            s.perm, s.sky_first, s.sky_ptr, s.sky_L, s.fp_ptr, s.fp_col, s.fp_val,
            s.fixed, s.pf_ptr, s.pf_col, s.pf_val, b.node_link, b.att_body, b.att_local,
            rb.c, rb.q, rb.v, rb.w, rb.mass, rb.inertia_body, rb.half_extents, rb.kinematic,
            rb.impulse_cache, b.gravity, b.terr_kind, b.terr, b.fric_model, b.fric, b.phys,
            b._f_work, b._b_work, sc.f_att, sc.x_att, sc.x_pred, sc.residual, sc.spine, rb.force, rb.torque,
            sc.Rb, sc.R, sc.Iw, sc.corner_of, sc.lin, sc.ang, sc.resp, sc.kn, sc.kt, sc.target, sc.lam, b.acc)


def _massspring_args(b: BodyRigidSpringChain) -> tuple:
    """``massspring.myriapod.advance_chain``'s arguments but n_steps, as ``BodyRigidSpringChain.advance``."""
    rb, sc = b.rigid, b.scratch
    return (b.x, b.v, b.mass, b.free, b.fixed, b.att_body, b.att_local, b.mesh.node_link, b.springs, b.stiffness,
            b.damping, b.rest, rb.c, rb.q, rb.v, rb.w, rb.mass, rb.inertia_body, rb.half_extents, rb.kinematic,
            rb.impulse_cache, b.gravity, b.terr_kind, b.terr, b.fric_model, b.fric, b.phys,
            b._f_work, sc.f_att, sc.x_att, sc.x_pred, sc.residual, sc.spine, rb.force, rb.torque, sc.Rb, sc.R, sc.Iw,
            sc.corner_of, sc.lin, sc.ang, sc.resp, sc.kn, sc.kt, sc.target, sc.lam, b.acc)


# body class -> (chunk kernel, its body arguments)
BODY_KERNELS = {BodyHybrid: (hybrid_chunk, _hybrid_args), BodyRigidSpringChain: (massspring_chunk, _massspring_args),
                BodyFEMChain: (fem_chunk, _fem_args)}


class FusedLeggedWalk:
    """``advance(t0, n) -> (steps done, status)`` of a legged body and its leg controller in one compiled call.

    ``act`` is the stepper's actuation: its support fields are left as the Python path leaves them
    (the last step's support, already taken by the body).  ``monitor``: the run's ``LeggedMonitor``
    or None.
    """

    def __init__(self, body, controller: MyriapodController, act, monitor=None):
        self.body, self.controller, self.act, self.monitor = body, controller, act, monitor
        self._kernel, self._args = BODY_KERNELS[type(body)]
        self.cs = CC.ControllerState(controller)
        n_seg, n_legs = controller.n_seg, controller.n_legs
        self.err_scratch = np.zeros(n_seg)
        self.Rseg = np.zeros((n_seg, 3, 3))
        if type(body) is BodyFEMChain:  # the blocks' poses are sensed from the nodes every step
            self.S = (body._held, body.block_nodes, body.rest_offsets, np.zeros((n_seg, 3)), np.zeros((n_seg, 3, 3)),
                      self.Rseg)
        else:
            self.S = (body._held, np.ascontiguousarray(body.mesh.link_nodes, dtype=np.int64), self.Rseg, np.zeros(4))
        self._alloc(1, n_seg, n_legs)

    def _alloc(self, rows: int, n_seg: int, n_legs: int) -> None:
        self.rec_t = np.zeros(rows)
        self.rec_states = np.zeros((rows, n_legs), np.int8)
        self.rec_tips = np.zeros((rows, n_legs, 3))
        self.rec_brain = np.zeros(rows, np.int64)
        self.rec_contact = np.zeros((rows, 2), np.bool_)
        self.rec_centres = np.zeros((rows, n_seg, 3))
        self.rec_c = np.zeros((rows, n_seg, 3))
        self.rec_R = np.zeros((rows, n_seg, 3, 3))
        self.rec_links = np.zeros((rows, n_seg - 1, 3))

    def advance(self, t0: float, n: int) -> tuple[int, int]:
        ctrl, cs = self.controller, self.cs
        rows = n // ctrl.record_every + 1
        if self.rec_t.shape[0] < rows:
            self._alloc(rows, ctrl.n_seg, ctrl.n_legs)
        A = cs.pack()
        cs.draws(n)
        C = (cs.fs, cs.ints, A, cs.rnd, cs.ant_rnd, self.err_scratch)
        REC = (self.rec_t, self.rec_states, self.rec_tips, self.rec_brain, self.rec_contact, self.rec_centres,
               self.rec_c, self.rec_R, self.rec_links)
        k, code, n_rec = self._kernel(float(t0), int(n), C, self._args(self.body), self.S, REC)
        cs.unpack()
        cs.settle()
        self._replay(int(n_rec))
        if k > 0:  # the last step's support, as the Python path's actuation holds it
            act = self.act
            act.support_kinematic[:] = ctrl.kinematic
            act.support_c[:] = ctrl.c_T
            act.support_R[:] = ctrl.R_T
            act.support_new = False
        return int(k), int(code)

    def compile(self) -> None:
        """Compile (or load from the numba cache) the chunk kernel: a chunk of zero steps changes nothing."""
        self.advance(0.0, 0)

    def _replay(self, n_rec: int) -> None:
        """The chunk's timeline samples into the controller's lists and the monitor (as ``step`` and
        ``LeggedMonitor.after_control`` append them).  Each buffer's rows are copied once per chunk and
        the lists get row views of that copy (the Python path appends a copy per row: the same values),
        and the monitor takes the chunk's samples in one ``sample_many`` call: a chunk's replay no
        longer costs Python work per sample (a fixed cost per step that made small bodies slow)."""
        if n_rec == 0:
            return
        ctrl, mon = self.controller, self.monitor
        n_seg = ctrl.n_seg
        tips = self.rec_tips[:n_rec].copy()
        rec_c = self.rec_c[:n_rec]
        ctrl.timeline_t.extend(self.rec_t[:n_rec].tolist())
        ctrl.timeline_states.extend(self.rec_states[:n_rec].copy())
        ctrl.timeline_tips.extend(tips)
        ctrl.timeline_brain.extend(self.rec_brain[:n_rec].tolist())
        ctrl.timeline_contact.extend(self.rec_contact[:n_rec].copy())
        ctrl.timeline_centers.extend(self.rec_centres[:n_rec].copy())
        if mon is not None:
            centres = np.empty((n_rec, 2 * n_seg - 1, 3))
            centres[:, 0::2] = rec_c
            centres[:, 1::2] = self.rec_links[:n_rec]
            mon.sample_many(rec_c, self.rec_R[:n_rec], centres, tips)
