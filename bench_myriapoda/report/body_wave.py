"""The body-wave sweep (beyond the paper): speed per stride against the body wave's phase offset.

A matrix that sweeps ``controller.body_wave_phase_rad`` (``scenarios/matrix/body-wave.toml``)
gets one plot per creature, body model and amplitude: ``speed_bl_per_stride``
(metrics/gait.py, body lengths per leg cycle) against the offset of the lateral
body wave from the leg wave, with the same creature's cases without a wave
(amplitude 0) as a dashed line.  Scolopendra reaches its highest speed per
cycle near 2.5 rad; the plot shows where this controller's optimum lies.
"""
from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from .figure_files import figure_section, finish_plot  # noqa: E402

PHASE_KEY = "controller.body_wave_phase_rad"
AMPLITUDE_KEY = "controller.body_wave_amplitude"
METRIC = "metric.speed_bl_per_stride"
SCOLOPENDRA_BEST_RAD = 2.5


def has_body_wave_sweep(df: pd.DataFrame, grid_keys) -> bool:
    """True when the matrix sweeps the body wave's phase offset and measured speed per stride."""
    return PHASE_KEY in grid_keys and f"grid.{PHASE_KEY}" in df and METRIC in df


def _amplitude(row) -> float:
    v = row.get(f"grid.{AMPLITUDE_KEY}", math.nan)
    return float(v) if pd.notna(v) else math.nan


def plot_speed_per_stride_vs_offset(df: pd.DataFrame, path: Path) -> Path:
    """One line per (creature, body, amplitude) of speed per stride [body lengths] against the offset [rad].

    df: the matrix's cases (``report.matrix_data``); the swept ones have a ``grid.PHASE_KEY``
    value.  Cases of the same creature and body without that key are the no-wave baseline.
    """
    swept = df[df[f"grid.{PHASE_KEY}"].notna() & (df["status"] == "ok")]
    fig, ax = plt.subplots(figsize=(6.0, 3.6))
    colors = plt.get_cmap("tab10")
    for n, ((creature, body), sub) in enumerate(swept.groupby(["creature", "body"])):
        amps = sub.apply(_amplitude, axis=1)
        for amp in sorted(set(amps.dropna())) or [math.nan]:
            s = sub[amps == amp] if math.isfinite(amp) else sub
            s = s.sort_values(f"grid.{PHASE_KEY}")
            label = f"{creature} / {body}" + (f", amplitude {amp:g} rad" if math.isfinite(amp) else "")
            ax.plot(s[f"grid.{PHASE_KEY}"], s[METRIC], "o-", color=colors(n % 10), ms=4, lw=1.2, label=label)
        base = df[(df["creature"] == creature) & (df["body"] == body) & df[f"grid.{PHASE_KEY}"].isna()
                  & (df["status"] == "ok")][METRIC].dropna()
        if len(base):
            ax.axhline(float(base.mean()), color=colors(n % 10), ls="--", lw=1.0,
                       label=f"{creature} / {body}, no body wave")
    ax.axvline(SCOLOPENDRA_BEST_RAD, color="0.5", ls=":", lw=1.0, label="Scolopendra's best offset (~2.5 rad)")
    ax.set_xlim(0.0, 2.0 * np.pi)
    return finish_plot(fig, ax, path, "body wave phase offset from the leg wave [rad]",
                       "speed per stride [body lengths]", dpi=110)


def report_section(page, res) -> None:
    """The report's body-wave section (``report.build``): the plot and a line on what it shows."""
    figure_section(page, "body-wave", "Body wave: speed per stride against the phase offset",
                   "body_wave_speed_per_stride.png", plot_speed_per_stride_vs_offset, res.df,
                   "Speed per stride (net COM speed / stride frequency / body length) against the offset of "
                   "the lateral body wave from the head legs' phase; dashed: the same creature without a wave.")
