"""``hybrid``: the myriapod paper's body (Sec. 3): rigid segments joined by FEM links.

A hybrid creature has ``creature.segments`` rigid exoskeletal segments (boxes,
``RigidBoxes``) in a row, rigid 0 (the head) at the front; the body is built
along -x from the head (creatures face +x, y up, z to the right).  Between
consecutive boxes sits a deformable link: a structured tetrahedral block
(``fem.mesh.box_grid``) of the fixed-corotational material of App. A whose two
end faces are glued to the facing faces of the two boxes.  The coupling is the
paper's staggered three-step scheme, run inside one numba kernel
(``kernels.advance``, whose docstring gives the steps).

Defaults and why
----------------
* Material: the paper's App. A presets read in SI units, E = 4000 Pa,
  nu = 0.4, rho = 1 kg/m^3, gamma = 50 N s/m^4, and dt = 1/3000 s.  The paper
  gives them without units; they form a consistent set at its own scale of
  segments about 1 unit long (a 1 m link then stretches by well under 1 % per
  kg hanging from it, and the explicit elastic update is far inside its
  stability limit at dt = 1/3000 s), so ``models/chain.toml`` uses 1 m
  segments.
* Rigid segment size: the creature's segment length, width and height, so one
  creature file describes the same animal for every body backend.
* Rigid density: chosen so that the simulated mass (rigid boxes plus the free
  FEM nodes) equals ``creature.mass_kg``.  The lumped masses of the attached
  nodes are not simulated: that material belongs to the rigid segment, whose
  mass includes it.  An explicit ``rigid_density_kg_m3`` wins.
* Link: half a rigid segment long, with the rigid segment's cross-section.
* Resolution: 3 nodes per edge ("3 x 3 x 3", Sec. 6, read as nodes as in
  ``fem.mesh.segment_cells``; ``resolution_unit = "cells"`` gives the other
  reading), 6 tets per cell (Kuhn split): 48 tets per link.
* Rigid contact: the belly scales act on the boxes as on the nodes (``box_friction``): a box's
  x axis is its forward direction, so "coulomb" gives it the anisotropic forward, backward and
  transverse coefficients and "miller" stops its backward sliding (forward and sideways
  ``miller_mu_slide``).  With isotropic friction of ``mu_transverse`` on the boxes, which carry
  most of the mass, a hybrid snake slithered at half the lattice's speed at the same body shape
  and the hybrid worm fell 35 % short of eps * Lambda (issue 11).  The "stick" rule, or an
  explicit ``rigid_friction_mu``, keeps isotropic Coulomb friction of that coefficient
  (``friction.mu_transverse`` by default).  Restitution 0 (Miller's
  inelastic r_n = 0 default).
* FEM nodes touch the ground through the suite's shared point-mass contact
  (``contact_kernels``: the scenario's friction model, then Miller's path
  collision with ``collision.r_n``, ``r_t``), like every other body.

Damping and rotation: eq. 13 pulls every node of a tet toward the tet's mean
velocity, so it also brakes a rigidly *rotating* link (f_i = -gamma V w x
(x_i - x_mean)): a tumbling chain loses angular momentum through its links
(about 40 % in 0.4 s for ``models/chain.toml`` spinning at ~1.7 rad/s).  That is
the paper's damping model, kept as is; the coupling itself conserves linear
and angular momentum to round-off (tests/test_hybrid.py).

Suspended scenarios (Fig. 10): the body hangs straight down from the head
(body axis along -y) and the head box is kinematic, held fixed in place; the
forces the first link exerts on it are taken up by the support.

Muscles (beyond the paper; its Sec. 7 names "actively contractile deformable segments" as the
next step): a legless creature's muscle waves drive the links as active strain, exactly as the
``fem`` body drives its segments (``fem.body_kernels.active_coefficients``: each link tet's rest
shape is scaled along the body axis by the fibre stretch at its centroid).  The links are the
muscle segments (``muscle_s``: their centres' rest arc lengths); since a link of length l is
only part of the pitch P = rigid + link, it takes the strain of the whole pitch (gain P / l), so
a command bends or shortens the body by about as much per unit length as on the other bodies.

Observation: segment centres in body order (rigid 0, link 0, rigid 1, ...),
box centres and link node means; head and tail are the front face centre of
rigid 0 and the back face centre of the last rigid; energies and momenta count
the rigid boxes and the free FEM nodes (attached nodes are part of the boxes).
"""
from __future__ import annotations

import math
from collections import namedtuple
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ...core.errors import InputError
from ...core.kernel_records import plain
from ...core.feasibility import tet_mesh_footprint
from ...core.protocols import LEGS, MUSCLES, SEGMENTS, Actuation, Observation
from ...core.schema import rng
from ...core.specs import BodyProbes, BodySpec, Footprint, HangingBar
from .. import rigid_kernels as rk
from ..fem.element_quality import ElementQuality
from ..fem.mesh import RESOLUTION_UNITS, box_grid, cells_per_segment, segment_cells, signed_volumes
from ..fem.system import DT_PAPER, E_PAPER, GAMMA_PAPER, NU_PAPER, RHO_PAPER, FEMSystem
from ..friction_kernels import FRICTION_CAPABILITIES, friction_params
from ..carried_boxes import (PushedBoxes, box_chain_centers, box_poses, carried_boxes, carry_boxes,
                             carry_boxes_feet, sample_boxes)
