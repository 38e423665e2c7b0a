"""``massspring``: Miller's cube-lattice body (Miller 1988), orchestration only.

Units.  Miller gives k and D "per unit mass" in his own units.  We read them
as accelerations per unit length in units where time is one animation frame
(``frame_rate_hz``, 30 by default): a spring between masses m carries
k_SI = k * fps^2 * m [N/m] and D_SI = D * fps * m [N s/m].  The presets keep
Miller's numbers (worm k = 1.5, D = 0.9, 10 substeps per frame; snake k = 0.5,
D = 3.5, 25 substeps; caterpillar k = 0.3, D = 0.6) and the default time step
is one substep, dt = 1 / (fps * substeps).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ...core.errors import InputError
from ...core.feasibility import lattice_footprint
from ...core.protocols import LEGS, MUSCLES, SEGMENTS, Actuation, Observation
from ...core.schema import rng
from ...core.specs import BodyProbes, BodySpec, Footprint
from ..case_scalars import contact_scalars
from ..friction_kernels import FRICTION_CAPABILITIES, friction_params
from ..placement import place_points
from ..point_masses import point_mass_momentum_probes
from ..scene import Scene
from .lattice import LATTICE_SURFACE, SURFACE_KINDS, lattice_surface_faces
from .. import step_status as S
from ..segment_chain import chain_sizes, check_chain_segments, check_legged_gait, check_link_fit
from ..segment_frames import NodeSegments, csr_rest_offsets
from . import analytic_systems as AS
from . import benchmarks
from . import kernels as K
from .lattice import CUBE_FAMILIES, build_lattice, face_stride, spring_families
from .myriapod import STEP, BodyRigidSpringChain, SpringChainLegs  # the legged chain (make_*)

# The legless lattice's one step function (``BodySpec.legless_step``): ``advance(..., world, dt, n_steps)``
LEGLESS_STEP = K.advance


# Miller 1988 Sec. 5: spring constant k and damping D per unit mass, and substeps per frame
# (Miller gives no substep count for the caterpillar; we use the worm's 10).
MILLER_PRESETS = {
    "miller-worm": dict(stiffness=1.5, damping=0.9, substeps_per_frame=10),
    "miller-snake": dict(stiffness=0.5, damping=3.5, substeps_per_frame=25),
    "miller-caterpillar": dict(stiffness=0.3, damping=0.6, substeps_per_frame=10),
}
FROM_PRESET = -1  # default of the preset-backed keys: take the value from ``preset``


@dataclass(frozen=True)
class MassSpringConfig:
    """Keys of ``[bodies.massspring]`` in a creature file (and ``--set body.KEY``).

    ``stiffness``, ``damping`` and ``substeps_per_frame`` come from the named
    Miller preset unless given explicitly.
    """

    name: str = rng("massspring")
    preset: str = rng("miller-worm", choices=tuple(MILLER_PRESETS), doc="Miller's constants for a creature")
    stiffness: float = rng(float(FROM_PRESET), ge=0.0, doc="Miller's k per unit mass [1/frame^2]")
    damping: float = rng(float(FROM_PRESET), ge=0.0, doc="Miller's D per unit mass [1/frame]")
    frame_rate_hz: float = rng(60.0, gt=0.0, le=1.0e6,
                               doc="frame rate that defines Miller's time unit [Hz] (k_SI grows with its square)")
    substeps_per_frame: int = rng(FROM_PRESET, ge=1, le=100000, doc="integration substeps per frame; dt = 1/(fps*substeps)")
    integrator: str = rng("symplectic", choices=("symplectic", "euler"),
                          doc="semi-implicit Euler, or Miller's explicit Euler x += v dt + a dt^2/2")
    # Legged creatures only (``massspring.myriapod.BodyRigidSpringChain``): rigid boxes joined by
    # spring-cube links.  The Miller lattice ignores these keys; -1 = derived from the creature.
    rigid_length_m: float = rng(-1.0, doc="legged chain: rigid segment length [m]; -1: creature.segment_length_m")
    rigid_width_m: float = rng(-1.0, doc="legged chain: rigid segment width (z) [m]; -1: creature.width_m")
    rigid_height_m: float = rng(-1.0, doc="legged chain: rigid segment height (y) [m]; -1: creature.height_m")
    link_length_m: float = rng(-1.0, doc="legged chain: spring link length [m]; -1: half the rigid length")
    link_width_m: float = rng(-1.0, doc="legged chain: link width [m] (<= rigid width); -1: the rigid width")
    link_height_m: float = rng(-1.0, doc="legged chain: link height [m] (<= rigid height); -1: the rigid height")
    link_cells: int = rng(2, ge=1, le=64, doc="legged chain: spring cubes along a link (>= 2 gives free nodes)")
    link_stiffness_n_m: float = rng(600.0, gt=0.0, doc="legged chain: spring constant of every link spring [N/m]")
    link_damping_n_s_m: float = rng(5.0, ge=0.0, doc="legged chain: damping constant of every link spring [N s/m]")
    link_density_kg_m3: float = rng(1.0, gt=0.0, doc="legged chain: link density, lumped equally on its nodes [kg/m^3]")
    rigid_friction_mu: float = rng(-1.0, doc="legged chain: Coulomb mu of the boxes; -1: friction.mu_transverse")

    def __post_init__(self):
        for key, value in MILLER_PRESETS[self.preset].items():
            if getattr(self, key) == FROM_PRESET:
                object.__setattr__(self, key, value)


def default_dt(cfg: MassSpringConfig) -> float:
    return 1.0 / (cfg.frame_rate_hz * cfg.substeps_per_frame)


class BodyMassSpring(NodeSegments):
    """A creature as a Miller cube lattice on a terrain.

    State: ``x``, ``v`` (n_nodes, 3) [m], [m/s].  The body is built lying
    along +x (head first) with its underside ``start_height_m`` above the
    terrain, turned to lie along a slope if the terrain is one.
    """

    # the declarations and the case's unpacking below are alike in every body class by design (as in
    # ``fem.body.BodyFEM``)
    name = "massspring"
    capabilities = frozenset({MUSCLES})

    def __init__(self, case, world):
        cre = case.creature
        cfg: MassSpringConfig = case.body
        self.case = case
        self.lattice = lat = build_lattice(cre.segments, cre.segment_length_m, cre.width_m, cre.height_m)
        n = lat.n_nodes
        m_node = cre.mass_kg / n
        self.mass = np.full(n, m_node)
        self.inv_mass = 1.0 / self.mass
        if case.scenario.suspended:
            self.inv_mass[:4] = 0.0  # the head face is held: the kernel leaves masses with 1/m = 0 in place
        fps = cfg.frame_rate_hz
        self.stiffness = np.full(lat.n_springs, cfg.stiffness * fps * fps * m_node)
        self.damping = np.full(lat.n_springs, cfg.damping * fps * m_node)
        # muscle segments: one per lattice segment, at its centre's rest arc length from the head [m]
        self.n_segments = self.n_muscle_segments = cre.segments
        self.muscle_s = (np.arange(cre.segments) + 0.5) * cre.segment_length_m
        self.body_length_m = cre.body_length_m
        self.segment_pitch_m = cre.segment_length_m  # centre-to-centre distance of segments [m]
        # segment i owns the 8 nodes of faces i and i + 1 (CSR for ``segment_frames``)
        self.seg_ptr = np.arange(cre.segments + 1, dtype=np.int64) * 8
        self.seg_nodes = np.concatenate([np.arange(4 * i, 4 * i + 8) for i in range(cre.segments)]).astype(np.int64)
        self.seg_rest_offsets = csr_rest_offsets(lat.rest_nodes, self.seg_ptr, self.seg_nodes)
        # the run's world (``world.world``: built once by the runner; a body builds none of its own)
        self.world = world
        self.terr_kind, self.terr = self.world.terrain
        self.fric_model, self.fric = friction_params(case.friction)
        # g [m/s^2] of the world the step is given (``energy``'s potential; the step reads it from the world)
        self.gravity_m_s2 = world.scenario.gravity_m_s2
        self.dt = float(case.dt)
        phys = np.zeros(K.N_PHYS)
        phys[K.VOLUME] = 1.0 if case.gait.volume_conserving else 0.0
        contact_scalars(phys, (K.R_N, K.R_T, K.MAX_SPEED, K.MAX_PEN), case)
        phys[K.INTEGRATOR] = K.EULER if cfg.integrator == "euler" else K.SYMPLECTIC
        self.phys = phys
        self.x = place_points(lat.rest_nodes, case, self.world)
        self.v = np.zeros_like(self.x)
        # work arrays and accumulators for the kernel
        self._act = np.zeros((cre.segments, 3))
        self._rest = lat.rest_length.copy()
        self._face_scale = np.ones(cre.segments + 1)
        self._stretch = np.ones((cre.segments, 4))
        self._spine = np.zeros((cre.segments + 1, 3))
        self.acc = np.zeros(S.N_ACC)
        # the step kernel's spring families (its column loops take lattice.CUBE_FAMILIES and CUBE_PLAN as
        # constants) and corner-major work arrays (kernels module docstring); the families' work arrays serve
        # their reference kernels (tests)
        n_faces = cre.segments + 1
        self.families = spring_families(lat, self.stiffness, self.damping)
        if tuple(tuple(int(c) for c in r) for r in self.families.index) != CUBE_FAMILIES:
            raise ValueError("the lattice's spring families are not lattice.CUBE_FAMILIES, which the step kernel runs")
        stride = face_stride(n_faces)
        # positions and velocities carry a fifth, padding corner row: the spring loops over whole rows
        # read b ends up to one column past the fourth
        self._xc, self._vc = np.zeros((3, 5, stride)), np.zeros((3, 5, stride))
        self._fc = np.zeros((3, 4, stride))
        self._st, self._fs = np.ones(4 * stride), np.ones(4 * stride)
        self._dfs = np.zeros((3, stride))
        self._rest_fam = np.zeros((self.families.index.shape[0], stride))
        self._stretch_c = np.ones((4, cre.segments))

    # ------------------------------------------------------------------ stepping
    def advance(self, t0: float, n_steps: int, act: Actuation | None = None) -> tuple[int, int]:
        """Run ``n_steps`` steps in one kernel call reading ``act.muscle`` (row k at step k); return
        (steps done, status code).  t0 [s] is not needed: the actuation carries the time.
        Without ``act`` the muscles are at rest (a passive body)."""
        if act is None:
            act = self._rest_actuation
        return LEGLESS_STEP(self.x, self.v, self.inv_mass, self.families.params, act.muscle, self.fric_model,
                            self.fric, self.phys,
                            (self._xc, self._vc, self._fc, self._st, self._fs, self._face_scale, self._spine),
                            self._act, self.acc, self.world.step_world, self.dt, n_steps)

    def compile(self) -> None:
        """Trigger (or load from cache) the JIT compilation without changing the state."""
        x, v, acc, a = self.x.copy(), self.v.copy(), self.acc.copy(), self._act.copy()
        self.advance(0.0, 1, Actuation.for_body(self))
        self.energy(0.0)
        self.sense(Observation(), 0.0)
        self.x[:], self.v[:], self.acc[:], self._act[:] = x, v, acc, a

    @staticmethod
    def status_text(code: int) -> str:
        return S.STATUS_TEXT.get(code, f"status {code}")

    # ------------------------------------------------------------------ observation

    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        x = self.x
        faces = x.reshape(-1, 4, 3).mean(axis=1)
        seg = 0.5 * (faces[:-1] + faces[1:])
        com = (self.mass[:, None] * x).sum(axis=0) / self.mass.sum()
        obs = Observation(t=t, segment_centers=seg, com=com, head=faces[0], tail=faces[-1],
                          energy=np.array(self.energy(t)), nodes=x.copy() if with_nodes else None)
        return self._observe_segments(obs, t)

    @cached_property
    def _surface_faces(self) -> np.ndarray:
        """(8 n_seg + 4, 3) outward triangles of the lattice's outer faces; static, built on first use."""
        return lattice_surface_faces(self.lattice.n_seg)

    def scene(self) -> Scene:
        """The lattice's outer surface (every node is on it) and all springs, world coordinates [m]."""
        x = self.x
        return Scene(triangles=[(x.copy(), self._surface_faces, LATTICE_SURFACE)],
                     springs=x[self.lattice.springs])  # (S, 2, 3); fancy indexing copies

    def energy(self, t: float) -> tuple[float, float, float]:
        """(kinetic, elastic, gravitational) [J] with the rest lengths of the current actuation (the
        row of the end time of the last ``advance``)."""
        lat = self.lattice
        K.lattice_rest_lengths(self._act, self.phys[K.VOLUME] != 0.0, lat.kind, lat.seg, lat.corner_a,
                               lat.corner_b, lat.L0, lat.Lc, self._face_scale, self._stretch, self._rest)
        return K.lattice_energy(self.x, self.v, self.mass, lat.springs, self.stiffness, self._rest,
                                self.gravity_m_s2)

    def extra_metrics(self) -> dict[str, float]:
        """Backend-specific metrics (none beyond the common ones for the lattice)."""
        return {}

    def contact_fraction_mean(self) -> float:
        return float(self.acc[S.ACC_CONTACT_SUM] / max(self.acc[S.ACC_STEPS], 1.0))

    def max_penetration(self) -> float:
        return float(self.acc[S.ACC_MAX_PEN])


