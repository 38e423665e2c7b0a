"""What a legged controller tells the runner and the metrics of its run (issue 30, item 6).

A controller that drives legs (``core.protocols.LEGS``) records, every few time steps, a
:class:`LegTimeline` row: the leg states and tips, the head's behaviour mode, the antennae's
contacts and the segment positions.  After the run it reports a :class:`LeggedSummary` of the
whole run, and while it runs it can show its legs as a :class:`LegsPose` (for drawings).  The
harness (``harness.legged``) and the metrics (``metrics.gait``) read only these records, never a
controller's own attributes, so a new legged controller that fills them is measured and drawn like
the paper's (``controllers.myriapod``), with no change to the harness.

Leg state codes (paper Sec. 4.2) are part of the record: a timeline's ``states`` hold them.

Units: SI (s, m); shapes below with T samples, n_legs legs (two per segment, leg k = 2 segment +
side, side 0 left, 1 right, segment 0 the head) and n_seg segments.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Mapping, Protocol, runtime_checkable

import numpy as np

# --- Leg states (paper Sec. 4.2) -------------------------------------------------------------------------
# SF1: PEP up to MUP; SF2: MUP down to AEP (leads to STANCE); SB1: AEP down to MDP (to find the ground);
# SB2: MDP up to PEP (last state of the unsupported loop); STANCE: tip planted, IK; ADJUST: entered when the
# previous leg enters STANCE (rule 4).  The paper's Switcher (``controllers.myriapod.switcher``) runs on these
# codes; another legged controller maps its own phases onto them to be measured by ``metrics.gait``.
SF1, SF2, SB1, SB2, STANCE, ADJUST = 0, 1, 2, 3, 4, 5
N_STATES = 6
STATE_NAMES = ("SF1", "SF2", "SB1", "SB2", "STANCE", "ADJUST")


class LegTimeline:
    """The samples a legged controller records during a run, one row per sample.

    Rows are appended by the controller (``append``; a compiled path replays a chunk's rows with
    ``extend``) and read as arrays after the run:

    * ``t`` (T,) [s] sample times;
    * ``states`` (T, n_legs) int8 leg state codes (``SF1`` ... ``ADJUST``);
    * ``tips`` (T, n_legs, 3) [m] world leg-tip positions;
    * ``modes`` (T,) int64 the head's behaviour mode (an index into the summary's ``mode_names``);
    * ``contacts`` (T, 2) bool antenna contact (left, right); all False without antennae;
    * ``centres`` (T, n_seg, 3) [m] segment positions the controller observed.

    The lists hold one array per row (the rows as recorded: a row is never changed after it is
    appended), so a run's arrays are the rows stacked.
    """

    def __init__(self, n_legs: int, n_segments: int):
        self.n_legs = int(n_legs)
        self.n_segments = int(n_segments)
        self.t: list[float] = []
        self.states: list[np.ndarray] = []
        self.tips: list[np.ndarray] = []
        self.modes: list[int] = []
        self.contacts: list[np.ndarray] = []
        self.centres: list[np.ndarray] = []

    def __len__(self) -> int:
        return len(self.t)

    def append(self, t: float, states: np.ndarray, tips: np.ndarray, mode: int, contact: np.ndarray,
               centres: np.ndarray) -> None:
        """One row: t [s], states (n_legs,) int8, tips (n_legs, 3) [m], mode, contact (2,) bool, centres (n_seg, 3)
        [m]; the arrays are kept as given (the caller passes copies)."""
        self.t.append(t)
        self.states.append(states)
        self.tips.append(tips)
        self.modes.append(mode)
        self.contacts.append(contact)
        self.centres.append(centres)

    def extend(self, t: np.ndarray, states: np.ndarray, tips: np.ndarray, modes: np.ndarray, contacts: np.ndarray,
               centres: np.ndarray) -> None:
        """k rows at once: t (k,), states (k, n_legs), tips (k, n_legs, 3), modes (k,), contacts (k, 2),
        centres (k, n_seg, 3); each list gets the rows of the given arrays (as ``append`` would, row by row)."""
        self.t.extend(np.asarray(t).tolist())
        self.states.extend(states)
        self.tips.extend(tips)
        self.modes.extend(np.asarray(modes).tolist())
        self.contacts.extend(contacts)
        self.centres.extend(centres)

    def legs(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(t (T,) [s], states (T, n_legs) int8, tips (T, n_legs, 3) [m]) recorded so far."""
        if not self.t:
            return np.zeros(0), np.zeros((0, self.n_legs), np.int8), np.zeros((0, self.n_legs, 3))
        return np.array(self.t), np.stack(self.states), np.stack(self.tips)

    def mode_array(self) -> np.ndarray:
        """The head's mode (T,) int64 at the sample times."""
        return np.array(self.modes, dtype=np.int64)

    def contact_array(self) -> np.ndarray:
        """Antenna contact (T, 2) bool (left, right) at the sample times."""
        return np.array(self.contacts, dtype=bool).reshape(-1, 2)

    def centre_array(self) -> np.ndarray:
        """Segment positions (T, n_seg, 3) [m] at the sample times."""
        if not self.centres:
            return np.zeros((0, self.n_segments, 3))
        return np.stack(self.centres)


