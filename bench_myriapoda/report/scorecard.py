"""The scorecard: which body model to trust for each creature, from one matrix output directory.

One row per creature x body pair of the matrix, in four groups (``COLUMNS`` gives each column's unit and
one-line definition; the report, ``scorecard`` and ``scorecard --json`` print them):

``stability``   the bracket [largest stable, smallest unstable] dt of the pair's headline case, bisected to
                10 % on 1 s runs by the main job (``harness.stable_dt.brackets_for_cases``, kept in
                DIR/stable_dt.json) -- else from the matrix's dt sweeps of the pair (at the default value of
                every other swept key), else from the latest ``stable-dt`` run of the pair in the results
                store -- and the default dt's margin under its stable end (largest stable dt / default dt;
                < 1: the default dt is not stable);
``fidelity``    the verdicts of the pair (``report.scorecard_verdicts``: the ``validate`` checks of that
                creature on that body and the body's own checks, and the checks judged on the matrix's own
                case, the same rows the reproduced figures print), their counts and the worst check with
                its measured value and reference;
``locomotion``  the headline case's speed against a reference where one applies: the kinematic
                slithering model (``reference/slithering.py``) for lateral undulation, eps * Lambda
                for the rectilinear worm; a commanded speed (``metrics.walk.COMMANDED``) is no
                result and is left out, with the walk's emergent measures shown instead;
``cost``        CPU seconds per simulated second and steps/s of the headline case: the median over its
                timed repeats (the matrix's seeds) with their spread (max - min).

The error a recommendation ranks by (``Row.error``, ``ERROR_KINDS``): the locomotion error where there is one; for a
myriapod (whose walking speed is commanded) the ``paper.kinematic-shortcut-<creature>`` check of ``validate``: how
far the paper's kinematic stance walks from the dynamic stance, in body lengths (``shortcut_error``; on every
legged body, fem included); else the share of FAIL verdicts.

Every group is a number or a stated reason; where a cell has no data the reason names the command
that fills it.  Per creature, a one-line recommendation (``recommend``) ranks the bodies by error and
cost, calling two bodies a tie where they differ by no more than the measured spread, says which axis
decided, names a default dt within ``DT_RISK_MARGIN`` of its stability limit as a risk, and makes no
claim when only one body ran.  Plain Python: the report (``report/build.py``), the ``scorecard``
command and tests call :func:`build_scorecard`.
"""
from __future__ import annotations

import json
import math
import re
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from ..harness.store import StoreReadError, read_latest_stable_dt
from ..metrics.shape_tracking import SHAPE_ERROR_THRESHOLD as SHAPE_THRESHOLD
from ..metrics.shape_tracking import shape_control_mode
from ..metrics.walk import EMERGENT_WALK_METRICS, commanded_metric
from .scorecard_verdicts import BODY_CHECKS, CHECK_CREATURE, check_creature, row_labels  # noqa: F401 (re-exported)
from .sweeps import sweep_mask

SHAPE_METRIC, SHAPE_FLAG = "metric.shape_tracking_error", "metric.shape_not_achieved"
# the myriapods' error axis (issue 43): validate's kinematic-shortcut check of the creature on the body, the largest
# distance between the heads of its kinematic-stance walk (the paper's, what the matrix runs) and its dynamic-stance
# walk (legs that push through friction-limited feet), in body lengths (validation/shortcut.py)
SHORTCUT_CHECK = "paper.kinematic-shortcut-{creature}"
SHORTCUT_KIND = "BL kinematic-shortcut error"
# the error kinds a creature's rows are ranked by, the first that any of its rows has (one kind per creature)
ERROR_KINDS = ("speed error", SHORTCUT_KIND, "validate FAIL share")
DT_RISK_MARGIN = 1.2   # a default dt whose stable end is less than this many times above it is a risk
MIN_REPEATS = 3        # timed repeats a cost needs before it is ranked


@dataclass(frozen=True)
class Column:
    """A scorecard column: its heading, the unit of its numbers and a one-line definition."""

    key: str
    heading: str
    unit: str
    definition: str


COLUMNS: tuple[Column, ...] = (
    Column("stability", "stability: stable dt bracket [s] (margin)", "s (margin: x, dimensionless)",
           "[largest stable, smallest unstable] time step of the headline case, bisected to 10 % on 1 s runs; "
           "margin = largest stable dt / default dt (< 1.2: a risk, < 1: the default blows up)"),
    Column("fidelity", "fidelity: verdicts [count] (worst check)", "count of verdicts; measured and reference in the "
           "check's unit", "PASS / FAIL / NOT APPLICABLE / INFO counts of the validate checks that apply to the pair "
           "and of the checks judged on this matrix's case, and the worst check: a FAIL, else the one closest to "
           "its tolerance"),
    Column("locomotion", "locomotion vs reference [BL/cycle]", "BL/cycle (body lengths per gait cycle); error in %",
           "the headline case's forward speed against the kinematic slithering model (snake) or eps * Lambda "
           "(worm); a commanded walking speed is no result"),
    Column("shape", "shape tracking [1]", "1 (dimensionless: curvature error in units of the commanded amplitude)",
           "shape_tracking_error: RMS over the steady window and the body of (measured - commanded) ground "
           "curvature x body length / commanded curvature amplitude; 0: the commanded wave, 0.71: a straight body, "
           "over 0.1: shape not achieved"),
    Column("cost", "cost [CPU s/s, steps/s]", "CPU s per simulated s (one core); steps/s",
           "CPU seconds the kernel takes per simulated second (1 / realtime factor) and time steps per second of "
           "the headline case: the median over its timed repeats, +/- half their range"),
)


@dataclass
class Group:
    """One group of a scorecard row: ``value`` (the number it is ranked by, or None), ``text`` (how the
    cell reads), ``reason`` (why there is no number, naming the command that fills it) and details."""

    value: float | None
    text: str
    reason: str | None = None
    details: dict = field(default_factory=dict)


