"""The scorecard: which body model to trust for each creature, from one matrix output directory.

One row per creature x body pair of the matrix, in four groups:

``stability``   the largest stable dt found -- from the matrix's dt sweeps of the pair (at the
                default value of every other swept key), else from the latest ``stable-dt`` run of
                the pair in the results store -- and the default dt's margin under it
                (largest stable dt / default dt; < 1: the default dt is not stable);
``fidelity``    the ``validate`` verdicts for the pair (the checks of that creature on that body,
                and the body's own checks), their counts and the worst deviation from its
                reference with the check's name;
``locomotion``  the headline case's speed against a reference where one applies: the kinematic
                slithering model (``reference/slithering.py``) for lateral undulation, eps * Lambda
                for the rectilinear worm; a commanded speed (``metrics.walk.COMMANDED``) is no
                result and is left out, with the walk's emergent measures shown instead;
``cost``        CPU seconds per simulated second and steps/s of the headline case, with their
                spread over seeds (sample standard deviation / mean) when it ran with several.

Every group is a number or a stated reason; where a cell has no data the reason names the command
that fills it.  Per creature, a one-line recommendation names the bodies on the Pareto front of
error against cost (``pareto_front``) and why.  Plain Python: the report (``report/build.py``), the
``scorecard`` command and tests call :func:`build_scorecard`.
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
from .sweeps import sweep_mask

# validate checks that concern one creature (by name prefix); the others test a body model as such
CHECK_CREATURE = (("analytic.worm", "worm"), ("miller.image1", "worm"), ("cross_body.worm", "worm"),
                  ("analytic.slithering", "snake"), ("miller.image2", "snake"), ("miller.image3", "snake"),
                  ("miller.image4", "caterpillar"), ("paper.fig4", "chain"), ("paper.wave-millipede", "millipede"),
                  ("paper.", "centipede"), ("cross_body.centipede", "centipede"), ("cross_body.hang", "centipede"),
                  ("throughput.", "centipede"))
BODY_CHECKS = ("analytic.hanging-bar", "analytic.cantilever", "analytic.rigid-rotation",
               "analytic.free-fall-momentum", "analytic.stable-dt", "analytic.damping-pure-mode",
               "analytic.damping-oscillating-mode")
SHAPE_METRIC, SHAPE_FLAG = "metric.shape_tracking_error", "metric.shape_not_achieved"


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
    error: float | None = None       # the error the recommendation ranks by (locomotion, else fidelity)
    error_kind: str = ""


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
                      "recommendations": self.recommendations})


def _num(v) -> float | None:
    try:
        f = float(v)
    except (TypeError, ValueError):
        return None
    return f if math.isfinite(f) else None


def _case(row) -> dict:
    return json.loads(row["case_json"]) if isinstance(row.get("case_json"), str) else {}


def _labels(row) -> dict:
    try:
        return json.loads(row.get("labels_json") or "{}")
    except (TypeError, ValueError):
        return {}


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


def stability_group(df: pd.DataFrame, grid_keys, creature: str, body: str, default_dt: float | None,
                    scenario: str, store: Path | None) -> Group:
    """Largest stable dt of the pair and the default dt's margin under it (module docstring)."""
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
    v = _num(json.loads(row[0]).get("stable_dt_max_s"))
    return None if v is None else (v, row[1])


# --------------------------------------------------------------------------- fidelity

def check_creature(check: str) -> str | None:
    """The creature a validate check concerns (None: a check of the body model itself)."""
    if check in BODY_CHECKS:
        return None
    for prefix, creature in CHECK_CREATURE:
        if check.startswith(prefix):
            return creature
    return None


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