@dataclass(frozen=True)
class LegsPose:
    """A legged controller's legs now, for drawing: ``geom`` (n_legs, N_LEG_GEOM) leg geometry rows and
    ``angles`` (n_legs, 3) [rad] joint angles as in ``kinematics.legs`` (the drawing places them on the
    segments' current poses by forward kinematics), ``states`` (n_legs,) leg state codes; the antennae's
    link points (2, n_points, 3) [m] and contact (2,) bool, or None without antennae."""

    geom: np.ndarray
    angles: np.ndarray
    states: np.ndarray
    antenna_points: np.ndarray | None = None
    antenna_contact: np.ndarray | None = None


@dataclass(frozen=True)
class LeggedSummary:
    """What a legged controller reports of its whole run beyond the timeline.

    * ``t_walk_s`` [s]: when the creature started walking (nan: never); the gait is measured from one
      second after it;
    * ``touch_fraction_at_walk`` [-]: fraction of legs touching the ground then;
    * ``heading_error_deg`` [deg]: mean heading error under a commanded heading, None when none was commanded;
    * ``tracking_error_mean_m`` [m]: mean distance of the supported segments from their targets (nan: none);
    * ``mode_final``: the head's mode at the end, an index into ``mode_names``;
    * ``mode_fractions``: fraction of the steps spent in named modes (metric ``brain_<name>_fraction``);
    * ``metrics``: the controller's own further figures (metric name -> value), reported as they are.
    """

    t_walk_s: float = math.nan
    touch_fraction_at_walk: float = math.nan
    heading_error_deg: float | None = None
    tracking_error_mean_m: float = math.nan
    mode_final: int = 0
    mode_names: tuple[str, ...] = ("",)
    mode_fractions: Mapping[str, float] = field(default_factory=dict)
    metrics: Mapping[str, float] = field(default_factory=dict)


@runtime_checkable
class LeggedController(Protocol):
    """A controller with legs as the harness sees it (``harness.legged``).

    ``leg_timeline``: its :class:`LegTimeline` (rows added while it steps); ``legs_pose()``: its legs now;
    ``place_on(c, R)``: put parts drawn with the body (antennae) on the segment poses c (n_seg, 3) [m],
    R (n_seg, 3, 3) before the first step, without changing the run; ``summary()``: the run so far.
    """

    leg_timeline: LegTimeline

    def legs_pose(self) -> LegsPose: ...

    def place_on(self, c: np.ndarray, R: np.ndarray) -> None: ...

    def summary(self) -> LeggedSummary: ...