@dataclass
class Row:
    creature: str
    body: str
    stability: Group
    fidelity: Group
    locomotion: Group
    cost: Group
    shape: Group
    error: float | None = None       # the error the recommendation ranks by (locomotion, else the myriapods'
    #                                  kinematic-shortcut check, else fidelity: ERROR_KINDS)
    error_kind: str = ""
    error_spread: float = 0.0        # its spread over repeats (0: one deterministic run; a rerun gives the same)


@dataclass
class Scorecard:
    rows: list[Row]
    recommendations: dict[str, str]  # creature -> one line
    source: str                      # the matrix directory

    def to_json(self) -> dict:
        """The scorecard as plain JSON (NaN as null)."""
        def clean(v):
            if isinstance(v, dict):
                return {k: clean(x) for k, x in v.items()}
            if isinstance(v, (list, tuple)):
                return [clean(x) for x in v]
            if isinstance(v, (float, np.floating)):
                return float(v) if math.isfinite(v) else None
            if isinstance(v, np.integer):
                return int(v)
            return v
        return clean({"source": self.source, "pairs": [asdict(r) for r in self.rows],
                      "recommendations": self.recommendations,
                      "columns": {c.key: {"heading": c.heading, "unit": c.unit, "definition": c.definition}
                                  for c in COLUMNS}})


def _num(v) -> float | None:
    try:
        f = float(v)
    except (TypeError, ValueError):
        return None
    return f if math.isfinite(f) else None


def _case(row) -> dict:
    return json.loads(row["case_json"]) if isinstance(row.get("case_json"), str) else {}


def _labels(row) -> dict:
    return row_labels(row)


def _legged(row) -> bool:
    return bool(_case(row).get("creature", {}).get("legs_per_segment", 0))


def _cmd(creature: str, body: str, scenario: str = "") -> str:
    return f"--creature {creature} --body {body}" + (f" --scenario {scenario}" if scenario else "")


def headline_rows(df: pd.DataFrame, grid_keys, creature: str, body: str) -> pd.DataFrame:
    """The pair's cases outside the stability and scaling sweeps (all of them when it only ran in sweeps)."""
    sub = df[(df["creature"] == creature) & (df["body"] == body)]
    main = sub[~sweep_mask(sub, grid_keys)]
    return main if not main.empty else sub


# --------------------------------------------------------------------------- stability

def _default_value(case: dict, key: str):
    section, _, name = key.partition(".")
    if not name:
        return case.get(section)
    return case.get(section, {}).get(name)


def bracket_group(entry: dict, default_dt: float | None) -> Group:
    """The stability cell of a bisected bracket (``harness.stable_dt.bracket_entry``): "[lo, hi] s" and the
    default dt's margin under lo."""
    lo, hi = _num(entry.get("stable_dt_max_s")), _num(entry.get("unstable_dt_min_s"))
    default_dt = default_dt or _num(entry.get("default_dt_s"))
    runs = len(entry.get("trials") or [])
    how = (f"bisection to {100 * float(entry.get('rel_tol', 0.1)):g} % on {float(entry.get('trial_duration_s', 0)):g}"
           f" s runs ({runs} runs)")
    details = {"source": how, "largest_stable_dt_s": lo, "smallest_unstable_dt_s": hi, "default_dt_s": default_dt,
               "margin": lo / default_dt if lo is not None and default_dt else None, "bracketed": hi is not None,
               "trials": entry.get("trials")}
    pair = _cmd(str(entry.get("creature")), str(entry.get("body")), str(entry.get("scenario") or ""))
    cmd = f"`bench-myriapoda stable-dt {pair}`"
    if entry.get("error"):
        return Group(None, "bisection stopped", f"{str(entry['error']).splitlines()[0]}; run {cmd}", details)
    if lo is None:
        return Group(None, f"unstable at every dt tried (down to {min(t[0] for t in entry['trials']):.3g} s)"
                     if entry.get("trials") else "not measured", f"no stable dt found by {how}; run {cmd}", details)
    margin = details["margin"]
    text = f"[{lo:.3g}, {hi:.3g}] s" if hi is not None else f">= {lo:.3g} s (no blow-up up to it)"
    if margin is not None:
        text += f"; default {default_dt:.3g} s, margin {margin:.3g}x"
        if margin < 1.0:
            text += " (default unstable)"
        elif margin < DT_RISK_MARGIN:
            text += f" (under {DT_RISK_MARGIN:g}x: a risk)"
    return Group(lo, text, None, details)


