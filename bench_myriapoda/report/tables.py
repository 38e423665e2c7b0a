"""Comparison tables: one per creature, a row per case, the body models side by side.

The columns are the suite's headline metrics in five groups -- speed, gait,
shape, stability, throughput -- and a column is shown for a creature only when at
least one of its cases has a value (a worm has no leg-wave metrics, a legged
creature no muscle-wave speed).  Every case is a row, the cases of parameter
sweeps too, each naming its grid point; a metric that means nothing for a case
(``NOT_APPLICABLE``: the speed of a dropped passive chain, the energy drift of a
driven creature, per-cycle speed of a legged one) is shown as '-' with a
footnote giving the reason.  The same table is written as HTML (for
``index.html``) and as Markdown (for ``summary.md``).
"""
from __future__ import annotations

import html
import json
import math
from dataclasses import dataclass
from typing import Sequence

import pandas as pd

from ..core.cells import fmt

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
    ("metric.shape_tracking_error", "shape error", "shape"),
    ("metric.muscle_saturation_fraction", "muscle saturation", "shape"),
    ("metric.t_fail_s", "t_fail [s]", "stability"),
    ("metric.posture_fault", "posture fault", "stability"),
    ("metric.max_penetration_m", "max penetration [m]", "stability"),
    ("metric.energy_drift_rel", "energy drift [rel]", "stability"),
    ("metric.inverted_elements_max", "inverted tets (max)", "stability"),
    ("steps_per_s", "steps/s", "throughput"),
    ("realtime_factor", "x realtime", "throughput"),
)
CASE_COLUMNS = ("body", "gait", "scenario", "seed")
SWEPT_COLUMN = "swept values"

# Why a metric means nothing for a case: (footnote key, the columns it blanks, the footnote's text).
# Checked in this order; a cell takes the first reason that applies.
NOT_APPLICABLE: tuple[tuple[str, tuple[str, ...], str], ...] = (
    ("passive", ("metric.speed_m_per_s", "metric.speed_bl_per_s", "metric.speed_bl_per_cycle",
                 "metric.travel_angle_deg", "metric.slip_ratio"),
     "a passive body (gait 'passive') is dropped or hangs; it does not travel, so its speed and travel "
     "direction are round-off (e.g. 1e-13 m/s at 97 degrees)"),
    ("suspended", ("metric.speed_m_per_s", "metric.speed_bl_per_s", "metric.speed_bl_per_cycle",
                   "metric.travel_angle_deg", "metric.slip_ratio"),
     "suspended from its head (scenario 'hang'): the body does not travel"),
    ("driven", ("metric.energy_drift_rel",),
     "actively driven (muscles or legs put energy in and take it out): the energy drift measures the "
     "integrator only for a passive body"),
    ("legged", ("metric.speed_bl_per_cycle",),
     "legged: the body has no muscle-wave cycle (the gait's frequency_hz is unused); the legs' cycle is "
     "the stride frequency"),
    ("shape", ("metric.speed_m_per_s", "metric.speed_bl_per_s", "metric.speed_bl_per_cycle",
               "metric.travel_angle_deg", "metric.slip_ratio"),
     "shape_not_achieved: the body did not bend as commanded (shape error > 10 %, metrics/shape_tracking.py); "
     "its locomotion is that of another shape and is not compared across bodies (the values stay in the results "
     "store and --json)"),
)


def not_applicable_reason(row, column: str) -> str | None:
    """The NOT_APPLICABLE key that blanks ``column`` for this case (a matrix DataFrame row), or None."""
    gait, scenario = str(row.get("gait", "")), str(row.get("scenario", ""))
    legged = gait == "leg-wave"
    case_json = row.get("case_json")
    if isinstance(case_json, str):
        legged = bool(json.loads(case_json).get("creature", {}).get("legs_per_segment", 0))
    applies = {"passive": gait == "passive", "suspended": scenario == "hang", "driven": gait != "passive",
               "legged": legged, "shape": row.get("metric.shape_not_achieved") == 1.0}
    for key, columns, _ in NOT_APPLICABLE:
        if column in columns and applies[key]:
            return key
    return None


def swept_values(row, grid_columns: Sequence[str]) -> str:
    """The case's grid point as text, e.g. "dt=0.002, body.stiffness=1.5" ("" outside any sweep)."""
    parts = []
    for col in grid_columns:
        v = row.get(col)
        if v is None or (isinstance(v, float) and not math.isfinite(v)):
            continue
        key = col.removeprefix("grid.")
        parts.append(f"{key}={v:.4g}" if isinstance(v, float) else f"{key}={v}")
    return ", ".join(parts)


