"""``massspring`` for legged creatures: rigid boxes joined by Miller spring-cube links.

The centipede of ``models/centipede.toml`` with the hybrid body's rigid
segments (same boxes, masses, box-terrain contact, ``RigidBoxes`` /
``rigid_kernels``) but the FEM links replaced by Miller's cube lattice
(``lattice.build_lattice``: four corner masses per cross-section face, springs
along every cube edge and across every face diagonal, f = k (L - l) - D dl/dt,
``kernels.spring_forces``).  A link of ``link_cells`` cubes along the body has
``link_cells + 1`` faces; its two end faces' corners are glued to the facing
faces of the two boxes (attached nodes), the inner faces' corners are free
point masses (symplectic Euler, the suite's shared ground contact
``contact_kernels``, like the hybrid's free FEM nodes).

Coupling: the hybrid's three staggered steps (paper Sec. 3), inside one numba
kernel running n steps per call (the rigid segment chain's ``rigid_chain.advance_chain``, with
this module's spring links, ``SpringLinks``, as its link element):

1. spring forces at (x^n, v^n); free nodes: v += dt (f/m + g), ground contact,
   x += dt v;
2. the forces on the attached nodes act on their boxes as force + torque about
   the box centre; rigid step (``rigid_kernels._step_body``, gravity and
   box-terrain contact) of every non-kinematic box;
3. the attached nodes are put back onto their boxes (x = c + R l,
   v = v_c + w x (x - c)).

Springs between two nodes glued to the same box are dropped (they never change
length).  Spring forces are internal, so the total linear momentum of boxes and
free nodes changes only by gravity and contact (tests/test_myriapod_bodies.py).

SI units throughout: ``link_stiffness_n_m`` [N/m] and ``link_damping_n_s_m``
[N s/m] are per spring (not Miller's per-unit-mass frame units of the lattice
body).  The default 600 N/m gives a 2-cube, 0.5 m link of the centipede's
1 x 0.5 m cross-section an axial stiffness of about 2000 N/m, the order of the
hybrid's FEM link (E A / L = 4000 N/m).  Masses: the link density
(``link_density_kg_m3``, App. A's 1 kg/m^3) lumped equally on a link's nodes;
the attached nodes' share belongs to the boxes, whose mass makes boxes + free
nodes weigh ``creature.mass_kg``.
"""
from __future__ import annotations

from collections import namedtuple
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numba import njit

from .. import rigid_kernels as rk
from ..contact_kernels import NOT_CLEAR, advance_point, advance_point_if_clear
from ..friction_kernels import friction_params
from ..rigid_chain import (ACC_RES_COUNT, ACC_RES_MAX, ACC_RES_SUM, N_ACC, Attachment, Boxes, ChainParams, Coupling,
                           advance_chain, boxes_of, chain_phys, chain_scalars, coupling_of, link_spines,
                           place_attached_nodes, register_link)
from ..carried_boxes import (PushedBoxes, box_chain_centers, box_poses, carried_boxes, carry_boxes,
                             carry_boxes_feet, sample_boxes)
from ..legged_chunk import LeggedPackOps, chain_step, register
from ...core.kernel_records import plain
from ...core.protocols import Actuation, Observation
from ..placement import place_box_chain
from ..rigid import ContactSettings, RigidBoxes
from ..scene import RIGID_BOX, Scene, box_triangles
from .lattice import LATTICE_SURFACE, lattice_surface_faces
from ..segment_chain import CouplingScratch, LeggedSegments, SegmentChainLayout, chain_sizes
from ..step_status import ACC_CONTACT_SUM, ACC_MAX_PEN, ACC_STEPS, OK
from ..step_status import STATUS_TEXT
from ...world.world import StepWorld
from .kernels import spring_forces
from .lattice import build_lattice