def stability_group(df: pd.DataFrame, grid_keys, creature: str, body: str, default_dt: float | None,
                    scenario: str, store: Path | None, bracket: dict | None = None) -> Group:
    """The pair's stable dt: its bisected ``bracket`` (``harness.stable_dt``) when the main job found one, else
    the largest stable dt of its dt sweeps or a stable-dt run, and the default dt's margin (module docstring)."""
    if bracket is not None:
        return bracket_group(bracket, default_dt)
    sub = df[(df["creature"] == creature) & (df["body"] == body)]
    col = "grid.dt"
    sweep = sub[sub[col].notna()] if col in sub else sub.iloc[0:0]
    if not sweep.empty:
        others = [k for k in grid_keys if k != "dt" and f"grid.{k}" in sweep and sweep[f"grid.{k}"].notna().any()]
        at_default = sweep
        note = ""
        head = headline_rows(df, grid_keys, creature, body)
        ref_case = _case(head.iloc[0]) if not head.empty else {}
        for k in others:
            want = _default_value(ref_case, k) if ref_case else None
            vals = pd.to_numeric(at_default[f"grid.{k}"], errors="coerce")
            if want is not None and np.isclose(vals, float(want)).any():
                at_default = at_default[np.isclose(vals, float(want))]
                note += f", {k} = {float(want):g} (default)"
            else:  # the default value was not swept: every swept value must be stable at that dt
                note += f", every {k} swept"
        by_dt = at_default.groupby("dt")["status"].apply(lambda s: bool((s == "ok").all())).sort_index()
        stable = [dt for dt, ok in by_dt.items() if ok]
        unstable = [dt for dt, ok in by_dt.items() if not ok]
        if not stable:
            return Group(None, f"none of dt = {', '.join(f'{d:g}' for d in by_dt.index)} s stable",
                         f"every swept dt blew up{note}; run `bench-myriapoda stable-dt {_cmd(creature, body, scenario)}`",
                         {"source": "matrix dt sweep", "unstable_dt_min_s": min(unstable)})
        best = max(stable)
        above = [d for d in unstable if d > best]
        margin = best / default_dt if default_dt else None
        # no blow-up above the largest swept stable dt: the true limit lies higher, the cell says "at least"
        at_least = "" if above else ">= "
        text = f"{at_least}{best:.3g} s" + (f" ({at_least}{margin:.3g}x default)" if margin is not None else "")
        return Group(best, text, None, {"source": f"matrix dt sweep{note}", "largest_stable_dt_s": best,
                                         "smallest_unstable_dt_s": min(above) if above else None,
                                         "default_dt_s": default_dt, "margin": margin,
                                         "bracketed": bool(above)})
    found = _stable_dt_from_store(store, creature, body)
    if found is not None:
        best, when = found
        margin = best / default_dt if default_dt else None
        return Group(best, f"{best:.3g} s" + (f" ({margin:.3g}x default)" if margin is not None else ""), None,
                     {"source": f"stable-dt in {store} ({when})", "largest_stable_dt_s": best,
                      "default_dt_s": default_dt, "margin": margin})
    return Group(None, "not measured", f"no dt sweep of this pair in the matrix and no stable-dt result; run "
                 f"`bench-myriapoda stable-dt {_cmd(creature, body, scenario)}`", {"default_dt_s": default_dt})


def _stable_dt_from_store(store: Path | None, creature: str, body: str):
    if store is None or not Path(store).is_file():
        return None
    try:
        row = read_latest_stable_dt(store, creature, body)
    except StoreReadError:
        return None
    if row is None:
        return None
    from .inputs import parse_json
    metrics = parse_json(row[0], str(store), "runs (stable-dt)", "row (metrics_json)")
    v = _num(metrics.get("stable_dt_max_s")) if isinstance(metrics, dict) else None
    return None if v is None else (v, row[1])


# --------------------------------------------------------------------------- fidelity

def deviation(measured, reference) -> float | None:
    """|measured - reference| / |reference| for numbers (|measured| against a zero reference), else None."""
    m, r = _num(measured), _num(reference)
    if m is None or r is None:
        return None
    return abs(m - r) / abs(r) if r != 0 else abs(m)


_RELATIVE = re.compile(r"^\s*([0-9.eE+-]+)\s*%\s*relative\s*$")
_BOUND = re.compile(r"^\s*(<=|<|>=|>)\s*([0-9.eE+-]+)\s*$")


def tolerance_used(measured, reference, tolerance) -> tuple[float | None, float | None, str]:
    """(share of its tolerance a validate row uses, its relative deviation, how to say it).

    Tolerances validate writes as numbers: ``"N % relative"`` (share: the deviation over N %),
    ``"<= X"`` / ``"< X"`` (|measured| is itself an error against a bound X: |measured| / X; no deviation
    from the reference, which is then the exact value or a formula) and ``">= X"`` / ``"> X"`` (a lower
    bound: X / measured).  A share above 1 is outside the tolerance.  Rows judged in words (behaviour
    counts, wave signs) have no share, and a deviation only when measured and reference are numbers."""
    m, tol = _num(measured), str(tolerance or "")
    dev = deviation(measured, reference)
    if m is None:
        return None, None, ""
    bound = _BOUND.match(tol)
    if bound:
        op, limit = bound.group(1), float(bound.group(2))
        if op.startswith("<") and limit > 0:
            return abs(m) / limit, None, f"{m:.3g}, bound {op} {limit:g}"
        if op.startswith(">") and m > 0:
            return limit / m, None, f"{m:.3g}, bound {op} {limit:g}"
        return None, None, f"{m:.3g}, bound {op} {limit:g}"
    said = f"{100 * dev:.3g} % off" if dev is not None else ""
    rel = _RELATIVE.match(tol)
    if rel and dev is not None and float(rel.group(1)) > 0:
        return dev / (float(rel.group(1)) / 100.0), dev, said
    return None, dev, said


