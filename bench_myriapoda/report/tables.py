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

# (column of the matrix DataFrame, header, group).  The groups are the report's tables per creature:
# "stability" and "throughput" in the first, "speed" and "gait" in the second, so each fits 1400 px.
COMPARISON_COLUMNS: tuple[tuple[str, str, str], ...] = (
    ("metric.speed_m_per_s", "speed [m/s]", "speed"),
    ("metric.speed_bl_per_s", "speed [BL/s]", "speed"),
    ("metric.speed_bl_per_cycle", "speed [BL/cycle]", "speed"),
    ("metric.travel_angle_deg", "travel angle [deg]", "speed"),
    ("metric.steady_cycles", "steady cycles", "speed"),
    ("metric.slip_ratio", "slip ratio", "gait"),
    ("metric.body_speed_ratio", "body / commanded speed", "gait"),
    ("metric.lateral_sway_bl", "lateral sway [BL]", "gait"),
    ("metric.foot_slip_mean_m", "foot slip [m]", "gait"),
    ("metric.cost_of_transport_mech", "mech. cost of transport", "gait"),
    ("metric.phase_lag_mean", "phase lag [cycles]", "gait"),
    ("metric.duty_factor_mean", "duty factor", "gait"),
    ("metric.stride_frequency_hz", "stride freq. [Hz]", "gait"),
    ("metric.walking_cycle_leg_fraction", "legs in walking cycle", "gait"),
    ("metric.shape_tracking_error", "shape error", "shape"),
    ("metric.muscle_saturation_fraction", "muscle saturation", "shape"),
    ("metric.t_fail_s", "t_fail [s]", "stability"),
    ("metric.posture_fault", "posture fault", "stability"),
    ("metric.max_penetration_m", "max penetration [m]", "stability"),
    ("metric.energy_drift_rel", "energy drift [rel]", "stability"),
    ("metric.energy_drift_free_rel", "integrator drift [rel]", "stability"),
    ("metric.impact_energy_loss_rel", "impact loss [rel]", "contact"),
    ("metric.inverted_elements_max", "inverted tets (max)", "stability"),
    ("steps_per_s", "steps/s", "throughput"),
    ("realtime_factor", "x realtime", "throughput"),
)
# the metric behind each header, so that a cell under its round-off prints as 0 (core.cells.ROUND_OFF)
HEADER_QUANTITY = {head: col for col, head, _ in COMPARISON_COLUMNS}
TABLE_GROUPS = (("", ("stability", "contact", "throughput")), ("locomotion and gait", ("speed", "shape", "gait")))
SWEEP_GROUPS = ("stability", "throughput")  # a sweep's rows are short runs: their speeds are not shown
CASE_COLUMNS = ("body", "gait", "scenario", "seed")
SWEPT_COLUMN = "swept values"
DURATION_COLUMN = "duration [s]"

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
    ("driven", ("metric.energy_drift_rel", "metric.energy_drift_free_rel", "metric.impact_energy_loss_rel"),
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


# Why a cell of a case holds no number, beyond what the metric means (``row_reason``): (key, columns, text).
ROW_REASONS: tuple[tuple[str, tuple[str, ...], str], ...] = (
    ("unstable", tuple(c for c, _, g in COMPARISON_COLUMNS if g in ("speed", "gait")) + ("metric.energy_drift_rel",
                                                                                        "metric.energy_drift_free_rel"),
     "the run blew up (status unstable, at t_fail): what it measured until then is no result"),
    ("controller_unstable", tuple(c for c, _, g in COMPARISON_COLUMNS if g in ("speed", "gait")),
     "controller_unstable: the closed-loop shape tracker drove the body beyond the commanded shape and backed off "
     "to the calibrated open loop (controllers/shape_tracking.py, LoopGuard); its locomotion is not that of the "
     "commanded shape (the values stay in the results store and --json; the run's message says when)"),
    ("commanded", ("metric.speed_m_per_s", "metric.speed_bl_per_s"),
     "commanded: a legged walk's speed is the head speed the controller commands (controller.head_speed_m_s), "
     "the same on every body model; left out of comparisons (see body / commanded speed, foot slip, sway)"),
    ("too_short", ("metric.speed_m_per_s", "metric.speed_bl_per_s", "metric.speed_bl_per_cycle",
                   "metric.travel_angle_deg", "metric.slip_ratio", "metric.body_speed_ratio", "metric.lateral_sway_bl",
                   "metric.cost_of_transport_mech"),
     "too short: measured over fewer steady gait cycles (after the ramp and warm-up) than "
     "metrics.min_steady_cycles (2); not a number (the run's reason is in its labels: --json, the store)"),
    ("contact", ("metric.energy_drift_rel",),
     "the body hits the ground: the energy change is the impact loss (its own column), not integrator drift; "
     "the integrator drift is measured before the first contact"),
)


def row_reason(row, column: str) -> str | None:
    """The ROW_REASONS key that blanks ``column`` for this case (a matrix DataFrame row), or None.

    Unstable runs, commanded speeds of legged walks, too-short runs (``labels.too_short``) and the
    energy change of a passive body that hit the ground (``metric.impact_energy_loss_rel`` set).
    """
    legged = str(row.get("gait", "")) == "leg-wave"
    case_json = row.get("case_json")
    if isinstance(case_json, str):
        legged = bool(json.loads(case_json).get("creature", {}).get("legs_per_segment", 0))
    labels = {}
    if isinstance(row.get("labels_json"), str):
        try:
            labels = json.loads(row["labels_json"]) or {}
        except ValueError:
            labels = {}
    impact = row.get("metric.impact_energy_loss_rel")
    applies = {"unstable": row.get("status") == "unstable", "commanded": legged,
               "controller_unstable": row.get("status") == "controller_unstable",
               "too_short": bool(labels.get("too_short")),
               "contact": isinstance(impact, float) and math.isfinite(impact)}
    for key, columns, _ in ROW_REASONS:
        if column in columns and applies[key]:
            return key
    return None


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


def _table(sub: pd.DataFrame, grid_columns: Sequence[str], groups: Sequence[str], sweep: bool) -> ComparisonTable | None:
    """One table of ``sub``'s cases: case columns, then the metrics of ``groups`` that some case has
    (a metric blank with a footnote key where it does not apply to a case).  None when no metric shows."""
    cols = [c for c in CASE_COLUMNS if c in sub]
    table = sub[cols].copy()
    if "seed" in table and table["seed"].isna().all():
        table = table.drop(columns="seed")
    for c in ("gait", "scenario"):  # a column with one value for every row says nothing a heading does not
        if sweep and c in table and table[c].nunique() == 1:
            table = table.drop(columns=c)
    swept = [swept_values(r, grid_columns) for _, r in sub.iterrows()]
    if any(swept):
        table[SWEPT_COLUMN] = swept
    table[DURATION_COLUMN] = pd.to_numeric(sub["duration"], errors="coerce") if "duration" in sub else float("nan")
    table["status"] = sub["status"]
    notes = pd.DataFrame("", index=table.index, columns=list(table.columns))
    shown = 0
    for col, head, group in COMPARISON_COLUMNS:
        if group not in groups or col not in sub:
            continue
        values = pd.to_numeric(sub[col], errors="coerce")
        reasons = pd.Series([not_applicable_reason(r, col) or row_reason(r, col) or "" for _, r in sub.iterrows()],
                            index=sub.index)
        # measured for some case, or blank for a stated reason (a too-short speed): shown
        if values.notna().any() or (reasons.isin(["too_short", "commanded"]) & (sub["status"] == "ok")).any():
            table[head] = values.where(reasons == "")
            notes[head] = reasons
            shown += 1
    if not shown:
        return None
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
    texts = [(k, text) for k, _, text in NOT_APPLICABLE + ROW_REASONS if k in used]
    return ComparisonTable(table, notes, dict(texts))


def sweep_key_sets(df: pd.DataFrame, grid_columns: Sequence[str]) -> pd.Series:
    """Each case's swept keys, e.g. "dt x body.stiffness" ("" outside any sweep)."""
    return pd.Series([" x ".join(c.removeprefix("grid.") for c in grid_columns
                                 if c in df and not (isinstance(r.get(c), float) and math.isnan(r.get(c)))
                                 and r.get(c) is not None)
                      for _, r in df.iterrows()], index=df.index, dtype=object)


def comparison_tables(df: pd.DataFrame, grid_columns: Sequence[str] = (),
                      sweep: pd.Series | None = None) -> dict[str, list[tuple[str, ComparisonTable | None]]]:
    """Creature -> its tables, each (title, table): first its cases outside sweeps, in two tables --
    (creature, stability and throughput), (creature + ": locomotion and gait", speeds and gait metrics) --
    then one table per sweep, titled by its swept keys, with stability and throughput columns.

    sweep: which cases belong to a stability or scaling sweep (``sweeps.sweep_mask``; default: a case with
    any grid value).  Every table has a duration column; ``swept values`` names a row's grid point.  A table
    of the creature's headline cases is None when it has none (it ran only in sweeps).
    """
    out: dict[str, list[tuple[str, ComparisonTable | None]]] = {}
    grid_columns = [c for c in grid_columns if c in df]
    keysets = sweep_key_sets(df, grid_columns)
    if sweep is None:
        sweep = keysets != ""
    for creature, sub in df.groupby("creature", sort=True):
        tables: list[tuple[str, ComparisonTable | None]] = []
        main = sub[~sweep.loc[sub.index]]
        if main.empty:
            tables.append((str(creature), None))
        for title, groups in TABLE_GROUPS:
            if main.empty:
                break
            t = _table(main, [c for c in grid_columns if main[c].notna().any()], groups, False)
            if t is not None or not title:
                tables.append((f"{creature}: {title}" if title else str(creature), t))
        swept = sub[sweep.loc[sub.index]]
        for keyset, part in swept.groupby(keysets.loc[swept.index], sort=True):
            cols = [c for c in grid_columns if part[c].notna().any()]
            t = _table(part, cols, SWEEP_GROUPS, True)
            tables.append((f"{creature}: sweep over {keyset}", t))
        out[str(creature)] = tables
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
                cells.append(f"<td>{html.escape(fmt(v, HEADER_QUANTITY.get(str(df.columns[j]), '')))}</td>")
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
            cells.append(f"-({marks[key]})" if key else fmt(v, HEADER_QUANTITY.get(cols[j], "")).replace("|", "/"))
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"
