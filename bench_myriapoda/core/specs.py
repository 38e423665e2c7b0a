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