def fidelity_group(verdicts, creature: str, body: str) -> Group:
    """The verdicts of the pair: counts and the worst row: a FAIL if there is one, else the row that comes
    closest to its tolerance, as a share of that tolerance (``tolerance_used``), with its measured value and
    reference.  ``verdicts``: a ``scorecard_verdicts.PairVerdicts`` (validate rows and the matrix's own cases),
    a ``validation.ValidationData`` (its rows only) or None."""
    from .scorecard_verdicts import NOT_VALIDATED, PairVerdicts, validate_rows

    cmd = f"run `bench-myriapoda validate --body {body} --out DIR` (DIR: this matrix directory)"
    if verdicts is None:
        return Group(None, "not validated", f"no validate results; {cmd}")
    if not isinstance(verdicts, PairVerdicts):  # a validate run's rows alone
        verdicts = PairVerdicts(validate_rows(verdicts), verdicts.origin)
    mine = verdicts.for_pair(creature, body)
    if verdicts.origin is None and mine.empty:
        return Group(None, "not validated", f"no validate results; {cmd}")
    rows = verdicts.rows
    mine = rows[(rows["body"] == body) & ((rows["creature"] == creature) | rows["creature"].isna())]
    mine = mine[mine["verdict"] != NOT_VALIDATED]
    if mine.empty:
        return Group(None, "no check ran", f"{verdicts.origin or 'this matrix'} has no check of {creature} on "
                     f"{body}; {cmd}")
    counts = {k: int(v) for k, v in mine["verdict"].value_counts().items()}
    judged_rows = [(*tolerance_used(m, r, t), c, v, m, r, u) for m, r, t, c, v, u in
                   zip(mine["measured"], mine["reference"], mine["tolerance"], mine["check"], mine["verdict"],
                       mine["unit"])
                   if v in ("PASS", "FAIL")]
    rank = lambda d: -1.0 if d[0] is None else d[0]  # noqa: E731  (share of tolerance used)
    failed = [d for d in judged_rows if d[4] == "FAIL"]
    if failed:  # a FAIL is the worst; among FAILs the furthest past its tolerance, else the largest deviation
        worst = max(failed, key=lambda d: (rank(d), -1.0 if d[1] is None else d[1]))
    else:
        pool = [d for d in judged_rows if d[0] is not None]
        worst = max(pool, key=rank) if pool else None
    judged = counts.get("PASS", 0) + counts.get("FAIL", 0)
    share = counts.get("FAIL", 0) / judged if judged else None
    text = ", ".join(f"{n} {v}" for v, n in sorted(counts.items()))
    if worst is not None:
        used, dev, said, check, verdict, measured, reference, unit = worst
        text += f"; worst: {check}" if verdict == "FAIL" else f"; closest to its tolerance: {check}"
        text += f" ({said})" if said else f" ({verdict})"
        if used is not None:
            text += f", {100 * used:.3g} % of its tolerance"
        text += f"; measured {_said(measured, unit)}, reference {_said(reference, unit)}"
    return Group(share, text, None if share is not None else "no PASS or FAIL verdict to count",
                 {"counts": counts, "worst_check": worst[3] if worst else None,
                  "worst_measured": worst[5] if worst else None, "worst_reference": worst[6] if worst else None,
                  "worst_deviation_rel": worst[1] if worst else None,
                  "worst_tolerance_used": worst[0] if worst else None,
                  "fail_share": share, "origin": verdicts.origin,
                  "checks": [{"check": c, "verdict": v, "kind": k} for c, v, k in
                             zip(mine["check"], mine["verdict"], mine["kind"])]})


def _said(v, unit) -> str:
    """A measured value or reference as a cell says it: 3 significant digits and its unit (round-off as 0)."""
    f = _num(v)
    if f is None:
        return "-" if v is None or (isinstance(v, float) and not math.isfinite(v)) else str(v)
    u = f" {unit}" if isinstance(unit, str) and unit else ""
    return f"{f:.3g}{u}"


# --------------------------------------------------------------------------- locomotion

def slithering_speed(curvature_amplitude: float, wavelength_bl: float, friction: dict) -> float | str:
    """Steady speed [BL/cycle] of the kinematic slithering model for a wave (peak curvature x L, wavelength / L)
    and a Coulomb friction table, or the reason it has none."""
    from ..reference.slithering import steady_slithering

    try:
        return float(steady_slithering(curvature_amplitude, wavelength_bl, float(friction["mu_forward"]),
                                       float(friction["mu_backward"]), float(friction["mu_transverse"]),
                                       n_points=100, n_time=48).speed_bl_per_cycle)
    except (ValueError, KeyError) as exc:
        return f"the kinematic reference could not be solved: {exc}"


def _reference_speed(row, case: dict) -> tuple[float | None, str, str | None]:
    """(reference value, what it is, reason when none) for the case's headline locomotion metric."""
    gait, creature = str(row.get("gait")), str(row.get("creature"))
    m = lambda k: _num(row.get(f"metric.{k}"))  # noqa: E731
    if gait == "lateral-undulation":
        fr, g = case.get("friction", {}), case.get("gait", {})
        if fr.get("model") != "coulomb":
            return None, "", f"the kinematic reference assumes Coulomb friction, this case has {fr.get('model')!r}"
        # The commanded shape (issue 27): every body is asked for the same wave, so the speed it should give is
        # the reference's at that wave; a body that bends less is slower and says so in its shape cell.  Only a
        # gait commanded in raw strain (curvature_amplitude 0) has no commanded shape: then the measured wave.
        curv, wl = _num(g.get("curvature_amplitude")), _num(g.get("wavelength_bl"))
        what = "kinematic slithering model (Hu et al. 2009) at the commanded wave"
        if not curv:
            curv, wl = m("curvature_amplitude"), m("body_wavelength_bl")
            what = "kinematic slithering model (Hu et al. 2009) at the body's measured wave (raw-strain gait)"
        if curv is None or wl is None or wl <= 0:
            return None, "", "no commanded or measurable body wave (curvature or wavelength)"
        ref = slithering_speed(curv, wl, fr)
        if isinstance(ref, str):
            return None, "", ref
        return ref, what, None
    if creature == "worm" and gait == "rectilinear":
        from ..validation.references import worm_displacement_per_cycle

        # as validate's analytic.worm-eps-lambda: D = eps * Lambda with Lambda = wavelength_bl x the creature's
        # segments x segment length, against the measured displacement per cycle, in the same body lengths
        g, c, length = case.get("gait", {}), case.get("creature", {}), m("body_length_m")
        if length is None or length <= 0:
            return None, "", "no body length in this case's metrics"
        ref = worm_displacement_per_cycle(float(g["amplitude"]), float(g["wavelength_bl"]) * int(c["segments"])
                                          * float(c["segment_length_m"]))
        return ref / length, "eps * Lambda (perfect anchoring, analytic)", None
    return None, "", f"no speed reference for the {gait} gait"