def fidelity_group(vdata, creature: str, body: str) -> Group:
    """The validate verdicts of the pair: counts and the worst row: a FAIL if there is one, else the row
    that comes closest to its tolerance, as a share of that tolerance (``tolerance_used``)."""
    cmd = f"run `bench-myriapoda validate --body {body} --out DIR` (DIR: this matrix directory)"
    if vdata is None:
        return Group(None, "not validated", f"no validate results; {cmd}")
    rows = vdata.rows
    concerns = np.array([check_creature(str(c)) in (creature, None) for c in rows["check"]], dtype=bool)
    mine = rows[(rows["body"] == body).to_numpy() & concerns]
    if mine.empty:
        return Group(None, "no check ran", f"{vdata.origin} has no check of {creature} on {body}; {cmd}")
    counts = {k: int(v) for k, v in mine["verdict"].value_counts().items()}
    tolerances = mine["tolerance"] if "tolerance" in mine else [None] * len(mine)
    judged_rows = [(*tolerance_used(m, r, t), c, v) for m, r, t, c, v in
                   zip(mine["measured"], mine["reference"], tolerances, mine["check"], mine["verdict"])
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
        used, dev, said, check, verdict = worst
        text += f"; worst: {check}" if verdict == "FAIL" else f"; closest to its tolerance: {check}"
        text += f" ({said})" if said else f" ({verdict})"
        if used is not None:
            text += f", {100 * used:.3g} % of its tolerance"
    return Group(share, text, None if share is not None else "no PASS or FAIL verdict to count",
                 {"counts": counts, "worst_check": worst[3] if worst else None,
                  "worst_deviation_rel": worst[1] if worst else None,
                  "worst_tolerance_used": worst[0] if worst else None,
                  "fail_share": share, "origin": vdata.origin})


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

def cost_group(rows: pd.DataFrame, creature: str, body: str) -> Group:
    """CPU s per simulated s (1 / realtime factor: the kernel runs on one core) and steps/s of the headline
    case, mean over its seeds with the relative spread."""
    ok = rows[rows["status"] == "ok"] if not rows.empty else rows
    if ok.empty:
        return Group(None, "no finished case", f"run `bench-myriapoda run {_cmd(creature, body)}`")
    first = ok.iloc[0]
    same = ok[(ok["gait"] == first["gait"]) & (ok["scenario"] == first["scenario"])]
    rt = pd.to_numeric(same.get("realtime_factor"), errors="coerce").dropna()
    sps = pd.to_numeric(same.get("steps_per_s"), errors="coerce").dropna()
    if rt.empty or (rt <= 0).any():
        return Group(None, "not timed", "no timing stored for this case")
    cpu = 1.0 / rt
    mean = float(cpu.mean())
    details = {"cpu_s_per_sim_s": mean, "steps_per_s": float(sps.mean()) if not sps.empty else None,
               "runs": int(len(cpu)), "case": str(first.get("label", ""))}
    text = f"{mean:.3g} CPU s/s, {details['steps_per_s']:.3g} steps/s"
    if len(cpu) > 1:
        details["cpu_spread_rel"] = float(cpu.std(ddof=1) / mean)
        details["steps_per_s_spread_rel"] = float(sps.std(ddof=1) / sps.mean()) if len(sps) > 1 else None
        text += f" (+/- {100 * details['cpu_spread_rel']:.2g} % over {len(cpu)} seeds)"
    else:
        details["spread_reason"] = ("one run: no spread; give the matrix seeds = [0, 1, 2] or time it with "
                                    "`bench-myriapoda regress`")
        text += " (1 run)"
    return Group(mean, text, None, details)


# --------------------------------------------------------------------------- the whole card

def pareto_front(points: dict[str, tuple[float, float]]) -> list[str]:
    """The names whose (error, cost) no other point beats in both (<= in both, < in one)."""
    front = []
    for name, (e, c) in points.items():
        if not any((e2 <= e and c2 <= c) and (e2 < e or c2 < c) for n2, (e2, c2) in points.items() if n2 != name):
            front.append(name)
    return sorted(front, key=lambda n: points[n][1])


def recommend(creature: str, rows: list[Row]) -> str:
    """One line: the bodies on the Pareto front of error against cost, and why."""
    costed = {r.body: r for r in rows if r.cost.value is not None}
    if not costed:
        return f"{creature}: no body finished a timed case; nothing to recommend yet."
    scored = {b: (r.error, r.cost.value) for b, r in costed.items() if r.error is not None}
    cheapest = min(costed.values(), key=lambda r: r.cost.value)
    if not scored:
        why = "; ".join(sorted({r.locomotion.reason or r.fidelity.reason or "" for r in costed.values()} - {""}))[:300]
        return (f"{creature}: {cheapest.body} is cheapest ({cheapest.cost.value:.3g} CPU s per simulated s); no error "
                f"measure to rank by ({why}).")
    kind = next(r.error_kind for r in costed.values() if r.error is not None)
    front = pareto_front(scored)
    parts = [f"{b} ({100 * scored[b][0]:.3g} % {kind}, {scored[b][1]:.3g} CPU s/s)" for b in front]
    if len(front) == 1:
        why = "lowest error and lowest cost" if len(scored) > 1 else "the only body with an error measure"
        if len(scored) > 1:
            beaten = [b for b in scored if b not in front]
            why = f"{', '.join(beaten)}: more error or more cost, and no better in the other"
        line = f"{creature}: {parts[0]} -- {why}."
    else:
        line = (f"{creature}: {' or '.join(parts)} -- the Pareto front: the cheaper one costs less, the other "
                "is closer to the reference; pick by your error budget.")
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
    return line


def build_scorecard(res, vdata=None, store: Path | None = None) -> Scorecard:
    """The scorecard of a matrix directory's results (``report.matrix_data.MatrixResults``).

    vdata: ``report.validation.ValidationData`` or None; store: a results store with stable-dt runs.
    """
    from ..core.config import resolve_case

    df = res.df
    rows: list[Row] = []
    if df.empty:
        return Scorecard([], {}, str(res.directory))
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
        row = Row(creature, body, stability_group(df, res.grid_keys, creature, body, default_dt, scenario, store),
                  fidelity_group(vdata, creature, body), loc, cost_group(head, creature, body), shape_group(first))
        if loc.value is not None:
            row.error, row.error_kind = loc.value, "speed error"
        elif row.fidelity.value is not None:
            row.error, row.error_kind = row.fidelity.value, "validate FAIL share"
        rows.append(row)
    recs = {}
    for creature in sorted({r.creature for r in rows}):
        mine = [r for r in rows if r.creature == creature]
        kinds = {r.error_kind for r in mine if r.error is not None}
        if len(kinds) > 1:  # rank one creature by one kind of error only
            for r in mine:
                if r.error_kind != "speed error":
                    r.error, r.error_kind = None, ""
        recs[creature] = recommend(creature, mine)
    return Scorecard(rows, recs, str(res.directory))


def scorecard_table(card: Scorecard) -> pd.DataFrame:
    """The scorecard as a table: one row per pair, a column per group (text cells)."""
    out = []
    for r in card.rows:
        out.append({"creature": r.creature, "body": r.body,
                    "stability: largest stable dt (margin)": _cell(r.stability),
                    "fidelity: validate": _cell(r.fidelity),
                    "locomotion vs reference": _cell(r.locomotion),
                    "shape tracking": r.shape.text,
                    "cost": _cell(r.cost)})
    return pd.DataFrame(out)


def _cell(g: Group) -> str:
    return g.text if g.reason is None else f"{g.text} -- {g.reason}"


def scorecard_for_dir(directory: Path | str, store: Path | None = None) -> Scorecard:
    """``build_scorecard`` of a matrix output directory, with the validate verdicts the report would show
    (``report.validation.load_validation``: DIR/validation.json, DIR's store, then ``store``).
    An ``InputError`` naming DIR when it is not a matrix output directory."""
    from .matrix_data import load_matrix_dir
    from .validation import load_validation

    res = load_matrix_dir(directory, "DIR")
    if store is not None and Path(store).exists() and not Path(store).is_file():
        from ..core.errors import InputError
        raise InputError("--history-store", None, f"{store} is not a file")
    return build_scorecard(res, load_validation(res.directory, store), store)


def scorecard_lines(card: Scorecard) -> list[str]:
    """The scorecard as terminal text: per creature its recommendation, then a block per body."""
    out = [f"scorecard of {card.source}"]
    for creature in sorted({r.creature for r in card.rows}):
        out.append("")
        out.append(f"{creature}: {card.recommendations[creature].split(': ', 1)[-1]}")
        for r in (r for r in card.rows if r.creature == creature):
            out.append(f"  {r.body}")
            for name, g in (("stability", r.stability), ("fidelity", r.fidelity), ("locomotion", r.locomotion),
                            ("shape", r.shape), ("cost", r.cost)):
                out.append(f"    {name:<11}{_cell(g)}")
    return out