from ..legged_chunk import LeggedPackOps, chain_step, register
from ..placement import place_box_chain
from ..rigid_chain import boxes_of, chain_phys, coupling_of
from ..rigid import ContactSettings, RigidBoxes
from ..fem.surfaces import FEM_SURFACE, SURFACE_KINDS as FEM_SURFACE_KINDS
from ..scene import RIGID_BOX, Scene, box_triangles, compact, tet_boundary_faces
from ..segment_chain import (CouplingScratch, SegmentChainLayout, SupportedSegments, chain_sizes, check_chain_segments,
                             check_link_fit)
from . import benchmarks
from . import kernels as K

# The hybrid's one step function (``BodySpec.step``): ``advance`` calls it with a chunk's n steps, the fused legged
# walk with one (``legged_chunk.chain_step``)
STEP = K.advance
STEP_CHAIN_ITEMS = 6  # STEP's body arguments: links, att, boxes, params, coupling, acc (the pack's chain); then world,
#                       dt, n_steps, given by whoever runs it
DERIVED = -1.0  # default of the keys derived from the creature, the friction or the rigid size (HybridConfig)
CONFIG_SOURCE = "[bodies.hybrid]"


@dataclass(frozen=True)
class HybridConfig:
    """Keys of ``[bodies.hybrid]`` in a creature file (and ``--set body.KEY``).

    Keys defaulting to -1 are derived (module docstring): rigid sizes from the
    creature, the rigid density from ``creature.mass_kg``, the link length as
    half a rigid segment, the link cross-section as the rigid one, the boxes'
    friction from ``friction.mu_transverse``.
    """

    name: str = rng("hybrid")
    rigid_length_m: float = rng(DERIVED, gt=0.0, doc="rigid segment length along the body [m]; default creature.segment_length_m")
    rigid_width_m: float = rng(DERIVED, gt=0.0, doc="rigid segment width (along z) [m]; default creature.width_m")
    rigid_height_m: float = rng(DERIVED, gt=0.0, doc="rigid segment height (along y) [m]; default creature.height_m")
    rigid_density_kg_m3: float = rng(DERIVED, gt=0.0,
                                     doc="rigid density [kg/m^3]; default: boxes + free FEM nodes weigh creature.mass_kg")
    link_length_m: float = rng(DERIVED, gt=0.0, doc="deformable link length between two boxes [m]; default half the rigid length")
    link_width_m: float = rng(DERIVED, gt=0.0, doc="link width [m], at most the rigid width; default the rigid width")
    link_height_m: float = rng(DERIVED, gt=0.0, doc="link height [m], at most the rigid height; default the rigid height")
    youngs_modulus_pa: float = rng(E_PAPER, gt=0.0, doc="Young's modulus of the links [Pa] (paper App. A: 4000)")
    poisson_ratio: float = rng(NU_PAPER, gt=-1.0, lt=0.5, doc="Poisson's ratio of the links (paper: 0.4)")
    density_kg_m3: float = rng(RHO_PAPER, gt=0.0, doc="density of the links [kg/m^3] (paper: 1)")
    damping_gamma: float = rng(GAMMA_PAPER, ge=0.0, doc="damping coefficient of eq. 13 [N s/m^4] (paper: 50)")
    resolution: int = rng(3, ge=2, le=64, doc="mesh resolution of a link per edge, in resolution_unit")
    resolution_unit: str = rng("nodes", choices=RESOLUTION_UNITS, doc="'nodes': 3 = 3x3x3 nodes (2x2x2 cells); 'cells'")
    tets_per_cell: int = rng(6, choices=(5, 6), doc="tets per hexahedral cell: 6 (Kuhn) or 5")
    mirror_split: bool = rng(True, doc="6 tets per cell: mirror the Kuhn split across the sagittal plane so the links "
                                       "bend alike to the left and to the right (false: the plain Kuhn split)")
    rigid_restitution: float = rng(0.0, ge=0.0, le=1.0, doc="restitution of box-terrain impacts")
    rigid_friction_mu: float = rng(DERIVED, ge=0.0, doc="Coulomb coefficient of the boxes; default friction.mu_transverse")
    dt_s: float = rng(DT_PAPER, gt=0.0, doc="default time step [s] (paper: 1/3000)")

    def __post_init__(self):
        if self.resolution_unit == "nodes" and self.resolution < 3:
            raise InputError(CONFIG_SOURCE, "resolution", f"{self.resolution} nodes per edge leave no free node "
                                                          "inside a link; use >= 3 nodes (or >= 2 cells)")


def default_dt(cfg: HybridConfig) -> float:
    """``dt_s``: the paper's time step, 1/3000 s (App. A), unless a creature file sets its own."""
    return cfg.dt_s


def hybrid_layout(cfg: HybridConfig, creature) -> SegmentChainLayout:
    """Sizes of the body from the config, defaults taken from the creature (module docstring)."""
    if creature.segments < 2:
        raise ValueError(f"a hybrid body needs at least 2 rigid segments (one link); creature "
                         f"{creature.name!r} has {creature.segments}")
    lr, wr, hr, ll, wl, hl = chain_sizes(cfg, creature).values()
    if wl > wr or hl > hr:
        raise ValueError(f"the link cross-section {hl} x {wl} m (height x width) must fit on the rigid "
                         f"face {hr} x {wr} m")
    cells = segment_cells(cfg.resolution, cfg.resolution_unit)
    return SegmentChainLayout(creature.segments, lr, wr, hr, ll, wl, hl, cells)


