"""Seed-to-seed spread: a creature's cases that ran with several seeds, as means with error bars.

A matrix with ``seeds = [0, 1, ...]`` runs every case once per seed (the
random walk of the head, the terrain, the food, the antennae's targets).  For
each case without its seed -- (body, gait, scenario) -- ``plot_seed_spread``
draws the mean over the seeds with an error bar of one sample standard
deviation, and every seed's own value as a small dot, for speed [BL/s] and
throughput [steps/s].
"""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from .figure_files import WIDE_IN, save_figure  # noqa: E402
from .tables import not_applicable_reason  # noqa: E402

GROUP_COLUMNS = ("body", "gait", "scenario")
SPREAD_METRICS = (("metric.speed_bl_per_s", "speed [body lengths/s]"), ("steps_per_s", "throughput [steps/s]"))


def seed_spread(df: pd.DataFrame, column: str) -> pd.DataFrame:
    """Per (body, gait, scenario): n seeds, mean, sample std (NaN for one seed) and the values of ``column``.

    Cases for which the metric does not apply (``tables.not_applicable_reason``) and runs that did not
    finish are left out.
    """
    if column not in df or "seed" not in df:
        return pd.DataFrame(columns=[*GROUP_COLUMNS, "n", "mean", "std", "values"])
    ok = df[df["status"].isin(["ok", "unstable"])]
    ok = ok[[not_applicable_reason(r, column) is None for _, r in ok.iterrows()]]
    rows = []
    for key, sub in ok.groupby(list(GROUP_COLUMNS), sort=True):
        v = pd.to_numeric(sub[column], errors="coerce").dropna().to_numpy(float)
        if len(v):
            rows.append({**dict(zip(GROUP_COLUMNS, key)), "n": len(v), "mean": float(v.mean()),
                         "std": float(v.std(ddof=1)) if len(v) > 1 else np.nan, "values": v})
    return pd.DataFrame(rows)


def has_several_seeds(df: pd.DataFrame) -> bool:
    """True when some case ran with more than one seed."""
    if "seed" not in df or df.empty:
        return False
    return bool((df.groupby(list(GROUP_COLUMNS))["seed"].nunique() > 1).any())


def plot_seed_spread(df: pd.DataFrame, path: Path, title: str) -> Path:
    """One panel per metric of ``SPREAD_METRICS``: mean +- 1 std over seeds per case, seeds as dots."""
    fig, axes = plt.subplots(1, len(SPREAD_METRICS), figsize=(WIDE_IN, 4.2), layout="constrained", squeeze=False)
    for ax, (col, label) in zip(axes[0], SPREAD_METRICS):
        stats = seed_spread(df, col)
        if stats.empty:
            ax.text(0.5, 0.5, "no values", ha="center", va="center", transform=ax.transAxes)
            ax.set_axis_off()
            continue
        x = np.arange(len(stats))
        ax.errorbar(x, stats["mean"], yerr=stats["std"].fillna(0.0), fmt="o", ms=6, capsize=5, lw=1.4,
                    color="C0", label="mean +- 1 std over seeds")
        for k, v in enumerate(stats["values"]):
            ax.plot(np.full(len(v), k) + np.linspace(-0.12, 0.12, len(v)), v, ".", color="0.35", ms=5,
                    label="each seed" if k == 0 else None)
        ax.set_xticks(x, [f"{r.body}\n{r.gait}\n{r.scenario}\n(n = {r.n})" for r in stats.itertuples()])
        ax.set_ylabel(label)
        ax.grid(True, axis="y", alpha=0.3)
        ax.set_xlim(-0.6, len(stats) - 0.4)
    labelled = [ax for ax in axes[0] if ax.get_legend_handles_labels()[1]]
    if labelled:  # the first panel may say "no values": the legend goes on the first one with data
        labelled[0].legend(loc="best")
    fig.suptitle(title)
    return save_figure(fig, path)
