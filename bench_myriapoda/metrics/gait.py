"""Gait-wave metrics of a many-legged creature, from its recorded leg-state timeline.

The myriapod controller (Fang, Jiang & Terzopoulos 2013, Sec. 4.2) drives each
leg through six states; the simulator records them as a timeline and this
module turns that timeline into flat scalar metrics and state-sequence
summaries (paper Fig. 10).  Everything here is plain numpy: the work is a few
vectorised passes per leg, far from a hot loop.

Inputs, shared by every function
--------------------------------
t : (T,) [s]
    Sample times, strictly increasing; the spacing may be irregular.
states : (T, n_legs) int
    Leg state codes (``SF1`` ... ``ADJUST`` below).  Leg index
    ``leg = 2 * segment + side``; side 0 is left, 1 is right; segment 0 is the
    head, indices grow toward the tail (PAPER-NOTES.md).
tips : (T, n_legs, 3) [m]
    Leg tip positions in the world frame (y up).
com : (T, 3) [m]
    Body centre of mass.

Conventions used by every metric
--------------------------------
* Sample-and-hold: the state recorded at ``t[i]`` is taken to hold over
  ``[t[i], t[i+1])``.  Time fractions and durations weight sample ``i`` by
  ``t[i+1] - t[i]``; the last sample of the recording has zero weight.  This
  makes every time-based quantity correct under irregular sampling.
* Measurement window: the samples with ``t[i] >= t[0] + warmup_s``.  A window
  with fewer than two samples makes every metric NaN.
* Stance onset: a sample ``i`` with both ``i - 1`` and ``i`` in the window,
  ``states[i] == STANCE`` and ``states[i-1] != STANCE``; its time is ``t[i]``
  (the first sample seen in stance).  The window is self-contained: a leg
  already in stance at the window's first sample has no onset there, so
  whatever happened during the warm-up cannot fake a touchdown.
* Stride: the interval between two consecutive stance onsets of one leg, both
  in the window.  A leg with fewer than two onsets has no complete stride and
  is left out of the per-leg averages (it is counted by
  ``stepping_leg_fraction`` instead); a metric averaged over legs is NaN when
  no leg has a complete stride (e.g. no stance at all).
* Phases are fractions of a cycle.  ``wrap_phase`` maps them to
  (-0.5, 0.5]; averages of phases are circular (the angle of the mean of
  ``exp(2 pi i phase)``), so lags straddling +-0.5 average correctly instead
  of cancelling to 0.
"""
from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass
from typing import NamedTuple, Sequence

import numpy as np

# --- Leg states (paper Sec. 4.2): codes and names of the legged timeline record (core.leg_timeline) ---
# SF1: PEP up to MUP; SF2: MUP down to AEP (leads to STANCE); SB1: AEP down to MDP (to find the
# ground); SB2: MDP up to PEP (last state of the unsupported loop); STANCE: tip planted, IK;
# ADJUST: entered when the previous leg enters STANCE (rule 4); makes the wave.
from ..core.leg_timeline import (ADJUST, N_STATES, SB1, SB2, SF1, SF2,  # noqa: E402,F401
                                 STANCE, STATE_NAMES)

STATE_DESCRIPTIONS: tuple[str, ...] = (
    "sway forward 1 (PEP to MUP)",
    "sway forward 2 (MUP to AEP)",
    "sway backward 1 (AEP to MDP)",
    "sway backward 2 (MDP to PEP)",
    "stance (tip planted)",
    "adjust (phase set by the anterior leg)",
)
# Forward swings blue, backward swings warm, stance dark green, adjust magenta: distinct
# hues so that a gait diagram reads at a glance and its pixels can be told apart in tests.
STATE_COLORS: tuple[str, ...] = ("#4575b4", "#91bfdb", "#fdae61", "#d73027", "#1b7837", "#e7298a")

LEFT, RIGHT = 0, 1
SIDE_NAMES = ("L", "R")

# Paper Fig. 10: suspended legs loop SF1 -> SF2 -> SB1 -> SB2 (A); once walking they converge
# to SF1 -> SF2 -> STANCE with short appearances of ADJUST and SB1 (D).
SUSPENDED_CYCLE: tuple[int, ...] = (SF1, SF2, SB1, SB2)
WALKING_CYCLE: tuple[int, ...] = (SF1, SF2, STANCE)
WALKING_BRIEF_STATES: tuple[int, ...] = (ADJUST, SB1)