@dataclass(frozen=True)
class HybridMesh:
    """The links' mesh in the body frame (head front face at x = 0, axis on y = z = 0).

    nodes (n_nodes, 3) [m]; tets (n_tets, 4); node_link (n_nodes,) link of each
    node; link_nodes (n_links, nodes per link) node ids of each link; attached
    (n_nodes,) bool; att_body (n_nodes,) the rigid segment an attached node is
    glued to (-1 for free nodes); rigid_centres (n_rigid, 3) [m].
    """

    nodes: np.ndarray
    tets: np.ndarray
    node_link: np.ndarray
    link_nodes: np.ndarray
    attached: np.ndarray
    att_body: np.ndarray
    rigid_centres: np.ndarray


MILLER_BACKWARD_MU = 1.0e3  # Miller's rule on a box: backward sliding all but impossible


def box_friction(friction, rigid_friction_mu: float, scaled: bool = True) -> np.ndarray:
    """The boxes' anisotropic friction (``rigid_kernels`` aniso layout: on, mu_f, mu_b, mu_t) for the
    scenario's friction model: a box has a forward axis (its x axis, toward the head) as the
    nodes' spine, so the belly scales act on it as on the nodes.  ``coulomb``: its three kinetic
    coefficients; ``miller``: backward sliding stopped (coefficient ``MILLER_BACKWARD_MU``),
    forward and sideways ``miller_mu_slide``.  Off (isotropic ``rigid_friction_mu``) for ``stick``
    or when ``rigid_friction_mu`` is given explicitly, and for a body without belly scales
    (``scaled`` False: a creature with legs, or the passive Fig. 4 chain: plain boxes)."""
    out = np.zeros(rk.N_ANISO)
    if not scaled or rigid_friction_mu != DERIVED or friction.model == "stick":
        return out
    if friction.model == "coulomb":
        out[:] = (1.0, friction.mu_forward, friction.mu_backward, friction.mu_transverse)
    else:  # miller
        out[:] = (1.0, friction.miller_mu_slide, MILLER_BACKWARD_MU, friction.miller_mu_slide)
    return out


def build_mesh(lay: SegmentChainLayout, tets_per_cell: int = 6, mirror: bool = False) -> HybridMesh:
    """Links between consecutive boxes: link k spans x in [-(k+1) P, -k P - L_rigid] (P the pitch)."""
    nx, ny, nz = lay.cells
    per_layer = (ny + 1) * (nz + 1)
    P = lay.pitch
    all_nodes, all_tets, node_link, attached, att_body, link_nodes = [], [], [], [], [], []
    offset = 0
    for k in range(lay.n_rigid - 1):
        x0 = -(k + 1) * P
        nd, tt = box_grid((lay.link_length, lay.link_height, lay.link_width), (nx, ny, nz),
                          origin=(x0, -0.5 * lay.link_height, -0.5 * lay.link_width), tets_per_cell=tets_per_cell,
                          mirror_z=0.0 if mirror else None)
        layer = np.arange(len(nd)) // per_layer  # node (i, j, k) has index i * per_layer + ...
        back, front = layer == 0, layer == nx
        body = np.full(len(nd), -1, dtype=np.int64)
        body[front] = k          # front face on the back face of rigid k
        body[back] = k + 1       # back face on the front face of rigid k + 1
        all_nodes.append(nd)
        all_tets.append(tt + offset)
        node_link.append(np.full(len(nd), k, dtype=np.int64))
        attached.append(front | back)
        att_body.append(body)
        link_nodes.append(np.arange(len(nd), dtype=np.int64) + offset)
        offset += len(nd)
    centres = np.zeros((lay.n_rigid, 3))
    centres[:, 0] = -np.arange(lay.n_rigid) * P - 0.5 * lay.rigid_length
    return HybridMesh(np.concatenate(all_nodes), np.concatenate(all_tets), np.concatenate(node_link),
                      np.stack(link_nodes), np.concatenate(attached), np.concatenate(att_body), centres)


