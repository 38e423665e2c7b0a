"""The ``regress`` history as a figure: normalized throughput per suite entry against run and commit.

``plot_regress_history(load_history(store), path)`` (``harness/regress.py``) draws two panels
sharing the run axis: the normalized figure (steps/s / reference ops/s) of every entry on a log
scale with error bars of its measured noise, and each entry's change relative to its first run
in the history, where a regression shows as a drop.  Ticks name the run id and commit
(``+`` for a dirty tree).
"""
from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from .figure_files import layout_once


def plot_regress_history(df, path: Path | str, title: str | None = None) -> Path:
    """Write the history figure to ``path`` (PNG, SVG or PDF by suffix); return the path.

    df: the DataFrame of ``harness.regress.load_history`` (columns run_id, entry, git_commit,
    git_dirty, normalized, spread, reference_spread; ``commit_short`` is used when present).
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9.0, 6.5), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 2]})
    if df is None or len(df) == 0:
        top.text(0.5, 0.5, "no regress runs yet", ha="center", va="center", transform=top.transAxes)
        top.set_yticks([])
        bottom.set_yticks([])
    else:
        runs = sorted(int(r) for r in df["run_id"].unique())
        pos = {r: i for i, r in enumerate(runs)}
        if "commit_short" in df:
            short = dict(zip(df["run_id"], df["commit_short"]))
        else:
            short = {r: (c[:7] if isinstance(c, str) else "?") + ("+" if d == 1 else "")
                     for r, c, d in zip(df["run_id"], df["git_commit"], df["git_dirty"])}
        for name, g in df.sort_values("run_id").groupby("entry", sort=True):
            x = np.array([pos[int(r)] for r in g["run_id"]], dtype=float)
            y = g["normalized"].to_numpy(dtype=float)
            noise = np.hypot(g["spread"].to_numpy(dtype=float), g["reference_spread"].to_numpy(dtype=float))
            line = top.errorbar(x, y, yerr=y * noise, marker="o", ms=4, capsize=2, lw=1.2, label=name)
            rel = 100.0 * (y / y[0] - 1.0)
            bottom.errorbar(x, rel, yerr=100.0 * noise * y / y[0], marker="o", ms=4, capsize=2, lw=1.2,
                            color=line[0].get_color())
        top.set_yscale("log")
        top.set_ylabel("steps/s / reference ops/s")
        top.legend(fontsize=9, ncol=2, loc="best")
        top.grid(True, which="both", alpha=0.3)
        bottom.axhline(0.0, color="0.4", lw=0.8)
        bottom.set_ylabel("change vs. first run [%]")
        bottom.grid(True, alpha=0.3)
        step = max(1, math.ceil(len(runs) / 20))  # at most about 20 labels
        ticks = list(range(0, len(runs), step))
        bottom.set_xticks(ticks)
        bottom.set_xticklabels([f"{runs[i]}\n{short[runs[i]]}" for i in ticks], fontsize=9)
        bottom.set_xlabel("regress run / commit")
        bottom.set_xlim(-0.5, len(runs) - 0.5)
    top.set_title(title or "Normalized throughput per regress run")
    fig.tight_layout()
    layout_once(fig, path, 110)  # savefig draws once, not twice (figure_files.layout_once)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def peer_ratio_history(df):
    """Ours / peer speed-ups per ``peers`` run: a DataFrame with columns run_id, commit_short, timestamp,
    pair (``ours vs peer``) and speedup (ours steps/s / peer steps/s, > 1: ours is faster), one row
    per pair present in a run (``harness.peers.peer_pairs``); empty when no run holds a pair."""
    import pandas as pd

    from ..harness.peers import peer_pairs

    rows = []
    if df is not None and len(df):
        pairs = peer_pairs()
        for run_id, g in df.groupby("run_id", sort=True):
            sps = dict(zip(g["entry"], g["steps_per_s"]))
            first = g.iloc[0]
            for peer, ours in pairs.items():
                if peer in sps and ours in sps and sps[peer] > 0:
                    rows.append({"run_id": int(run_id), "commit_short": first.get("commit_short", "?"),
                                 "timestamp": first["timestamp"], "pair": f"{ours} vs {peer}",
                                 "speedup": float(sps[ours]) / float(sps[peer])})
    return pd.DataFrame(rows, columns=["run_id", "commit_short", "timestamp", "pair", "speedup"])