# Thresholds of the Fig. 10 convergence test (walking_cycle_check); see its docstring.
BRIEF_STATE_MAX_FRACTION = 0.15   # "brief": at most this fraction of the analysed time, per state
MIN_CYCLE_SHARE = 0.8             # the walking cycle must be at least this share of complete cycles
MIN_CYCLES = 2                    # and must be seen completely at least this many times

FLOAT_METRICS: tuple[str, ...] = (
    "duty_factor_mean", "duty_factor_std", "stride_frequency_hz", "phase_lag_mean", "phase_lag_cv",
    "legs_per_wave", "lr_phase_diff", "stance_fraction_min", "stance_fraction_mean",
    "stride_length_bl", "foot_slip_mean_m", "stepping_leg_fraction", "walking_cycle_leg_fraction",
    "speed_bl_per_stride",
)
LABEL_METRICS: tuple[str, ...] = ("wave_direction",)
RETROGRADE, DIRECT, SYNCHRONOUS, UNDEFINED = "retrograde", "direct", "synchronous", "undefined"


# --- Leg indexing ---------------------------------------------------------------------------
def leg_index(segment: int, side: int) -> int:
    """Column of leg (segment, side) in ``states``; side 0 left, 1 right."""
    return 2 * segment + side


def leg_segment_side(leg: int) -> tuple[int, int]:
    """(segment, side) of leg column ``leg``."""
    return leg // 2, leg % 2


def leg_label(leg: int) -> str:
    """Short label, e.g. ``"L0"`` for the head's left leg, ``"R3"`` for segment 3's right leg."""
    seg, side = leg_segment_side(leg)
    return f"{SIDE_NAMES[side]}{seg}"


# --- Input checks and the measurement window ------------------------------------------------
def check_timeline(t, states) -> tuple[np.ndarray, np.ndarray]:
    """Validated ``(t float (T,), states int (T, n_legs))``; a 1-D ``states`` is one leg.

    Raises ValueError on mismatched shapes, non-integer or unknown state codes,
    or times that do not strictly increase.
    """
    t = np.asarray(t, dtype=float)
    states = np.asarray(states)
    if states.ndim == 1:  # one leg given as a flat sequence
        states = states[:, None]
    if t.ndim != 1 or states.ndim != 2 or states.shape[0] != t.shape[0]:
        raise ValueError(f"t must be (T,) and states (T, n_legs); got {t.shape} and {states.shape}")
    if not np.issubdtype(states.dtype, np.integer):
        raise ValueError(f"states must hold integer state codes, got dtype {states.dtype}")
    if len(t) > 1 and not np.all(np.diff(t) > 0):
        raise ValueError("t must be strictly increasing")
    if states.size and (states.min() < 0 or states.max() >= N_STATES):
        bad = sorted(set(np.unique(states).tolist()) - set(range(N_STATES)))
        raise ValueError(f"unknown leg state codes {bad}; known: {dict(enumerate(STATE_NAMES))}")
    return t, states


def window_start(t: np.ndarray, warmup_s: float) -> int:
    """Index of the first sample with ``t[i] >= t[0] + warmup_s`` (``len(t)`` if none)."""
    t = np.asarray(t, dtype=float)
    if len(t) == 0:
        return 0
    return int(np.searchsorted(t, t[0] + warmup_s, side="left"))


def hold_durations(t: np.ndarray) -> np.ndarray:
    """(T,) [s]: how long each sample's state holds, ``t[i+1] - t[i]``; 0 for the last sample."""
    t = np.asarray(t, dtype=float)
    return np.append(np.diff(t), 0.0) if len(t) else np.zeros(0)


def _weighted_mean(values: np.ndarray, weights: np.ndarray, axis=0) -> np.ndarray:
    """Time-weighted mean along ``axis``; falls back to the plain mean when all weights are 0."""
    wsum = weights.sum()
    if wsum > 0:
        shape = [1] * values.ndim
        shape[axis] = -1
        return (values * weights.reshape(shape)).sum(axis=axis) / wsum
    return values.mean(axis=axis)