def chain_layout(cfg, creature) -> SegmentChainLayout:
    """Sizes from ``[bodies.massspring]`` with defaults from the creature (-1 = derived, ``segment_chain.chain_sizes``)."""
    if creature.segments < 2:
        raise ValueError(f"a rigid-spring chain needs at least 2 segments; {creature.name!r} has {creature.segments}")
    lr, wr, hr, ll, wl, hl = chain_sizes(cfg, creature).values()
    if min(lr, wr, hr, ll, wl, hl) <= 0.0:
        raise ValueError("rigid and link sizes must be positive")
    if wl > wr or hl > hr:
        raise ValueError(f"the link cross-section {hl} x {wl} m must fit on the rigid face {hr} x {wr} m")
    return SegmentChainLayout(creature.segments, lr, wr, hr, ll, wl, hl, int(cfg.link_cells))


@dataclass(frozen=True)
class ChainMesh:
    """Spring links in the build frame (head front face at x = 0, axis on y = z = 0, body along -x).

    nodes (n_nodes, 3) [m]; springs (n_springs, 2); rest (n_springs,) [m];
    node_link (n_nodes,); link_nodes (n_links, 4 (cells + 1)); mass (n_nodes,)
    [kg]; attached (n_nodes,) bool; att_body (n_nodes,) box of an attached node
    (-1 if free); rigid_centres (n_rigid, 3) [m].
    """

    nodes: np.ndarray
    springs: np.ndarray
    rest: np.ndarray
    node_link: np.ndarray
    link_nodes: np.ndarray
    mass: np.ndarray
    attached: np.ndarray
    att_body: np.ndarray
    rigid_centres: np.ndarray


def build_chain(lay: SegmentChainLayout, density: float) -> ChainMesh:
    """Link k: a ``lay.cells``-cube Miller lattice spanning x in [-(k+1) P, -k P - L_rigid]."""
    P = lay.pitch
    nodes, springs, rest, node_link, mass, attached, att_body, link_nodes = [], [], [], [], [], [], [], []
    offset = 0
    for k in range(lay.n_rigid - 1):
        lat = build_lattice(lay.cells, lay.link_length / lay.cells, lay.link_width, lay.link_height)
        nd = lat.rest_nodes + np.array([-k * P - lay.rigid_length, -0.5 * lay.link_height, 0.0])
        n = len(nd)
        face = np.arange(n) // 4
        body = np.full(n, -1, dtype=np.int64)
        body[face == 0] = k                 # front face on rigid k's back face
        body[face == lay.cells] = k + 1     # back face on rigid k+1's front face
        sp = lat.springs
        keep = ~((body[sp[:, 0]] >= 0) & (body[sp[:, 0]] == body[sp[:, 1]]))  # same-box springs never stretch
        nodes.append(nd)
        springs.append(sp[keep] + offset)
        rest.append(lat.rest_length[keep])
        node_link.append(np.full(n, k, dtype=np.int64))
        mass.append(np.full(n, density * lay.link_length * lay.link_width * lay.link_height / n))
        attached.append(body >= 0)
        att_body.append(body)
        link_nodes.append(np.arange(n, dtype=np.int64) + offset)
        offset += n
    centres = np.zeros((lay.n_rigid, 3))
    centres[:, 0] = -np.arange(lay.n_rigid) * P - 0.5 * lay.rigid_length
    return ChainMesh(np.concatenate(nodes), np.ascontiguousarray(np.concatenate(springs)), np.concatenate(rest),
                     np.concatenate(node_link), np.stack(link_nodes), np.concatenate(mass),
                     np.concatenate(attached), np.concatenate(att_body), centres)


# The spring link element of the rigid segment chain (``rigid_chain.link_step``), a named record: x, v (n_nodes, 3)
# [m], [m/s] UPDATED (attached rows rewritten from the boxes every step); n_free the free nodes; mass (n_nodes,) [kg];
# free (n_free,) node ids; node_link (n_nodes,); springs (n_springs, 2), stiffness [N/m], damping [N s/m], rest [m]
# (n_springs,); scratch f_work (n_nodes, 3).
SpringLinks = namedtuple("SpringLinks", "x v n_free mass free node_link springs stiffness damping rest f_work")


