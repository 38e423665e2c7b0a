"""A fourth body model WITH LEGS, defined in this one file and added with one table row at run time (issue 42,
item 4), as ``tests/test_fourth_body.py`` adds a legless one.

``jointedboxes``: one rigid box per segment (the creature's segment size, mass ``creature.mass_kg / segments``,
the inertia of a solid box), each carrying its pair of legs, and neighbouring boxes joined by a stiff 6-DOF
spring-damper at their shared end.  Box i reaches ``link_length_m / 2`` beyond its back face (a rigid, massless
strut: the segment's end), box i + 1 as far beyond its front face, so the two segments' ends meet in the middle
of the gap; there four zero-length springs with dampers join the corners of the two ends' cross-sections (a
bushing: the four pairs resist every relative translation and rotation, so 6 DOF, f = k (p_b - p_a) + c (v_b -
v_a)).  Each pair's force acts on both boxes at the pair's midpoint, so the joints cancel in the total linear
AND angular momentum.  The boxes move by the suite's rigid-body kernels (``rigid_kernels.advance``: gravity, the
corners' terrain contact with Coulomb friction, the position projection), the supported ones are carried to the
leg controller's targets as the paper's kinematic legs carry the other bodies' segments
(``kinematic_targets.drive_to_targets``, Sec. 4.1), and the fused legged walk drives it through a pack registered
with ``legged_chunk.register``: its poses, support, sample and step are the same compiled kernels the Python
methods call, so the two paths give the same doubles (``test_the_fused_walk_equals_the_python_walk_bit_for_bit``).

It declares everything the suite asks of a body model in one ``BodySpec`` (``BODIES`` below), read by the
catalog as a plugin (``BENCH_MYRIAPODA_PLUGINS=test_fourth_body_legged``); no creature file and no module of the
package names it: the centipede (and the millipede) run on it through ``run``, ``matrix``, the fused path and
``validate --quick``.  The one package change a legged plugin needed is generic: the fused walk compiles a pack
class from outside the package into a copy of its chunk kernel with a numba cache index of its own
(``fused.legged_walk.chunk_kernel`` says why: in the package kernel's index this module's class broke every later
legged run of a process that cannot import it).
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from collections import namedtuple
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from numba import njit

from bench_myriapoda.bodies import rigid_kernels as rk
from bench_myriapoda.bodies import step_status as S
from bench_myriapoda.bodies.friction_kernels import CONTACT_DISTANCE, FRICTION_CAPABILITIES, friction_params
from bench_myriapoda.bodies.kinematic_targets import drive_to_targets
from bench_myriapoda.bodies.legged_chunk import copy_frames, copy_rows, register
from bench_myriapoda.bodies.placement import place_box_chain
from bench_myriapoda.bodies.rigid import ContactSettings, RigidBoxes
from bench_myriapoda.bodies.scene import RIGID_BOX, Scene, box_triangles
from bench_myriapoda.bodies.segment_chain import LeggedSegments, check_chain_segments, check_legged_gait
from bench_myriapoda.core import registry
from bench_myriapoda.core.errors import InputError
from bench_myriapoda.core.feasibility import lattice_footprint
from bench_myriapoda.core.kernel_records import plain
from bench_myriapoda.core.protocols import LEGS, SEGMENTS, Actuation, Observation
from bench_myriapoda.core.schema import rng
from bench_myriapoda.core.specs import BodySpec
from bench_myriapoda.world.terrain_kernels import signed_distance

NAME = "jointedboxes"
MODULE = "test_fourth_body_legged"  # this file as the plugin module (pytest puts tests/ on sys.path)
ROOT = Path(__file__).resolve().parents[1]
DERIVED = -1.0


@dataclass(frozen=True)
class JointedBoxesConfig:
    """Keys of ``[bodies.jointedboxes]`` (a creature file may name none: ``BodySpec.default_params``)."""

    name: str = rng(NAME)
    link_length_m: float = rng(DERIVED, doc="gap between neighbouring boxes [m], their joint in its middle; "
                                            "-1: half a segment, the hybrid's and massspring's link length")
    joint_hz: float = rng(40.0, gt=0.0, doc="natural frequency of two neighbouring boxes' relative translation on "
                                            "their joint [Hz] (sets the corner springs' stiffness)")
    joint_damping_ratio: float = rng(0.5, ge=0.0, doc="damping of that translation, a fraction of its critical "
                                                      "damping")
    friction_mu: float = rng(DERIVED, doc="Coulomb friction of the box corners [-]; -1: the creature's "
                                          "friction.mu_transverse")
    dt_s: float = rng(1.0 / 3000.0, gt=0.0, doc="default time step [s] (the hybrid centipede's)")


# --------------------------------------------------------------------------- the kernels

# phys vector: the step's scalars
DT, K_JOINT, C_JOINT, MAX_SPEED, MAX_PEN, CONTACT_DIST = range(6)
N_PHYS = 6

# The body's arrays, one named record (numba compiles it as a struct of its fields): boxes, the ``rigid_kernels.
# BoxArrays`` of the boxes as a plain tuple (c, q, v, w (n, 3)/(n, 4) UPDATED); contact, ``ContactParams`` as a
# plain tuple; kinematic (n,) bool, held (n,) bool (the suspended head); end_back (4, 3), end_front (4, 3) [m]
# the joint's corner points in the frame of the box ahead (its back end) and behind (its front end); gravity (3,)
# [m/s^2]; terr_kind, terr (``terrain_kernels``); phys (N_PHYS,); acc (``step_status``'s N_ACC) ACCUMULATES;
# Rb (n, 3, 3), qtmp (4,) scratch.
Jointed = namedtuple("Jointed", "boxes contact kinematic held end_back end_front gravity terr_kind terr phys acc "
                                "Rb qtmp")


@njit(cache=True, error_model="numpy", inline="always")
def _corner_point(c, R, i, end, k):
    """World position [m] of corner k of end (4, 3) (body-frame points) of box i (c (n, 3), R (n, 3, 3))."""
    lx, ly, lz = end[k, 0], end[k, 1], end[k, 2]
    return (c[i, 0] + R[i, 0, 0] * lx + R[i, 0, 1] * ly + R[i, 0, 2] * lz,
            c[i, 1] + R[i, 1, 0] * lx + R[i, 1, 1] * ly + R[i, 1, 2] * lz,
            c[i, 2] + R[i, 2, 0] * lx + R[i, 2, 1] * ly + R[i, 2, 2] * lz)


@njit(cache=True, error_model="numpy")
def joint_centres(c, R, end_back, end_front, out):
    """OVERWRITE out (n - 1, 3) [m]: each joint's centre, the mean of its four corner pairs' midpoints."""
    for j in range(c.shape[0] - 1):
        sx = sy = sz = 0.0
        for k in range(4):
            ax, ay, az = _corner_point(c, R, j, end_back, k)
            bx, by, bz = _corner_point(c, R, j + 1, end_front, k)
            sx += 0.5 * (ax + bx)
            sy += 0.5 * (ay + by)
            sz += 0.5 * (az + bz)
        out[j, 0], out[j, 1], out[j, 2] = 0.25 * sx, 0.25 * sy, 0.25 * sz


@njit(cache=True, error_model="numpy", inline="always")
def _load(i, s, fx, fy, fz, mx, my, mz, c, force, torque):
    """Add s (fx, fy, fz) [N] at the world point (mx, my, mz) [m] to box i's force and torque about its centre."""
    px, py, pz = mx - c[i, 0], my - c[i, 1], mz - c[i, 2]
    force[i, 0] += s * fx
    force[i, 1] += s * fy
    force[i, 2] += s * fz
    torque[i, 0] += s * (py * fz - pz * fy)
    torque[i, 1] += s * (pz * fx - px * fz)
    torque[i, 2] += s * (px * fy - py * fx)