# --- Phases ---------------------------------------------------------------------------------
def wrap_phase(x):
    """Wrap phases [cycles] to (-0.5, 0.5]; exactly half a cycle maps to +0.5."""
    x = np.asarray(x, dtype=float)
    return x - np.ceil(x - 0.5)


def circular_mean(phases) -> float:
    """Circular mean of phases [cycles], in (-0.5, 0.5]; NaN if empty or the phases cancel out."""
    phases = np.asarray(phases, dtype=float)
    if phases.size == 0:
        return math.nan
    z = np.exp(2j * np.pi * phases).mean()
    if abs(z) < 1e-12:  # e.g. two opposite phases: no meaningful mean direction
        return math.nan
    return float(wrap_phase(np.angle(z) / (2 * np.pi)))


def circular_deviation(phases, mean: float) -> float:
    """RMS of ``wrap_phase(phases - mean)`` [cycles]: the spread around a circular mean."""
    phases = np.asarray(phases, dtype=float)
    if phases.size == 0 or not math.isfinite(mean):
        return math.nan
    return float(np.sqrt(np.mean(wrap_phase(phases - mean) ** 2)))


def relative_phases(ref_onsets: np.ndarray, onsets: np.ndarray) -> np.ndarray:
    """Phase of each onset in ``onsets`` within the reference leg's stride that contains it.

    ``ref_onsets``, ``onsets``: sorted onset times [s].  For an onset at ``o``
    with ``ref[k] <= o < ref[k+1]`` the phase is
    ``(o - ref[k]) / (ref[k+1] - ref[k])`` in [0, 1), returned wrapped to
    (-0.5, 0.5]: the delay of the onset after the reference onset, as a
    fraction of the reference stride period.  Onsets outside a complete
    reference stride are dropped.  Returns (n_events,) [cycles].
    """
    ref = np.asarray(ref_onsets, dtype=float)
    o = np.asarray(onsets, dtype=float)
    if len(ref) < 2 or len(o) == 0:
        return np.zeros(0)
    k = np.searchsorted(ref, o, side="right") - 1
    ok = (k >= 0) & (k < len(ref) - 1)
    k, o = k[ok], o[ok]
    return wrap_phase((o - ref[k]) / (ref[k + 1] - ref[k]))


# --- Stance onsets and strides --------------------------------------------------------------
def stance_onset_indices(states: np.ndarray, i0: int = 0) -> list[np.ndarray]:
    """Per leg, the sample indices ``i >= i0 + 1`` where STANCE starts (see module docstring)."""
    states = np.asarray(states)
    if states.ndim == 1:
        states = states[:, None]
    stance = states == STANCE
    start = np.zeros_like(stance)
    start[1:] = stance[1:] & ~stance[:-1]
    start[: max(i0, 0) + 1] = False  # the sample before an onset must be in the window too
    return [np.flatnonzero(start[:, leg]) for leg in range(states.shape[1])]


@dataclass(frozen=True)
class StrideStats:
    """Per-leg stride statistics over the window; NaN for legs without a complete stride.

    duty_factor: (n_legs,) mean over the leg's strides of (time in STANCE within
        the stride) / (stride period).
    stride_frequency_hz: (n_legs,) number of strides / (last onset - first
        onset) = 1 / mean stride period [Hz].
    n_onsets: (n_legs,) stance onsets in the window.
    onset_times: per leg, (n_onsets,) onset times [s].
    """

    duty_factor: np.ndarray
    stride_frequency_hz: np.ndarray
    n_onsets: np.ndarray
    onset_times: list[np.ndarray]