def _spring_links_step(L, A, B, M, W, C, acc, dt, step, flat, ground):
    """``rigid_chain.link_step`` of the spring links: step 1 of the module docstring (spring forces at
    (x^n, v^n); free nodes: v += dt (f/m + g), ground contact, x += dt v)."""
    x, v, n_free, mass, free, node_link, f_work = L.x, L.v, L.n_free, L.mass, L.free, L.node_link, L.f_work
    springs, stiffness, damping, rest = L.springs, L.stiffness, L.damping, L.rest
    fixed = A.fixed
    gravity, terr_kind, terr, fric_model, fric, phys = W.gravity, W.terr_kind, W.terr, M.fric_model, M.fric, M.phys
    f_att, x_att, x_pred, spine = C.f_att, C.x_att, C.x_pred, C.spine
    n_fixed = fixed.shape[0]
    r_n, r_t, max_pen, vmax, contact_dist = chain_scalars(phys, fric)
    vmax2 = vmax * vmax
    gx, gy, gz = gravity[0], gravity[1], gravity[2]
    status = OK
    f_work[:, :] = 0.0
    spring_forces(x, v, springs, stiffness, damping, rest, f_work)
    for a in range(n_fixed):
        p = fixed[a]
        for d in range(3):
            f_att[a, d] = f_work[p, d]
            x_att[a, d] = x[p, d]
            x_pred[a, d] = x[p, d] + dt * v[p, d]
    link_spines(B.c, spine)
    n_contact = 0
    for k in range(n_free):
        i = free[k]
        inv_m = 1.0 / mass[i]
        vx = v[i, 0] + dt * (f_work[i, 0] * inv_m + gx)
        vy = v[i, 1] + dt * (f_work[i, 1] * inv_m + gy)
        vz = v[i, 2] + dt * (f_work[i, 2] * inv_m + gz)
        st = advance_point_if_clear(x, v, i, vx, vy, vz, dt, terr_kind, terr, flat, ground, contact_dist, vmax2,
                                    True)
        if st != NOT_CLEAR:  # in the air: moved, as advance_point would
            if st != OK:
                status = st
            continue
        # a node not clear: ``advance_point`` on its link's spine; alike in each link element by design, as is
        # the entry kernel below (``hybrid.kernels._fem_links_step`` and ``advance`` say why)
        s = node_link[i]
        touching, st = advance_point(x, v, i, (vx, vy, vz), (spine[s, 0], spine[s, 1], spine[s, 2]), terr_kind,
                                     terr, fric_model, fric, (dt, r_n, r_t, contact_dist, max_pen, vmax2), acc,
                                     False, (0.0, 0.0, 0.0))
        n_contact += touching
        if st != OK:
            status = st
    return status, n_contact


register_link(SpringLinks, _spring_links_step)


# inline: the fused legged walk's step is this function with n = 1 (``legged_chunk.chain_step``), inlined into its
# chunk, so no kernel of its own sits between the chain and the chunk on a cold start
@njit(cache=True, error_model="numpy", inline="always")
def advance_spring_chain(links, att, boxes, params, coupling, acc, world, dt, n_steps):
    """The legged chain's one step function: n_steps of dt [s] of ``rigid_chain.advance_chain`` of the spring-linked
    chain in world, from Python (``BodyRigidSpringChain.advance``) and in the fused legged walk: the body's records
    ``SpringLinks``, ``Attachment``, ``Boxes``, ``ChainParams`` and ``Coupling`` and the run's world
    (``world.world.StepWorld``) as plain tuples (``core.kernel_records``), named here; acc (N_ACC,) ACCUMULATES;
    returns (steps, status)."""
    return advance_chain(SpringLinks(*links), Attachment(*att), Boxes(*boxes), ChainParams(*params),
                         Coupling(*coupling), acc, StepWorld(*world), dt, n_steps)


# The legged chain's one step function: ``advance`` calls it with a chunk's n steps, the fused legged walk with one
# (``legged_chunk.chain_step``)
STEP = advance_spring_chain
STEP_CHAIN_ITEMS = 6  # STEP's body arguments: links, att, boxes, params, coupling, acc (the pack's chain); then world,
#                       dt, n_steps, given by whoever runs it