@njit(cache=True, error_model="numpy")
def joint_loads(c, v, w, R, end_back, end_front, k, damping, force, torque):
    """OVERWRITE force, torque (n, 3) [N], [N m] with the joints' loads on the boxes (about their centres).

    Corner pair (a on box j, b on box j + 1): f = k (p_b - p_a) + damping (v_b - v_a) on box j, -f on box j + 1,
    both at the pair's midpoint, so the pair's torques about any point cancel: the joints change neither the
    total linear nor the total angular momentum."""
    force[:, :] = 0.0
    torque[:, :] = 0.0
    for j in range(c.shape[0] - 1):
        for kk in range(4):
            ax, ay, az = _corner_point(c, R, j, end_back, kk)
            bx, by, bz = _corner_point(c, R, j + 1, end_front, kk)
            # point velocities v + w x r (Baraff 1997 I, Sec. 2.5)
            rax, ray, raz = ax - c[j, 0], ay - c[j, 1], az - c[j, 2]
            rbx, rby, rbz = bx - c[j + 1, 0], by - c[j + 1, 1], bz - c[j + 1, 2]
            vax = v[j, 0] + w[j, 1] * raz - w[j, 2] * ray
            vay = v[j, 1] + w[j, 2] * rax - w[j, 0] * raz
            vaz = v[j, 2] + w[j, 0] * ray - w[j, 1] * rax
            vbx = v[j + 1, 0] + w[j + 1, 1] * rbz - w[j + 1, 2] * rby
            vby = v[j + 1, 1] + w[j + 1, 2] * rbx - w[j + 1, 0] * rbz
            vbz = v[j + 1, 2] + w[j + 1, 0] * rby - w[j + 1, 1] * rbx
            fx = k * (bx - ax) + damping * (vbx - vax)
            fy = k * (by - ay) + damping * (vby - vay)
            fz = k * (bz - az) + damping * (vbz - vaz)
            mx, my, mz = 0.5 * (ax + bx), 0.5 * (ay + by), 0.5 * (az + bz)
            _load(j, 1.0, fx, fy, fz, mx, my, mz, c, force, torque)
            _load(j + 1, -1.0, fx, fy, fz, mx, my, mz, c, force, torque)