def stride_stats(t, states, warmup_s: float = 0.0) -> StrideStats:
    """Duty factor and stride frequency of every leg (definitions in ``StrideStats``)."""
    t, states = check_timeline(t, states)
    n_legs = states.shape[1]
    i0 = window_start(t, warmup_s)
    onsets = stance_onset_indices(states, i0)
    # cumulative stance time, so the stance time of a stride [a, b) is cs[b] - cs[a]
    stance_dt = (states == STANCE) * hold_durations(t)[:, None]
    cs = np.vstack([np.zeros((1, n_legs)), np.cumsum(stance_dt, axis=0)])
    duty = np.full(n_legs, math.nan)
    freq = np.full(n_legs, math.nan)
    for leg, idx in enumerate(onsets):
        if len(idx) < 2:
            continue
        a, b = idx[:-1], idx[1:]
        period = t[b] - t[a]
        duty[leg] = float(np.mean((cs[b, leg] - cs[a, leg]) / period))
        freq[leg] = (len(idx) - 1) / (t[idx[-1]] - t[idx[0]])
    return StrideStats(duty, freq, np.array([len(i) for i in onsets]), [t[i] for i in onsets])


# --- Phase lags along the body and between sides --------------------------------------------
def _anterior_pairs(n_legs: int) -> list[tuple[int, int]]:
    """(anterior leg, leg) for every leg whose same-side leg in the segment ahead exists."""
    return [(leg - 2, leg) for leg in range(2, n_legs)]


def _left_right_pairs(n_legs: int) -> list[tuple[int, int]]:
    """(left leg, right leg) of every segment that has both."""
    return [(leg, leg + 1) for leg in range(0, n_legs - 1, 2)]


def phase_lag_events(onset_times: Sequence[np.ndarray]) -> dict[int, np.ndarray]:
    """Per leg with an anterior same-side neighbour: its individual phase lags [cycles].

    One event per stance onset of the leg that falls inside a complete stride
    of the anterior leg: ``relative_phases(anterior onsets, leg onsets)``.
    Positive: the leg touches down after the anterior leg (retrograde wave).
    """
    return {leg: relative_phases(onset_times[ant], onset_times[leg])
            for ant, leg in _anterior_pairs(len(onset_times))}


