"""The interfaces between body models, controllers and the runner, and the data passed between them.

A **body** (``bodies/``) integrates a creature's dynamics; a **controller** (``controllers/``)
decides how the creature acts.  They never import each other: the runner
(``harness/runner.py``) builds one of each and passes data between them:

* the body fills an :class:`Observation` (what a controller may read), and
* the controller writes an :class:`Actuation` (what the body reads).

Two kinds of controller keep the hot loop compiled (ARCHITECTURE.md, "Controllers in a
compiled loop"):

* **open loop** (``controller.open_loop`` is True, e.g. Miller's muscle waves): for each chunk
  of steps the controller fills ``actuation.muscle`` with one row per step
  (:meth:`Controller.fill`), and the body's kernel reads row k at step k;
* **closed loop** (the paper's leg controller, a researcher's own policy): the runner calls
  :meth:`Controller.step` every ``1 / rate_hz`` seconds (every time step when ``rate_hz`` is 0,
  as the paper's controller) with a fresh observation, and the body holds the actuation
  constant until the next tick.

Frames: world y up, gravity along -y; a segment frame has x forward (toward the head), y up
(dorsal), z to the creature's right (PAPER-NOTES.md).  SI units throughout.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping, Protocol, runtime_checkable

import numpy as np

# Muscle channels of an actuation row (Miller Sec. 4 reading, ``controllers/muscle_waves.py``):
# a fibre at cross-section corner (y_s, z_s) in [-1, 1]^2 (y_s = -1 ventral, z_s = -1 left)
# has stretch 1 + axial + lateral z_s + dorsal y_s.
AXIAL, LATERAL, DORSAL = 0, 1, 2
N_CHANNELS = 3
# A positive LATERAL strain bends the body toward its left; walked from head to tail its centre line then
# turns right: a negative ground curvature in ``metrics.body_shape.ground_curvature``'s sign (left turn
# positive).  The commanded curvature profile on the ground is this sign x the strain wave's.
LATERAL_GROUND_SIGN = -1.0

# Capabilities a body declares and a controller may require.
MUSCLES = "muscles"      # reads actuation.muscle (per-segment channel strains)
SEGMENTS = "segments"    # moves supported segments kinematically to actuation.support targets (legs)
LEGS = "legs"            # a creature morphology with legs (legs_per_segment > 0)


@dataclass
class Actuation:
    """What a controller commands and a body reads.

    muscle: (n_rows, n_seg, 3) fibre strains [-] of the AXIAL, LATERAL, DORSAL channels of every
        muscle segment; row k drives step k of the body's next ``advance`` (rows past the last
        repeat it, so one row holds a closed-loop command constant).  The segment count is the
        body's ``n_muscle_segments``; ``muscle_s`` (n_seg,) is each one's rest arc length from the
        head [m], where a wave is evaluated.
    muscles_on: False when no muscle is driven at all (a passive or legged creature): a body may
        then skip the active-strain update.
    support_kinematic: (n_seg,) bool, segments the legs support this step (paper Sec. 4.1); the
        body carries them to ``support_c`` (n_seg, 3) [m] and ``support_R`` (n_seg, 3, 3) over one
        step and lets the others follow the dynamics.  Only read by bodies with ``SEGMENTS``.
    support_new: True when the controller wrote new support targets since the body last read them.
    support_states: (n_legs,) int64 leg states (``core.leg_timeline`` codes) and support_tips (n_legs, 3) [m]
        the feet: the controller's own arrays, for a body in dynamic stance (``legs.stance = "dynamic"``,
        ``bodies.dynamic_stance``), which moves the STANCE feet that slide (support_tips UPDATED).  None
        from a controller without legs.
    """

    muscle: np.ndarray
    muscle_s: np.ndarray
    muscles_on: bool = False
    support_kinematic: np.ndarray | None = None
    support_c: np.ndarray | None = None
    support_R: np.ndarray | None = None
    support_new: bool = False
    support_states: np.ndarray | None = None
    support_tips: np.ndarray | None = None

    @classmethod
    def for_body(cls, body: "Body", rows: int = 1) -> "Actuation":
        """Zero actuation shaped for ``body`` with ``rows`` muscle rows."""
        n = body.n_muscle_segments
        act = cls(muscle=np.zeros((max(rows, 1), n, N_CHANNELS)), muscle_s=np.asarray(body.muscle_s, float))
        if SEGMENTS in body.capabilities:
            m = body.n_segments
            act.support_kinematic = np.zeros(m, dtype=bool)
            act.support_c = np.zeros((m, 3))
            act.support_R = np.tile(np.eye(3), (m, 1, 1))
        return act

    def ensure_rows(self, rows: int) -> None:
        """Make ``muscle`` hold at least ``rows`` rows (kept values are undefined)."""
        if self.muscle.shape[0] < rows:
            self.muscle = np.zeros((rows,) + self.muscle.shape[1:])


@dataclass
class Observation:
    """What a body reports: at every control tick (``Body.sense``) and every sample (``Body.observe``).

    Control fields (filled by ``sense``, cheap enough for every time step):
      t [s]; seg_pos (n_seg, 3) [m] and seg_rot (n_seg, 3, 3) (segment -> world) of the
      creature's segments (rigid boxes for a body that has them, otherwise the best-fit frame of
      each segment's nodes); seg_vel (n_seg, 3) [m/s]; seg_half (n_seg, 3) [m] half extents
      (length, height, width) of each segment's box.
    Sample fields (filled by ``observe``; the runner records these):
      segment_centers (n_c, 3) [m] body-order centres (segment 0 the head; a hybrid body lists
      rigid 0, link 0, rigid 1, ...); com (3,) [m]; head, tail (3,) [m] centres of the front and
      back end faces; energy (3,) [J] kinetic, elastic, gravitational (from y = 0);
      seg_contact (n_seg,) bool, a segment touches the ground; nodes (n_nodes, 3) [m] or None.
    """

    t: float = 0.0
    seg_pos: np.ndarray | None = None
    seg_rot: np.ndarray | None = None
    seg_vel: np.ndarray | None = None
    seg_half: np.ndarray | None = None
    segment_centers: np.ndarray | None = None
    com: np.ndarray | None = None
    head: np.ndarray | None = None
    tail: np.ndarray | None = None
    energy: np.ndarray | None = None
    seg_contact: np.ndarray | None = None
    nodes: np.ndarray | None = None
    extra: dict[str, Any] = field(default_factory=dict)


@runtime_checkable
class Body(Protocol):
    """A body model backend (``bodies/<name>/``): owns the state, integrates the dynamics.

    Declared attributes: ``name``; ``capabilities`` (frozenset of MUSCLES, SEGMENTS, LEGS);
    ``n_segments``; ``segment_pitch_m`` [m] rest distance of neighbouring segment centres;
    ``n_muscle_segments`` and ``muscle_s`` (n_muscle_segments,) [m]; ``body_length_m`` [m] rest
    length head to tail.  A body with SEGMENTS also has ``apply_support(act)``,
    ``segment_poses()``, ``segment_centers()`` and ``segment_half_extents`` (n_segments, 3) [m].
    """

    name: str
    capabilities: frozenset

    def compile(self) -> None:
        """JIT-compile (or load) the kernels; the state is left unchanged."""

    def advance(self, t0: float, n_steps: int, act: Actuation) -> tuple[int, int]:
        """Integrate ``n_steps`` steps from t0 [s] reading ``act``; return (steps done, status code)."""

    def sense(self, obs: Observation, t: float) -> None:
        """Fill the control fields of ``obs`` (in place, no allocation beyond the first call)."""

    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        """A full sample (control and sample fields)."""

    def energy(self, t: float) -> tuple[float, float, float]:
        """(kinetic, elastic, gravitational) [J]."""

    def status_text(self, code: int) -> str: ...
    def extra_metrics(self) -> dict[str, float]: ...
    def contact_fraction_mean(self) -> float: ...
    def max_penetration(self) -> float: ...
    def scene(self) -> Any: ...


@runtime_checkable
class Controller(Protocol):
    """A gait: reads observations, writes actuation, never touches a body's internals.

    ``requires``: capabilities the body must have; ``open_loop``: fills whole chunks (``fill``)
    instead of ticking (``step``); ``rate_hz``: closed-loop tick rate, 0 = every time step.
    """

    requires: frozenset
    open_loop: bool
    rate_hz: float

    def reset(self, case: Any, body_info: Mapping[str, Any], rng: np.random.Generator) -> None:
        """Prepare a run: ``body_info`` holds ``n_segments``, ``muscle_s``, ``body_length_m``, ``dt``."""

    def step(self, obs: Observation, t: float, act: Actuation) -> None:
        """Closed loop: update ``act`` for the time from t [s] to the next tick."""


@runtime_checkable
class OpenLoopController(Controller, Protocol):
    """A controller whose actuation depends on time only: it fills whole chunks (``open_loop`` True)."""

    def fill(self, t0: float, dt: float, n_steps: int, act: Actuation) -> None:
        """Write rows 0..n_steps-1 of ``act.muscle`` for the steps from t0 [s] (row k: t0 + k dt)."""


def body_info(body: Body, dt: float) -> dict[str, Any]:
    """What a controller's ``reset`` learns of the body: sizes, arc positions and the time step, and for a body
    with rigid segments their boxes' half extents (``segment_half_extents``)."""
    info = {"n_segments": body.n_segments, "muscle_s": np.asarray(body.muscle_s, float),
            "body_length_m": float(body.body_length_m), "dt": float(dt), "capabilities": body.capabilities,
            "segment_pitch_m": float(body.segment_pitch_m)}
    if SEGMENTS in body.capabilities:  # (n_segments, 3) [m]: the rigid segments' boxes
        info["segment_half_extents"] = np.array(body.segment_half_extents, dtype=float)
    return info


def controller_settings(ctrl) -> tuple[frozenset, bool, float]:
    """(requires, open_loop, rate_hz) of a controller; each attribute is optional with the default
    of a plain-Python closed-loop controller: no requirement, closed loop, every time step."""
    return (frozenset(getattr(ctrl, "requires", frozenset())), bool(getattr(ctrl, "open_loop", False)),
            float(getattr(ctrl, "rate_hz", 0.0)))