@njit(cache=True, error_model="numpy")
def advance_jointed(record, n_steps):
    """``n_steps`` steps of the jointed boxes (``record``: a ``Jointed`` as a plain tuple, ``core.kernel_records``,
    named here); returns (steps done, ``step_status`` code).

    Each step: the joints' loads at the current state (``joint_loads``), then one step of the suite's rigid-body
    kernel (``rigid_kernels.advance``, n = 1: gravity and the loads kick, the corners' contact and Coulomb friction,
    the drift, the position projection; kinematic boxes left where the legs put them), then the corners' contact
    statistics and the deep-penetration check.  ``rigid_kernels.advance`` is the public entry: it allocates its
    contact scratch per call (a few (8, 3) arrays, about a microsecond), which this test body accepts rather than
    calling the module's private one-box step."""
    J = Jointed(*record)
    B = rk.BoxArrays(*J.boxes)
    c, q, v, w, half, force, torque = B.c, B.q, B.v, B.w, B.half_extents, B.force, B.torque
    phys, acc, Rb = J.phys, J.acc, J.Rb
    n = c.shape[0]
    n_points = 8 * n
    for step in range(n_steps):
        rk.quat_to_matrix(q, Rb)
        joint_loads(c, v, w, Rb, J.end_back, J.end_front, phys[K_JOINT], phys[C_JOINT], force, torque)
        done, status = rk.advance(J.boxes, J.kinematic, 1, phys[DT], J.gravity, J.terr_kind, J.terr, J.contact,
                                  phys[MAX_SPEED])
        rk.quat_to_matrix(q, Rb)
        touching = 0
        deepest = acc[S.ACC_MAX_PEN]
        for i in range(n):
            for corner in range(8):
                sx = half[i, 0] if corner & 1 else -half[i, 0]
                sy = half[i, 1] if corner & 2 else -half[i, 1]
                sz = half[i, 2] if corner & 4 else -half[i, 2]
                px = c[i, 0] + Rb[i, 0, 0] * sx + Rb[i, 0, 1] * sy + Rb[i, 0, 2] * sz
                py = c[i, 1] + Rb[i, 1, 0] * sx + Rb[i, 1, 1] * sy + Rb[i, 1, 2] * sz
                pz = c[i, 2] + Rb[i, 2, 0] * sx + Rb[i, 2, 1] * sy + Rb[i, 2, 2] * sz
                phi = signed_distance(J.terr_kind, J.terr, px, py, pz)
                if phi < phys[CONTACT_DIST]:
                    touching += 1
                if -phi > deepest:
                    deepest = -phi
        acc[S.ACC_MAX_PEN] = deepest
        if status == S.OK and deepest > phys[MAX_PEN]:
            status = S.DEEP_PENETRATION
        acc[S.ACC_CONTACT_SUM] += touching / n_points
        acc[S.ACC_STEPS] += 1.0
        if status != S.OK:
            return step + 1, status
    return n_steps, S.OK


@njit(cache=True, error_model="numpy")
def support_boxes(record, supported, c_T, R_T):
    """The legs' support (paper Sec. 4.1) of the jointed boxes (``record`` as ``advance_jointed``'s): kinematic =
    supported (n,) bool | held, and the kinematic boxes put at their targets c_T (n, 3) [m], R_T (n, 3, 3) with
    the velocities that take them there in one step."""
    J = Jointed(*record)
    B = rk.BoxArrays(*J.boxes)
    c, q, v, w = B.c, B.q, B.v, B.w
    rk.quat_to_matrix(q, J.Rb)
    for i in range(c.shape[0]):
        J.kinematic[i] = supported[i] or J.held[i]
    drive_to_targets(c, q, v, w, J.Rb, J.kinematic, c_T, R_T, J.phys[DT], J.qtmp)


# The fused legged walk's pack (``legged_chunk``): J the ``Jointed`` record as a plain tuple (``advance_jointed``'s);
# Rseg (n, 3, 3) scratch for the rotations it hands the controller and the monitor.
JointedLegs = namedtuple("JointedLegs", "J Rseg")


def _legs_poses(P):
    """``legged_chunk.poses``: the boxes' centres and rotations (into P.Rseg)."""
    B = rk.BoxArrays(*Jointed(*P.J).boxes)
    rk.quat_to_matrix(B.q, P.Rseg)
    return B.c, P.Rseg


def _legs_carry(P, kinematic, c_T, R_T):
    """``legged_chunk.carry``: the body's ``set_support`` (the same kernel)."""
    support_boxes(P.J, kinematic, c_T, R_T)


def _legs_sample(P, c_out, R_out, links_out):
    """``legged_chunk.sample``: the poses after the support, and the joints' centres (``segment_centers``)."""
    J = Jointed(*P.J)
    B = rk.BoxArrays(*J.boxes)
    c = B.c
    rk.quat_to_matrix(B.q, P.Rseg)
    copy_rows(c, c_out)
    copy_frames(P.Rseg, R_out)
    joint_centres(c, P.Rseg, J.end_back, J.end_front, links_out)


def _legs_step(P, world, dt):
    """``legged_chunk.step``: one step of the body's own kernel (np.int64: a literal 1 compiles a second
    signature).  The fused walk's world and dt are this body's own (its record holds them, as its ``advance``
    steps): a plugin body may keep its step's form, and the interface hands it the run's."""
    return advance_jointed(P.J, np.int64(1))