def phase_lags_per_leg(t, states, warmup_s: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Per-leg phase lag behind the same-side leg of the segment ahead, for plots.

    Returns (mean, spread), each (n_legs,) [cycles]: the circular mean of the
    leg's lag events and their RMS deviation from it.  NaN for the head's legs
    (no segment ahead) and for legs without a lag event.
    """
    st = stride_stats(t, states, warmup_s)
    n_legs = len(st.onset_times)
    mean = np.full(n_legs, math.nan)
    spread = np.full(n_legs, math.nan)
    for leg, ev in phase_lag_events(st.onset_times).items():
        mean[leg] = circular_mean(ev)
        spread[leg] = circular_deviation(ev, mean[leg])
    return mean, spread


def wave_direction(phase_lag: float) -> str:
    """"retrograde" (lag > 0, head to tail), "direct" (< 0), "synchronous" (0), "undefined" (NaN)."""
    if not math.isfinite(phase_lag):
        return UNDEFINED
    if phase_lag > 0:
        return RETROGRADE
    if phase_lag < 0:
        return DIRECT
    return SYNCHRONOUS


def wave_metrics(onset_times: Sequence[np.ndarray]) -> tuple[dict[str, float], dict[str, str]]:
    """Phase-lag metrics from per-leg onset times [s].

    phase_lag_mean: circular mean of all lag events of all legs pooled
        (``phase_lag_events``), in (-0.5, 0.5] cycles; positive = retrograde.
        A lag of exactly half a cycle is ambiguous in direction and reads +0.5.
    phase_lag_cv: RMS deviation of the pooled events from that mean (wrapped,
        so it is small for lags clustered around +-0.5) divided by
        ``|phase_lag_mean|``; NaN if the mean is 0 or NaN.
    legs_per_wave: ``1 / |phase_lag_mean|``, legs per wavelength along one side.
    lr_phase_diff: for every segment with both legs, the phases of the right
        leg's onsets in the left leg's strides (``relative_phases``), pooled
        over segments; the absolute value of their circular mean, in [0, 0.5]
        (0: in phase, 0.5: antiphase).
    """
    n_legs = len(onset_times)
    events = list(phase_lag_events(onset_times).values())
    lags = np.concatenate(events) if events else np.zeros(0)
    lag = circular_mean(lags)
    dev = circular_deviation(lags, lag)
    cv = dev / abs(lag) if math.isfinite(lag) and lag != 0 else math.nan
    per_wave = 1.0 / abs(lag) if math.isfinite(lag) and lag != 0 else math.nan
    lr_events = [relative_phases(onset_times[l], onset_times[r]) for l, r in _left_right_pairs(n_legs)]
    lr = circular_mean(np.concatenate(lr_events)) if lr_events else math.nan
    metrics = {"phase_lag_mean": lag, "phase_lag_cv": cv, "legs_per_wave": per_wave,
               "lr_phase_diff": abs(lr) if math.isfinite(lr) else math.nan}
    return metrics, {"wave_direction": wave_direction(lag)}


# --- Support, slip and stride length --------------------------------------------------------
def stance_fraction(states) -> np.ndarray:
    """(T,): fraction of all legs in STANCE at each sample."""
    states = np.asarray(states)
    if states.ndim == 1:
        states = states[:, None]
    return (states == STANCE).mean(axis=1)


def foot_slip_mean(t, states, tips, warmup_s: float = 0.0) -> float:
    """Mean drift [m] of planted leg tips from their touchdown positions.

    For each maximal run of STANCE samples of a leg, the touchdown position is
    the tip at the run's first sample (which may precede the window; for a run
    already under way at ``t[0]`` it is the tip at ``t[0]``).  The slip at a
    stance sample is the 3-D distance of the tip from that touchdown position.
    Returns the plain mean over all (leg, sample) pairs in the window with the
    leg in STANCE (the touchdown sample itself counts, with slip 0); NaN if
    there are none.
    """
    t, states = check_timeline(t, states)
    tips = np.asarray(tips, dtype=float)
    if tips.shape != states.shape + (3,):
        raise ValueError(f"tips must be (T, n_legs, 3) = {states.shape + (3,)}, got {tips.shape}")
    i0 = window_start(t, warmup_s)
    stance = states == STANCE
    start = stance.copy()
    start[1:] &= ~stance[:-1]
    idx = np.arange(len(t))[:, None]
    # latest run start at or before each sample: within a stance run, that is the run's touchdown
    touchdown = np.maximum.accumulate(np.where(start, idx, 0), axis=0)
    legs = np.broadcast_to(np.arange(states.shape[1]), states.shape)
    sel = stance.copy()
    sel[:i0] = False
    if not sel.any():
        return math.nan
    drift = tips[sel] - tips[touchdown[sel], legs[sel]]
    return float(np.linalg.norm(drift, axis=1).mean())


def stride_length(t, com, stride_frequency_hz: float, t_start: float) -> float:
    """COM distance per stride [m], from ``t_start`` to ``t[-1]``.

    The COM path is sampled once per mean stride period ``P = 1 / f`` at
    ``t_start + k P`` (linear interpolation), for the ``K = floor(W / P)``
    whole periods that fit in the window of length ``W``; the result is the
    summed 3-D chord length over K.  Sampling at the stride period removes any
    bob or sway that repeats every stride while still following turns.  NaN if
    ``f`` is not positive and finite or no whole period fits.
    """
    t = np.asarray(t, dtype=float)
    com = np.asarray(com, dtype=float)
    if com.shape != (len(t), 3):
        raise ValueError(f"com must be (T, 3) = {(len(t), 3)}, got {com.shape}")
    if not (math.isfinite(stride_frequency_hz) and stride_frequency_hz > 0):
        return math.nan
    period = 1.0 / stride_frequency_hz
    k = int(math.floor((t[-1] - t_start) / period + 1e-9))
    if k < 1:
        return math.nan
    ts = t_start + period * np.arange(k + 1)
    pts = np.column_stack([np.interp(ts, t, com[:, j]) for j in range(3)])
    return float(np.linalg.norm(np.diff(pts, axis=0), axis=1).sum() / k)


def speed_per_stride(t, com, stride_frequency_hz: float, t_start: float) -> float:
    """Net COM speed over the window divided by the stride frequency [m per stride].

    v = |com(t[-1]) - com(t_start)| / (t[-1] - t_start) (COM linearly interpolated
    at t_start), over f: how far the body gets per leg cycle -- the "speed per
    cycle" of centipede studies (divide by the body length for body lengths per
    stride).  Unlike ``stride_length`` it counts net progress, so sway and turning
    lower it.  NaN if f is not positive and finite or the window is empty.
    """
    t = np.asarray(t, dtype=float)
    com = np.asarray(com, dtype=float)
    if com.shape != (len(t), 3):
        raise ValueError(f"com must be (T, 3) = {(len(t), 3)}, got {com.shape}")
    if not (math.isfinite(stride_frequency_hz) and stride_frequency_hz > 0) or not t[-1] > t_start:
        return math.nan
    start = np.array([np.interp(t_start, t, com[:, j]) for j in range(3)])
    v = float(np.linalg.norm(com[-1] - start)) / (t[-1] - t_start)
    return float(v / stride_frequency_hz)


# --- State sequences (paper Fig. 10) --------------------------------------------------------
class StateRuns(NamedTuple):
    """Run-length encoding of one leg's states: each (n_runs,).

    codes: state of each run; start: index of its first sample; t_start [s];
    duration [s]: sample-and-hold time of the run (up to the next run's start,
    or to the last sample for the final run).
    """

    codes: np.ndarray
    start: np.ndarray
    t_start: np.ndarray
    duration: np.ndarray


def run_lengths(t, leg_states) -> StateRuns:
    """Run-length encode one leg's state sequence ``leg_states`` (T,)."""
    t, s = check_timeline(t, leg_states)
    s = s[:, 0]
    if len(s) == 0:
        empty = np.zeros(0)
        return StateRuns(np.zeros(0, dtype=s.dtype), np.zeros(0, dtype=int), empty, empty)
    start = np.flatnonzero(np.r_[True, s[1:] != s[:-1]])
    ends = np.r_[t[start[1:]], t[-1]]
    return StateRuns(s[start], start, t[start], ends - t[start])


