"""Plots of parameter sweeps: stability over (dt, stiffness) and throughput against problem size.

A matrix sweeps a parameter through a grid key (``[matrix.grid]`` or a block's
``grid``).  Two kinds of sweep have their own report section:

* stability -- ``dt`` together with a stiffness key (``STIFFNESS_KEYS``): a
  heatmap per creature and body model, each cell stable (green) or the time
  the run blew up (red, darker = earlier), annotated with ``t_fail``;
* throughput scaling -- a size key (``SIZE_KEYS``): steps per second against
  the segment count or the mesh resolution (tetrahedra), log-log, with the
  exponent p of a least-squares fit steps/s ~ N^p.
"""
from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

from .figure_files import save_figure  # noqa: E402

# stiffness of each body model: Miller's k per unit mass, Young's modulus, the legged chain's springs
STIFFNESS_KEYS = ("body.stiffness", "body.youngs_modulus_pa", "body.link_stiffness_n_m")
# problem size: number of segments, mesh resolution per segment edge
SIZE_KEYS = ("creature.segments", "body.resolution")
# the body wave's phase offset (report/body_wave.py) has its own section too
SWEEP_KEYS = ("dt",) + STIFFNESS_KEYS + SIZE_KEYS + ("controller.body_wave_phase_rad",)


def _has(df: pd.DataFrame, key: str) -> pd.Series:
    """Cases whose grid point sets ``key`` (column ``grid.KEY`` of ``report.matrix_data``)."""
    col = f"grid.{key}"
    return df[col].notna() if col in df else pd.Series(False, index=df.index)


def sweep_mask(df: pd.DataFrame, grid_keys) -> pd.Series:
    """Cases that belong to a stability or scaling sweep (a sweep key is one of their grid axes)."""
    keys = [k for k in grid_keys if k in SWEEP_KEYS]
    mask = pd.Series(False, index=df.index)
    for k in keys:
        mask |= _has(df, k)
    return mask


# --------------------------------------------------------------------------- stability

def stability_groups(df: pd.DataFrame, grid_keys) -> list[tuple[str, str, str, pd.DataFrame]]:
    """(creature, body, stiffness key, cases) for every dt x stiffness sweep in the matrix."""
    if "dt" not in grid_keys:
        return []
    out = []
    for key in STIFFNESS_KEYS:
        if key not in grid_keys:
            continue
        sel = df[_has(df, key) & _has(df, "dt")]
        for (creature, body), sub in sel.groupby(["creature", "body"], sort=True):
            out.append((str(creature), str(body), key, sub))
    return out


def plot_stability_heatmap(sub: pd.DataFrame, key: str, path: Path, title: str) -> Path:
    """Heatmap over (dt, stiffness): green = stable for the whole run, red = blew up at t_fail, grey = error."""
    kcol = f"grid.{key}"
    dts = sorted(sub["dt"].astype(float).unique())
    ks = sorted(sub[kcol].astype(float).unique())
    duration = float(sub["duration"].max())
    # value: 1 = stable, 0..1 exclusive = fraction of the run survived, NaN = error or timeout
    val = np.full((len(ks), len(dts)), np.nan)
    text = np.empty((len(ks), len(dts)), dtype=object)
    text[:] = ""
    for _, r in sub.iterrows():
        i, j = ks.index(float(r[kcol])), dts.index(float(r["dt"]))
        if r["status"] == "ok":
            val[i, j], text[i, j] = 1.0, "stable"
        elif r["status"] == "unstable":
            tf = float(r.get("metric.t_fail_s", np.nan))
            val[i, j] = 0.95 * (tf / duration if math.isfinite(tf) and duration > 0 else 0.0)
            text[i, j] = f"{tf:.2g} s" if math.isfinite(tf) else "unstable"
        else:
            text[i, j] = str(r["status"])
    fig, ax = plt.subplots(figsize=(1.2 * len(dts) + 2.6, 0.6 * len(ks) + 1.8))
    reds = plt.get_cmap("Reds_r")(np.linspace(0.15, 0.75, 64))
    cmap = ListedColormap(np.vstack([reds, [[0.35, 0.75, 0.4, 1.0]]])).with_extremes(bad=(0.8, 0.8, 0.8))
    # the last bin (value 1) is green; NaN (error, timeout) grey
    ax.imshow(np.ma.masked_invalid(val), cmap=cmap, vmin=0.0, vmax=1.0, origin="lower", aspect="auto")
    for i in range(len(ks)):
        for j in range(len(dts)):
            ax.text(j, i, text[i, j], ha="center", va="center", fontsize=7)
    ax.set_xticks(range(len(dts)), [f"{d:.3g}" for d in dts], fontsize=7)
    ax.set_yticks(range(len(ks)), [f"{k:.3g}" for k in ks], fontsize=7)
    ax.set_xlabel("time step dt [s]")
    ax.set_ylabel(key)
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    return save_figure(fig, path, dpi=100)


# --------------------------------------------------------------------------- throughput scaling

def fit_exponent(n: np.ndarray, steps_per_s: np.ndarray) -> tuple[float, float]:
    """(p, c) of the least-squares line log(steps/s) = p log(N) + log(c); NaN with fewer than 2 sizes."""
    ok = np.isfinite(n) & np.isfinite(steps_per_s) & (n > 0) & (steps_per_s > 0)
    if np.unique(n[ok]).size < 2:
        return math.nan, math.nan
    p, logc = np.polyfit(np.log(n[ok]), np.log(steps_per_s[ok]), 1)
    return float(p), float(math.exp(logc))


def scaling_series(df: pd.DataFrame, grid_keys) -> list[tuple[str, str, str, np.ndarray, np.ndarray]]:
    """(size key, creature, body, N (k,), steps/s (k,)) for every size sweep; N in segments or tetrahedra."""
    out = []
    for key in SIZE_KEYS:
        if key not in grid_keys:
            continue
        sel = df[_has(df, key) & (df["status"] == "ok")]
        for (creature, body), sub in sel.groupby(["creature", "body"], sort=True):
            if key == "body.resolution" and "metric.n_tets" in sub and sub["metric.n_tets"].notna().all():
                n = sub["metric.n_tets"].to_numpy(float)
            else:
                n = sub[f"grid.{key}"].to_numpy(float)
            order = np.argsort(n)
            out.append((key, str(creature), str(body), n[order], sub["steps_per_s"].to_numpy(float)[order]))
    return out


def plot_throughput_scaling(series, path: Path, key: str) -> tuple[Path, dict[str, float]]:
    """Log-log steps/s against size for each (creature, body) of one size key; returns the fitted exponents."""
    fig, ax = plt.subplots(figsize=(6.0, 4.0))
    fits = {}
    for k, creature, body, n, sps in series:
        if k != key:
            continue
        p, c = fit_exponent(n, sps)
        name = f"{creature}/{body}"
        fits[name] = p
        line, = ax.loglog(n, sps, "o-", label=f"{name}: p = {p:.2f}" if math.isfinite(p) else name)
        if math.isfinite(p):
            xs = np.geomspace(n.min(), n.max(), 20)
            ax.loglog(xs, c * xs ** p, "--", color=line.get_color(), lw=0.8)
    ax.set_xlabel("segments" if key == "creature.segments" else "mesh size [tetrahedra] (swept by body.resolution)")
    ax.set_ylabel("steps per second")
    ax.set_title(f"Throughput against {'segment count' if key == 'creature.segments' else 'mesh resolution'}"
                 " (dashed: fit steps/s ~ N^p)", fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    return save_figure(fig, path, dpi=100), fits