def make_massspring(case, world):
    """Miller's lattice; a creature with legs is built as rigid boxes joined by spring-cube links
    (``massspring.myriapod``): legs attach to rigid segments (the creature's morphology; the leg
    controller itself is composed by the runner); world: the run's ``world.world.World``."""
    if case.creature.legs_per_segment:
        return BodyRigidSpringChain(case, world)
    return BodyMassSpring(case, world)


# --------------------------------------------------------------------------- the backend's declaration
# Everything the suite asks of this body model (the catalog row ``massspring``, ``core.specs.BodySpec``): config
# loading, feasibility and validation read this record and never name the body.

def footprint(case) -> Footprint:
    """Miller's lattice: four nodes per cross-section; a legged chain: four per link cross-section."""
    n = int(case.creature.segments)
    if case.creature.legs_per_segment:
        return lattice_footprint(max(1, n - 1) * 4.0 * (int(case.body.link_cells) + 1))
    return lattice_footprint(4.0 * (n + 1))


def check_buildable(case, source: str) -> None:
    """A legged chain (rigid boxes joined by spring cubes, ``massspring.myriapod``) needs >= 2 segments, links
    that fit on the boxes' faces, and a creature heavier than the links' free nodes; the lattice builds anything."""
    body, cre = case.body, case.creature
    if not cre.legs_per_segment:
        return
    check_chain_segments(case, source, "a legged massspring chain")
    check_legged_gait(case, source, "a legged massspring chain")
    check_link_fit(case, source)
    lay = chain_sizes(body, cre)
    cells = int(body.link_cells)
    free = ((cre.segments - 1) * body.link_density_kg_m3 * lay["ll"] * lay["wl"] * lay["hl"]
            * (cells - 1) / (cells + 1))
    if not cre.mass_kg > free:
        raise InputError(source, "creature.mass_kg", f"{cre.mass_kg} kg is not more than the free link nodes' "
                                                     f"{free:.4g} kg; must be larger (or lower "
                                                     "body.link_density_kg_m3)")


