"""Gait diagrams of a many-legged creature: leg states over time, and phase lags along the body.

``plot_gait_diagram`` draws the right panel of paper Fig. 10 (Fang, Jiang &
Terzopoulos 2013): one row per leg, head at the top, time to the right, each
state run a bar in its state colour (``metrics.gait.STATE_COLORS``).  A
retrograde wave shows as stance bars whose onsets move later from row to row
down each side; a direct wave as onsets moving earlier.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from ..metrics.gait import (  # noqa: E402
    LEFT,
    N_STATES,
    RIGHT,
    STATE_COLORS,
    STATE_DESCRIPTIONS,
    STATE_NAMES,
    check_timeline,
    leg_index,
    leg_label,
    phase_lags_per_leg,
    run_lengths,
    stride_stats,
    wave_metrics,
)
from .figure_files import LABEL_PT, TITLE_PT, WIDE_IN, save_figure  # noqa: E402

# the legend's title: the leg-tip positions the state descriptions name (paper Sec. 4.2)
LEGEND_TITLE = ("leg state (Fang et al. 2013, Sec. 4.2)\nPEP / AEP: posterior / anterior extreme position\n"
                "MUP / MDP: middle up / down position")
ROW_HEIGHT = 0.9        # bar height as a fraction of the row pitch: thin white gaps separate legs
GROUP_GAP_ROWS = 0.8    # extra space between the left and the right block in the grouped layout
ROW_PITCH_IN = 0.2      # [in] per leg row: room for a 9 pt label
MAX_HEIGHT_IN = 16.0    # [in] taller diagrams label every other leg


def leg_rows(n_legs: int, layout: str = "grouped") -> list[tuple[int, float]]:
    """(leg, y) for each leg; y grows downward from 0 (head at the top).

    ``"grouped"``: all left legs head to tail, a gap, then all right legs, so
    that each side's wave is one unbroken diagonal.  ``"interleaved"``: L0, R0,
    L1, R1, ... so that left/right pairs sit next to each other.
    """
    if layout == "interleaved":
        return [(leg, float(leg)) for leg in range(n_legs)]
    if layout != "grouped":
        raise ValueError(f"layout must be 'grouped' or 'interleaved', got {layout!r}")
    n_seg = (n_legs + 1) // 2
    left = [(leg_index(s, LEFT), float(s)) for s in range(n_seg) if leg_index(s, LEFT) < n_legs]
    right = [(leg_index(s, RIGHT), n_seg + GROUP_GAP_ROWS + s) for s in range(n_seg)
             if leg_index(s, RIGHT) < n_legs]
    return left + right



def plot_gait_diagram(t, states, path, last_seconds: float = 1.0, title: str | None = None,
                      layout: str = "grouped") -> Path:
    """Leg-state diagram of the last ``last_seconds`` of a run (paper Fig. 10, right panel).

    t: (T,) [s]; states: (T, n_legs) int state codes, leg = 2 * segment + side.
    Each state holds from its sample to the next (sample-and-hold), so
    irregular sampling is drawn to scale.  Writes a PNG to ``path`` and returns it.
    """
    t, states = check_timeline(t, states)
    if len(t) == 0:
        raise ValueError("empty timeline")
    i0 = int(np.searchsorted(t, t[-1] - last_seconds, side="left"))
    t, states = t[i0:], states[i0:]
    n_legs = states.shape[1]
    rows = leg_rows(n_legs, layout)
    y_max = max((y for _, y in rows), default=0.0) + 1

    # a row pitch of at least 0.2 in keeps the 9 pt leg labels apart (taller than 16 in: every other label)
    fig_h = min(max(2.6, ROW_PITCH_IN * y_max + 1.4), MAX_HEIGHT_IN)
    fig, ax = plt.subplots(figsize=(WIDE_IN * 0.85, fig_h))
    # Every bar in one collection (one artist, not one per leg and state: a 36-legged diagram had 100 or
    # more), in the order, corners and colours broken_barh per leg and state would draw them.
    verts, colors = [], []
    for leg, y in rows:
        runs = run_lengths(t, states[:, leg])
        y0 = y - ROW_HEIGHT / 2
        y1 = y0 + ROW_HEIGHT
        for code in range(N_STATES):
            sel = runs.codes == code
            for x0, dx in zip(runs.t_start[sel], runs.duration[sel]):
                x1 = x0 + dx
                verts.append([(x0, y0), (x0, y1), (x1, y1), (x1, y0)])
                colors.append(STATE_COLORS[code])
    if verts:
        # antialiasing off: bar interiors keep their exact state colour, edges do not blend
        ax.add_collection(PolyCollection(np.array(verts), facecolors=colors, edgecolors="none", antialiased=False))
    every = 1 if (fig_h - 1.4) / y_max >= ROW_PITCH_IN * 0.99 else 2
    ax.set_yticks([y for _, y in rows][::every])
    ax.set_yticklabels([leg_label(leg) for leg, _ in rows][::every], fontsize=LABEL_PT)
    ax.set_ylim(y_max - 0.5, -0.5)  # head at the top
    ax.set_xlim(t[0], t[-1] if t[-1] > t[0] else t[0] + 1e-3)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("leg (L/R, segment; head at top)")
    # each state named and explained where it is drawn: the codes alone (SF1, SB2) say nothing to a reader
    handles = [Patch(facecolor=STATE_COLORS[c], label=f"{STATE_NAMES[c]}: {STATE_DESCRIPTIONS[c]}")
               for c in range(N_STATES)]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=LABEL_PT, frameon=False,
              title=LEGEND_TITLE, title_fontsize=LABEL_PT, alignment="left")
    ax.set_title(title or f"Leg states, last {t[-1] - t[0]:.2f} s", fontsize=TITLE_PT)
    fig.tight_layout()
    return save_figure(fig, path)


def plot_phase_lags(t, states, path, warmup_s: float = 0.0, title: str | None = None) -> Path:
    """Per-leg phase lag behind the same-side leg ahead, along the body.

    x: segment index (1 = first segment behind the head); y: lag in cycles,
    (-0.5, 0.5]; positive = retrograde (head-to-tail) wave.  Left and right
    legs are separate series with error bars showing the RMS spread of each
    leg's lag events; the dashed line is ``phase_lag_mean``.  Writes a PNG to
    ``path`` and returns it.  ``phase_lag_data`` then ``draw_phase_lags``.
    """
    return draw_phase_lags(phase_lag_data(t, states, warmup_s), path, title)


@dataclass(frozen=True)
class PhaseLags:
    """What ``draw_phase_lags`` plots: per-leg mean lag and RMS spread [cycles] (n_legs,), and the wave's
    mean lag and its label (``metrics.gait.wave_metrics``)."""

    mean: np.ndarray
    spread: np.ndarray
    lag_mean: float
    wave_direction: str
    n_legs: int


def phase_lag_data(t, states, warmup_s: float = 0.0) -> PhaseLags:
    """The lags of a leg timeline t (T,) [s], states (T, n_legs); ValueError for a timeline that has none."""
    t, states = check_timeline(t, states)
    mean, spread = phase_lags_per_leg(t, states, warmup_s)
    wave, labels = wave_metrics(stride_stats(t, states, warmup_s).onset_times)
    return PhaseLags(mean, spread, wave["phase_lag_mean"], labels["wave_direction"], states.shape[1])


def draw_phase_lags(lags: PhaseLags, path, title: str | None = None) -> Path:
    """The figure of ``plot_phase_lags`` from measured lags; writes a PNG to ``path`` and returns it."""
    mean, spread, n_legs = lags.mean, lags.spread, lags.n_legs
    fig, ax = plt.subplots(figsize=(WIDE_IN * 0.8, 4.4))
    for side, marker, name in ((LEFT, "o", "left"), (RIGHT, "s", "right")):
        legs = np.arange(side, n_legs, 2)
        seg = legs // 2
        ax.errorbar(seg + (0.08 if side == RIGHT else -0.08), mean[legs], yerr=spread[legs], fmt=marker,
                    ms=4, capsize=2, lw=0.8, label=f"{name} legs")
    ax.axhline(0.0, color="0.5", lw=0.8)
    lag = lags.lag_mean
    if math.isfinite(lag):
        ax.axhline(lag, color="k", ls="--", lw=0.8, label=f"mean {lag:+.3f} ({lags.wave_direction})")
    ax.set_ylim(-0.5, 0.5)
    ax.text(0.01, 0.97, "retrograde (head to tail)", transform=ax.transAxes, va="top", fontsize=LABEL_PT, color="0.4")
    ax.text(0.01, 0.03, "direct (tail to head)", transform=ax.transAxes, va="bottom", fontsize=LABEL_PT, color="0.4")
    ax.set_xlabel("segment (0 = head)")
    ax.set_ylabel("phase lag behind the leg ahead [cycles]")
    ax.set_xlim(0.5, max((n_legs + 1) // 2 - 0.5, 1.5))
    ax.legend(fontsize=LABEL_PT, loc="best")
    ax.set_title(title or "Inter-leg phase lag along the body", fontsize=TITLE_PT)
    fig.tight_layout()
    return save_figure(fig, path)