class BodyHybrid(LeggedPackOps, PushedBoxes, SupportedSegments):
    """Rigid boxes (``self.rigid``) joined by FEM links (``self.fem``) on a terrain.

    State: ``self.x``, ``self.v`` (n_nodes, 3) [m], [m/s] are the FEM's arrays
    (attached rows always equal the rigid bodies' points); the boxes' c, q, v, w
    live in ``self.rigid``.  ``self.free`` / ``self.fixed``: node ids; the kernel
    arrays of the attachment are in ``fixed`` order (``att_body``, ``att_local``).

    Its segment interface (``segment_poses``, ``set_support``, ``push_support``, ``legged_sample``) is
    ``legged_chunk.LeggedPackOps``: the functions registered for ``HybridLegs`` below, which the fused walk runs.
    """

    name = "hybrid"

    def __init__(self, case, world):
        cre = case.creature
        cfg: HybridConfig = case.body
        sc = case.scenario
        self.case = case
        # links take muscle strains; the boxes can be carried by legs (when the creature has them)
        self.capabilities = frozenset({MUSCLES, SEGMENTS} | ({LEGS} if cre.legs_per_segment else set()))
        self.layout = lay = hybrid_layout(cfg, cre)
        mesh = build_mesh(lay, cfg.tets_per_cell, cfg.mirror_split)
        self.mesh = mesh
        self.dt = float(case.dt)
        self.gravity = np.array([0.0, -sc.gravity_m_s2, 0.0])

        # ---- FEM links (App. A) with the attached nodes fixed in the solve
        self.fem = fem = FEMSystem(mesh.nodes, mesh.tets, E=cfg.youngs_modulus_pa, nu=cfg.poisson_ratio,
                                   rho=cfg.density_kg_m3, gamma=cfg.damping_gamma)
        fem.set_fixed(mesh.attached)
        self.solver = fem.solver(self.dt)
        self.fixed = self.solver.fixed            # sorted attached node ids
        # ---- active links: the muscle segments are the links (module docstring, "Muscles")
        n_links = lay.n_rigid - 1
        self.n_segments = lay.n_rigid
        self.segment_pitch_m = lay.pitch
        self.n_muscle_segments = n_links
        self.muscle_s = np.arange(n_links) * lay.pitch + lay.rigid_length + 0.5 * lay.link_length
        cen = mesh.nodes[mesh.tets].mean(axis=1)
        # ``kernels.ActiveLinks`` but its act_buf (each call's muscle buffer, ``_chain_args``)
        self._muscle_static = dict(Dm_inv_rest=fem.Dm_inv.copy(), vol=fem.vol, mu=fem.mu, lam=fem.lam,
                                   tet_link=np.ascontiguousarray(mesh.node_link[mesh.tets[:, 0]]),
                                   tet_y=np.ascontiguousarray(cen[:, 1] / (0.5 * lay.link_height)),
                                   tet_z=np.ascontiguousarray(cen[:, 2] / (0.5 * lay.link_width)))
        self.free = np.sort(fem.free_nodes)
        self.att_body = np.ascontiguousarray(mesh.att_body[self.fixed])
        self.node_link = mesh.node_link

        # ---- rigid boxes
        half = np.array([0.5 * lay.rigid_length, 0.5 * lay.rigid_height, 0.5 * lay.rigid_width])
        free_mass = float(fem.mass[self.free].sum())
        box_volume = lay.rigid_length * lay.rigid_height * lay.rigid_width
        if cfg.rigid_density_kg_m3 == DERIVED:
            m_rigid = (cre.mass_kg - free_mass) / lay.n_rigid
            if m_rigid <= 0.0:
                raise ValueError(f"creature.mass_kg = {cre.mass_kg} kg is less than the free FEM nodes' mass "
                                 f"{free_mass:.4g} kg; raise it or set body.rigid_density_kg_m3")
        else:
            m_rigid = cfg.rigid_density_kg_m3 * box_volume
        self.rigid = RigidBoxes(np.tile(half, (lay.n_rigid, 1)), np.full(lay.n_rigid, m_rigid))
        self.segment_half_extents = np.tile(half, (lay.n_rigid, 1))
        self.total_mass = m_rigid * lay.n_rigid + free_mass

        # ---- world placement, terrain, attached nodes on the boxes
        # the run's world (``world.world``: built once by the runner; a body builds none of its own)
        self.world = world
        self.terr_kind, self.terr = self.world.terrain
        self.fric_model, self.fric = friction_params(case.friction)
        place_box_chain(case, self.world, mesh.nodes, mesh.attached, mesh.rigid_centres, half, self.rigid, self.x,
                        self.v)
        att_local = mesh.nodes[self.fixed] - mesh.rigid_centres[self.att_body]
        self.att_local = np.ascontiguousarray(att_local)  # body frame = the build frame
        self._held = np.zeros(lay.n_rigid, dtype=bool)
        if sc.suspended:
            self.rigid.set_kinematic(0, True)  # the head is held (Fig. 10)
            self._held[0] = True

        # ---- kernel parameters and scratch
        contact = ContactSettings(friction=(case.friction.mu_transverse if cfg.rigid_friction_mu == DERIVED
                                            else cfg.rigid_friction_mu),
                                  restitution=cfg.rigid_restitution)
        self.contact = contact
        phys = chain_phys(case, contact)
        # a link of length l in a pitch P takes the fibre strain of the whole pitch: gain P / l
        phys[K.MUSCLE_GAIN] = lay.pitch / lay.link_length
        # Miller's volume conservation (gait.volume_conserving) thickens a shortening section.  Here the
        # rigid boxes hold the cross-section of both ends of every link, so no thickening can happen; asked
        # for one, the glued link only builds transverse stress that resists its own axial shortening (the
        # worm then fell 27 % short of eps * Lambda; -0.2 % without it).  The links are driven axially only.
        phys[K.VOLUME] = 0.0
        phys[K.RIGID_ANISO:K.RIGID_ANISO + rk.N_ANISO] = box_friction(
            case.friction, cfg.rigid_friction_mu,
            scaled=not case.creature.legs_per_segment and case.gait.name != "passive")
        self.phys = phys
        n_nodes, n_fixed, n_rigid = fem.n_nodes, len(self.fixed), lay.n_rigid
        self._f_work = np.zeros((n_nodes, 3))
        self._b_work = np.zeros((len(self.free), 3))
        self.scratch = CouplingScratch.new(n_fixed, n_rigid, rk.N_CORNERS)
        self.acc = np.zeros(K.N_ACC)
        self.quality = ElementQuality(fem.n_tets)
        self.sync_attached()
        self._setup_stance(case)  # the dynamic stance (legs.stance, bodies.dynamic_stance)

    # ------------------------------------------------------------------ state
    @property
    def x(self) -> np.ndarray:
        return self.fem.x

    @property
    def v(self) -> np.ndarray:
        return self.fem.v

    def sync_attached(self) -> None:
        """Put the attached nodes on the boxes' current state (after editing the rigid state by hand)."""
        x_pred = np.ascontiguousarray(self.x[self.fixed])
        K.place_attached_nodes(self.fixed, self.att_body, self.att_local, self.rigid.c, self.rigid.q,
                               self.rigid.v, self.rigid.w, self.scratch.Rb, self.x, self.v, x_pred, self.scratch.residual)

    # ------------------------------------------------------------------ stepping
    def advance(self, t0: float, n_steps: int, act: Actuation | None = None) -> tuple[int, int]:
        """Run ``n_steps`` coupled steps in one kernel call; return (steps done, status code).

        ``act.muscle`` (rows, n_links, 3) drives the links as active strain (row k at step k) when
        ``act.muscles_on``; supported segments are moved by ``apply_support``.  t0 [s] is unused.
        """
        if act is None or not act.muscles_on:
            self.phys[K.MUSCLES_ON] = 0.0
            buf = self._no_muscle
        else:
            self.phys[K.MUSCLES_ON] = 1.0
            buf = act.muscle
        return STEP(*self._chain_args(buf), self.acc, self.world.step_world, self.dt, int(n_steps))

    def _chain_args(self, muscle_buf: np.ndarray) -> tuple:
        """``hybrid.kernels.advance``'s records (``kernels.FEMLinks``, ``rigid_chain``'s ``Attachment``, ``Boxes``,
        ``ChainParams``, ``Coupling``) as plain tuples (``core.kernel_records``: the call's cost), with muscle_buf (rows,
        n_links, 3) the links' active strain: ``_packs`` with this call's muscle buffer put in."""
        links, att, boxes, params, coupling = self._packs
        muscle = links[_MUSCLE][:-1] + (muscle_buf,)  # ``ActiveLinks``' last field, act_buf
        return links[:_MUSCLE] + (muscle,) + links[_MUSCLE + 1:], att, boxes, params, coupling

    @cached_property
    def _packs(self) -> tuple:
        """``_chain_args``' plain tuples, built once by field name: they refer to the body's own arrays, which are
        changed in place only (building them at every call cost about 6 us of the Python path's step)."""
        fem, s = self.fem, self.solver
        links = K.FEMLinks(x=fem.x, v=fem.v, n_free=len(s.perm), tets=fem.tets, Dm_inv=fem.Dm_inv_eff, coef=fem.coef,
                           muscle=plain(K.ActiveLinks(act_buf=self._no_muscle, **self._muscle_static)), mass=fem.mass,
                           q_ws=fem.q_ws, F_work=fem.F_work, H_work=fem.H_work, inc_ptr=fem.inc_ptr,
                           inc_off=fem.inc_off, perm=s.perm, sky_first=s.sky_first, sky_ptr=s.sky_ptr, sky_L=s.sky_L,
                           fp_ptr=s.fp_ptr, fp_col=s.fp_col, fp_val=s.fp_val, pf_ptr=s.pf_ptr, pf_col=s.pf_col,
                           pf_val=s.pf_val, node_link=self.node_link, f_work=self._f_work, b_work=self._b_work)
        params = K.ChainParams(fric_model=self.fric_model, fric=self.fric, phys=self.phys)
        return (plain(links), plain(K.Attachment(fixed=s.fixed, att_body=self.att_body, att_local=self.att_local)),
                plain(boxes_of(self.rigid)), plain(params), plain(coupling_of(self.scratch)))

    def legged_pack(self) -> "HybridLegs":
        """The fused legged walk's pack (``legged_chunk``): the carried boxes and the step's arguments
        without muscles (the fused path does not actuate the links)."""
        self.phys[K.MUSCLES_ON] = 0.0
        return HybridLegs(self._carried(), self._chain_args(self._no_muscle) + (self.acc,))

    def _carried(self):
        """The boxes' ``carried_boxes.CarriedBoxes`` (legged_pack, push_support)."""
        return carried_boxes(self.rigid, self._held, self.x, self.v, self.fixed, self.att_body, self.att_local,
                             self.mesh.link_nodes, self.scratch.Rb, self.scratch.qtmp, self.dt, self.stance)

    @cached_property
    def _no_muscle(self) -> np.ndarray:
        return np.zeros((1, self.n_muscle_segments, 3))

    def _state_arrays(self) -> HybridDynamicState:
        """The arrays ``compile``'s trial step changes, by name (the live arrays, not copies)."""
        rb = self.rigid
        return HybridDynamicState(x=self.x, v=self.v, q_ws=self.fem.q_ws, rigid_c=rb.c, rigid_q=rb.q, rigid_v=rb.v,
                                  rigid_w=rb.w, impulse_cache=rb.impulse_cache, kinematic=rb.kinematic,
                                  acc=self.acc, dm_inv_eff=self.fem.Dm_inv_eff, coef=self.fem.coef)

    def _state(self) -> HybridDynamicState:
        return HybridDynamicState(*(a.copy() for a in self._state_arrays()))

    def _restore(self, saved: HybridDynamicState) -> None:
        """Copy ``saved`` (from ``_state``) back into the live arrays in place (kernels and packs hold them)."""
        for name, dst in self._state_arrays()._asdict().items():
            dst[...] = getattr(saved, name)

    def compile(self) -> None:
        """Trigger (or load from cache) the JIT compilation without changing the state."""
        saved = self._state()
        act = Actuation.for_body(self)
        act.muscles_on = True  # compile the active-link path too
        self.advance(0.0, 1, act)
        self.observe(0.0)
        self.set_support(np.zeros(self.n_segments, bool), *self.segment_poses(), self.dt)
        if self.dynamic_stance:
            stance_acc = self.stance.acc.copy()
            self.push_support(np.zeros(self.n_segments, bool), *self.segment_poses(),
                              np.zeros(2 * self.n_segments, np.int64), np.zeros((2 * self.n_segments, 3)))
            self.stance.acc[:] = stance_acc
        self.energy(0.0)
        self.momenta()
        self.tet_quality()
        self._restore(saved)
        self.quality.reset()

    @staticmethod
    def status_text(code: int) -> str:
        return K.STATUS_TEXT.get(code, f"status {code}")

    # ------------------------------------------------------------------ observation
    def rotation_matrices(self) -> np.ndarray:
        """(n_rigid, 3, 3) body-to-world rotations of the boxes."""
        return self.rigid.rotation_matrices()

    def box_corners(self) -> np.ndarray:
        """(n_rigid * 8, 3) [m] box corners, corner k of a box at signs (bit 0: +x, bit 1: +y, bit 2: +z)."""
        return self.rigid.corners()

    @cached_property
    def _link_surface(self) -> tuple[np.ndarray, np.ndarray]:
        """(boundary node ids (V,), outward triangles (F, 3) indexing them) of the FEM links; static."""
        faces, _ = tet_boundary_faces(self.fem.tets)
        return compact(faces)

    def scene(self) -> Scene:
        """The boxes and the links' boundary triangles, world coordinates [m] (``bodies.scene``).

        A link's end faces lie on its boxes' faces (attached nodes); they are kept
        so that every link is a closed surface in an exported mesh.
        """
        verts, faces = box_triangles(self.box_corners())
        tris = [(verts, faces, RIGID_BOX)]
        if self.fem.n_tets:
            nodes, link_faces = self._link_surface
            tris.append((self.x[nodes], link_faces, FEM_SURFACE))
        return Scene(triangles=tris)

    # ------------------------------------------------------------------ segment interface (legged creatures)
    def segment_velocities(self) -> np.ndarray:
        """(n_rigid, 3) [m/s] velocities of the boxes' centres."""
        return self.rigid.v

    @property
    def body_length_m(self) -> float:
        """Rest length from the head's front face to the tail's back face, links included [m]."""
        return self.layout.body_length

    def segment_centers(self) -> np.ndarray:
        """(2 n_rigid - 1, 3) [m]: rigid 0, link 0, rigid 1, ..., rigid n-1 (box centres, link node means)."""
        return box_chain_centers(self.rigid.c, self.x, self.mesh.link_nodes)

    def centre_of_mass(self) -> np.ndarray:
        """(3,) [m] of the boxes and the free nodes (the attached nodes' mass is in the boxes)."""
        rb = self.rigid
        m_free = self.fem.mass[self.free]
        return (rb.mass @ rb.c + m_free @ self.x[self.free]) / self.total_mass

    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        rb = self.rigid
        R = self.rotation_matrices()
        head, tail = rb.chain_ends(R, self.layout.rigid_length)
        com = self.centre_of_mass()
        self.quality.sample(self.x, self.fem.tets, self.fem.Dm_inv)
        nodes = np.vstack([self.x, self.box_corners()]) if with_nodes else None
        obs = Observation(t=t, segment_centers=self.segment_centers(), com=com, head=head, tail=tail,
                          energy=np.array(self.energy(t)), nodes=nodes)
        return self._observe_segments(obs, t)

    def energy(self, t: float = 0.0) -> tuple[float, float, float]:
        """(kinetic, elastic, gravitational) [J] of the boxes and free nodes; gravity from y = 0.

        Elastic energy of every tet (eq. 6), including those touching attached nodes.
        """
        rb = self.rigid
        e_r = rb.energy(self.gravity)
        m = self.fem.mass[self.free]
        v = self.v[self.free]
        kinetic = float(e_r.kinetic_linear.sum() + e_r.kinetic_rotational.sum() + 0.5 * np.einsum("i,ij,ij->", m, v, v))
        g = -self.gravity[1]
        grav = float(g * (rb.mass @ rb.c[:, 1] + m @ self.x[self.free, 1]))
        return kinetic, self.fem.elastic_energy(), grav

    def momenta(self, origin=None) -> tuple[np.ndarray, np.ndarray]:
        """Total linear momentum P (3,) [kg m/s] and angular momentum L (3,) [kg m^2/s] about
        ``origin`` (default: the centre of mass), of the boxes and the free nodes."""
        rb = self.rigid
        if origin is None:
            origin = self.centre_of_mass()
        out = np.zeros(6)
        rk.quat_to_matrix(rb.q, self.scratch.Rb)
        K.momenta(self.x, self.v, self.fem.mass, self.free, rb.c, rb.v, rb.w, rb.mass, rb.inertia_body,
                  self.scratch.Rb, np.ascontiguousarray(origin, dtype=np.float64), out)
        return out[:3].copy(), out[3:].copy()

    # ------------------------------------------------------------------ metrics
    def tet_quality(self) -> tuple[float, int, float]:
        """(min J, count of tets with J <= 0, max principal strain max |sigma_i - 1|) of the current state.

        One SVD per tet (``fem.kernels.tet_invariants``), F from the rest shape.
        """
        return self.quality.current(self.x, self.fem.tets, self.fem.Dm_inv)

    def coupling_residual(self) -> tuple[float, float]:
        """(max, mean) [m] over all steps and attached nodes of |x_p + dt v_p - x_p(rigid, n+1)|."""
        acc = self.acc
        mean = acc[K.ACC_RES_SUM] / acc[K.ACC_RES_COUNT] if acc[K.ACC_RES_COUNT] > 0 else 0.0
        return float(acc[K.ACC_RES_MAX]), float(mean)

    def extra_metrics(self) -> dict[str, float]:
        """Tet quality over the observation samples and the coupling residual over all steps."""
        res_max, res_mean = self.coupling_residual()
        q = self.quality
        return {"min_J": q.min_J, "inverted_elements_max": float(q.inverted_max),
                "inverted_elements_final": float(q.inverted_last), "max_strain": q.max_strain,
                "coupling_residual_max_m": res_max, "coupling_residual_mean_m": res_mean, **self.stance_statistics()}

    def contact_fraction_mean(self) -> float:
        """Mean fraction of contact points (free nodes and box corners) within the contact distance."""
        return float(self.acc[K.ACC_CONTACT_SUM] / max(self.acc[K.ACC_STEPS], 1.0))

    def max_penetration(self) -> float:
        """Deepest free node (after Miller's collision, before the push-out) or box corner [m]."""
        return float(self.acc[K.ACC_MAX_PEN])


