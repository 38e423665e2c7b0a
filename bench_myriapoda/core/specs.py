"""What the catalog says of a body model backend and of a gait (``bench_myriapoda.catalog``).

A body backend is closed: everything the suite asks of a body model is a field of its
:class:`BodySpec`, which the backend's own subpackage declares (``bodies/<name>/body.py``)
and the catalog lists by name.  Config loading, feasibility and validation read these fields
and never name a body.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

from .schema import GaitConfig


@dataclass(frozen=True)
class Footprint:
    """What building a body will take, counted from its configuration (nothing built).

    ``body_bytes``: memory of the body's state and scratch [bytes]; ``nodes``: positions a
    sample holds when every node is recorded (``run --record``); ``mesh``: the size in words
    for a refusal's message (e.g. ``"3,240 tets, 1,000 nodes"``; empty: not worth saying).
    """

    body_bytes: float
    nodes: float
    mesh: str = ""


@dataclass(frozen=True)
class SurfaceStyle:
    """How the animations (``report.animate``, ``report.animate3d``) draw one kind of triangle surface of a
    body's scene (``bodies.scene.Scene``): ``color`` its faces' colour (a matplotlib colour, shaded per face);
    ``edges_in_face_color``: its triangles' edges drawn in the face's own colour (a box side, two triangles,
    shows no diagonal) instead of the thin dark edge that shows a mesh."""

    color: str
    edges_in_face_color: bool = False


@dataclass(frozen=True)
class HangingBar:
    """A legged chain body as the 1-D bar it is when hanging by its head (``validation.cross_body``).

    ``s_mass``, ``mass``: (m,) its simulated point masses [m along the rest axis from the head, kg];
    ``n_segments``, ``pitch`` [m] (segment to segment), ``head_length`` [m]: each segment's stiff piece (a
    rigid box, a stiff block) from ``k pitch`` to ``k pitch + head_length``, a link from there to the next;
    ``piece_ea``: (stiff piece, link) axial stiffness E A [N] (inf: rigid).
    """

    s_mass: Any
    mass: Any
    n_segments: int
    pitch: float
    head_length: float
    piece_ea: tuple[float, float]


@dataclass(frozen=True)
class BodyProbes:
    """What ``validation``'s analytic checks measure of a body model's own systems, published by the body so that
    validation names no body and reads no body's internals (issue 42).  Each field is optional: a check whose
    probe a body does not publish does not apply to it (the check says why).  Positions [m], velocities [m/s],
    masses [kg], forces [N], times [s].

    - ``rigid_motion_residual(build, angles, draw)``: the largest elastic force of the body's elements with its
      rest shape moved rigidly by ``draw(angle) -> (R (3, 3), t (3,))`` for each of ``angles`` [rad], relative to
      the force scale ``rigid_motion_scale`` names (0 for an exactly corotational element); ``build()`` gives a
      built 4-segment worm of the body, if the probe needs one.  ``rigid_motion_not_applicable``:
      why the check does not apply when there is no such probe.
    - ``omega_max(body)``: the largest angular eigenfrequency [rad/s] of a built body linearized at rest, damping
      off; ``undamped``: the ``--set`` overrides that remove the body's damping (``analytic.stable-dt``).
    - ``linear_momentum(body) -> (3,)``, ``total_mass(body)`` and ``add_velocity(body, dv (3,))`` (every point
      mass of a built body, its carried parts included): ``analytic.free-fall-momentum``.
    - ``bar_under_own_weight(n_len, nu, E, rho, g, L) -> (system, u)``: a bar (cells n/4 x n x n/4) hanging from
      its top face, relaxed; u its bottom face's mean displacement [m].
    - ``cantilever_tip(cells, P, E, nu, L, H, W) -> u``: a beam along x clamped at x = 0 with a tip load P [N];
      u the tip's mean deflection [m].
    - ``pure_damping_modes(gamma, h) -> [(lam, factor)]``: for some generalized eigenvectors D phi = lam M phi of
      a clamped mesh, the per-node ratio (array) of the velocity after one step of h to before it.
    - ``one_node_step_eigenvalues(rho, gamma, h) -> (6,)``: eigenvalues of the linearized one-step map of the one
      free node of a unit tet with three nodes fixed.
    - ``density_and_modulus(case) -> (rho [kg/m^3], E [Pa]) or None``: a continuum body's, for the analytic
      elongation of the hanging worm (``validation.work_precision``).
    """

    rigid_motion_residual: Callable[[Any, Any, Any], float] | None = None
    rigid_motion_scale: str = ""
    rigid_motion_not_applicable: str = "the body publishes no rigid-motion probe"
    omega_max: Callable[[Any], float] | None = None
    undamped: tuple[str, ...] = ()
    linear_momentum: Callable[[Any], Any] | None = None
    total_mass: Callable[[Any], float] | None = None
    add_velocity: Callable[[Any, Any], None] | None = None
    bar_under_own_weight: Callable[..., tuple[Any, float]] | None = None
    cantilever_tip: Callable[..., float] | None = None
    pure_damping_modes: Callable[[float, float], list] | None = None
    one_node_step_eigenvalues: Callable[[float, float, float], Any] | None = None
    density_and_modulus: Callable[[Any], tuple[float, float] | None] | None = None


# How a suite scene is built and timed (``SuiteCase.run``; ``harness.throughput_suite`` runs each).
RESTART, BARE, WALK_ON, KERNEL = "restart", "bare", "walk-on", "kernel"


@dataclass(frozen=True)
class SuiteCase:
    """One entry of the throughput suite of ``bench-myriapoda regress`` (``harness.throughput_suite``), published
    by the body it times (``BodyBenchmarks.suite``) so that the suite names no body.

    - ``entry``: its name in ``regress_history`` (the history compares by name: never renamed); ``description``.
    - ``steps``: steps of one timed repetition.
    - ``creature``, ``scenario``, ``overrides``: the scene, a case of this body (``core.config.resolve_case``).
    - ``run``: how it is built and timed:
      ``RESTART``: with its gait's controller as a run builds it (``harness.runner.Creature``), compiled, advanced
      ``settle_steps`` in the runner's chunks; every repetition restores ``restart_state(creature)`` (name ->
      array, copied after the settling) and advances from the settled time in chunks;
      ``BARE``: the body alone (``harness.runner.build_body``, no controller), ``prepare(body)`` setting its start
      state, ``restart_state(body)`` copied, compiled; every repetition restores it and advances in one call;
      ``WALK_ON``: with its controller (``fused``: one compiled call per chunk, False: the Python path), compiled,
      walked in ``settle_steps`` in one call; every repetition walks on in one call;
      ``KERNEL``: ``kernel(steps) -> (step, steps)`` builds a kernel of the body's own (no case, no world), and
      its ``step(n)`` restarts it and runs n steps.
    - ``scaling_settle_steps``: > 0: this scene at other numbers of segments is the suite's cost-against-size
      fit of its creature (``throughput_suite.scaling_scene``), settled that many steps in chunks; a ``RESTART``
      scene restores ``restart_state`` between the timed runs, a ``WALK_ON`` one walks on.
    """

    entry: str
    description: str
    steps: int
    run: str
    creature: str = ""
    scenario: str = "flat"
    overrides: tuple[str, ...] = ()
    settle_steps: int = 0
    fused: bool = True
    restart_state: Callable[[Any], Mapping[str, Any]] | None = None
    prepare: Callable[[Any], None] | None = None
    kernel: Callable[[int], tuple[Callable[[int], None], int]] | None = None
    scaling_settle_steps: int = 0


@dataclass(frozen=True)
class PeerCase:
    """One of our entries of ``bench-myriapoda peers`` (``harness.peers``), published by the body it times.

    ``entry``: its name in ``regress_history`` (never renamed); ``group``: the peer scene it is compared with
    (``harness.peers``: ``soft-<tets>``, ``snake``); ``elements`` per step of kind ``element_kind`` (``"tet"``,
    ``"segment"``); ``case``: what is timed, a ``SuiteCase`` (the same work as that suite entry where it is one);
    ``dt``: the time step [s] of one step (None: the step of ``case``'s scene).
    """

    entry: str
    description: str
    group: str
    elements: int
    element_kind: str
    case: SuiteCase
    dt: float | None = None


@dataclass(frozen=True)
class BodyBenchmarks:
    """What the harness's benchmarks time of a body, published by the body (issue 42; ``bodies/<name>/benchmarks.py``).

    - ``suite``: its entries of the throughput suite (``SuiteCase``).
    - ``peers``: its entries of ``bench-myriapoda peers`` (``PeerCase``).
    - ``probe_scene``: (creature, scenario) of a short case of this body whose kernels are the cheapest of the
      catalog's to load: the worker-cost probe's case (``harness.worker_costs`` takes the first body that
      declares one); None: not this body.
    """

    suite: tuple[SuiteCase, ...] = ()
    peers: tuple[PeerCase, ...] = ()
    probe_scene: tuple[str, str] | None = None


@dataclass(frozen=True)
class BodySpec:
    """A body model backend.

    - ``config_cls``: frozen dataclass of the backend's ``[body]`` keys (has a ``name`` field).
    - ``factory``: ``factory(case, world) -> Body`` (``core.protocols.Body``) for a resolved case in the run's
      world (``world.world.World``, built once by the runner; a body builds no world of its own).
    - ``capabilities``: what the backend can honour, e.g. ``{"muscles", "friction:coulomb"}``.
    - ``default_dt``: ``default_dt(body_config) -> float``, the time step [s] when none is given.
    - ``footprint``: ``footprint(case) -> Footprint``, the memory estimate (``core.feasibility``).
    - ``check_buildable``: ``check_buildable(case, source)`` raises ``InputError`` naming ``source`` and
      the key for a case the factory cannot build (cheap: nothing compiled).
    - ``default_params``: the ``[bodies.<name>]`` keys of a creature whose file has no such table, or
      None: every creature must name its own (the backend's keys are calibrated per creature, so a
      missing table is refused).
    - ``checks``: validation check name -> True when ``validate --quick`` runs it on this body
      (``validation.registry``; a check runs on the bodies that declare it).
    - ``shape_gain_p``: the proportional gain [-] of the closed-loop shape tracking of a bending wave
      (``controllers.shape_tracking``) that this body's own dynamics tolerate; ``gait.shape_gain_p = -1``
      (the default) takes it.  0: the tracker corrects the wave's amplitude and phase only.
    - ``shape_harmonic_gain_per_cycle``: the integral gain per gait cycle [-] of the same tracker's correction of
      the wave's temporal harmonics (``gait.shape_harmonics``) that this body's dynamics tolerate;
      ``gait.shape_harmonic_gain_per_cycle = -1`` (the default) takes it.  0: no harmonic is corrected.
    - ``step_cost_s``: legged (False / True) -> wall time of one step per unit of size [s] with warm kernels
      (``harness.schedule.size_of``: segments x FEM nodes per link), for a kind of case neither the results
      store nor the throughput suite knows; only the order in which a matrix starts its cases depends on it.
      Empty: ``harness.schedule.UNKNOWN_STEP_S``.
    - ``suite_scenes``: creature -> (throughput-suite entry, its scene's size in ``size_of``'s units): the
      suite's measured rate of this body with that creature, scaled to other sizes (``harness.schedule``).
    - ``hanging_bar``: ``hanging_bar(body, case) -> HangingBar``, the 1-D bar a built legged chain of this body
      is when it hangs by its head (``validation.cross_body``'s reference), or None: the body has none.
      ``hang_dt_s``: the time step [s] of that hanging comparison's run (None: the body's default).
    - ``probes``: what validation's analytic checks measure of the body's own systems (``BodyProbes`` above).
    - ``benchmarks``: what the throughput suite, the peers and the worker-cost probe time of it
      (``BodyBenchmarks`` above).
    - ``surface_kinds``: kind -> ``SurfaceStyle`` of the kinds of triangle surface the body's ``scene()`` draws
      that are its own (a kind the bodies share, the rigid box, is ``bodies.scene``'s); the animations read the
      styles from the specs and name no body.
    - ``step``: the body's one step function, ``step(*records, world, dt, n_steps) -> (steps done, status)`` (a
      numba kernel; ``Body.advance`` calls it with a chunk's steps, and for a legged body the fused walk with one):
      the body's own records first (its constants and its state), then the run's world (``world.world.StepWorld``
      as a plain tuple, ``World.step_world``) and the time step dt [s], plain arguments given by whoever runs it
      (issue 42 item 2; no body's parameters hold either).  A spec that builds two body models, a legless body and
      a legged chain (``massspring``, ``fem``), names here the step of the body it builds for a creature with legs
      (the chain's module names it ``STEP``) and in ``legless_step`` the other's.  A body whose implicit solve is
      factored for one dt (the FEM bodies' M + dt D) is given that dt, its own ``dt``.
    - ``legless_step``: the step function, in ``step``'s form, of the body model the spec builds for a creature
      without legs where that is another body model than the legged one; None: ``step`` is every body's step.
    - ``legged_pack``: for a body with a fused legged walk (``bodies.legged_chunk``), the class of its pack, for
      which the body registers its legged operations (poses, support, sample, and its step as ``chain_step(step)``)
      once: the fused walk and the body's Python methods (``legged_chunk.LeggedPackOps``) both run those.  None:
      no fused legged walk.
    """

    name: str
    description: str
    config_cls: type
    factory: Callable[[Any, Any], Any]
    capabilities: frozenset
    default_dt: Callable[[Any], float]
    footprint: Callable[[Any], Footprint]
    check_buildable: Callable[[Any, str], None]
    default_params: Mapping[str, Any] | None = None
    checks: Mapping[str, bool] = field(default_factory=dict)
    shape_gain_p: float = 0.0
    shape_harmonic_gain_per_cycle: float = 0.0
    step_cost_s: Mapping[bool, float] = field(default_factory=dict)
    suite_scenes: Mapping[str, tuple[str, float]] = field(default_factory=dict)
    hanging_bar: Callable[[Any, Any], HangingBar] | None = None
    hang_dt_s: float | None = None
    probes: BodyProbes = field(default_factory=BodyProbes)
    benchmarks: BodyBenchmarks = field(default_factory=BodyBenchmarks)
    surface_kinds: Mapping[str, SurfaceStyle] = field(default_factory=dict)
    step: Callable[..., tuple[int, int]] | None = None
    legless_step: Callable[..., tuple[int, int]] | None = None
    legged_pack: type | None = None


@dataclass(frozen=True)
class GaitSpec:
    """A gait: what it needs from a body (``requires``), the controller that drives it
    (``controller(case) -> Controller``, ``core.protocols.Controller``; with ``takes_world`` True,
    ``controller(case, world=world)`` in the run's world, as a body factory) and the frozen dataclass of its
    ``[gaits.<name>]`` keys (``config_cls``, ``case.gait``).  A gait with keys of its own declares a
    subclass of ``GaitConfig`` next to its controller: the base's keys (period, wave, volume rule) are
    the ones the runner, the metrics and the bodies read of every gait."""

    name: str
    description: str
    requires: frozenset
    controller: Callable[[Any], Any] | None = None
    config_cls: type = GaitConfig
    takes_world: bool = False