# check name -> run by ``validate --quick`` (validation.registry): the lattice is the quick set's reference body
CHECKS = {"analytic.worm-eps-lambda": True, "analytic.rigid-rotation": True, "analytic.free-fall-momentum": True,
          "analytic.stable-dt": True, "analytic.slithering": True,
          "analytic.slithering-measured-shape": True, "miller.image1-worm-book": True,
          "miller.image2-snake-coils": True, "miller.image3-sidewinder": True,
          "miller.image4-caterpillar-arch": True, "miller.image4-caterpillar-up": False,
          "miller.image4-caterpillar-down": False, "paper.fig10a-hang": False, "paper.fig10d-walk": False,
          "paper.wave-centipede": False, "paper.kinematic-shortcut-centipede": True,
          "paper.kinematic-shortcut-millipede": True,
          "paper.kinematic-shortcut-worlds": False}

# The record itself has the same shape in every backend (the fields of core.specs.BodySpec, in order): a
# declaration, not repeated logic.
BACKEND = BodySpec(
    name="massspring",
    description="Miller 1988: cube lattice of point masses, edge and face-diagonal springs, directional friction",
    config_cls=MassSpringConfig, factory=make_massspring, default_dt=default_dt,
    capabilities=frozenset({MUSCLES, SEGMENTS, LEGS}) | FRICTION_CAPABILITIES,
    footprint=footprint, check_buildable=check_buildable, checks=CHECKS,
    # the lattice's proportional shape gain (controllers/shape_tracking.py): without it the tracked snake
    # diverged at mu_t / mu_f = 1 and missed the shape by 0.20 at 5 (docs/explanation/shape-tracking.md)
    shape_gain_p=2.0,
    # its third-harmonic correction at gain 1 per cycle: the grid of issue 27 at 78.5 s passes on every ratio
    # (shape error 0.016-0.058; docs/explanation/shape-tracking.md)
    shape_harmonic_gain_per_cycle=1.0,
    # per-step wall [s] per size unit with warm kernels, unlegged / legged (harness.schedule): from the quick
    # matrix on the development machine (2-core x86-64, 2026-11-27, 2 workers, heavily shared with other jobs):
    # the median over its cases of (wall - compile) / steps / size, divided by 10, the ratio of that run's
    # summed case times (235 s) to the quiet 16-core machine's (23 s, 1 worker)
    step_cost_s={False: 1.0e-6, True: 2.2e-5},
    # the throughput suite's scenes of this body and their sizes, and what the benchmarks time (benchmarks.py)
    suite_scenes=benchmarks.SUITE_SCENES, benchmarks=benchmarks.BENCHMARKS,
    # its kind of scene surface, the lattice's (lattice.py; its legged chain's boxes are a shared kind)
    surface_kinds=SURFACE_KINDS,
    # what validation's analytic checks measure of the lattice (analytic_systems.py); body.damping=0 takes its
    # springs' damping off for the undamped stable-dt limit
    # its two body models' steps, the legged chain's and the legless lattice's (core.specs.BodySpec), and the legged
    # chain's pack, whose registered functions are its legged operations (bodies.legged_chunk)
    step=STEP, legless_step=LEGLESS_STEP, legged_pack=SpringChainLegs,
    probes=BodyProbes(rigid_motion_residual=AS.rigid_motion_residual, rigid_motion_scale="k L",
                      omega_max=AS.omega_max, undamped=("body.damping=0",),
                      **point_mass_momentum_probes(lambda body: body.mass)))