def state_sequences(t, states) -> list[np.ndarray]:
    """Per leg, the sequence of distinct states it visits (codes of its runs, in order)."""
    t, states = check_timeline(t, states)
    return [run_lengths(t, states[:, leg]).codes for leg in range(states.shape[1])]


def state_time_fractions(t, states, warmup_s: float = 0.0) -> np.ndarray:
    """(n_legs, N_STATES): time-weighted fraction of the window each leg spends in each state."""
    t, states = check_timeline(t, states)
    i0 = window_start(t, warmup_s)
    w = hold_durations(t)[i0:]
    s = states[i0:]
    if len(s) == 0:
        return np.full((states.shape[1], N_STATES), math.nan)
    onehot = (s[:, :, None] == np.arange(N_STATES)).astype(float)
    return _weighted_mean(onehot, w, axis=0)


def format_cycle(cycle: Sequence[int]) -> str:
    """E.g. ``"SF1 -> SF2 -> STANCE"``."""
    return " -> ".join(STATE_NAMES[c] for c in cycle)


@dataclass(frozen=True)
class CycleSummary:
    """The dominant state cycle of one leg over the analysed part of a run.

    cycle: the most frequent complete cycle (state codes, starting at the
        anchor state), () if none was completed.
    share: fraction of the complete cycles equal to ``cycle`` (NaN if none).
    n_cycles: number of complete cycles.
    fractions: (N_STATES,) time fractions of each state over the analysed part,
        ignored states included.
    t_from: start of the analysed part [s].
    """

    cycle: tuple[int, ...]
    share: float
    n_cycles: int
    fractions: np.ndarray
    t_from: float

    def __str__(self) -> str:
        fr = ", ".join(f"{n} {f:.2f}" for n, f in zip(STATE_NAMES, self.fractions) if f > 0)
        return f"{format_cycle(self.cycle) or '(none)'} x{self.n_cycles} (share {self.share:.2f}; {fr})"