def make_hybrid(case, world):
    """The hybrid body, for every creature (legged or not: the runner composes the controller), in the run's
    world (``world.world.World``)."""
    return BodyHybrid(case, world)


# --------------------------------------------------------------------------- the backend's declaration
# Everything the suite asks of this body model (the catalog row ``hybrid``, ``core.specs.BodySpec``): config
# loading, feasibility and validation read this record and never name the body.

def footprint(case) -> Footprint:
    """The links' tetrahedral mesh: ``n - 1`` links of cells of ``tets_per_cell`` tets (the boxes are 13 numbers
    each)."""
    body = case.body
    cx, cy, cz = cells_per_segment(body.resolution, body.resolution_unit)
    links = max(1, int(case.creature.segments) - 1)
    return tet_mesh_footprint(links * cx * cy * cz * int(body.tets_per_cell), links * (cx + 1) * (cy + 1) * (cz + 1))


def check_buildable(case, source: str) -> None:
    """>= 2 segments (one link), links that fit on the boxes' faces and, with the boxes' density derived, a
    creature heavier than the links' free nodes."""
    check_chain_segments(case, source, "a hybrid body")
    check_link_fit(case, source)
    cre = case.creature
    if case.body.rigid_density_kg_m3 == DERIVED:
        free = free_link_mass(case)
        if not cre.mass_kg > free:
            raise InputError(source, "creature.mass_kg", f"{cre.mass_kg} kg is not more than the free FEM nodes' "
                                                         f"mass {free:.4g} kg; must be larger (or set "
                                                         "body.rigid_density_kg_m3)")