@dataclass
class ComparisonTable:
    """One creature's table: ``table`` (cells), ``notes`` (same shape: the NOT_APPLICABLE key of a blanked
    cell, else ""), and the footnotes used, {key: text} in NOT_APPLICABLE order."""

    table: pd.DataFrame
    notes: pd.DataFrame
    footnotes: dict[str, str]


def comparison_tables(df: pd.DataFrame, grid_columns: Sequence[str] = ()) -> dict[str, ComparisonTable]:
    """Creature -> table of all its cases (body, gait, scenario, seed, swept values, status, metrics).

    Every case is a row, sweep cases included: ``swept values`` names each row's grid point (``grid_columns``:
    the ``grid.KEY`` columns).  Rows: cases outside sweeps first, then by body and swept values.  A metric
    that does not apply to a case (``not_applicable_reason``) is blank with a footnote key in ``notes``.
    """
    out: dict[str, ComparisonTable] = {}
    grid_columns = [c for c in grid_columns if c in df]
    for creature, sub in df.groupby("creature", sort=True):
        cols = [c for c in CASE_COLUMNS if c in sub]
        table = sub[cols].copy()
        if "seed" in table and table["seed"].isna().all():
            table = table.drop(columns="seed")
        swept = [swept_values(r, grid_columns) for _, r in sub.iterrows()]
        if any(swept):
            table[SWEPT_COLUMN] = swept
        table["status"] = sub["status"]
        notes = pd.DataFrame("", index=table.index, columns=list(table.columns))
        for col, head, _ in COMPARISON_COLUMNS:
            if col not in sub:
                continue
            values = pd.to_numeric(sub[col], errors="coerce")
            reasons = pd.Series([not_applicable_reason(r, col) or "" for _, r in sub.iterrows()], index=sub.index)
            if values.notna().any():  # measured for some case: shown, blanked (with the reason) where meaningless
                table[head] = values.where(reasons == "")
                notes[head] = reasons
        # outside sweeps first; then by body, gait, scenario, the swept values (numerically) and the seed
        keys = table.assign(_sweep=[bool(x) for x in swept])
        by = ["_sweep"] + [c for c in ("body", "gait", "scenario") if c in table]
        for col in grid_columns:
            keys[col] = pd.to_numeric(sub[col], errors="coerce")
            by.append(col)
        if "seed" in table:
            by.append("seed")
        order = keys.sort_values(by, na_position="first").index
        table, notes = table.loc[order].reset_index(drop=True), notes.loc[order].reset_index(drop=True)
        used = set(notes.to_numpy().ravel()) - {""}
        out[str(creature)] = ComparisonTable(table, notes, {k: text for k, _, text in NOT_APPLICABLE if k in used})
    return out


def footnote_marks(footnotes: dict[str, str]) -> dict[str, str]:
    """Footnote key -> its mark: a, b, c, ... in order."""
    return {k: "abcdefghij"[i] for i, k in enumerate(footnotes)}


def html_table(df: pd.DataFrame, row_classes: Sequence[str] | None = None, notes: pd.DataFrame | None = None,
               marks: dict[str, str] | None = None) -> str:
    """A plain HTML table; ``row_classes[i]`` is the CSS class of row i (e.g. 'regression').

    notes, marks: a cell whose ``notes`` entry is a footnote key shows '-' with that key's mark as a
    superscript (``footnote_marks``).
    """
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in df.columns)
    rows = []
    for i, (_, r) in enumerate(df.iterrows()):
        cls = f' class="{row_classes[i]}"' if row_classes and row_classes[i] else ""
        cells = []
        for j, v in enumerate(r.values):
            key = notes.iat[i, j] if notes is not None else ""
            if key:
                cells.append(f'<td class="na">-<sup>{html.escape(marks[key])}</sup></td>')
            else:
                cells.append(f"<td>{html.escape(fmt(v))}</td>")
        rows.append(f"<tr{cls}>{''.join(cells)}</tr>")
    return f'<table><thead><tr>{head}</tr></thead><tbody>{"".join(rows)}</tbody></table>'


def md_table(df: pd.DataFrame, notes: pd.DataFrame | None = None, marks: dict[str, str] | None = None) -> str:
    """A GitHub-flavoured Markdown table (blanked cells as '-' and their footnote mark, e.g. '-(a)')."""
    if df.empty:
        return "_(no rows)_\n"
    cols = [str(c) for c in df.columns]
    lines = ["| " + " | ".join(cols) + " |", "|" + "|".join("---" for _ in cols) + "|"]
    for i, (_, r) in enumerate(df.iterrows()):
        cells = []
        for j, v in enumerate(r.values):
            key = notes.iat[i, j] if notes is not None else ""
            cells.append(f"-({marks[key]})" if key else fmt(v).replace("|", "/"))
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"