def dominant_cycle(t, leg_states, last_fraction: float = 0.5, ignore: Sequence[int] = (),
                   anchor: int = SF1) -> CycleSummary:
    """Most frequent state cycle of one leg in the last part of a run.

    The analysed part is the samples with ``t >= t[-1] - last_fraction *
    (t[-1] - t[0])``.  Its run-length encoding, with runs of the ``ignore``
    states dropped and adjacent equal runs then merged, is cut before every
    run of ``anchor`` (SF1 starts both loops of paper Fig. 10).  Each piece
    between two anchor runs is one complete cycle (the pieces before the first
    and after the last anchor run are partial and dropped); the most frequent
    piece is the dominant cycle.  Ties go to the cycle seen first.
    """
    if not 0 < last_fraction <= 1:
        raise ValueError(f"last_fraction must be in (0, 1], got {last_fraction}")
    t, s = check_timeline(t, leg_states)
    if len(t) == 0:
        return CycleSummary((), math.nan, 0, np.full(N_STATES, math.nan), math.nan)
    t_from = t[-1] - last_fraction * (t[-1] - t[0])
    i0 = int(np.searchsorted(t, t_from, side="left"))
    t, s = t[i0:], s[i0:, 0]
    fractions = state_time_fractions(t, s)[0]
    codes = [int(c) for c in run_lengths(t, s).codes if int(c) not in set(ignore)]
    merged = [c for i, c in enumerate(codes) if i == 0 or c != codes[i - 1]]
    cuts = [i for i, c in enumerate(merged) if c == anchor]
    cycles = [tuple(merged[a:b]) for a, b in zip(cuts[:-1], cuts[1:])]
    if not cycles:
        return CycleSummary((), math.nan, 0, fractions, float(t[0]))
    counts = Counter(cycles)  # insertion order breaks ties toward the cycle seen first
    best, n_best = max(counts.items(), key=lambda kv: kv[1])
    return CycleSummary(best, n_best / len(cycles), len(cycles), fractions, float(t[0]))


@dataclass(frozen=True)
class WalkingCycleCheck:
    """Result of ``walking_cycle_check``: the verdict, why, and the evidence."""

    converged: bool
    reasons: tuple[str, ...]
    summary: CycleSummary

    def __bool__(self) -> bool:
        return self.converged


def walking_cycle_check(t, leg_states, last_fraction: float = 0.5) -> WalkingCycleCheck:
    """Has one leg converged to SF1 -> SF2 -> STANCE with brief ADJUST and SB1 (paper Fig. 10 D)?

    Over the last ``last_fraction`` of the run (see ``dominant_cycle``), all of:
      1. the dominant cycle, with ADJUST and SB1 runs ignored, is
         ``WALKING_CYCLE`` = (SF1, SF2, STANCE);
      2. it is at least ``MIN_CYCLE_SHARE`` of the complete cycles, and at least
         ``MIN_CYCLES`` of them were seen;
      3. ADJUST and SB1 are brief: each takes at most
         ``BRIEF_STATE_MAX_FRACTION`` of the analysed time.
    SB2 is not ignored, so the suspended loop SF1 -> SF2 -> SB1 -> SB2
    (Fig. 10 A) fails rule 1 (and rule 3, SB1 being a quarter of the time).
    """
    summary = dominant_cycle(t, leg_states, last_fraction, ignore=WALKING_BRIEF_STATES)
    reasons = []
    if summary.cycle != WALKING_CYCLE:
        reasons.append(f"dominant cycle is {format_cycle(summary.cycle) or '(none)'}, "
                       f"not {format_cycle(WALKING_CYCLE)}")
    elif summary.n_cycles < MIN_CYCLES or not summary.share >= MIN_CYCLE_SHARE:
        reasons.append(f"walking cycle is {summary.share:.2f} of {summary.n_cycles} cycles, "
                       f"needs >= {MIN_CYCLE_SHARE} of >= {MIN_CYCLES}")
    for c in WALKING_BRIEF_STATES:
        if not summary.fractions[c] <= BRIEF_STATE_MAX_FRACTION:
            reasons.append(f"{STATE_NAMES[c]} takes {summary.fractions[c]:.2f} of the time, "
                           f"brief means <= {BRIEF_STATE_MAX_FRACTION}")
    return WalkingCycleCheck(not reasons, tuple(reasons), summary)


def walking_cycle_leg_fraction(t, states, last_fraction: float = 0.5) -> float:
    """Fraction of legs that pass ``walking_cycle_check``; NaN without legs."""
    t, states = check_timeline(t, states)
    if states.shape[1] == 0:
        return math.nan
    return float(np.mean([walking_cycle_check(t, states[:, leg], last_fraction).converged
                          for leg in range(states.shape[1])]))


