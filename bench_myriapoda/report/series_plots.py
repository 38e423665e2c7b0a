"""Plots of recorded time series: energy over time, and side-view film strips.

Energy: kinetic, elastic and gravitational energy [J] as recorded by every
body model (``Observation.energy``), one panel per case.  A passive body that
gains energy is numerically unstable; a driven one exchanges energy with its
muscles or its kinematic legs, so only the shape is comparable across bodies.

Film strip: the body's segment centres seen from the side (x right, y up) at
evenly spaced times, the way the papers' figures show a drop (myriapod paper
Fig. 4 and 10) or a worm sliding off a book (Miller, Image 1).
"""
from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..core.schema import ScenarioConfig  # noqa: E402
from ..harness.recorder import Series  # noqa: E402
from ..world.terrain_kernels import terrain_phi_numpy  # noqa: E402
from .figure_files import LABEL_PT, WIDE_IN, save_figure  # noqa: E402

ENERGY_NAMES = ("kinetic", "elastic", "gravitational")


def plot_energy(runs: Sequence[tuple[str, Series]], path: Path) -> Path:
    """One panel per run: the three energies and their sum [J] against time [s]."""
    n = len(runs)
    cols = min(n, 3)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(WIDE_IN if cols > 1 else 8.5, 3.4 * rows + 0.4), squeeze=False,
                             layout="constrained")
    for ax, (title, s) in zip(axes.flat, runs):
        e = np.asarray(s.energy, dtype=float)
        for k, name in enumerate(ENERGY_NAMES):
            ax.plot(s.t, e[:, k] - e[0, k], lw=1.0, label=f"{name}")
        ax.plot(s.t, e.sum(axis=1) - e[0].sum(), "k-", lw=1.4, label="total")
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_title(title, fontsize=LABEL_PT + 1)
        ax.set_xlabel("time [s]")
        ax.set_ylabel("E - E(0) [J]")
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    axes[0][0].legend(loc="best")
    return save_figure(fig, path)


def motion_spaced_frames(centers: np.ndarray, frames: int) -> np.ndarray:
    """Sample indices at equal steps of accumulated body motion, not of time.

    centers: (T, n_seg, 3) [m].  A drop is over in a fraction of a second and then the body rests:
    evenly spaced times would show one falling frame and five resting ones.  Spacing by the
    cumulative mean displacement of the segments puts the frames where the body moves; the first
    and last samples are always included.
    """
    T = len(centers)
    if T <= frames:
        return np.arange(T)
    step = np.linalg.norm(np.diff(centers, axis=0), axis=2).mean(axis=1)
    travelled = np.concatenate([[0.0], np.cumsum(step)])
    if travelled[-1] <= 0:
        return np.linspace(0, T - 1, frames).astype(int)
    idx = np.searchsorted(travelled, np.linspace(0.0, travelled[-1], frames), side="left")
    return np.unique(np.clip(idx, 0, T - 1))


def plot_side_strip(title: str, s: Series, scenario: dict, path: Path, frames: int = 6, *, world) -> Path:
    """The body from the side at ``frames`` times spaced by its motion, over the terrain profile.

    Coloured by ``viridis`` in time order: dark purple first, yellow last; the legend gives the times.
    """
    xy = s.segment_centers[..., :2].reshape(-1, 2)
    span = xy.max(axis=0) - xy.min(axis=0)
    tall = span[1] > span[0]  # a hanging body: a portrait figure
    fig, ax = plt.subplots(figsize=(8.5, 7.0) if tall else (WIDE_IN, 3.8), layout="constrained")
    idx = motion_spaced_frames(s.segment_centers, frames)
    cmap = plt.get_cmap("viridis")
    for k, i in enumerate(idx):
        c = s.segment_centers[i]
        color = cmap(k / max(frames - 1, 1))
        ax.plot(c[:, 0], c[:, 1], "-o", color=color, lw=1.6, ms=2.5, label=f"t = {s.t[i]:.2f} s")
    x0, x1 = float(s.segment_centers[..., 0].min()), float(s.segment_centers[..., 0].max())
    pad = 0.1 * max(x1 - x0, 1e-3)
    xs = np.linspace(x0 - pad, x1 + pad, 400)
    ys_all = s.segment_centers[..., 1]
    y_lo, y_hi = float(ys_all.min()), float(ys_all.max())
    if scenario.get("terrain", "plane") != "none":
        kind, f = world.terrain  # the case's world, built once by the caller (``MatrixResults.world``)
        # terrain profile in the x-y plane: the highest y with phi <= 0 below each x, by bisection on a grid
        ygrid = np.linspace(min(y_lo, scenario.get("ground_height_m", 0.0)) - 0.5 * (y_hi - y_lo + 0.1), y_hi, 600)
        P = np.stack(np.broadcast_arrays(xs[:, None], ygrid[None, :], 0.0 * xs[:, None]), axis=-1).reshape(-1, 3)
        inside = (terrain_phi_numpy(kind, f, P) <= 0).reshape(len(xs), len(ygrid))
        top = np.where(inside.any(axis=1), ygrid[np.where(inside, np.arange(len(ygrid)), 0).max(axis=1)], np.nan)
        ax.fill_between(xs, top, ygrid[0], color="burlywood", alpha=0.5, lw=0)
        ax.plot(xs, top, color="saddlebrown", lw=1.0)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(title)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False, title="dark to light:")
    return save_figure(fig, path)


def stored_section(cls, data: dict | None):
    """A stored case's section (``Case.to_dict()[...]``) as its config dataclass ``cls``.

    A recording made by an older version lacks the keys added since: they take their defaults,
    and keys no longer known are dropped, so old matrix directories still draw.  The values were
    validated when the case ran; a stored case is rebuilt as it was, not re-checked.
    """
    known = {f.name for f in dataclasses.fields(cls)}
    return cls(**{k: tuple(v) if isinstance(v, list) else v for k, v in (data or {}).items() if k in known})


def scenario_config(scenario: dict) -> ScenarioConfig:
    """A stored case's scenario section as a ``ScenarioConfig`` (see ``stored_section``)."""
    return stored_section(ScenarioConfig, scenario)