register(JointedLegs, _legs_poses, _legs_carry, _legs_sample, _legs_step)


# --------------------------------------------------------------------------- the body

def _gap(cfg, cre) -> float:
    return 0.5 * cre.segment_length_m if cfg.link_length_m == DERIVED else float(cfg.link_length_m)


class BodyJointedBoxes(LeggedSegments):
    """Rigid boxes (``self.rigid``) joined by 6-DOF corner-spring joints (module docstring); SEGMENTS and LEGS
    (``segment_chain.LeggedSegments``: the legs' support is its only actuation)."""

    name = NAME

    def __init__(self, case, world):
        cre, cfg, sc = case.creature, case.body, case.scenario
        n = cre.segments
        self.case = case
        self.dt = float(case.dt)
        L, W, H, gap = cre.segment_length_m, cre.width_m, cre.height_m, _gap(cfg, cre)
        self.n_segments = n
        self.segment_pitch_m = L + gap
        self.body_length_m = n * L + (n - 1) * gap
        self.half = np.array([0.5 * L, 0.5 * H, 0.5 * W])
        self.segment_half_extents = np.tile(self.half, (n, 1))
        m = cre.mass_kg / n
        self.rigid = RigidBoxes(self.segment_half_extents, np.full(n, m))
        self.total_mass = float(cre.mass_kg)
        self.gravity = np.array([0.0, -sc.gravity_m_s2, 0.0])
        self.terr_kind, self.terr = world.terrain  # the run's world, built once by the runner
        self.fric = friction_params(case.friction)[1]
        # the joint's corners: the end of box j's back strut and of box j + 1's front strut, in their own frames
        ends = np.array([[sy * 0.5 * H, sz * 0.5 * W] for sy in (-1, 1) for sz in (-1, 1)])
        self.end_back = np.ascontiguousarray(np.column_stack([np.full(4, -(0.5 * L + 0.5 * gap)), ends]))
        self.end_front = np.ascontiguousarray(np.column_stack([np.full(4, 0.5 * L + 0.5 * gap), ends]))
        centres = np.zeros((n, 3))
        centres[:, 0] = -np.arange(n) * self.segment_pitch_m - 0.5 * L
        centres[:, 1] = 0.5 * H
        place_box_chain(case, world, np.zeros((0, 3)), np.zeros(0, bool), centres, self.half, self.rigid,
                        np.zeros((0, 3)), np.zeros((0, 3)))
        self._held = np.zeros(n, dtype=np.bool_)
        if sc.suspended:
            self.rigid.set_kinematic(0, True)
            self._held[0] = True  # the suspended head stays held whatever the controller asks
        mu = case.friction.mu_transverse if cfg.friction_mu == DERIVED else cfg.friction_mu
        self.contact = ContactSettings(friction=mu, restitution=0.0)
        k, c_spring = joint_spring(m, cfg)
        self.phys = np.zeros(N_PHYS)
        self.phys[[DT, K_JOINT, C_JOINT, MAX_SPEED, MAX_PEN, CONTACT_DIST]] = (
            self.dt, k, c_spring, case.stability.max_speed_m_s, case.stability.max_penetration_m,
            self.fric[CONTACT_DISTANCE])
        self.acc = np.zeros(S.N_ACC)
        self._Rb = np.zeros((n, 3, 3))
        self._Rseg = np.zeros((n, 3, 3))
        self._qtmp = np.zeros(4)
        self._links = np.zeros((max(n - 1, 0), 3))

    # ------------------------------------------------------------------ stepping
    def _record(self) -> tuple:
        """``advance_jointed``'s record as a plain tuple (``core.kernel_records``), of the body's own arrays."""
        rb = self.rigid
        boxes = plain(rk.BoxArrays(c=rb.c, q=rb.q, v=rb.v, w=rb.w, mass=rb.mass, inertia_body=rb.inertia_body,
                                   half_extents=rb.half_extents, force=rb.force, torque=rb.torque,
                                   impulse_cache=rb.impulse_cache))
        return plain(Jointed(boxes=boxes, contact=self.contact.kernel_params, kinematic=rb.kinematic,
                             held=self._held, end_back=self.end_back, end_front=self.end_front,
                             gravity=self.gravity, terr_kind=self.terr_kind, terr=self.terr, phys=self.phys,
                             acc=self.acc, Rb=self._Rb, qtmp=self._qtmp))

    def advance(self, t0: float, n_steps: int, act: Actuation | None = None) -> tuple[int, int]:
        """``n_steps`` steps in one kernel call (t0 unused: no muscles; the legs act through ``apply_support``)."""
        return advance_jointed(self._record(), np.int64(n_steps))

    def legged_pack(self) -> JointedLegs:
        """The fused legged walk's pack (``bodies.legged_chunk``)."""
        return JointedLegs(self._record(), self._Rseg)

    def set_support(self, kinematic, c_T, R_T, dt: float) -> None:
        """Supported boxes (kinematic (n,) bool) carried to c_T (n, 3) [m], R_T (n, 3, 3) (Sec. 4.1); dt is the
        body's own (the record's)."""
        support_boxes(self._record(), np.ascontiguousarray(kinematic, dtype=np.bool_),
                      np.ascontiguousarray(c_T, dtype=np.float64), np.ascontiguousarray(R_T, dtype=np.float64))

    def _state(self):
        rb = self.rigid
        return [a.copy() for a in (rb.c, rb.q, rb.v, rb.w, rb.impulse_cache, rb.kinematic, self.acc)]

    def compile(self) -> None:
        """Compile (or load) the kernels; the state is left as it was."""
        saved = self._state()
        self.advance(0.0, 1)
        self.set_support(np.zeros(self.n_segments, bool), *self.segment_poses(), self.dt)
        self.observe(0.0)
        rb = self.rigid
        for dst, src in zip((rb.c, rb.q, rb.v, rb.w, rb.impulse_cache, rb.kinematic, self.acc), saved):
            dst[...] = src

    # ------------------------------------------------------------------ segment interface
    def segment_poses(self) -> tuple[np.ndarray, np.ndarray]:
        """Centres (n, 3) [m] and rotations (n, 3, 3) of the boxes."""
        return self.rigid.c, self.rigid.rotation_matrices()

    def segment_velocities(self) -> np.ndarray:
        return self.rigid.v

    def segment_centers(self) -> np.ndarray:
        """(2 n - 1, 3) [m]: box 0, joint 0, box 1, ... (the fused sample's kernel for the joints)."""
        c, R = self.segment_poses()
        joint_centres(c, R, self.end_back, self.end_front, self._links)
        out = np.empty((2 * len(c) - 1, 3))
        out[0::2] = c
        out[1::2] = self._links
        return out

    # ------------------------------------------------------------------ observation
    def momentum(self) -> np.ndarray:
        """(3,) [kg m/s] total linear momentum."""
        return self.rigid.mass @ self.rigid.v

    def angular_momentum(self) -> np.ndarray:
        """(3,) [kg m^2/s] total angular momentum about the origin."""
        rb = self.rigid
        return (np.cross(rb.c, rb.mass[:, None] * rb.v) + rb.angular_momentum()).sum(axis=0)

    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        rb = self.rigid
        R = rb.rotation_matrices()
        head, tail = rb.chain_ends(R, 2.0 * self.half[0])
        obs = Observation(t=t, segment_centers=self.segment_centers(), com=rb.mass @ rb.c / rb.mass.sum(),
                          head=head, tail=tail, energy=np.array(self.energy(t)),
                          nodes=rb.corners() if with_nodes else None)
        return self._observe_segments(obs, t)

    def joint_gaps(self) -> np.ndarray:
        """(n - 1, 4) [m] distance of each joint's corner pairs (0 at rest)."""
        c, R = self.segment_poses()
        a = c[:-1, None, :] + np.einsum("nij,kj->nki", R[:-1], self.end_back)
        b = c[1:, None, :] + np.einsum("nij,kj->nki", R[1:], self.end_front)
        return np.linalg.norm(b - a, axis=2)

    def energy(self, t: float = 0.0) -> tuple[float, float, float]:
        """(kinetic, the joints' elastic 1/2 k |p_b - p_a|^2, gravitational from y = 0) [J]."""
        rb = self.rigid
        e = rb.energy(self.gravity)
        elastic = 0.5 * self.phys[K_JOINT] * float((self.joint_gaps() ** 2).sum())
        return float(e.kinetic_linear.sum() + e.kinetic_rotational.sum()), elastic, float(e.potential.sum())

    def status_text(self, code: int) -> str:
        return S.STATUS_TEXT.get(code, f"status {code}")

    def extra_metrics(self) -> dict[str, float]:
        return {}

    def contact_fraction_mean(self) -> float:
        return float(self.acc[S.ACC_CONTACT_SUM] / max(self.acc[S.ACC_STEPS], 1.0))

    def max_penetration(self) -> float:
        return float(self.acc[S.ACC_MAX_PEN])

    def scene(self) -> Scene:
        verts, faces = box_triangles(self.rigid.corners())
        return Scene(triangles=[(verts, faces, RIGID_BOX)])