def locomotion_group(row) -> Group:
    """The headline case's speed against its reference; commanded and too-short speeds say so."""
    if row is None:
        return Group(None, "no case", "the pair ran only in sweeps")
    if row["status"] == "controller_unstable":
        return Group(None, "controller_unstable", f"the shape tracker drove the body beyond the commanded shape and "
                     f"backed off (no speed of the commanded shape): {row.get('message') or ''}"[:400])
    if row["status"] != "ok":
        return Group(None, f"{row['status']}", f"the headline case ended {row['status']} at t = "
                     f"{_num(row.get('metric.t_fail_s')) or float('nan'):.3g} s: no speed")
    labels = _labels(row)
    case = _case(row)
    creature, body = row["creature"], row["body"]
    if str(row.get("gait")) == "passive":
        return Group(None, "does not travel", "a passive body (dropped or hanging): no locomotion to compare")
    if _legged(row):
        cmd = commanded_metric("speed_m_per_s", True)
        # foot_slip_mean_m is left out: the paper's legs are kinematic, a planted tip is held at its touchdown
        # point, so it reads 0 on every body and tells none apart
        emergent = {k: _num(row.get(f"metric.{k}")) for k in EMERGENT_WALK_METRICS}
        shown = ", ".join(f"{k} {v:.3g}" for k, v in emergent.items() if v is not None)
        why = labels.get("too_short") or ""
        return Group(None, "speed commanded" + (f"; {shown}" if shown else ""),
                     f"the walking speed equals the command {cmd} (left out of comparisons); no reference for the "
                     "emergent measures" + (f"; {why}" if why else ""), {"commanded": {"speed_m_per_s": cmd},
                                                                          "emergent": emergent})
    if labels.get("too_short"):
        return Group(None, "too short", f"{labels['too_short']} (e.g. `bench-myriapoda run "
                     f"{_cmd(creature, body, str(row.get('scenario')))} --duration 10`)")
    v = _num(row.get("metric.speed_bl_per_cycle"))
    if v is None:
        return Group(None, "not measured", "no speed_bl_per_cycle in this case's metrics")
    ref, what, reason = _reference_speed(row, case)
    details = {"speed_bl_per_cycle": v, "steady_cycles": _num(row.get("metric.steady_cycles"))}
    if _num(row.get(SHAPE_FLAG)):
        details["shape_not_achieved"] = True
    if ref is None:
        return Group(None, f"{v:.3g} BL/cycle", reason, details)
    err = abs(v - ref) / abs(ref) if ref else None
    details.update({"reference_bl_per_cycle": ref, "reference": what, "error_rel": err})
    if "commanded wave" in what:
        # informational, as validate's analytic.slithering-measured-shape: the friction balance alone
        curv, wl = _num(row.get("metric.curvature_amplitude")), _num(row.get("metric.body_wavelength_bl"))
        at_measured = slithering_speed(curv, wl, case.get("friction", {})) if curv and wl and wl > 0 else None
        details["reference_at_measured_shape_bl_per_cycle"] = at_measured if isinstance(at_measured, float) else None
    text = f"{v:.3g} vs {ref:.3g} BL/cycle ({100 * err:.3g} % off)"
    if details.get("shape_not_achieved"):
        text += " [shape not achieved]"
    return Group(err, text, None, details)


def shape_group(row) -> Group:
    """``shape_tracking_error`` (issue 27) where the results have it."""
    v = _num(row.get(SHAPE_METRIC)) if row is not None else None
    if v is None:
        return Group(None, "not measured", "no shape_tracking_error in these results")
    flagged = bool(_num(row.get(SHAPE_FLAG)))
    mode = shape_control_mode(_case(row).get("gait", {}))  # which shape control the row ran (issue 44)
    return Group(v, f"{v:.3g}" + (" (shape not achieved)" if flagged else "") + f" [shape_control {mode}]", None,
                 {"shape_not_achieved": flagged, "shape_control": mode})


# --------------------------------------------------------------------------- cost

def repeat_rows(rows: pd.DataFrame) -> pd.DataFrame:
    """The timed repeats of a pair's headline case: its finished runs with the first one's gait, scenario and
    duration (the matrix's seeds of it)."""
    ok = rows[rows["status"] == "ok"] if not rows.empty else rows
    if ok.empty:
        return ok
    first = ok.iloc[0]
    same = ok[(ok["gait"] == first["gait"]) & (ok["scenario"] == first["scenario"])]
    if "duration" in same and pd.notna(first.get("duration")):
        same = same[np.isclose(pd.to_numeric(same["duration"], errors="coerce"), float(first["duration"]))]
    return same


