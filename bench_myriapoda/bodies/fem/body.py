"""``fem``: a creature whose every segment is a fixed-corotational FEM block (orchestration only).

The mesh is a structured chain of tetrahedralized boxes, one per segment
(``mesh.chain_grid``), sharing their end faces; the paper's "3 x 3 x 3
deformable mesh resolution" is ``resolution`` with ``resolution_unit`` nodes
(default: 3 x 3 x 3 nodes = 2 x 2 x 2 cells) or cells.  Muscles scale the rest
shape of each tet (active strain, see ``body_kernels``), so the worm, snake,
sidewinder and caterpillar gaits of the mass-spring body run unchanged; the
same friction models act on the nodes that touch the ground.

Materials in the creature files match the Miller lattice of the same creature:
the lattice's axial stiffness gives an equivalent Young's modulus E = 8 k_s / w
(four edge springs and eight side diagonals per segment, k_s the spring
constant, w the side of the cube).  The damping coefficient keeps the paper's
ratio gamma / E = 50 / 4000 s: eq. 13 damps every relative velocity of an
element's nodes, rigid rotation included, so matching the lattice's relaxation
time instead (gamma = tau E / h^2) makes bending so viscous that a snake cannot
undulate.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ...core.errors import InputError
from ...core.feasibility import tet_mesh_footprint
from ...core.kernel_records import plain
from ...core.protocols import LEGS, MUSCLES, SEGMENTS, Actuation, Observation
from ...core.schema import rng
from ...core.specs import BodyProbes, BodySpec, Footprint, HangingBar
from ..case_scalars import contact_scalars
from .. import step_status as S
from ..friction_kernels import FRICTION_CAPABILITIES, friction_params
from ..placement import place_points
from ..point_masses import point_mass_momentum_probes
from ..scene import Scene, compact, tet_boundary_faces
from ..segment_chain import check_chain_segments, check_legged_gait
from ..segment_frames import NodeSegments, csr_rest_offsets
from . import analytic_systems as AS
from . import benchmarks
from . import body_kernels as BK
from . import kernels as FK
from .element_quality import ElementQuality
from .mesh import cell_lumped_mass, cells_per_segment, chain_grid, signed_volumes, tetrahedralize_surface
from .surfaces import FEM_SURFACE, SURFACE_KINDS
from .system import DT_PAPER, FEMSystem
from .myriapod import STEP, BodyFEMChain, BlockChainLegs  # the legged chain (make_*)

# The legless FEM body's one step function (``BodySpec.legless_step``): ``advance(..., world, dt, n_steps)``
LEGLESS_STEP = BK.advance

FROM_CREATURE = -1.0
MIN_DENSITY_KG_M3 = 1.0e-6  # a given density below it makes node masses denormal and their inverses infinite


def _check_density(v) -> str | None:
    if 0.0 < v < MIN_DENSITY_KG_M3:
        return f"{v!r} is out of range; must be >= {MIN_DENSITY_KG_M3:g} kg/m^3 (or <= 0: from the creature's mass)"
    return None


@dataclass(frozen=True)
class FEMConfig:
    """Keys of ``[bodies.fem]`` in a creature file (and ``--set body.KEY``)."""

    name: str = rng("fem")
    youngs_modulus_pa: float = rng(4000.0, gt=0.0, doc="Young's modulus E [Pa] (paper preset 4000)")
    poisson_ratio: float = rng(0.4, ge=0.0, lt=0.5, doc="Poisson's ratio nu (paper preset 0.4)")
    damping_gamma: float = rng(50.0, ge=0.0, doc="damping coefficient gamma of eq. 13 [N s/m^4] (paper preset 50)")
    density_kg_m3: float = rng(FROM_CREATURE, check=_check_density,
                               doc="density [kg/m^3]; default: creature mass / body volume")
    resolution: int = rng(3, ge=1, le=50, doc="mesh resolution per segment edge (nodes or cells, see resolution_unit)")
    resolution_unit: str = rng("nodes", choices=("nodes", "cells"),
                               doc="the paper's '3 x 3 x 3 resolution' read as nodes (default) or cells")
    tets_per_cell: int = rng(6, choices=(5, 6), doc="tetrahedra per hexahedral cell")
    mass_lumping: str = rng("tets", choices=("tets", "cells"),
                            doc="nodal masses: 'tets' (a quarter of every tet's mass to each of its nodes, eq. 12) "
                                "or 'cells' (an eighth of every hexahedral cell's mass to each corner: the "
                                "dual-cell mass, independent of the tet split; mesh = 'grid' only)")
    mirror_split: bool = rng(True, doc="6 tets per cell: mirror the Kuhn split across the sagittal plane z = 0 so "
                                       "the body bends alike to the left and right (false: the plain Kuhn split, "
                                       "whose straight gait circles by about 6 degrees per cycle)")
    dt_s: float = rng(DT_PAPER, gt=0.0, doc="default time step [s] (paper: 1/3000)")
    mesh: str = rng("grid", doc="'grid' (structured boxes), 'capsule' (a smooth procedural body), "
                                "or a path to a closed surface trimesh loads (tetrahedralized with fTetWild)")
    mesh_edge_length_fac: float = rng(0.06, gt=0.0, le=1.0,
                                      doc="fTetWild target edge length as a fraction of the bounding-box diagonal")
    # Legged creatures only (``fem.myriapod.BodyFEMChain``); the muscle-driven body ignores these keys.
    link_length_m: float = rng(-1.0, doc="legged chain: soft link length between two stiff blocks [m]; -1: half a segment")
    block_density_kg_m3: float = rng(-1.0, doc="legged: density of the stiff blocks [kg/m^3]; -1: the rest of creature.mass_kg")
    rigid_stiffness_factor: float = rng(20.0, ge=1.0, doc="legged chain: Young's modulus of the segment blocks / E")
    support_stiffness_n_m: float = rng(1.0e7, gt=0.0,
                                       doc="legged chain: implicit penalty spring pulling a supported block's "
                                           "leg-attachment node to its target [N/m]")

    def __post_init__(self):
        from ...core.errors import InputError
        if self.resolution_unit == "nodes" and self.resolution < 2:
            raise InputError("body", "body.resolution", f"{self.resolution} nodes per edge give no cell; must be >= 2")
        if self.mesh not in ("grid", "capsule") and not os.path.isfile(self.mesh):
            raise InputError(self.mesh, "body.mesh", "no such file; use 'grid', 'capsule' or the path of a closed "
                                                     "surface mesh trimesh can load")
        if self.mass_lumping == "cells" and self.mesh != "grid":
            raise InputError("body", "body.mass_lumping", "'cells' needs body.mesh = 'grid' (a surface mesh has "
                                                          "no hexahedral cells); use 'tets'")
        if self.mesh != "grid":
            missing = missing_mesh_packages()
            if missing:
                raise InputError(self.mesh, "body.mesh", f"a surface mesh other than 'grid' is tetrahedralized with "
                                                         f"fTetWild, which needs {' and '.join(missing)} (not "
                                                         f"installed): pip install 'bench-myriapoda[mesh]'")


def missing_mesh_packages() -> list[str]:
    """The packages of the ``[mesh]`` extra that are not installed (found without importing them:
    pyvista, which pytetwild imports, takes seconds to import)."""
    import importlib.util

    return [m for m in ("pytetwild", "pyvista") if importlib.util.find_spec(m) is None]


def surface_body_mesh(cfg: FEMConfig, n_seg: int, L: float, w: float, h: float):
    """Tetrahedralize a closed surface scaled to the body's extents: head at x = 0, along -x.

    The surface is ``capsule`` (trimesh's, a smooth worm-like body) or any file
    trimesh loads; its bounding box is mapped onto [-n_seg L, 0] x [0, h] x
    [-w/2, w/2] (its longest axis becomes the body axis).  fTetWild runs once per
    surface and parameter set (disk cache, ``mesh.tetrahedralize_surface``).
    Returns nodes (n, 3) [m], tets (m, 4), tet_segment (m,).
    """
    import trimesh

    from ...core.errors import InputError
    if cfg.mesh == "capsule":
        surf = trimesh.creation.capsule(height=1.0, radius=0.5, count=(16, 16))
    else:
        try:
            surf = trimesh.load_mesh(cfg.mesh, force="mesh")
        except (OSError, ValueError) as exc:
            raise InputError(str(cfg.mesh), "body.mesh", f"cannot load a surface mesh ({exc})") from None
        if not surf.is_watertight:
            raise InputError(str(cfg.mesh), "body.mesh", "the surface is not closed (watertight)")
    v = np.asarray(surf.vertices, dtype=float)
    order = np.argsort(-(v.max(axis=0) - v.min(axis=0)))  # longest extent -> x, then y, then z
    v = v[:, order]
    lo, hi = v.min(axis=0), v.max(axis=0)
    target_lo = np.array([-n_seg * L, 0.0, -0.5 * w])
    target_hi = np.array([0.0, h, 0.5 * w])
    v = target_lo + (v - lo) / (hi - lo) * (target_hi - target_lo)
    faces = np.asarray(surf.faces)
    if np.linalg.det(np.eye(3)[order]) < 0:
        faces = faces[:, ::-1]  # an odd axis permutation mirrors the surface: keep it outward
    nodes, tets = tetrahedralize_surface((v, faces), edge_length_fac=cfg.mesh_edge_length_fac)
    cx = nodes[tets].mean(axis=1)[:, 0]
    tet_seg = np.clip(np.floor(-cx / L).astype(np.int64), 0, n_seg - 1)
    return nodes, tets, tet_seg


def spine_interpolation(s: np.ndarray, pitch: float, n_seg: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Segments (a, b) (n,) int64 and weight w (n,) [-] whose spines interpolate the body's tangent
    at rest arc lengths s (n,) [m from the head]: segment centres sit at (i + 1/2) pitch, and a node
    between centres a and b = a + 1 takes (1 - w) spine[a] + w spine[b] (normalized by the kernel);
    before the first centre or past the last one, the end segment's spine (w = 0)."""
    u = np.clip(np.asarray(s, dtype=float) / pitch - 0.5, 0.0, n_seg - 1.0)
    a = np.minimum(np.floor(u).astype(np.int64), n_seg - 1)
    b = np.minimum(a + 1, n_seg - 1)
    w = np.where(b > a, u - a, 0.0)
    return a, b, np.ascontiguousarray(w)


def default_dt(cfg: FEMConfig) -> float:
    return cfg.dt_s


class BodyFEM(NodeSegments):
    """A segmented creature as one connected tetrahedral mesh, lying along +x (head first)."""

    # the declarations and the case's unpacking below are alike in every body class by design (as in
    # ``massspring.body.BodyMassSpring``)
    name = "fem"
    capabilities = frozenset({MUSCLES})

    def __init__(self, case, world):
        cre = case.creature
        cfg: FEMConfig = case.body
        self.case = case
        n_seg, L, w, h = cre.segments, cre.segment_length_m, cre.width_m, cre.height_m
        if cfg.mesh == "grid":
            nodes, tets, tet_seg = chain_grid(n_seg, L, (h, w), cfg.resolution, cfg.resolution_unit,
                                              cfg.tets_per_cell, mirror=cfg.mirror_split)
            nodes[:, 0] -= n_seg * L  # head face at x = 0, body along -x (as the lattice)
        else:
            nodes, tets, tet_seg = surface_body_mesh(cfg, n_seg, L, w, h)
        volume = float(np.sum(signed_volumes(nodes, tets)))
        rho = cfg.density_kg_m3 if cfg.density_kg_m3 > 0 else cre.mass_kg / volume
        self.density = rho
        lumped = None
        if cfg.mass_lumping == "cells":
            lumped = cell_lumped_mass(tets, signed_volumes(nodes, tets), np.full(len(tets), rho),
                                      cfg.tets_per_cell, len(nodes))
        self.system = sysm = FEMSystem(nodes, tets, E=cfg.youngs_modulus_pa, nu=cfg.poisson_ratio, rho=rho,
                                       gamma=cfg.damping_gamma, mass=lumped)
        self.rest = nodes
        self.tet_seg = np.ascontiguousarray(tet_seg)
        cen = nodes[tets].mean(axis=1)
        self.tet_y = np.ascontiguousarray((cen[:, 1] - 0.5 * h) / (0.5 * h))
        self.tet_z = np.ascontiguousarray(cen[:, 2] / (0.5 * w))
        self.n_segments = self.n_muscle_segments = n_seg
        self.muscle_s = (np.arange(n_seg) + 0.5) * L   # segment centres' rest arc length from the head [m]
        self.body_length_m = cre.body_length_m
        self.segment_pitch_m = cre.segment_length_m  # centre-to-centre distance of segments [m]
        # Each node's friction frame: the spine interpolated to the node's own rest arc length s
        # between the two nearest segment centres (at (i + 1/2) L), node_w * spine[b] + (1 - node_w)
        # * spine[a].  Taking the spine of the (anterior) segment a node belongs to turned the
        # friction frame of every end-face node (2/3 of a 3-node-per-edge mesh) by up to
        # kappa L / 2 (10 degrees at curvature 7 / BL, 20 segments) against the body's own
        # tangent there, and the FEM snake slithered 22 % faster than the kinematic reference
        # (issue 11).  Segment centres average the nodes of each segment's tets.
        self.node_seg, self.node_seg_b, self.node_w = spine_interpolation(-nodes[:, 0], L, n_seg)
        members = [np.unique(tets[tet_seg == i]) for i in range(n_seg)]
        self.seg_ptr = np.concatenate([[0], np.cumsum([len(m) for m in members])]).astype(np.int64)
        self.seg_nodes = np.concatenate(members).astype(np.int64)
        self.seg_rest_offsets = csr_rest_offsets(nodes, self.seg_ptr, self.seg_nodes)
        # the end faces (a smooth surface has no flat end: the nodes within 2 % of a body length)
        end_band = 1e-9 if cfg.mesh == "grid" else 0.02 * n_seg * L
        self.head_nodes = np.flatnonzero(nodes[:, 0] >= nodes[:, 0].max() - end_band)
        self.tail_nodes = np.flatnonzero(nodes[:, 0] <= nodes[:, 0].min() + end_band)

        # the run's world (``world.world``: built once by the runner; a body builds none of its own)
        self.world = world
        self.terr_kind, self.terr = self.world.terrain
        self.fric_model, self.fric = friction_params(case.friction)
        # g [m/s^2] of the world the step is given (``energy``'s potential; the step reads it from the world)
        self.gravity_m_s2 = world.scenario.gravity_m_s2
        self.dt = float(case.dt)
        phys = np.zeros(BK.N_PHYS)
        phys[BK.VOLUME] = 1.0 if case.gait.volume_conserving else 0.0
        contact_scalars(phys, (BK.R_N, BK.R_T, BK.MAX_SPEED, BK.MAX_PEN), case)
        self.phys = phys

        held = np.zeros(len(nodes), dtype=bool)
        if case.scenario.suspended:
            held[self.head_nodes] = True
        sysm.set_fixed(held)
        self.solver = sysm.solver(self.dt)  # the factor of (M + dt D): the step must be given this dt
        sysm.x[:] = place_points(nodes, case, self.world)
        sysm.v[:] = 0.0
        self.x, self.v = sysm.x, sysm.v
        self._b_work = np.zeros((len(self.solver.perm), 3))
        self._force = np.zeros_like(self.x)
        self._act = np.zeros((n_seg, 3))
        self._centers = np.zeros((n_seg, 3))
        self._spine = np.zeros((n_seg, 3))
        self.acc = np.zeros(S.N_ACC)
        self.quality = ElementQuality(len(tets))

    # ------------------------------------------------------------------ stepping
    def advance(self, t0: float, n_steps: int, act: Actuation | None = None) -> tuple[int, int]:
        """``n_steps`` steps in one kernel call reading ``act.muscle`` (row k at step k); return
        (steps done, status code).  t0 [s] is not needed: the actuation carries the time.
        Without ``act`` the muscles are at rest (a passive body)."""
        if act is None:
            act = self._rest_actuation
        self.phys[BK.MUSCLES] = 1.0 if act.muscles_on else 0.0
        mesh, factor, frames, work = self._packs
        return LEGLESS_STEP(self.x, self.v, mesh, act.muscle, factor, frames, self.fric_model, self.fric, self.phys,
                            work, self._act, self.acc, self.world.step_world, self.dt, n_steps)

    @cached_property
    def _packs(self) -> tuple:
        """``body_kernels.advance``'s records (``BodyMesh``, ``BodyFactor``, ``NodeFrames``, ``BodyWork``) as plain
        tuples (``core.kernel_records``: the call's cost), built once by field name: they refer to the body's own
        arrays, which are changed in place only."""
        s, so = self.system, self.solver
        mesh = BK.BodyMesh(mass=s.mass, tets=s.tets, Dm_inv=s.Dm_inv, vol=s.vol, mu=s.mu, lam=s.lam,
                           tet_seg=self.tet_seg, tet_y=self.tet_y, tet_z=self.tet_z)
        factor = BK.BodyFactor(perm=so.perm, sky_first=so.sky_first, sky_ptr=so.sky_ptr, sky_L=so.sky_L,
                               fp_ptr=so.fp_ptr, fp_col=so.fp_col, fp_val=so.fp_val)
        frames = BK.NodeFrames(node_seg=self.node_seg, node_seg_b=self.node_seg_b, node_w=self.node_w,
                               seg_ptr=self.seg_ptr, seg_nodes=self.seg_nodes)
        work = BK.BodyWork(Dm_inv_eff=s.Dm_inv_eff, coef=s.coef, q_ws=s.q_ws, F_work=s.F_work, H_work=s.H_work,
                           inc_ptr=s.inc_ptr, inc_off=s.inc_off, force=self._force, b_work=self._b_work,
                           centers=self._centers, spine=self._spine)
        return plain(mesh), plain(factor), plain(frames), plain(work)

    def compile(self) -> None:
        x, v, acc = self.x.copy(), self.v.copy(), self.acc.copy()
        q = self.system.q_ws.copy()
        Dm, coef = self.system.Dm_inv_eff.copy(), self.system.coef.copy()
        act = Actuation.for_body(self)
        act.muscles_on = True  # compile the active-strain path too
        self.advance(0.0, 1, act)
        self.energy(0.0)
        self._sample_invariants()
        self.sense(Observation(), 0.0)
        self.x[:], self.v[:], self.acc[:] = x, v, acc
        self.system.q_ws[:] = q
        self.system.Dm_inv_eff[:], self.system.coef[:] = Dm, coef
        self.quality.reset()

    @staticmethod
    def status_text(code: int) -> str:
        return S.STATUS_TEXT.get(code, f"status {code}")

    # ------------------------------------------------------------------ observation
    def _sample_invariants(self) -> None:
        self.quality.sample(self.x, self.system.tets, self.system.Dm_inv_eff)


    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        self._sample_invariants()
        BK.segment_spines(self.x, self.seg_ptr, self.seg_nodes, self._centers, self._spine)
        m = self.system.mass
        com = (m[:, None] * self.x).sum(axis=0) / m.sum()
        obs = Observation(t=t, segment_centers=self._centers.copy(), com=com,
                          head=self.x[self.head_nodes].mean(axis=0), tail=self.x[self.tail_nodes].mean(axis=0),
                          energy=np.array(self.energy(t)), nodes=self.x.copy() if with_nodes else None)
        return self._observe_segments(obs, t)

    @cached_property
    def _surface(self) -> tuple[np.ndarray, np.ndarray]:
        """(boundary node ids (V,), outward boundary triangles (F, 3) indexing them); static."""
        faces, _ = tet_boundary_faces(self.system.tets)
        return compact(faces)

    def scene(self) -> Scene:
        """The mesh's boundary triangles over its boundary nodes, world coordinates [m] (``bodies.scene``)."""
        nodes, faces = self._surface
        return Scene(triangles=[(self.x[nodes], faces, FEM_SURFACE)])  # fancy indexing copies

    def energy(self, t: float) -> tuple[float, float, float]:
        """(kinetic, elastic, gravitational) [J]; elastic against the current active rest shape."""
        s = self.system
        ke, pg = BK.kinetic_and_gravity(self.x, self.v, s.mass, self.gravity_m_s2)
        el = FK.elastic_energy(self.x, s.tets, s.Dm_inv_eff, s.vol, s.mu, s.lam)
        return ke, el, pg

    def extra_metrics(self) -> dict[str, float]:
        q = self.quality
        return {"min_J": q.min_J, "inverted_elements_max": float(q.inverted_max),
                "max_strain": q.max_strain, "n_tets": float(len(self.system.tets)),
                "n_nodes": float(len(self.x))}

    def contact_fraction_mean(self) -> float:
        return float(self.acc[S.ACC_CONTACT_SUM] / max(self.acc[S.ACC_STEPS], 1.0))

    def max_penetration(self) -> float:
        return float(self.acc[S.ACC_MAX_PEN])


def make_fem(case, world):
    """The FEM body; a creature with legs is built as one mesh of stiff segment blocks and soft links
    (``fem.myriapod``): legs attach to rigid segments (the creature's morphology; the leg controller
    itself is composed by the runner); world: the run's ``world.world.World``."""
    if case.creature.legs_per_segment:
        return BodyFEMChain(case, world)
    return BodyFEM(case, world)


# --------------------------------------------------------------------------- the backend's declaration
# Everything the suite asks of this body model (the catalog row ``fem``, ``core.specs.BodySpec``): config
# loading, feasibility and validation read this record and never name the body.

def footprint(case) -> Footprint:
    """A grid mesh: segments (a legged chain: blocks and links) of cells of ``tets_per_cell`` tets; a surface mesh
    tetrahedralized by fTetWild at a target edge of fac * bounding-box diagonal: about (1 / fac)^3 tets, within
    a factor of 10."""
    body, n = case.body, int(case.creature.segments)
    tpc = int(body.tets_per_cell)
    if case.creature.legs_per_segment or body.mesh == "grid":
        cx, cy, cz = cells_per_segment(body.resolution, body.resolution_unit)
        parts = max(1, 2 * n - 1) if case.creature.legs_per_segment else n
        return tet_mesh_footprint(parts * cx * cy * cz * tpc, (parts * cx + 1) * (cy + 1) * (cz + 1))
    tets = 10.0 / float(body.mesh_edge_length_fac) ** 3
    return tet_mesh_footprint(tets, tets / 4.0)


def check_buildable(case, source: str) -> None:
    """A legged chain (stiff blocks and soft links in one mesh, ``fem.myriapod``) needs >= 2 segments and, with
    the blocks' density derived, a creature heavier than its links."""
    body, cre = case.body, case.creature
    if not cre.legs_per_segment:
        return
    check_chain_segments(case, source, "a legged fem chain")
    check_legged_gait(case, source, "a legged fem chain")
    if not body.block_density_kg_m3 > 0:
        ll = body.link_length_m if body.link_length_m > 0 else 0.5 * cre.segment_length_m
        rho = body.density_kg_m3 if body.density_kg_m3 > 0 else 1.0
        m_links = rho * (cre.segments - 1) * ll * cre.width_m * cre.height_m
        if not cre.mass_kg > m_links:
            raise InputError(source, "creature.mass_kg", f"{cre.mass_kg} kg is not more than the links' mass "
                                                         f"{m_links:.4g} kg; must be larger (or set "
                                                         "body.block_density_kg_m3)")


# check name -> run by ``validate --quick`` (validation.registry)
def hanging_bar(body, case) -> HangingBar:
    """The legged fem chain (``BodyFEMChain``) as a hanging bar (``core.specs.HangingBar``): every node's mass at
    its rest position along the axis; the blocks ``rigid_stiffness_factor`` E A, the links E A."""
    cfg, cre = case.body, case.creature
    E = cfg.youngs_modulus_pa
    a = cre.height_m * cre.width_m
    return HangingBar(-body.rest[:, 0], body.fem.mass, body.n_blocks, body.pitch, body.block_length,
                      (cfg.rigid_stiffness_factor * E * a, E * a))


def _density(case) -> float:
    """The worm's density [kg/m^3]: ``body.density_kg_m3``, else the creature's mass over its box volume
    (the analytic hanging elongation, ``BodyProbes.density_and_modulus``)."""
    cre = case.creature
    rho = case.body.density_kg_m3
    return rho if rho > 0 else cre.mass_kg / (cre.body_length_m * cre.width_m * cre.height_m)


CHECKS = {"analytic.worm-eps-lambda": True, "analytic.hanging-bar": True, "analytic.cantilever": True,
          "analytic.rigid-rotation": True, "analytic.free-fall-momentum": True, "analytic.damping-pure-mode": True,
          "analytic.damping-oscillating-mode": True, "analytic.slithering": False,
          "analytic.slithering-measured-shape": False,
          "miller.image1-worm-book": False, "miller.image2-snake-coils": False, "miller.image3-sidewinder": False,
          "miller.image4-caterpillar-arch": False, "miller.image4-caterpillar-up": False,
          "miller.image4-caterpillar-down": False, "paper.fig10a-hang": False, "paper.fig10d-walk": False,
          "paper.wave-centipede": False, "paper.kinematic-shortcut-centipede": True,
          "paper.kinematic-shortcut-millipede": True,
          "paper.kinematic-shortcut-worlds": False}

# The record itself has the same shape in every backend (the fields of core.specs.BodySpec, in order): a
# declaration, not repeated logic.
BACKEND = BodySpec(
    name="fem",
    description="Fang et al. 2013 App. A: every segment a fixed-corotational tetrahedral FEM block; "
                "muscles as active strain",
    config_cls=FEMConfig, factory=make_fem, default_dt=default_dt,
    capabilities=frozenset({MUSCLES, SEGMENTS, LEGS}) | FRICTION_CAPABILITIES,
    footprint=footprint, check_buildable=check_buildable, checks=CHECKS,
    # the proportional shape gain its lightly damped element-scale bending waves tolerate once the error is
    # smoothed along the body (controllers/shape_tracking.py; 2 curled the snake onto its back)
    shape_gain_p=0.5,
    # its third-harmonic correction at gain 1 per cycle: without it the snake ran 30 % short of the reference at
    # mu_t / mu_f = 1.5 (docs/explanation/shape-tracking.md)
    shape_harmonic_gain_per_cycle=1.0,
    # per-step wall [s] per size unit with warm kernels, unlegged / legged (harness.schedule): from the quick
    # matrix on the development machine (2-core x86-64, 2026-11-27, 2 workers, heavily shared with other jobs):
    # the median over its cases of (wall - compile) / steps / size, divided by 10, the ratio of that run's
    # summed case times (235 s) to the quiet 16-core machine's (23 s, 1 worker)
    step_cost_s={False: 2.3e-7, True: 4.0e-7},
    # what validation.cross_body's hanging-bar reference reads of a built chain
    hanging_bar=hanging_bar,
    hang_dt_s=1.0 / 6000.0,  # the chain at 5 nodes per edge blows up at 1/3000 s within 1 s
    # the throughput suite's scenes of this body and their sizes, and what the benchmarks time (benchmarks.py)
    suite_scenes=benchmarks.SUITE_SCENES, benchmarks=benchmarks.BENCHMARKS,
    # its kinds of scene surface (surfaces.py)
    surface_kinds=SURFACE_KINDS,
    # what validation's analytic checks measure of the FEM method's own systems (analytic_systems.py)
    # its two body models' steps, the legged chain's and the legless body's (core.specs.BodySpec), and the legged
    # chain's pack, whose registered functions are its legged operations (bodies.legged_chunk)
    step=STEP, legless_step=LEGLESS_STEP, legged_pack=BlockChainLegs,
    probes=BodyProbes(
        rigid_motion_residual=AS.rigid_motion_residual, rigid_motion_scale="mu V^(2/3)",
        bar_under_own_weight=AS.bar_under_own_weight, cantilever_tip=AS.cantilever_tip,
        pure_damping_modes=AS.pure_damping_modes, one_node_step_eigenvalues=AS.one_node_step_eigenvalues,
        density_and_modulus=lambda case: (_density(case), case.body.youngs_modulus_pa),
        **point_mass_momentum_probes(lambda body: body.system.mass)))