def joint_spring(m: float, cfg) -> tuple[float, float]:
    """(stiffness [N/m], damping [N s/m]) of one corner spring for boxes of mass m [kg]: two boxes' relative
    translation on a joint is the four springs (4 k) on the reduced mass m / 2, so omega^2 = 8 k / m, and the
    damping is ``joint_damping_ratio`` of that mode's critical damping 2 sqrt(4 k m / 2), shared by the four."""
    omega = 2.0 * math.pi * cfg.joint_hz
    k = m * omega * omega / 8.0
    return k, cfg.joint_damping_ratio * 2.0 * math.sqrt(4.0 * k * 0.5 * m) / 4.0


def omega_bound(case) -> float:
    """An upper bound [rad/s] of the joints' highest angular frequency (Gershgorin over the boxes' 6 DOF: a box
    on two joints, 8 springs, each at most |r| from its centre, neighbours of its own mass and inertia)."""
    cre, cfg = case.creature, case.body
    m = cre.mass_kg / cre.segments
    L, W, H, gap = cre.segment_length_m, cre.width_m, cre.height_m, _gap(cfg, cre)
    r2 = (0.5 * L + 0.5 * gap) ** 2 + (0.5 * H) ** 2 + (0.5 * W) ** 2
    i_min = m * min(H * H + W * W, L * L + W * W, L * L + H * H) / 12.0
    return math.sqrt(2.0 * 8.0 * joint_spring(m, cfg)[0] * (1.0 / m + r2 / i_min))