def cost_group(rows: pd.DataFrame, creature: str, body: str, bracket: dict | None = None) -> Group:
    """CPU s per simulated s (1 / realtime factor: the kernel runs on one core) and steps/s of the headline
    case: the median over its timed repeats and their spread, max - min (``spread_cpu_s_per_sim_s``; relative:
    over the median).  The repeats: the headline case's runs with the first one's gait, scenario and duration
    (the matrix's seeds) when there are ``MIN_REPEATS`` of them, else the main job's timed runs of the case at
    its default dt (``bracket``: ``harness.stable_dt.bracket_entry``, ``timed_cpu_s_per_sim_s``), else the
    one headline run."""
    same = repeat_rows(rows)
    if same.empty:
        return Group(None, "no finished case", f"run `bench-myriapoda run {_cmd(creature, body)}`")
    first = same.iloc[0]
    rt = pd.to_numeric(same.get("realtime_factor"), errors="coerce").dropna()
    sps = pd.to_numeric(same.get("steps_per_s"), errors="coerce").dropna()
    if rt.empty or (rt <= 0).any():
        return Group(None, "not timed", "no timing stored for this case")
    cpu = 1.0 / rt
    headline = float(cpu.median())
    timed = [v for v in ((bracket or {}).get("timed_cpu_s_per_sim_s") or []) if _num(v) and v > 0]
    what = f"{len(cpu)} runs"
    if len(cpu) < MIN_REPEATS and len(timed) >= MIN_REPEATS:
        cpu = pd.Series(timed, dtype=float)
        sps = pd.Series((bracket or {}).get("timed_steps_per_s") or [], dtype=float)
        what = f"{len(cpu)} timed {float(bracket.get('trial_duration_s', 0)):g} s runs"
    med = float(cpu.median())
    details = {"cpu_s_per_sim_s": med, "steps_per_s": float(sps.median()) if not sps.empty else None,
               "runs": int(len(cpu)), "case": str(first.get("label", "")), "headline_cpu_s_per_sim_s": headline,
               "cpu_s_per_sim_s_min": float(cpu.min()), "cpu_s_per_sim_s_max": float(cpu.max())}
    text = f"{med:.3g} CPU s/s, {details['steps_per_s']:.3g} steps/s"
    if len(cpu) > 1:
        spread = float(cpu.max() - cpu.min())
        details["spread_cpu_s_per_sim_s"] = spread
        details["cpu_spread_rel"] = spread / med
        details["steps_per_s_spread_rel"] = float((sps.max() - sps.min()) / sps.median()) if len(sps) > 1 else None
        text += f" (median of {what}, range {cpu.min():.3g}-{cpu.max():.3g})"
        if "timed" in what:
            text += f"; the {float(first['duration']):g} s run: {headline:.3g} CPU s/s"
        if len(cpu) < MIN_REPEATS:
            details["spread_reason"] = f"{len(cpu)} runs: fewer than {MIN_REPEATS}, not ranked on cost"
    else:
        details["spread_reason"] = ("one run: no spread, not ranked on cost; give the matrix seeds = [0, 1, 2] or "
                                    "time it with `bench-myriapoda regress`")
        text += " (1 run)"
    return Group(med, text, None, details)


# --------------------------------------------------------------------------- the whole card

def pareto_front(points: dict[str, tuple[float, float]]) -> list[str]:
    """The names whose (error, cost) no other point beats in both (<= in both, < in one)."""
    front = []
    for name, (e, c) in points.items():
        if not any((e2 <= e and c2 <= c) and (e2 < e or c2 < c) for n2, (e2, c2) in points.items() if n2 != name):
            front.append(name)
    return sorted(front, key=lambda n: points[n][1])


def _cost_spread(r: Row) -> float | None:
    """The absolute spread (max - min, CPU s/s) of a row's timed repeats; None under MIN_REPEATS runs."""
    d = r.cost.details
    if int(d.get("runs", 1)) < MIN_REPEATS:
        return None
    return _num(d.get("spread_cpu_s_per_sim_s"))


def compare(a: float, b: float, spread_a: float | None, spread_b: float | None) -> int | None:
    """-1 / 1 when ``a`` is below / above ``b`` by more than the larger of their measured spreads, 0 for a tie
    (they differ by no more than it), None when a spread is unknown (too few repeats: no ranking)."""
    if spread_a is None or spread_b is None:
        return None
    if abs(a - b) <= max(spread_a, spread_b):
        return 0
    return -1 if a < b else 1


def _dt_risks(rows: list[Row]) -> list[str]:
    out = []
    for r in sorted(rows, key=lambda r: r.body):
        d = r.stability.details
        m, lo, dt = _num(d.get("margin")), _num(d.get("largest_stable_dt_s")), _num(d.get("default_dt_s"))
        if m is None or lo is None or dt is None or m >= DT_RISK_MARGIN:
            continue
        if m < 1.0:
            out.append(f"{r.body}'s default dt {dt:.3g} s is not stable (stable up to {lo:.3g} s)")
        else:
            out.append(f"{r.body}'s default dt {dt:.3g} s is within {DT_RISK_MARGIN:g}x of its stability limit "
                       f"(stable up to {lo:.3g} s, margin {m:.3g}x)")
    return out


