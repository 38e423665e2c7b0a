"""Plots of parameter sweeps: stability over (dt, stiffness) and throughput against problem size.

A matrix sweeps a parameter through a grid key (``[matrix.grid]`` or a block's
``grid``).  Two kinds of sweep have their own report section:

* stability -- ``dt`` together with a stiffness key (``STIFFNESS_KEYS``): a
  heatmap per creature and body model over one dt grid shared by all of them,
  each cell stable (green) or the time the run blew up (red, darker = earlier,
  with a colour bar), annotated with ``t_fail``;
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
from matplotlib.cm import ScalarMappable  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from .figure_files import LABEL_PT, save_figure  # noqa: E402

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


BLOW_UP_KEYS = ("dt",) + STIFFNESS_KEYS  # a sweep over these looks for where the integrator blows up


def blow_up_sweep_mask(df: pd.DataFrame, grid_keys) -> pd.Series:
    """Cases with a swept dt or stiffness key: their blow-ups are intended (they map the stable range)."""
    mask = pd.Series(False, index=df.index)
    for k in grid_keys:
        if k in BLOW_UP_KEYS:
            mask |= _has(df, k)
    return mask


# --------------------------------------------------------------------------- stability

# axis names with units of the swept keys (the units of the bodies' configuration fields)
KEY_LABELS = {"dt": "time step dt [s]",
              "body.stiffness": "stiffness k per unit mass [1/frame^2] (body.stiffness)",
              "body.youngs_modulus_pa": "Young's modulus E [Pa] (body.youngs_modulus_pa)",
              "body.link_stiffness_n_m": "link spring constant [N/m] (body.link_stiffness_n_m)",
              "creature.segments": "segments (creature.segments)",
              "body.resolution": "mesh resolution per segment edge (body.resolution)"}
STABLE_COLOR = (0.30, 0.69, 0.40, 1.0)
ERROR_COLOR = (0.75, 0.75, 0.75, 1.0)
NOT_RUN_COLOR = (1.0, 1.0, 1.0, 1.0)


def key_label(key: str) -> str:
    """An axis name with unit for a swept key (the key itself when it has no entry in KEY_LABELS)."""
    return KEY_LABELS.get(key, key)


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


def shared_dt_grid(groups) -> list[float]:
    """Every dt [s] of any stability sweep, ascending: the common columns of all heatmaps, so that the
    bodies' stable ranges can be compared by eye (a body not run at a dt shows a blank cell)."""
    return sorted({float(d) for _, _, _, sub in groups for d in sub["dt"].astype(float)})