class BodyRigidSpringChain(LeggedPackOps, PushedBoxes, LeggedSegments):
    """Rigid boxes (``self.rigid``) joined by Miller spring-cube links, with the segment interface.

    State: ``x``, ``v`` (n_nodes, 3) [m], [m/s] of the link nodes (attached
    rows always equal the boxes' points); the boxes' c, q, v, w in ``self.rigid``.  Its segment interface
    (``segment_poses``, ``set_support``, ``push_support``, ``legged_sample``) is ``legged_chunk.LeggedPackOps``: the
    functions registered for ``SpringChainLegs`` below, which the fused walk runs.
    """

    name = "massspring"
    def __init__(self, case, world):
        cre = case.creature
        cfg = case.body
        sc = case.scenario
        self.case = case
        self.layout = lay = chain_layout(cfg, cre)
        self.mesh = mesh = build_chain(lay, cfg.link_density_kg_m3)
        self.dt = float(case.dt)
        self.gravity = np.array([0.0, -sc.gravity_m_s2, 0.0])
        self.mass = mesh.mass.copy()
        self.fixed = np.flatnonzero(mesh.attached).astype(np.int64)
        self.free = np.flatnonzero(~mesh.attached).astype(np.int64)
        self.att_body = np.ascontiguousarray(mesh.att_body[self.fixed])
        self.springs = mesh.springs
        self.rest = mesh.rest
        self.stiffness = np.full(len(self.rest), cfg.link_stiffness_n_m)
        self.damping = np.full(len(self.rest), cfg.link_damping_n_s_m)

        half = np.array([0.5 * lay.rigid_length, 0.5 * lay.rigid_height, 0.5 * lay.rigid_width])
        free_mass = float(self.mass[self.free].sum())
        m_rigid = (cre.mass_kg - free_mass) / lay.n_rigid
        if m_rigid <= 0.0:
            raise ValueError(f"creature.mass_kg = {cre.mass_kg} kg is less than the free link nodes' {free_mass:.4g} kg")
        self.rigid = RigidBoxes(np.tile(half, (lay.n_rigid, 1)), np.full(lay.n_rigid, m_rigid))
        self.total_mass = m_rigid * lay.n_rigid + free_mass
        self.n_segments = lay.n_rigid
        self.segment_pitch_m = lay.pitch
        self.segment_half_extents = np.tile(half, (lay.n_rigid, 1))

        # the run's world (``world.world``: built once by the runner; a body builds none of its own)
        self.world = world
        self.terr_kind, self.terr = self.world.terrain
        self.fric_model, self.fric = friction_params(case.friction)
        self.x = np.zeros_like(mesh.nodes)
        self.v = np.zeros_like(mesh.nodes)
        place_box_chain(case, self.world, mesh.nodes, mesh.attached, mesh.rigid_centres, half, self.rigid, self.x,
                        self.v)
        self.att_local = np.ascontiguousarray(mesh.nodes[self.fixed] - mesh.rigid_centres[self.att_body])
        self._held = np.zeros(lay.n_rigid, dtype=np.bool_)
        if sc.suspended:
            self.rigid.set_kinematic(0, True)
            self._held[0] = True  # the suspended head stays held whatever the controller asks

        mu = case.friction.mu_transverse if cfg.rigid_friction_mu < 0.0 else cfg.rigid_friction_mu
        self.contact = contact = ContactSettings(friction=mu, restitution=0.0)
        self.phys = chain_phys(case, contact)
        n_nodes, n_fixed, n_rigid = len(self.x), len(self.fixed), lay.n_rigid
        self._f_work = np.zeros((n_nodes, 3))
        self.scratch = CouplingScratch.new(n_fixed, n_rigid, rk.N_CORNERS)
        self.acc = np.zeros(N_ACC)
        self.sync_attached()
        self._setup_stance(case)  # the dynamic stance (legs.stance, bodies.dynamic_stance)

    def sync_attached(self) -> None:
        """Put the attached nodes on the boxes' current state."""
        x_pred = np.ascontiguousarray(self.x[self.fixed])
        place_attached_nodes(self.fixed, self.att_body, self.att_local, self.rigid.c, self.rigid.q,
                             self.rigid.v, self.rigid.w, self.scratch.Rb, self.x, self.v, x_pred, self.scratch.residual)

    # ------------------------------------------------------------------ stepping
    def advance(self, t0: float, n_steps: int, act: Actuation | None = None) -> tuple[int, int]:
        """Run ``n_steps`` coupled steps in one kernel call; return (steps done, status code). t0 unused;
        the links have no muscles (the supported segments are moved by ``apply_support``)."""
        return STEP(*self._chain_args, self.acc, self.world.step_world, self.dt, int(n_steps))

    @cached_property
    def _chain_args(self) -> tuple:
        """``advance_spring_chain``'s records (``SpringLinks``, ``rigid_chain``'s ``Attachment``, ``Boxes``,
        ``ChainParams``, ``Coupling``) as plain tuples (``core.kernel_records``: the call's cost), built once by field
        name: they refer to the body's own arrays, which are changed in place only."""
        links = SpringLinks(x=self.x, v=self.v, n_free=len(self.free), mass=self.mass, free=self.free,
                            node_link=self.mesh.node_link, springs=self.springs, stiffness=self.stiffness,
                            damping=self.damping, rest=self.rest, f_work=self._f_work)
        params = ChainParams(fric_model=self.fric_model, fric=self.fric, phys=self.phys)
        return (plain(links), plain(Attachment(fixed=self.fixed, att_body=self.att_body, att_local=self.att_local)),
                plain(boxes_of(self.rigid)), plain(params), plain(coupling_of(self.scratch)))

    def legged_pack(self) -> "SpringChainLegs":
        """The fused legged walk's pack (``legged_chunk``): the carried boxes and the step's arguments."""
        return SpringChainLegs(self._carried(), self._chain_args + (self.acc,))

    def _carried(self):
        """The boxes' ``carried_boxes.CarriedBoxes`` (legged_pack, push_support)."""
        return carried_boxes(self.rigid, self._held, self.x, self.v, self.fixed, self.att_body, self.att_local,
                             self.mesh.link_nodes, self.scratch.Rb, self.scratch.qtmp, self.dt, self.stance)

    def _state(self):
        rb = self.rigid
        return [a.copy() for a in (self.x, self.v, rb.c, rb.q, rb.v, rb.w, rb.impulse_cache, rb.kinematic, self.acc)]

    def _restore(self, saved) -> None:
        rb = self.rigid
        for dst, src in zip((self.x, self.v, rb.c, rb.q, rb.v, rb.w, rb.impulse_cache, rb.kinematic, self.acc), saved):
            dst[...] = src

    def compile(self) -> None:
        """Trigger (or load from cache) the JIT compilation without changing the state."""
        saved = self._state()
        self.advance(0.0, 1)
        self.set_support(np.zeros(self.layout.n_rigid, bool), *self.segment_poses(), self.dt)
        if self.dynamic_stance:
            stance_acc = self.stance.acc.copy()
            n = self.layout.n_rigid
            self.push_support(np.zeros(n, bool), *self.segment_poses(), np.zeros(2 * n, np.int64), np.zeros((2 * n, 3)))
            self.stance.acc[:] = stance_acc
        self.observe(0.0)
        self._restore(saved)

    @staticmethod
    def status_text(code: int) -> str:
        return STATUS_TEXT.get(code, f"status {code}")

    # ------------------------------------------------------------------ segment interface
    def segment_velocities(self) -> np.ndarray:
        """(n_rigid, 3) [m/s] velocities of the boxes' centres."""
        return self.rigid.v

    @property
    def body_length_m(self) -> float:
        return self.layout.body_length

    # ------------------------------------------------------------------ observation
    def box_corners(self) -> np.ndarray:
        """(n_rigid * 8, 3) [m] box corners (``rigid.RigidBoxes.corners``)."""
        return self.rigid.corners()

    @cached_property
    def _link_faces(self) -> np.ndarray:
        """(F, 3) outward triangles of every link lattice's outer faces, indexing ``x``; static."""
        per_link = lattice_surface_faces(self.layout.cells)
        # a link's nodes are consecutive in x (``build_chain``), face j's corner c at 4 j + c
        faces = np.concatenate([per_link + nodes[0] for nodes in self.mesh.link_nodes])
        faces.setflags(write=False)
        return faces

    def scene(self) -> Scene:
        """Boxes, the links' lattice surfaces and their springs, world coordinates [m] (``bodies.scene``)."""
        verts, faces = box_triangles(self.box_corners())
        return Scene(triangles=[(verts, faces, RIGID_BOX), (self.x.copy(), self._link_faces, LATTICE_SURFACE)],
                     springs=self.x[self.springs])  # (S, 2, 3); fancy indexing copies

    def segment_centers(self) -> np.ndarray:
        """(2 n_rigid - 1, 3) [m]: rigid 0, link 0, rigid 1, ... (box centres, link node means)."""
        return box_chain_centers(self.rigid.c, self.x, self.mesh.link_nodes)

    def centre_of_mass(self) -> np.ndarray:
        rb = self.rigid
        return (rb.mass @ rb.c + self.mass[self.free] @ self.x[self.free]) / self.total_mass

    def momentum(self) -> np.ndarray:
        """(3,) [kg m/s] linear momentum of the boxes and the free nodes (attached nodes are the boxes')."""
        rb = self.rigid
        return rb.mass @ rb.v + self.mass[self.free] @ self.v[self.free]

    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        rb = self.rigid
        R = rb.rotation_matrices()
        head, tail = rb.chain_ends(R, self.layout.rigid_length)
        nodes = np.vstack([self.x, self.box_corners()]) if with_nodes else None
        obs = Observation(t=t, segment_centers=self.segment_centers(), com=self.centre_of_mass(), head=head,
                          tail=tail, energy=np.array(self.energy(t)), nodes=nodes)
        return self._observe_segments(obs, t)

    def energy(self, t: float = 0.0) -> tuple[float, float, float]:
        """(kinetic, spring elastic 1/2 k (L - l)^2, gravitational from y = 0) [J] of boxes and free nodes."""
        rb = self.rigid
        e_r = rb.energy(self.gravity)
        m = self.mass[self.free]
        v = self.v[self.free]
        kinetic = float(e_r.kinetic_linear.sum() + e_r.kinetic_rotational.sum() + 0.5 * np.einsum("i,ij,ij->", m, v, v))
        d = self.x[self.springs[:, 1]] - self.x[self.springs[:, 0]]
        elastic = float(0.5 * np.sum(self.stiffness * (np.linalg.norm(d, axis=1) - self.rest) ** 2))
        g = -self.gravity[1]
        grav = float(g * (rb.mass @ rb.c[:, 1] + m @ self.x[self.free, 1]))
        return kinetic, elastic, grav

    # ------------------------------------------------------------------ metrics
    def extra_metrics(self) -> dict[str, float]:
        """Coupling residual |x_p + dt v_p - x_p(box, n+1)| over all steps and attached nodes [m]."""
        acc = self.acc
        mean = acc[ACC_RES_SUM] / acc[ACC_RES_COUNT] if acc[ACC_RES_COUNT] > 0 else 0.0
        return {"coupling_residual_max_m": float(acc[ACC_RES_MAX]), "coupling_residual_mean_m": float(mean),
                **self.stance_statistics()}

    def contact_fraction_mean(self) -> float:
        return float(self.acc[ACC_CONTACT_SUM] / max(self.acc[ACC_STEPS], 1.0))

    def max_penetration(self) -> float:
        return float(self.acc[ACC_MAX_PEN])


__all__ = ["BodyRigidSpringChain", "advance_chain", "build_chain", "chain_layout"]


# the fused legged walk's pack (``legged_chunk``): boxes a ``carried_boxes.CarriedBoxes``, chain ``STEP``'s
# body arguments (without world, dt and n_steps, which the fused walk gives); the registered functions below are the chain's legged operations on both paths
SpringChainLegs = namedtuple("SpringChainLegs", "boxes chain")


register(SpringChainLegs, box_poses, carry_boxes, sample_boxes, chain_step(STEP, STEP_CHAIN_ITEMS), carry_boxes_feet)