def check_buildable(case, source: str) -> None:
    """A chain of boxes needs two segments; its legs are its only actuation; symplectic Euler on the joints needs
    dt omega_max < 2 (``omega_bound``); a gap >= 0."""
    check_chain_segments(case, source, "a jointed-boxes body")
    check_legged_gait(case, source, "a jointed-boxes body")
    if case.legs.stance != "kinematic":
        raise InputError(source, "legs.stance", f"{case.legs.stance!r}: the jointed boxes carry only the paper's "
                                                "kinematic stance; must be 'kinematic'")
    gap = _gap(case.body, case.creature)
    if gap < 0.0:
        raise InputError(source, "body.link_length_m", f"{gap}: must be >= 0 (or -1: half a segment)")
    w = omega_bound(case)
    if not case.dt * w < 2.0:
        raise InputError(source, "dt", f"{case.dt} s: the jointed boxes' joints are unstable above "
                                       f"{2.0 / w:.3g} s; must be smaller (or lower body.joint_hz)")


# The one table row: what the suite knows of this body model.  ``validate --quick`` runs the first three on it: the
# paper's legged checks of one 10 s walk (the gait cycle and the wave) and a 3 s hang.  The full ``validate`` adds the
# brains' and the millipede's (each PASSed at its full size when this was written; in the quick set's 4 s the
# millipede's wave read retrograde, lag +0.48 cycles, too short a window).  Not ``analytic.free-fall-momentum``: it
# drops a worm, whose crawl needs muscles (the runner refuses the pair); the momentum test below is this body's.
CHECKS = {"paper.fig10a-hang": True, "paper.wave-centipede": True, "paper.fig10d-walk": True,
          "paper.wave-millipede": False, "paper.control-turn": False, "paper.foraging": False,
          "paper.avoidance": False}
BODIES = {NAME: BodySpec(
    name=NAME, description="rigid boxes joined by 6-DOF corner-spring joints, with the paper's kinematic legs "
                           "(tests/test_fourth_body_legged.py)",
    config_cls=JointedBoxesConfig, factory=BodyJointedBoxes, default_dt=lambda cfg: cfg.dt_s,
    capabilities=frozenset({SEGMENTS, LEGS}) | FRICTION_CAPABILITIES,
    footprint=lambda case: lattice_footprint(8.0 * case.creature.segments), check_buildable=check_buildable,
    default_params={}, checks=CHECKS)}


# --------------------------------------------------------------------------- the tests

QUICK_CHECKS = tuple(c for c, quick in CHECKS.items() if quick)
FREE = ("scenario.terrain=none", "scenario.passive=true", "scenario.gravity_m_s2=0")


@pytest.fixture(scope="module")
def plugin():
    """The fourth body in the lookups, read by the catalog's plugin mechanism as the CLI does (the env var);
    removed again afterwards so no other test sees it."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv(registry.PLUGINS_ENV, MODULE)
        registry.load_all()
        assert registry.BODIES[NAME] is sys.modules[MODULE].BODIES[NAME]
        yield registry.BODIES[NAME]
        registry.BODIES.pop(NAME, None)


def _case(creature, scenario, *sets, duration=1.0):
    from bench_myriapoda.core.config import resolve_case
    return resolve_case(creature, NAME, scenario, duration=duration, overrides=list(sets))


def _body(case):
    from bench_myriapoda.harness.runner import build_body
    body = build_body(case)
    body.compile()
    return body


def _state(cr) -> dict:
    """Every array the next step of a legged run depends on: the boxes', the controller's and the support's."""
    b, c, act = cr.body, cr.controller, cr.stepper.act
    rb = b.rigid
    return {"c": rb.c, "q": rb.q, "v": rb.v, "w": rb.w, "kinematic": rb.kinematic, "impulse": rb.impulse_cache,
            "acc": b.acc, "states": c.states, "angles": c.angles, "tips": c.tips, "c_T": c.c_T, "R_T": c.R_T,
            "brain_steps": c.brain_steps, "rng": c.rng.bit_generator.state["state"]["state"],
            "act_kin": act.support_kinematic, "act_c": act.support_c, "act_R": act.support_R}


# The walk both ways: the runner's chunks (50 steps at 60 Hz samples), single steps, and odd sizes so chunk ends fall
# anywhere in the timeline's record period; ADJUSTMENT ends at about 0.4 s, then the walk.
CHUNKS = [1] * 20 + [50] * 40 + [7, 13, 333, 1, 626]  # 3000 steps: 1 s at the default 1/3000 s


