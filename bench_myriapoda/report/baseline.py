"""A matrix run against a baseline run of the same matrix: what changed, and what got worse.

Cases are matched by case hash (the same resolved configuration); a case whose
configuration changed between the runs (say, a default changed in a creature
file) is matched by its label instead (creature/body/gait/scenario, seed and
grid point).  For every matched case and every numeric metric present in both
runs the change is reported; a change is a *regression* when

* the status got worse (ok -> unstable, error or timeout; unstable -> error or timeout), or
* throughput (``steps_per_s``) fell by more than ``throughput_threshold``
  (default 15 %: a single short run on a shared machine is noisy; use
  ``bench-myriapoda regress`` for a noise-aware measurement), or
* a metric with a known better direction (``LOWER_IS_BETTER``,
  ``HIGHER_IS_BETTER``) got worse by more than ``threshold`` (relative,
  default 10 %) and by more than ``ABS_FLOOR`` in absolute terms.

Other metrics (speeds, angles) have no better direction in a benchmark: a
change beyond the threshold is reported as ``changed``, not as a regression.
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd

from .matrix_data import MatrixResults

LOWER_IS_BETTER = ("max_penetration_m", "energy_drift_rel", "energy_max_dev_rel", "path_following_error_bl",
                   "inverted_elements_max", "inverted_elements_final", "coupling_residual_max_m",
                   "coupling_residual_mean_m", "foot_slip_mean_m", "tracking_error_mean_m", "time_to_walk_s",
                   "phase_lag_cv", "max_strain")
HIGHER_IS_BETTER = ("walking_cycle_leg_fraction", "min_J", "steps_per_s", "realtime_factor")
ABS_FLOOR = 1e-9
STATUS_RANK = {"ok": 0, "controller_unstable": 1, "unstable": 1, "timeout": 2, "error": 2}


def _match(now: pd.DataFrame, base: pd.DataFrame) -> list[tuple[pd.Series, pd.Series]]:
    by_hash = {r.case_hash: r for _, r in base.iterrows()}
    by_label = {r.label: r for _, r in base.iterrows()}
    pairs = []
    for _, r in now.iterrows():
        b = by_hash.get(r.case_hash)
        if b is None:
            b = by_label.get(r.label)
        if b is not None:
            pairs.append((r, b))
    return pairs


def _numeric(v) -> float:
    try:
        x = float(v)
    except (TypeError, ValueError):
        return math.nan
    return x


def compare_runs(now: MatrixResults, base: MatrixResults, threshold: float = 0.10,
                 throughput_threshold: float = 0.15) -> pd.DataFrame:
    """One row per (case, quantity) that changed: label, quantity, baseline, now, change, verdict.

    ``change`` is relative (now - baseline) / |baseline| (NaN when the baseline is 0); ``verdict``
    is ``regression``, ``improvement``, ``changed`` or ``unchanged`` (changes within the threshold
    are left out of the table).  Cases present in only one run are listed with quantity ``case``.
    """
    rows = []
    pairs = _match(now.df, base.df)
    matched_now = {r.case_hash for r, _ in pairs}
    matched_base = {b.case_hash for _, b in pairs}
    for r, b in pairs:
        if r.status != b.status:
            worse = STATUS_RANK.get(r.status, 2) > STATUS_RANK.get(b.status, 2)
            rows.append((r.label, "status", b.status, r.status, math.nan,
                         "regression" if worse else "improvement"))
        cols = [c for c in now.df.columns if c.startswith("metric.")] + ["steps_per_s", "realtime_factor"]
        for col in cols:
            if col not in base.df.columns:
                continue
            x, y = _numeric(b.get(col)), _numeric(r.get(col))
            if not (math.isfinite(x) and math.isfinite(y)):
                continue
            name = col.removeprefix("metric.")
            diff = y - x
            rel = diff / abs(x) if x != 0 else (0.0 if diff == 0 else math.copysign(math.inf, diff))
            limit = throughput_threshold if name in ("steps_per_s", "realtime_factor") else threshold
            if abs(rel) <= limit or abs(diff) <= ABS_FLOOR:
                continue
            if name in LOWER_IS_BETTER:
                verdict = "regression" if diff > 0 else "improvement"
            elif name in HIGHER_IS_BETTER:
                verdict = "regression" if diff < 0 else "improvement"
            else:
                verdict = "changed"
            rows.append((r.label, name, x, y, rel if math.isfinite(rel) else math.nan, verdict))
    for _, r in now.df[~now.df.case_hash.isin(matched_now)].iterrows():
        rows.append((r.label, "case", "absent", r.status, math.nan, "new"))
    for _, b in base.df[~base.df.case_hash.isin(matched_base)].iterrows():
        rows.append((b.label, "case", b.status, "absent", math.nan, "missing"))
    df = pd.DataFrame(rows, columns=["case", "quantity", "baseline", "now", "change", "verdict"])
    order = {"regression": 0, "missing": 1, "changed": 2, "new": 3, "improvement": 4}
    df["_o"] = df["verdict"].map(order).fillna(9)
    return df.sort_values(["_o", "case", "quantity"]).drop(columns="_o").reset_index(drop=True)


def format_change(rel: float) -> str:
    return "-" if not np.isfinite(rel) else f"{100 * rel:+.1f} %"
