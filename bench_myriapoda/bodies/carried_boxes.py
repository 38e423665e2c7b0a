"""The legs' hold on a chain of rigid boxes joined by links: the fused legged walk's poses, support
and sample (``legged_chunk``) for the hybrid and the legged mass-spring bodies.

Both bodies carry their supported boxes the same way (their ``set_support``): kinematic =
supported | held, the kinematic boxes driven to their targets (``kinematic_targets.drive_to_targets``,
paper Sec. 4.1), the attached link nodes put back on the boxes (``rigid_chain.place_on_box``,
the arithmetic of ``place_attached_nodes`` without its coupling residual, which the body's step
overwrites before reading it, so the fused support skips it).  Only their step differs, so each
body's pack is ``(boxes, step arguments)`` with ``boxes`` a ``CarriedBoxes``.

In dynamic stance (``legs.stance = "dynamic"``, ``bodies.dynamic_stance``) no supported box is kinematic:
``carry_dynamic`` gives each the impulse of its STANCE legs' friction-limited push instead, and only a held
box is still carried.  Both bodies' ``push_support`` (the Python path, ``legged_chunk.LeggedPackOps``) and the fused
path run it through ``carry_boxes_feet``.
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np
from numba import njit

from . import rigid_kernels as rk
from .rigid_chain import place_on_box
from .dynamic_stance import push_segments, stance_arrays, stance_params, stance_statistics
from .kinematic_targets import drive_to_targets
from .legged_chunk import copy_frames, copy_rows

# c, q, vr, w, kinematic: the boxes (``rigid.RigidBoxes``); held (n_seg,) bool: boxes held whatever the
# controller asks (the suspended head); x, v (n_nodes, 3): the link nodes; fixed, att_body, att_local: the
# attachment; link_nodes (n_links, m) int64: each link's nodes; Rseg, Rb (n_seg, 3, 3): the rotations before
# and after the support (scratch; Rb is the body's own, which its step overwrites); qtmp (4,) scratch;
# dt [s] the time step; stance: the dynamic stance's ``dynamic_stance.StanceArrays`` (its params.dynamic 0: the
# paper's kinematic stance).
CarriedBoxes = namedtuple("CarriedBoxes", "c q vr w kinematic held x v fixed att_body att_local link_nodes "
                                          "Rseg Rb qtmp dt stance")


def box_chain_centers(box_c: np.ndarray, x: np.ndarray, link_nodes: np.ndarray) -> np.ndarray:
    """(2 n_boxes - 1, 3) [m]: box 0, link 0, box 1, ..., box n-1 -- the box centres box_c (n_boxes, 3) and each
    link's node mean (x (n_nodes, 3) [m] at link_nodes (n_boxes - 1, m)); a body's ``segment_centers``."""
    out = np.empty((2 * len(box_c) - 1, 3))
    out[0::2] = box_c
    out[1::2] = x[link_nodes].mean(axis=1)
    return out


def carried_boxes(rb, held, x, v, fixed, att_body, att_local, link_nodes, Rb, qtmp, dt, stance) -> CarriedBoxes:
    """The pack of a body's boxes ``rb`` (``rigid.RigidBoxes``) and its links (module docstring); stance its
    ``dynamic_stance.StanceArrays``."""
    return CarriedBoxes(rb.c, rb.q, rb.v, rb.w, rb.kinematic, held, x, v, fixed, att_body, att_local,
                        np.ascontiguousarray(link_nodes, dtype=np.int64), np.zeros((len(rb.c), 3, 3)), Rb, qtmp,
                        float(dt), stance)


@njit(cache=True, error_model="numpy", inline="always")
def box_poses(P):
    """``legged_chunk.poses`` of a pack P whose ``boxes`` are a ``CarriedBoxes`` B: the box centres and their
    rotations (from the quaternions, into B.Rseg)."""
    B = P.boxes
    rk.quat_to_matrix(B.q, B.Rseg)
    return B.c, B.Rseg


@njit(cache=True, error_model="numpy", inline="always")
def carry_boxes(P, kinematic, c_T, R_T):
    """``legged_chunk.carry`` (module docstring) of P.boxes, after ``box_poses`` (B.Rseg holds the rotations:
    q has not changed since)."""
    B = P.boxes
    for i in range(B.c.shape[0]):
        B.kinematic[i] = kinematic[i] or B.held[i]
    drive_to_targets(B.c, B.q, B.vr, B.w, B.Rseg, B.kinematic, c_T, R_T, B.dt, B.qtmp)
    rk.quat_to_matrix(B.q, B.Rb)
    for a in range(B.fixed.shape[0]):
        place_on_box(a, B.att_body[a], B.fixed[a], B.att_local, B.c, B.vr, B.w, B.Rb, B.x, B.v)


@njit(cache=True, error_model="numpy", inline="always")
def carry_boxes_feet(P, kinematic, c_T, R_T, states, tips):
    """``legged_chunk.carry_feet`` of P.boxes: ``carry_dynamic`` in dynamic stance (returns True: feet may have
    moved), else ``carry_boxes`` (False)."""
    B = P.boxes
    if B.stance.params.dynamic != 0.0:
        carry_dynamic(B, kinematic, c_T, R_T, states, tips)
        return True
    carry_boxes(P, kinematic, c_T, R_T)
    return False


@njit(cache=True, error_model="numpy")
def carry_dynamic(B, supported, c_T, R_T, states, tips):
    """The dynamic stance's support of the boxes of the ``CarriedBoxes`` B: held boxes carried to their
    targets (as in the kinematic stance), every other ``supported`` (n_seg,) bool box pushed by its STANCE
    legs (``dynamic_stance.push_segments``: velocities UPDATED, feet tips (n_legs, 3) [m] UPDATED where they
    slide; states (n_legs,) the leg states), then the attached link nodes put on the boxes with their new
    velocities.  c_T (n_seg, 3) [m], R_T (n_seg, 3, 3): the Targeter's targets."""
    rk.quat_to_matrix(B.q, B.Rseg)
    for i in range(B.c.shape[0]):
        B.kinematic[i] = B.held[i]
    drive_to_targets(B.c, B.q, B.vr, B.w, B.Rseg, B.kinematic, c_T, R_T, B.dt, B.qtmp)
    push_segments(B.c, B.vr, B.w, B.Rseg, supported, B.held, c_T, R_T, states, tips, B.stance, B.dt)
    rk.quat_to_matrix(B.q, B.Rb)
    for a in range(B.fixed.shape[0]):
        place_on_box(a, B.att_body[a], B.fixed[a], B.att_local, B.c, B.vr, B.w, B.Rb, B.x, B.v)