@pytest.fixture(scope="module", params=["centipede", "millipede"])
def walked_both_ways(request, plugin):
    """The creature's walk (1.0 s) on the fused path and on the Python path, in ``CHUNKS``; after each chunk the
    names of the state arrays that differ (bitwise), and on the Python path the support the boxes took."""
    from bench_myriapoda.harness.runner import Creature
    case = _case(request.param, "walk")
    fused, ref = Creature(case, fused=True), Creature(case, fused=False)
    assert fused.stepper.fused is not None, fused.stepper.fused_reason
    assert ref.stepper.fused is None
    fused.compile()
    ref.compile()
    differ, support = [], []
    done = 0
    for n in CHUNKS:
        t = done * case.dt
        assert fused.advance(t, n) == ref.advance(t, n) == (n, 0)
        done += n
        sf, sr = _state(fused), _state(ref)
        differ.append((done, [k for k in sf if not np.array_equal(sf[k], sr[k])]))
        act, rb = ref.stepper.act, ref.body.rigid
        support.append((act.support_kinematic.copy(), act.support_c.copy(), act.support_R.copy(), rb.c.copy(),
                        rb.rotation_matrices(), rb.kinematic.copy()))
    return case, fused, ref, differ, support


def test_the_fused_walk_equals_the_python_walk_bit_for_bit(walked_both_ways):
    from test_fused_walk import assert_same_record
    case, fused, ref, differ, _ = walked_both_ways
    assert [d for d in differ if d[1]] == []  # every state array equal (==) after every chunk
    assert sum(CHUNKS) * case.dt >= 1.0 - 1e-9
    assert_same_record(fused, ref)  # the controllers' timelines, the monitors' samples and metrics, observations
    assert np.isfinite(fused.controller.t_walk)  # past ADJUSTMENT: the comparison covers walking
    # the package's chunk kernel was never compiled for this module's pack class, so its numba cache index stays
    # readable by a process that cannot import this module: the plugin's own copy was
    from bench_myriapoda.fused import legged_walk
    kernel = legged_walk.chunk_kernel(JointedLegs)
    assert kernel is not legged_walk.legged_chunk
    assert any("JointedLegs" in str(sig) for sig in kernel.signatures)
    assert not any("JointedLegs" in str(sig) for sig in legged_walk.legged_chunk.signatures)


def test_the_supported_segments_follow_their_kinematic_targets(walked_both_ways):
    # paper Sec. 4.1: a supported segment is carried to its target; the others follow the dynamics
    case, *_, support = walked_both_ways
    carried = free = 0
    for kin, c_T, R_T, c, R, box_kin in support:
        assert np.array_equal(box_kin, kin)  # no held box on the walk: the boxes the legs support, no others
        assert np.array_equal(c[kin], c_T[kin])  # carried exactly to the target centre ...
        assert np.abs(R[kin] - R_T[kin]).max(initial=0.0) < 1e-12  # ... and rotation (through a quaternion)
        carried += int(kin.sum())
        free += int((~kin).sum())
    assert carried > 0 and free > 0, (carried, free)


def test_a_joint_oscillates_at_its_declared_frequency(plugin):
    # two boxes in free space pulled apart along the body: the joint's axial mode, undamped, has the analytic
    # omega^2 = 8 k / m = (2 pi joint_hz)^2 (``joint_spring``); symplectic Euler shifts it by (omega dt)^2 / 24
    case = _case("centipede", "drop", *FREE, "creature.segments=2", "body.joint_damping_ratio=0")
    b = _body(case)
    rb = b.rigid
    rb.v[0, 0], rb.v[1, 0] = 0.01, -0.01
    n = int(round(0.3 / case.dt))
    rel = np.empty(n)
    for k in range(n):
        assert b.advance(k * case.dt, 1) == (1, 0)
        rel[k] = rb.v[0, 0] - rb.v[1, 0]
    ups = np.flatnonzero((rel[:-1] < 0) & (rel[1:] >= 0))
    t_up = (ups + rel[ups] / (rel[ups] - rel[ups + 1])) * case.dt  # interpolated upward zero crossings
    period = float(np.diff(t_up).mean())
    assert len(ups) >= 5
    assert period == pytest.approx(1.0 / case.body.joint_hz, rel=2e-3)
    assert np.abs(rb.v[:, 1:]).max() < 1e-12 and np.abs(rb.w).max() < 1e-12  # a pure axial mode stays one


def test_the_joints_keep_momentum_and_lose_energy_in_free_flight(plugin):
    # a tumbling, vibrating chain, no gravity, no ground: the joints' forces act in equal and opposite pairs at
    # one point each, so the total linear and angular momentum stay what they were; the dampers take energy
    case = _case("centipede", "drop", *FREE, "creature.segments=6")
    b = _body(case)
    rb = b.rigid
    gen = np.random.default_rng(7)
    rb.v[:] = gen.normal(scale=0.5, size=rb.v.shape)
    rb.w[:] = gen.normal(scale=1.0, size=rb.w.shape)
    P0, L0, E0 = b.momentum(), b.angular_momentum(), sum(b.energy())
    elastic = 0.0
    for k in range(30):
        assert b.advance(0.0, 100) == (100, 0)
        elastic = max(elastic, b.energy()[1])
        assert np.abs(b.momentum() - P0).max() < 1e-12 * np.abs(P0).max()
        assert np.abs(b.angular_momentum() - L0).max() < 1e-11 * np.abs(L0).max()
    E1 = sum(b.energy())
    assert elastic > 0.01 * E0  # the joints worked: not a chain moving rigidly
    assert E1 < 0.5 * E0, (E0, E1)