def plot_stability_heatmap(sub: pd.DataFrame, key: str, path: Path, title: str,
                           dts: list[float] | None = None) -> Path:
    """Heatmap over (dt, stiffness): each cell the fraction of the run survived before blowing up.

    Colour bar: t_fail / duration from 0 (blew up at once, dark red) to 1 (light); green = stable for
    the whole run; grey = error or timeout; white = not run at this dt.  Each cell is also labelled
    (``stable``, t_fail in s, or the status).  Several seeds in a cell: the earliest blow-up, with
    "(k/n)" when only k of the n seeds blew up.  dts: the columns [s] (``shared_dt_grid``), default this
    sweep's own.
    """
    kcol = f"grid.{key}"
    dts = sorted(sub["dt"].astype(float).unique()) if dts is None else list(dts)
    ks = sorted(sub[kcol].astype(float).unique())
    duration = float(sub["duration"].max())
    survived = np.full((len(ks), len(dts)), np.nan)   # t_fail / duration of unstable runs
    rgba = np.tile(NOT_RUN_COLOR, (len(ks), len(dts), 1))
    text = np.full((len(ks), len(dts)), "not run", dtype=object)
    cmap = plt.get_cmap("Reds_r")
    norm = Normalize(0.0, 1.0)
    sub = sub.assign(_k=sub[kcol].astype(float), _dt=sub["dt"].astype(float))
    for (k, dt), cell in sub.groupby(["_k", "_dt"], sort=False):  # several seeds share a cell
        i, j = ks.index(k), int(np.argmin([abs(d - dt) for d in dts]))
        status = list(cell["status"])
        n_unstable, n = status.count("unstable"), len(status)
        if n_unstable:  # the earliest blow-up of the cell's seeds; "k/n" when not every seed blew up
            tf = float(pd.to_numeric(cell.loc[cell.status == "unstable", "metric.t_fail_s"], errors="coerce").min()) \
                if "metric.t_fail_s" in cell else math.nan
            frac = tf / duration if math.isfinite(tf) and duration > 0 else 0.0
            survived[i, j] = frac
            rgba[i, j] = cmap(norm(0.8 * frac))  # at most 0.8 of the map: the lightest reds stay visible
            text[i, j] = (f"{tf:.2g} s" if math.isfinite(tf) else "unstable") + \
                ("" if n_unstable == n else f" ({n_unstable}/{n})")
        elif all(st == "ok" for st in status):
            rgba[i, j], text[i, j] = STABLE_COLOR, "stable"
        else:
            rgba[i, j], text[i, j] = ERROR_COLOR, next(st for st in status if st != "ok")
    fig, ax = plt.subplots(figsize=(max(8.5, 1.25 * len(dts) + 4.2), 0.62 * len(ks) + 2.6), layout="constrained")
    ax.imshow(rgba, origin="lower", aspect="auto")
    for i in range(len(ks)):
        for j in range(len(dts)):
            ax.text(j, i, text[i, j], ha="center", va="center", fontsize=LABEL_PT,
                    color="white" if math.isfinite(survived[i, j]) and survived[i, j] < 0.4 else "black")
    ax.set_xticks(range(len(dts)), [f"{d:.3g}" for d in dts])
    ax.set_yticks(range(len(ks)), [f"{k:.4g}" for k in ks])
    ax.set_xlabel(key_label("dt"))
    ax.set_ylabel(key_label(key).split(" (")[0])
    ax.set_title(title)
    bar = fig.colorbar(ScalarMappable(norm=Normalize(0.0, 1.25), cmap=cmap), ax=ax, fraction=0.05, pad=0.02,
                       ticks=[0.0, 0.25, 0.5, 0.75, 1.0])
    bar.ax.set_ylim(0.0, 1.0)
    bar.set_label("unstable: t_fail / run duration")
    ax.legend(handles=[Patch(facecolor=STABLE_COLOR, label="stable throughout"),
                       Patch(facecolor=ERROR_COLOR, label="error / timeout"),
                       Patch(facecolor=NOT_RUN_COLOR, edgecolor="0.5", label="not run at this dt")],
              loc="upper left", bbox_to_anchor=(0.0, -0.16 - 0.02 * max(0, 6 - len(ks))), ncol=3, frameon=False)
    return save_figure(fig, path)


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


def throughput_fits(series, key: str) -> dict[str, float]:
    """The fitted exponent p of each (creature, body) of one size key (``fit_exponent``), as
    ``plot_throughput_scaling`` returns them; named ``creature/body``."""
    return {f"{creature}/{body}": fit_exponent(n, sps)[0] for k, creature, body, n, sps in series if k == key}


def plot_throughput_scaling(series, path: Path, key: str) -> tuple[Path, dict[str, float]]:
    """Log-log steps/s against size for each (creature, body) of one size key; returns the fitted exponents."""
    fig, ax = plt.subplots(figsize=(9.0, 5.5), layout="constrained")
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
    ax.set_xlabel("segments (creature.segments)" if key == "creature.segments"
                  else "mesh size [tetrahedra] (swept by body.resolution)")
    ax.set_ylabel("steps per second")
    ax.set_title(f"Throughput against {'segment count' if key == 'creature.segments' else 'mesh resolution'}"
                 " (dashed: fit steps/s ~ N^p)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend()
    return save_figure(fig, path), fits