@njit(cache=True, error_model="numpy", inline="always")
def sample_boxes(P, c_out, R_out, links_out):
    """``legged_chunk.sample`` of P.boxes after ``carry_boxes``: the boxes' poses, and each link's centre as
    the mean of its nodes."""
    B = P.boxes
    copy_rows(B.c, c_out)
    copy_frames(B.Rb, R_out)   # carry_boxes left the new rotations there
    link_nodes = B.link_nodes
    n_links, per_link = link_nodes.shape[0], link_nodes.shape[1]
    for li in range(n_links):
        for a in range(3):
            s = 0.0
            for j in range(per_link):
                s += B.x[link_nodes[li, j], a]
            links_out[li, a] = s / per_link


class PushedBoxes:
    """The dynamic stance of a body whose segments are rigid boxes (``rigid.RigidBoxes`` ``self.rigid``), a
    mixin of the hybrid and the legged mass-spring bodies.  The body sets, before ``_setup_stance``:
    ``rigid``, ``gravity`` (3,) [m/s^2], ``terr_kind``, ``terr``, ``_held`` (n_seg,) bool; its ``push_support``
    is ``legged_chunk.LeggedPackOps``'s (``carry_boxes_feet`` -> ``carry_dynamic`` on its pack)."""

    dynamic_stance = False

    def _setup_stance(self, case) -> None:
        """``self.stance`` (``dynamic_stance.StanceArrays``) and ``self.dynamic_stance`` from the case's legs."""
        params = stance_params(case.legs, case.friction)
        self.dynamic_stance = params.dynamic != 0.0 and bool(case.creature.legs_per_segment)
        rb = self.rigid
        self.stance = stance_arrays(params, rb.mass, rb.inertia_body, self.gravity, rb.force, rb.torque,
                                    self.terr_kind, self.terr)

    def stance_statistics(self) -> dict[str, float]:
        """The dynamic stance's statistics of the run so far (``dynamic_stance.ACC_*``; empty in kinematic
        stance): foot-steps, slid foot-steps, summed slip [m], mean and largest foot force [N], positive leg
        work [J]."""
        if not self.dynamic_stance:
            return {}
        return stance_statistics(self.stance.acc)