def test_the_dropped_centipede_comes_to_rest_on_the_ground(plugin):
    # gravity, the boxes' ground contact and friction (rigid_kernels): dropped from 0.3 m, every box ends
    # lying on the plane, nothing sinks in
    case = _case("centipede", "drop", "scenario.passive=true")
    b = _body(case)
    assert b.rigid.c[:, 1].min() > 0.3
    assert b.advance(0.0, int(round(1.5 / case.dt))) == (int(round(1.5 / case.dt)), 0)
    half_height = 0.5 * case.creature.height_m
    assert np.abs(b.rigid.c[:, 1] - half_height).max() < 1e-4  # measured 1e-5: the contact's slop
    assert np.abs(b.rigid.v).max() < 1e-3
    assert b.max_penetration() < 2e-3  # measured 0.27 mm, on impact
    assert b.observe(1.5).seg_contact.all()
    assert b.joint_gaps().max() < 1e-6  # the joints hold the chain together at rest (measured 7e-10 m)


def _env(plugin: bool) -> dict:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), str(ROOT / "tests"),
                                                       os.environ.get("PYTHONPATH", "")]))
    env.pop(registry.PLUGINS_ENV, None)
    if plugin:
        env[registry.PLUGINS_ENV] = MODULE
    return env


def test_the_centipede_runs_on_the_legged_fourth_body_through_the_cli_run_and_matrix(tmp_path):
    # the CLI in its own process, the body found through the plugin variable only
    cli = [sys.executable, "-m", "bench_myriapoda.cli"]
    run = cli + ["run", "--creature", "centipede", "--body", NAME, "--scenario", "walk", "--duration", "0.5",
                 "--json", "--no-store"]
    out = subprocess.run(run, env=_env(True), capture_output=True, text=True, timeout=900)
    assert out.returncode == 0, out.stderr
    doc = json.loads(out.stdout)
    assert doc["status"] == "ok", doc
    matrix = tmp_path / "legged.toml"
    matrix.write_text('[matrix]\nname = "legged-fourth"\nseeds = [0]\n\n[[block]]\ncreatures = ["centipede", '
                      f'"millipede"]\nbodies = ["{NAME}"]\nscenarios = ["walk"]\nduration = 0.3\n')
    out = subprocess.run(cli + ["matrix", str(matrix), "--workers", "1", "--out", str(tmp_path / "out")],
                         env=_env(True), capture_output=True, text=True, timeout=900)
    assert out.returncode == 0, out.stderr
    from bench_myriapoda.api import load_results
    df = load_results(tmp_path / "out")
    assert sorted(zip(df["creature"], df["body"], df["status"])) == [("centipede", NAME, "ok"),
                                                                    ("millipede", NAME, "ok")]
    out = subprocess.run(run, env=_env(False), capture_output=True, text=True, timeout=600)
    assert out.returncode == 2 and f"unknown body model '{NAME}'" in out.stderr


def test_the_legged_fourth_body_runs_through_validate_quick(plugin, tmp_path, capsys):
    from creature_runs import validate_quick_rows

    code, rows = validate_quick_rows(NAME, tmp_path, capsys, QUICK_CHECKS)  # its quick checks, none broke on it
    for r in rows:  # a verdict on the physics: every one passes
        assert r["verdict"] == "PASS", r
    assert code == 0


def test_the_legged_fourth_body_declares_its_own_limits(plugin, capsys):
    from bench_myriapoda.cli import main
    base = ["run", "--creature", "centipede", "--body", NAME, "--scenario", "walk", "--no-store"]
    assert main(base + ["--dt", "0.01"]) == 2
    assert "unstable above" in capsys.readouterr().err
    assert main(base + ["--set", "legs.stance=dynamic"]) == 2
    assert "legs.stance" in capsys.readouterr().err
    assert main(["run", "--creature", "worm", "--body", NAME, "--scenario", "flat", "--no-store"]) == 2
    assert "needs muscles" in capsys.readouterr().err  # a legless crawler needs muscles this body has not


# How far the centipede's centre of mass moved along +x in the first 2 s of the walk scenario (ADJUSTMENT first, then
# walking at the commanded 1 m/s) on the built-in legged bodies, at their default time steps (how measured: the
# commit message that set these).
BUILT_IN_FORWARD_2S_M = {"massspring": 1.292, "hybrid": 1.302}
FORWARD_FRACTION = 0.9  # of the shorter built-in walk


def test_the_centipede_walks_forward_as_far_as_on_the_built_in_bodies(plugin):
    from bench_myriapoda.harness.runner import run_case
    r = run_case(_case("centipede", "walk", duration=2.0))
    assert r.status == "ok", r.message
    d = np.asarray(r.series.com)[-1] - np.asarray(r.series.com)[0]
    assert d[0] > FORWARD_FRACTION * min(BUILT_IN_FORWARD_2S_M.values()), d
    assert abs(d[2]) < 0.1 * d[0], d  # along its heading, not sideways
    assert r.metrics["max_penetration_m"] < 0.01