def free_link_mass(case) -> float:
    """Lumped mass of the links' free nodes [kg]: the link mesh is built (numpy only; its size is bounded by
    the resource check, which runs first) and each tet's mass shared by its four nodes."""
    lay = hybrid_layout(case.body, case.creature)
    m = build_mesh(lay, case.body.tets_per_cell)
    share = np.repeat(case.body.density_kg_m3 * signed_volumes(m.nodes, m.tets) / 4.0, 4)
    mass = np.bincount(m.tets.ravel(), weights=share, minlength=len(m.nodes))
    return float(mass[~m.attached].sum())


def _add_velocity(body: BodyHybrid, dv) -> None:
    """Add ``dv`` (3,) [m/s] to every free node and box, the attached nodes following their boxes
    (``BodyProbes.add_velocity``)."""
    dv = np.asarray(dv, dtype=float)
    body.v[:] += dv
    body.rigid.v[:] += dv
    body.sync_attached()


# check name -> run by ``validate --quick`` (validation.registry): the legged paper checks' quick body
CHECKS = {"analytic.worm-eps-lambda": False, "analytic.free-fall-momentum": True, "analytic.slithering": False,
          "analytic.slithering-measured-shape": False,
          "miller.image1-worm-book": False, "miller.image2-snake-coils": False, "miller.image3-sidewinder": False,
          "miller.image4-caterpillar-arch": False, "miller.image4-caterpillar-up": False,
          "miller.image4-caterpillar-down": False, "paper.fig4-drop": True, "paper.fig10a-hang": True,
          "paper.fig10d-walk": True, "paper.wave-centipede": True, "paper.wave-millipede": False,
          "paper.control-turn": False, "paper.foraging": False, "paper.avoidance": False,
          "paper.kinematic-shortcut-centipede": True, "paper.kinematic-shortcut-millipede": True,
          "paper.kinematic-shortcut-worlds": False,
          "throughput.sec6-headline": True}

