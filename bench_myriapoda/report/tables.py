"""Comparison tables: one per creature, a row per case, the body models side by side.

The columns are the suite's headline metrics in four groups -- speed, gait,
stability, throughput -- and a column is shown for a creature only when at
least one of its cases has a value (a worm has no leg-wave metrics, a legged
creature no muscle-wave speed).  The same table is written as HTML (for
``index.html``) and as Markdown (for ``summary.md``).
"""
from __future__ import annotations

import html
import math
from typing import Sequence

import pandas as pd

# (column of the matrix DataFrame, header, group)
COMPARISON_COLUMNS: tuple[tuple[str, str, str], ...] = (
    ("metric.speed_m_per_s", "speed [m/s]", "speed"),
    ("metric.speed_bl_per_s", "speed [BL/s]", "speed"),
    ("metric.speed_bl_per_cycle", "speed [BL/cycle]", "speed"),
    ("metric.travel_angle_deg", "travel angle [deg]", "speed"),
    ("metric.slip_ratio", "slip ratio", "gait"),
    ("metric.phase_lag_mean", "phase lag [cycles]", "gait"),
    ("metric.legs_per_wave", "legs per wave", "gait"),
    ("metric.duty_factor_mean", "duty factor", "gait"),
    ("metric.stride_frequency_hz", "stride freq. [Hz]", "gait"),
    ("metric.walking_cycle_leg_fraction", "legs in walking cycle", "gait"),
    ("metric.t_fail_s", "t_fail [s]", "stability"),
    ("metric.posture_fault", "posture fault", "stability"),
    ("metric.max_penetration_m", "max penetration [m]", "stability"),
    ("metric.energy_drift_rel", "energy drift [rel]", "stability"),
    ("metric.inverted_elements_max", "inverted tets (max)", "stability"),
    ("steps_per_s", "steps/s", "throughput"),
    ("realtime_factor", "x realtime", "throughput"),
)
CASE_COLUMNS = ("body", "gait", "scenario", "seed")


def fmt(v) -> str:
    """A table cell: 4 significant digits, '-' for missing or undefined."""
    if v is None:
        return "-"
    if isinstance(v, float):
        if not math.isfinite(v):
            return "-"
        return f"{v:.4g}"
    return str(v)


def comparison_tables(df: pd.DataFrame, extra_columns: Sequence[str] = ()) -> dict[str, pd.DataFrame]:
    """Creature -> table of its cases (body, gait, scenario, seed, status, metrics), rows sorted by body.

    ``extra_columns``: further axis columns to show (grid keys that vary within a creature).
    """
    out: dict[str, pd.DataFrame] = {}
    for creature, sub in df.groupby("creature", sort=True):
        cols = [c for c in CASE_COLUMNS if c in sub] + [c for c in extra_columns if c in sub and sub[c].nunique() > 1]
        table = sub[cols + ["status"]].copy()
        if "seed" in table and table["seed"].isna().all():
            table = table.drop(columns="seed")
        for col, head, _ in COMPARISON_COLUMNS:
            if col in sub and pd.to_numeric(sub[col], errors="coerce").notna().any():
                table[head] = pd.to_numeric(sub[col], errors="coerce")
        out[str(creature)] = table.sort_values([c for c in ("body", "gait", "scenario") if c in table]).reset_index(drop=True)
    return out


def html_table(df: pd.DataFrame, row_classes: Sequence[str] | None = None, cell_title: dict | None = None) -> str:
    """A plain HTML table; ``row_classes[i]`` is the CSS class of row i (e.g. 'regression')."""
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in df.columns)
    rows = []
    for i, (_, r) in enumerate(df.iterrows()):
        cls = f' class="{row_classes[i]}"' if row_classes and row_classes[i] else ""
        cells = "".join(f"<td>{html.escape(fmt(v))}</td>" for v in r.values)
        rows.append(f"<tr{cls}>{cells}</tr>")
    return f'<table><thead><tr>{head}</tr></thead><tbody>{"".join(rows)}</tbody></table>'


def md_table(df: pd.DataFrame) -> str:
    """A GitHub-flavoured Markdown table."""
    if df.empty:
        return "_(no rows)_\n"
    cols = [str(c) for c in df.columns]
    lines = ["| " + " | ".join(cols) + " |", "|" + "|".join("---" for _ in cols) + "|"]
    for _, r in df.iterrows():
        lines.append("| " + " | ".join(fmt(v).replace("|", "/") for v in r.values) + " |")
    return "\n".join(lines) + "\n"
