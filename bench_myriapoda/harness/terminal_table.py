"""The table ``matrix`` (and the main job) prints when a matrix is done, and its closing line.

Read on a terminal, it must explain itself without the report:

* each case shows its swept values and its duration as columns, so 16 runs of the same creature,
  body, gait and scenario are 16 different rows;
* the cases outside sweeps come first; then each sweep's rows under a heading naming its swept
  keys (``sweep over dt x body.stiffness``);
* a blow-up in a sweep over dt or a stiffness key is labelled ``unstable (intended)``: such a sweep
  looks for where the integrator fails;
* a value smaller than the round-off of its quantity (``core.cells.ROUND_OFF``) prints as 0, a speed measured
  over too few steady cycles as ``too short``, a commanded speed with ``(cmd)``, the speeds of a
  blown-up run or a passive body as '-';
* the closing line counts the statuses and the report's figure verdicts and links the report
  with a ``file://`` URL.
"""
from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any, Iterable, Sequence

from ..core.cells import fmt

# (metric, header): the columns after the case's own
METRIC_COLUMNS = (("speed_bl_per_cycle", "BL/cycle"), ("speed_m_per_s", "speed [m/s]"),
                  ("travel_angle_deg", "angle [deg]"), ("t_fail_s", "t_fail [s]"))
BLOW_UP_KEYS = ("dt", "body.stiffness", "body.youngs_modulus_pa", "body.link_stiffness_n_m")
LEGGED_GAITS = ("leg-wave",)


def cell(v: Any, quantity: str = "") -> str:
    """A value as the terminal shows it: '-' when missing, 0 under the quantity's round-off (``core.cells.ROUND_OFF``,
    shared with the report's tables: ``core.cells.fmt``), 4 digits."""
    return fmt(v, quantity)


def _swept(row: dict, grid_keys: Sequence[str]) -> str:
    parts = []
    for k in grid_keys:
        v = row.get(k)
        if v is None or (isinstance(v, float) and math.isnan(v)):
            continue
        parts.append(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}")
    return ", ".join(parts)


def _labels(row: dict) -> dict:
    try:
        return json.loads(row.get("labels_json") or "{}") or {}
    except (TypeError, ValueError):
        return {}


def _status(row: dict, keys: Sequence[str]) -> str:
    s = str(row.get("status"))
    if s == "unstable" and any(k in BLOW_UP_KEYS for k in keys):
        return "unstable (intended)"
    return s


def _metric_cell(row: dict, metric: str) -> str:
    v = row.get(f"metric.{metric}", row.get(metric))
    if metric in ("speed_bl_per_cycle", "speed_m_per_s", "travel_angle_deg"):
        if row.get("status") in ("unstable", "controller_unstable") or str(row.get("gait")) == "passive":
            # a blown-up run's speeds are no result, nor those of a shape the tracker drove away (issue 44); a
            # passive body does not travel
            return "-"
        if _labels(row).get("too_short"):
            return "too short"
        if metric == "speed_m_per_s" and str(row.get("gait")) in LEGGED_GAITS and cell(v) != "-":
            return cell(v, metric) + " (cmd)"
    return cell(v, metric)


def _point(row: dict, grid_keys: Sequence[str]) -> list[str]:
    """The grid keys the case was swept over: those in its ``axes`` (the matrix's own axis values; a row's
    top-level ``dt`` is the resolved time step of every case)."""
    axes = row.get("axes", row)
    return [k for k in grid_keys if axes.get(k) is not None and not (isinstance(axes[k], float) and math.isnan(axes[k]))]


def matrix_table_lines(rows: Iterable[dict], grid_keys: Sequence[str]) -> list[str]:
    """The lines of the table: headline cases, then one block per set of swept keys (module docstring).

    rows: one dict per case with creature, body, gait, scenario, duration, status, labels_json,
    ``metric.NAME``, steps_per_s, and ``axes``: the case's axis values in the matrix (its grid point);
    without ``axes`` the grid keys are read from the row itself.
    """
    rows = list(rows)
    head = ["creature", "body", "gait", "scenario", "swept values", "duration [s]", "status",
            *[h for _, h in METRIC_COLUMNS], "steps/s"]
    blocks: dict[str, list[list[str]]] = {}
    for r in rows:
        keys = _point(r, grid_keys)
        line = [str(r.get("creature")), str(r.get("body")), str(r.get("gait")), str(r.get("scenario")),
                _swept(r.get("axes", r), keys), cell(r.get("duration")), _status(r, keys),
                *[_metric_cell(r, m) for m, _ in METRIC_COLUMNS], cell(r.get("steps_per_s"), "steps_per_s")]
        blocks.setdefault(" x ".join(keys), []).append(line)
    table = [head] + [line for lines in blocks.values() for line in lines]
    widths = [max(len(row[i]) for row in table) for i in range(len(head))]

    def fmt(row):
        return "  ".join(v.ljust(w) for v, w in zip(row, widths)).rstrip()

    out = [fmt(head)]
    for keys in sorted(blocks, key=lambda k: (k != "", k)):
        if keys:
            out.append(f"-- sweep over {keys} ({len(blocks[keys])} cases)"
                       + (": blow-ups are intended, the sweep maps the stable range"
                          if any(k in BLOW_UP_KEYS for k in keys.split(" x ")) else ""))
        out += [fmt(line) for line in blocks[keys]]
    return out


def closing_line(rows: Sequence[dict], grid_keys: Sequence[str], report: Path | None,
                 verdicts: dict[str, int] | None = None) -> str:
    """'N cases: a ok, b unstable (c intended), d error, e timeout; paper figures: ...; report: file://...'."""
    counts: dict[str, int] = {}
    intended = 0
    for r in rows:
        s = str(r.get("status"))
        counts[s] = counts.get(s, 0) + 1
        keys = _point(r, grid_keys)
        intended += s == "unstable" and any(k in BLOW_UP_KEYS for k in keys)
    parts = [f"{counts.get('ok', 0)} ok", f"{counts.get('unstable', 0)} unstable ({intended} intended)",
             f"{counts.get('error', 0)} error", f"{counts.get('timeout', 0)} timeout"]
    if counts.get("controller_unstable"):  # the shape tracker backed off (issue 44): said only where it happened
        parts.insert(2, f"{counts['controller_unstable']} controller_unstable")
    line = f"{len(rows)} cases: " + ", ".join(parts)
    if verdicts:
        line += "; figure verdicts: " + ", ".join(f"{n} {v}" for v, n in sorted(verdicts.items()))
    if report is not None:
        line += f"; report: {Path(report).resolve().as_uri()}"
    return line