# where ``kernels.FEMLinks`` holds the muscles, and their buffer last in ``kernels.ActiveLinks`` (``_chain_args``)
_MUSCLE = K.FEMLinks._fields.index("muscle")
assert K.ActiveLinks._fields[-1] == "act_buf"

# The hybrid's dynamic state that ``BodyHybrid.compile`` saves before its trial step and restores after it:
# FEM nodes (x, v, acc), the tets' rotation warm starts (q_ws), the boxes' poses, velocities, contact impulse
# warm starts and kinematic flags (rigid_*), and the active links' Dm^-1 A^-1 and packed coefficients.
HybridDynamicState = namedtuple("HybridDynamicState", "x v q_ws rigid_c rigid_q rigid_v rigid_w impulse_cache "
                                "kinematic acc dm_inv_eff coef")

# the fused legged walk's pack (``legged_chunk``): boxes a ``carried_boxes.CarriedBoxes``, chain ``STEP``'s body
# arguments (without world, dt and n_steps, which the fused walk gives); the registered functions below are the hybrid's legged operations on both paths
HybridLegs = namedtuple("HybridLegs", "boxes chain")


register(HybridLegs, box_poses, carry_boxes, sample_boxes, chain_step(STEP, STEP_CHAIN_ITEMS), carry_boxes_feet)