def recommend(creature: str, rows: list[Row]) -> str:
    """One line per creature: the body to use and which axis decided it (error, cost or both), with ties where
    bodies differ by no more than the measured spread of their costs (``compare``; ``MIN_REPEATS`` timed
    repeats) or errors (``Row.error_spread``; 0 for one deterministic run, which a rerun reproduces exactly), a
    default dt within ``DT_RISK_MARGIN`` of its stability limit as a risk, and no ranking where only one body ran."""
    costed = {r.body: r for r in rows if r.cost.value is not None}
    risks = _dt_risks(rows)
    tail = (" Risk: " + "; ".join(risks) + ".") if risks else ""
    if not costed:
        return f"{creature}: no body finished a timed case; nothing to recommend yet.{tail}"
    if len(rows) == 1 or len(costed) == 1:
        (r,) = costed.values()
        others = "only body in this matrix" if len(rows) == 1 else "only body that finished a timed case"
        err = f", {100 * r.error:.3g} % {r.error_kind}" if r.error is not None else ""
        return (f"{creature}: {r.body} is the {others} ({r.cost.value:.3g} CPU s per simulated s{err}); nothing to "
                f"compare it with, so no ranking.{tail}")
    scored = {b: r for b, r in costed.items() if r.error is not None}
    spreads = {b: _cost_spread(r) for b, r in costed.items()}
    unknown = sorted(b for b, sp in spreads.items() if sp is None)
    cost_note = (f" Costs not ranked: {', '.join(unknown)} timed fewer than {MIN_REPEATS} times (no measured "
                 "spread)." if unknown else "")

    def cost_cmp(a: str, b: str) -> int:
        c = compare(costed[a].cost.value, costed[b].cost.value, spreads[a], spreads[b])
        return 0 if c is None else c  # an unknown spread ranks nothing: as a tie

    def cost_txt(b: str) -> str:
        sp = spreads[b]
        return f"{costed[b].cost.value:.3g}" + (f" +/- {sp / 2:.2g}" if sp is not None else "") + " CPU s/s"

    if len(scored) < 2:
        # rank by cost alone, ties by the spread
        order = sorted(costed, key=lambda b: costed[b].cost.value)
        best = [b for b in order if cost_cmp(b, order[0]) == 0]
        why = "; ".join(sorted({r.locomotion.reason or r.fidelity.reason or "" for r in costed.values()}
                               - {""}))[:300]
        kind = next((r.error_kind for r in scored.values()), "")
        what = (f"only {next(iter(scored))} has a {kind} measure" if scored else f"no error measure to rank by ({why})")
        if unknown:
            line = f"{creature}: not ranked -- {what}, and the costs have no measured spread."
        elif len(best) == 1:
            line = (f"{creature}: {best[0]} is cheapest ({cost_txt(best[0])}, beyond the spread of "
                    f"{', '.join(f'{b} {cost_txt(b)}' for b in order[1:])}) -- decided by cost alone; {what}.")
        else:
            line = (f"{creature}: a tie on cost between {' and '.join(f'{b} ({cost_txt(b)})' for b in best)}: they "
                    f"differ by less than their measured spread -- nothing decides between them; {what}.")
        return line + cost_note + tail
    kind = next(r.error_kind for r in scored.values())

    def err_cmp(a: str, b: str) -> int:
        ea, eb = scored[a].error, scored[b].error
        tol = max(scored[a].error_spread, scored[b].error_spread)
        return 0 if abs(ea - eb) <= tol else (-1 if ea < eb else 1)

    def dominates(a: str, b: str) -> bool:
        e, c = err_cmp(a, b), cost_cmp(a, b)
        return e <= 0 and c <= 0 and (e < 0 or c < 0)

    front = sorted((b for b in scored if not any(dominates(o, b) for o in scored if o != b)),
                   key=lambda b: costed[b].cost.value)
    parts = {b: f"{b} ({100 * scored[b].error:.3g} % {kind}, {cost_txt(b)})" for b in scored}
    losers = [b for b in scored if b not in front]
    if unknown:  # costs without a measured spread rank nothing: by error alone
        order = sorted(scored, key=lambda b: scored[b].error)
        best = [b for b in order if err_cmp(b, order[0]) == 0]
        rest = [b for b in order if b not in best]
        if len(best) == 1:
            line = f"{creature}: {parts[best[0]]} -- decided by error alone"
        else:
            line = (f"{creature}: a tie on error between {' and '.join(parts[b] for b in best)}, and costs without "
                    "a measured spread -- nothing decides")
        line += f"; {', '.join(parts[b] for b in rest)}: more error." if rest else "."
    elif len(front) == 1:
        w = front[0]
        by_err = all(err_cmp(w, o) < 0 for o in losers)
        by_cost = all(cost_cmp(w, o) < 0 for o in losers)
        axis = ("both error and cost" if by_err and by_cost else "error" if by_err else "cost" if by_cost
                else "error for some bodies, cost for the others")
        ties = [o for o in losers if err_cmp(w, o) == 0] if by_cost and not by_err else \
            [o for o in losers if cost_cmp(w, o) == 0 and not unknown]
        tie_axis = "error" if by_cost and not by_err else "cost"
        line = f"{creature}: {parts[w]} -- decided by {axis}"
        if ties:
            line += f" ({', '.join(ties)}: a tie on {tie_axis}, within the measured spread)"
        line += f"; {', '.join(parts[o] for o in losers)}: worse and no better in the other."
    elif all(err_cmp(a, b) == 0 and cost_cmp(a, b) == 0 for a in front for b in front if a != b):
        line = (f"{creature}: a tie between {' and '.join(parts[b] for b in front)}: errors and costs differ by "
                "less than the measured spread -- neither axis decides.")
        if losers:
            line += f" ({', '.join(losers)}: worse.)"
    else:
        line = (f"{creature}: {' or '.join(parts[b] for b in front)} -- a trade-off (the Pareto front): the cheaper "
                "one costs less, the other is closer to the reference beyond the measured spread; neither axis "
                "decides alone, pick by your error budget.")
        if losers:
            line += f" ({', '.join(losers)}: worse in one and no better in the other.)"
    unranked = [b for b in costed if b not in scored]
    if unranked:
        line += f" ({', '.join(unranked)}: no {kind} measure.)"
    missed = [r for r in costed.values() if r.shape.details.get("shape_not_achieved")]
    if missed and kind == "speed error":
        # issue 27: a body that did not bend to the commanded wave moved differently; its speed error is real,
        # but it measures the body's failure to follow the command, not the friction physics alone
        said = ", ".join(f"{r.body} {r.shape.value:.2g}" for r in sorted(missed, key=lambda r: r.body))
        line += (f" Caution: not at the commanded shape ({said} shape_tracking_error, over {SHAPE_THRESHOLD:g}); "
                 "those speeds are of a different motion.")
    return line + cost_note + tail


def shortcut_error(verdicts, creature: str, body: str) -> float | None:
    """The myriapod's error axis on ``body`` (``SHORTCUT_CHECK``): the measured value [BL] of validate's
    kinematic-shortcut check of ``creature`` on ``body`` in ``verdicts`` (a ``scorecard_verdicts.PairVerdicts``);
    None where that check has no finite measured value (not run, failed, a creature without the check)."""
    if verdicts is None or not hasattr(verdicts, "validate_row"):
        return None
    row = verdicts.validate_row(SHORTCUT_CHECK.format(creature=creature), body)
    if row is None or row["verdict"] == "FAIL":
        return None
    return _num(row["measured"])


