"""The slithering friction sweep (issue 27): speed against mu_t / mu_f with the kinematic reference.

A matrix that sweeps ``friction.mu_transverse`` for a bending gait that commands its shape
(``scenarios/matrix/slithering.toml``) gets one plot: ``speed_bl_per_cycle`` of each body against the
friction ratio mu_t / mu_f, with Hu et al.'s kinematic model (``reference.slithering.steady_slithering``)
at the COMMANDED curvature amplitude and wavelength and the belly's width drawn as a line.  A run
flagged ``shape_not_achieved`` (``metrics.shape_tracking``) is drawn hollow: its body did not bend as
commanded, so its speed is not the reference's case.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from .figure_files import figure_section, finish_plot  # noqa: E402

KEY = "friction.mu_transverse"
METRIC = "metric.speed_bl_per_cycle"
REFERENCE_RATIOS = np.array([1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.5, 8.0, 10.0])


def _command(case: dict) -> tuple | None:
    """(A, wavelength_bl, mu_f, mu_b / mu_f, belly width in body lengths) of a case commanding its shape, else None."""
    g, f, c = case["gait"], case["friction"], case["creature"]
    if g["name"] not in ("lateral-undulation", "sidewinding") or not g.get("curvature_amplitude"):
        return None
    if f.get("model") != "coulomb" or not f.get("mu_forward"):
        return None
    length = c["segments"] * c["segment_length_m"]
    return (g["curvature_amplitude"], g["wavelength_bl"], f["mu_forward"], f["mu_backward"] / f["mu_forward"],
            c["width_m"] / length)


def sweep_cases(df: pd.DataFrame) -> pd.DataFrame:
    """The ok cases with a swept mu_t of a gait that commands its shape, with columns ``ratio`` and ``command``."""
    col = f"grid.{KEY}"
    if col not in df or METRIC not in df:
        return df.iloc[0:0]
    sub = df[df[col].notna() & (df["status"] == "ok")].copy()
    if sub.empty:
        return sub
    cmds = [_command(json.loads(cj)) for cj in sub["case_json"]]
    sub["command"] = cmds
    sub = sub[[c is not None for c in cmds]]
    sub["ratio"] = [float(mt) / cmd[2] for mt, cmd in zip(sub[col], sub["command"])]
    return sub


def has_friction_sweep(df: pd.DataFrame, grid_keys) -> bool:
    """True when the matrix sweeps mu_t for a gait that commands its shape on Coulomb friction."""
    return KEY in grid_keys and not sweep_cases(df).empty


def plot_speed_vs_friction_ratio(df: pd.DataFrame, path: Path) -> Path:
    """speed_bl_per_cycle [BL/cycle] against mu_t / mu_f, one line per body; the kinematic reference per command."""
    from ..reference.slithering import steady_slithering

    sub = sweep_cases(df)
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    colors = plt.get_cmap("tab10")
    for n, (cmd, group) in enumerate(sub.groupby("command", sort=True)):
        a, lam, _, mub, width = cmd
        ref = [steady_slithering(a, lam, 1.0, mub, q, width_bl=width).speed_bl_per_cycle for q in REFERENCE_RATIOS]
        ax.plot(REFERENCE_RATIOS, ref, "k-" if n == 0 else "k--", lw=1.6,
                label=f"kinematic reference (Hu et al. 2009), A = {a:g}, wavelength {lam:g} BL")
        for m, ((creature, body), s) in enumerate(group.groupby(["creature", "body"], sort=True)):
            s = s.sort_values("ratio")
            color = colors(m % 10)
            ax.plot(s["ratio"], s[METRIC], "-", color=color, lw=1.0)
            flagged = s.get("metric.shape_not_achieved", pd.Series(0.0, index=s.index)).fillna(0.0) == 1.0
            ax.plot(s["ratio"][~flagged], s[METRIC][~flagged], "o", color=color, ms=5, label=f"{creature} / {body}")
            if flagged.any():
                ax.plot(s["ratio"][flagged], s[METRIC][flagged], "o", mfc="none", color=color, ms=7,
                        label=f"{creature} / {body}: shape not achieved")
    ax.set_xscale("log")
    ax.set_xticks([1, 1.5, 2, 3, 5, 10], labels=["1", "1.5", "2", "3", "5", "10"])
    return finish_plot(fig, ax, path, "friction ratio mu_t / mu_f", "forward speed [body lengths per cycle]",
                       legend_loc="upper left", dpi=130)


def report_section(page, res) -> None:
    """The report's friction-sweep section (``report.build``): the plot and a line on what it shows."""
    figure_section(page, "friction-sweep", "Slithering: speed against the friction ratio", "friction_sweep_speed.png",
                   plot_speed_vs_friction_ratio, res.df,
                   "Forward speed per gait cycle against mu_t / mu_f at a fixed Froude number, each body model "
                   "with the commanded shape tracked; line: Hu et al.'s kinematic model at the commanded curvature "
                   "amplitude and wavelength and the belly's width.  Hollow: shape_not_achieved (the body did not "
                   "bend as commanded: shape_tracking_error > 10 %).")