# The record itself has the same shape in every backend (the fields of core.specs.BodySpec, in order): a
# declaration, not repeated logic.
def hanging_bar(body, case) -> HangingBar:
    """The hybrid chain as a hanging bar (``core.specs.HangingBar``): its boxes' masses at their centres and its
    links' free nodes' at their rest positions (the attached nodes' share of a link's mass belongs to no one);
    the boxes rigid, the links E A."""
    lay = body.layout
    n, P = lay.n_rigid, lay.pitch
    s_mass = np.concatenate([np.arange(n) * P + 0.5 * lay.rigid_length, -body.mesh.nodes[body.free, 0]])
    mass = np.concatenate([body.rigid.mass, body.fem.mass[body.free]])
    return HangingBar(s_mass, mass, n, P, lay.rigid_length,
                      (math.inf, case.body.youngs_modulus_pa * lay.link_height * lay.link_width))


BACKEND = BodySpec(
    name="hybrid",
    description="Fang et al. 2013 Sec. 3: rigid box segments joined by fixed-corotational FEM links, staggered "
                "coupling; muscles as active strain of the links",
    config_cls=HybridConfig, factory=make_hybrid, default_dt=default_dt,
    capabilities=frozenset({MUSCLES, SEGMENTS, LEGS}) | FRICTION_CAPABILITIES,
    footprint=footprint, check_buildable=check_buildable, checks=CHECKS,
    # its one step and the pack whose registered functions are its legged operations (bodies.legged_chunk)
    step=STEP, legged_pack=HybridLegs,
    # the proportional shape gain its box-and-link chain tolerates once the error is smoothed along the body
    # (controllers/shape_tracking.py): 0.5 blew the snake up at mu_t / mu_f = 1, and 2 at 5
    shape_gain_p=0.25,
    # its third-harmonic correction at half the others' gain: at 1 per cycle the snake missed its shape at
    # mu_t / mu_f = 1 (error 0.153, the harmonic still settling after 11 cycles; docs/explanation/shape-tracking.md)
    shape_harmonic_gain_per_cycle=0.5,
    # per-step wall [s] per size unit with warm kernels, unlegged / legged (harness.schedule): from the quick
    # matrix on the development machine (2-core x86-64, 2026-11-27, 2 workers, heavily shared with other jobs):
    # the median over its cases of (wall - compile) / steps / size, divided by 10, the ratio of that run's
    # summed case times (235 s) to the quiet 16-core machine's (23 s, 1 worker)
    step_cost_s={False: 5.0e-7, True: 3.2e-7},
    # what validation.cross_body's hanging-bar reference reads of a built chain
    hanging_bar=hanging_bar,
    # the throughput suite's scenes of this body and their sizes, and what the benchmarks time (benchmarks.py)
    suite_scenes=benchmarks.SUITE_SCENES, benchmarks=benchmarks.BENCHMARKS,
    # its own kind of scene surface: the links, drawn as the fem body's meshes (its boxes are a shared kind)
    surface_kinds={FEM_SURFACE: FEM_SURFACE_KINDS[FEM_SURFACE]},
    # what validation's analytic checks measure: the momenta of boxes and free nodes together
    probes=BodyProbes(
        rigid_motion_not_applicable="the hybrid's links are the fem body's FEMSystem (checked on fem); its boxes "
                                    "are rigid",
        linear_momentum=lambda body: body.momenta()[0], total_mass=lambda body: float(body.total_mass),
        add_velocity=_add_velocity))