# --- Everything at once ---------------------------------------------------------------------
def gait_metrics(t, states, tips=None, com=None, body_length: float = math.nan,
                 warmup_s: float = 0.0) -> tuple[dict[str, float], dict[str, str]]:
    """All gait metrics over the window after ``warmup_s`` (module docstring for conventions).

    Shapes: t (T,) [s]; states (T, n_legs) int; tips (T, n_legs, 3) [m] or None;
    com (T, 3) [m] or None; body_length [m].  Returns ``(metrics, labels)``:
    ``metrics`` maps every name in ``FLOAT_METRICS`` to a float (NaN when
    undefined, or when the input it needs is None); ``labels`` maps
    ``"wave_direction"`` to "retrograde", "direct", "synchronous" or "undefined".

    duty_factor_mean, duty_factor_std: mean and population std over legs of the
        per-leg duty factor (``StrideStats``).
    stride_frequency_hz: mean over legs of the per-leg stride frequency.
    stepping_leg_fraction: fraction of legs with a complete stride in the
        window, i.e. those the two averages above are taken over.
    phase_lag_mean, phase_lag_cv, legs_per_wave, lr_phase_diff: ``wave_metrics``.
    stance_fraction_min, stance_fraction_mean: ``stance_fraction`` over the
        window samples: its minimum, and its time-weighted mean.
    stride_length_bl: ``stride_length`` at the mean stride frequency / body_length.
    speed_bl_per_stride: ``speed_per_stride`` at the mean stride frequency / body_length.
    foot_slip_mean_m: ``foot_slip_mean``.
    walking_cycle_leg_fraction: fraction of legs whose state sequence over the
        whole window passes ``walking_cycle_check`` (paper Fig. 10 D).
    """
    t, states = check_timeline(t, states)
    metrics = dict.fromkeys(FLOAT_METRICS, math.nan)
    labels = {"wave_direction": UNDEFINED}
    i0 = window_start(t, warmup_s)
    n_legs = states.shape[1]
    if len(t) - i0 < 2 or n_legs == 0:
        return metrics, labels

    st = stride_stats(t, states, warmup_s)
    stepping = np.isfinite(st.duty_factor)
    metrics["stepping_leg_fraction"] = float(stepping.mean())
    if stepping.any():
        metrics["duty_factor_mean"] = float(st.duty_factor[stepping].mean())
        metrics["duty_factor_std"] = float(st.duty_factor[stepping].std())
        metrics["stride_frequency_hz"] = float(st.stride_frequency_hz[stepping].mean())

    wave, labels = wave_metrics(st.onset_times)
    metrics.update(wave)

    frac = stance_fraction(states[i0:])
    metrics["stance_fraction_min"] = float(frac.min())
    metrics["stance_fraction_mean"] = float(_weighted_mean(frac, hold_durations(t)[i0:]))

    if com is not None and body_length > 0:
        metrics["stride_length_bl"] = stride_length(t, com, metrics["stride_frequency_hz"], t[i0]) / body_length
        metrics["speed_bl_per_stride"] = (speed_per_stride(t, com, metrics["stride_frequency_hz"], t[i0])
                                          / body_length)
    if tips is not None:
        metrics["foot_slip_mean_m"] = foot_slip_mean(t, states, tips, warmup_s)
    metrics["walking_cycle_leg_fraction"] = walking_cycle_leg_fraction(t[i0:], states[i0:], last_fraction=1.0)
    return metrics, labels


def body_undulation(centers: np.ndarray) -> float:
    """Mean half-width [m] of the segment centres' sideways spread about the head-tail line.

    centers: (T, n_seg, 3) [m].  At each sample, the horizontal distance of every
    centre from the line through the head and tail centres (signed, to the
    right); half of max - min, averaged over the samples.
    """
    a = centers[:, 0, [0, 2]]
    b = centers[:, -1, [0, 2]]
    d = a - b
    n = np.stack([-d[:, 1], d[:, 0]], axis=1) / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-12)
    off = np.einsum("tij,tj->ti", centers[:, :, [0, 2]] - b[:, None, :], n)
    return float(np.mean(0.5 * (off.max(axis=1) - off.min(axis=1))))