def build_scorecard(res, vdata=None, store: Path | None = None, brackets: dict | None = None) -> Scorecard:
    """The scorecard of a matrix directory's results (``report.matrix_data.MatrixResults``).

    vdata: a ``report.scorecard_verdicts.PairVerdicts`` (the report passes the one its figures read), a
    ``report.validation.ValidationData`` (then the table is built here from it and the matrix's cases) or None;
    store: a results store with stable-dt runs; brackets: headline case hash -> bisected stable-dt bracket
    (``harness.stable_dt.brackets_by_case``).
    """
    from ..core.config import resolve_case
    from .scorecard_verdicts import PairVerdicts, pair_verdicts

    df = res.df
    rows: list[Row] = []
    if df.empty:
        return Scorecard([], {}, str(res.directory))
    verdicts = vdata if isinstance(vdata, PairVerdicts) else pair_verdicts(res, vdata)
    brackets = brackets or {}
    for (creature, body), _sub in df.groupby(["creature", "body"], sort=True):
        head = headline_rows(df, res.grid_keys, creature, body)
        first = head.iloc[0] if not head.empty else None
        scenario = str(first["scenario"]) if first is not None else ""
        default_dt = None
        try:
            default_dt = resolve_case(creature, body, scenario, str(first["gait"]) if first is not None else None).dt
        except Exception:  # a scenario given as a file path the resolver cannot find from here
            default_dt = _num(first["dt"]) if first is not None else None
        loc = locomotion_group(first)
        bracket = brackets.get(str(first["case_hash"])) if first is not None and "case_hash" in first else None
        row = Row(creature, body, stability_group(df, res.grid_keys, creature, body, default_dt, scenario, store,
                                                  bracket),
                  fidelity_group(verdicts, creature, body), loc, cost_group(head, creature, body, bracket),
                  shape_group(first))
        if loc.value is not None:
            row.error, row.error_kind = loc.value, "speed error"
            errs = [locomotion_group(r).value for _, r in repeat_rows(head).iterrows()]
            errs = [e for e in errs if e is not None]
            row.error_spread = float(max(errs) - min(errs)) if len(errs) > 1 else 0.0
        elif (shortcut := shortcut_error(verdicts, creature, body)) is not None:
            row.error, row.error_kind = shortcut, SHORTCUT_KIND
        elif row.fidelity.value is not None:
            row.error, row.error_kind = row.fidelity.value, "validate FAIL share"
        rows.append(row)
    recs = {}
    for creature in sorted({r.creature for r in rows}):
        mine = [r for r in rows if r.creature == creature]
        kinds = {r.error_kind for r in mine if r.error is not None}
        if len(kinds) > 1:  # rank one creature by one kind of error only: the first of ERROR_KINDS it has
            keep = next(k for k in ERROR_KINDS if k in kinds)
            for r in mine:
                if r.error_kind != keep:
                    r.error, r.error_kind = None, ""
        recs[creature] = recommend(creature, mine)
    return Scorecard(rows, recs, str(res.directory))


def scorecard_table(card: Scorecard) -> pd.DataFrame:
    """The scorecard as a table: one row per pair, a column per group (text cells), headed with their units
    (``COLUMNS``; ``column_definitions`` gives each heading's definition)."""
    out = []
    heads = {c.key: c.heading for c in COLUMNS}
    for r in card.rows:
        out.append({"creature": r.creature, "body": r.body,
                    heads["stability"]: _cell(r.stability),
                    heads["fidelity"]: _cell(r.fidelity),
                    heads["locomotion"]: _cell(r.locomotion),
                    heads["shape"]: r.shape.text,
                    heads["cost"]: _cell(r.cost)})
    return pd.DataFrame(out)


def column_definitions() -> list[str]:
    """One line per scorecard column: its heading, unit and definition."""
    return [f"{c.heading}: {c.definition} (unit: {c.unit})" for c in COLUMNS]


def _cell(g: Group) -> str:
    return g.text if g.reason is None else f"{g.text} -- {g.reason}"


def scorecard_for_dir(directory: Path | str, store: Path | None = None) -> Scorecard:
    """``build_scorecard`` of a matrix output directory, with the validate verdicts the report would show
    (``report.validation.load_validation``: DIR/validation.json, DIR's store, then ``store``) and the stable-dt
    brackets the main job kept in DIR (``harness.stable_dt.brackets_by_case``).
    An ``InputError`` naming DIR when it is not a matrix output directory."""
    from ..harness.stable_dt import brackets_by_case
    from .matrix_data import load_matrix_dir
    from .validation import load_validation

    res = load_matrix_dir(directory, "DIR")
    if store is not None and Path(store).exists() and not Path(store).is_file():
        from ..core.errors import InputError
        raise InputError("--history-store", None, f"{store} is not a file")
    return build_scorecard(res, load_validation(res.directory, store), store, brackets_by_case(res.directory))


def scorecard_lines(card: Scorecard) -> list[str]:
    """The scorecard as terminal text: per creature its recommendation, then a block per body; the columns'
    units and definitions last."""
    out = [f"scorecard of {card.source}"]
    for creature in sorted({r.creature for r in card.rows}):
        out.append("")
        out.append(f"{creature}: {card.recommendations[creature].split(': ', 1)[-1]}")
        for r in (r for r in card.rows if r.creature == creature):
            out.append(f"  {r.body}")
            for name, g in (("stability", r.stability), ("fidelity", r.fidelity), ("locomotion", r.locomotion),
                            ("shape", r.shape), ("cost", r.cost)):
                out.append(f"    {name:<11}{_cell(g)}")
    out.append("")
    out.append("columns:")
    for c in COLUMNS:
        out.append(f"  {c.key:<11}[{c.unit}] {c.definition}")
    return out
