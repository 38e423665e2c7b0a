"""The report's "Validation" section and the verdict next to each reproduced paper figure.

Where the verdicts come from (first found wins):

1. ``DIR/validation.json``: a ``validate --out DIR`` run written into the matrix directory;
2. the latest ``validate`` run in the ``validation`` table of ``DIR/results.sqlite``;
3. the latest ``validate`` run in the results store passed as ``--history-store`` (default
   ``reports/results.sqlite``, where ``validate`` records by default).

The work-precision diagrams are read from the validation run's output directory (``out_dir``:
``work_precision.json`` and ``work_precision_*.png``) and copied into the report's figures.

Each reproduced-figure case also gets its own verdict, computed from that case's metrics and
recording with the same criteria the checks use (``validation.paper``, ``validation.miller``); a
figure that does not reproduce says so in red.  Figures no check covers say "not validated".
"""
from __future__ import annotations

import html
import json
import math
import shutil
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from ..harness.store import StoreReadError, read_latest_validation
from ..validation.core import FAIL, INFO, NA, PASS, Outcome

COLORS = {PASS: "#17692a", FAIL: "#b00000", NA: "#8a6d00", INFO: "#1f4e99", "NOT VALIDATED": "#666"}
ROW_CLASS = {PASS: "improvement", FAIL: "regression", NA: "missing", INFO: ""}
VALIDATION_COLUMNS = ("check", "family", "body", "quantity", "measured", "reference", "source", "tolerance",
                      "verdict", "detail", "unit", "seconds")  # what the section reads: None where a row lacks it


@dataclass
class ValidationData:
    """The rows of one ``validate`` run and where they came from."""

    rows: pd.DataFrame            # columns: check, family, body, quantity, measured, reference, source, tolerance,
    #                               verdict, detail, unit, seconds
    origin: str                   # a human-readable description of the source
    quick: bool = False
    out_dir: Path | None = None
    meta: dict = field(default_factory=dict)

    def lookup(self, check: str, body: str) -> pd.Series | None:
        m = self.rows[(self.rows["check"] == check) & (self.rows["body"] == body)]
        return None if m.empty else m.iloc[0]


def _from_json(path: Path) -> ValidationData | None:
    from .inputs import read_validation_json

    doc = read_validation_json(path)  # an InputError naming the file when it is there and not validate's
    if doc is None:
        return None
    rows = pd.DataFrame([{**dict.fromkeys(VALIDATION_COLUMNS), **r} for r in doc.get("rows", [])])
    if rows.empty:
        return None
    out = path.parent
    return ValidationData(rows, f"{path}", bool(doc.get("quick")), out, {"wall_s": doc.get("wall_s")})


def _from_store(path: Path) -> ValidationData | None:
    if not path.is_file():
        return None
    try:
        df = read_latest_validation(path)
    except StoreReadError:
        return None
    if df is None:
        return None
    rows = pd.DataFrame({
        "check": df["check_name"], "family": df["family"], "body": df["body"], "quantity": df["quantity"],
        "measured": [json.loads(v) if v else None for v in df["measured_json"]],
        "reference": [json.loads(v) if v else None for v in df["reference_json"]],
        "source": df["source"], "tolerance": df["tolerance"], "verdict": df["verdict"], "detail": df["detail"],
        "unit": df["unit"], "seconds": df["seconds"]})
    out = df["out_dir"].iloc[0]
    run = int(df["run_id"].iloc[0])  # read_latest_validation returns one run's rows: they share run_id
    return ValidationData(rows, f"validate run {run} in {path} ({df['timestamp'].iloc[0]})",
                          bool(df["quick"].iloc[0]), Path(out) if out else None)


def load_validation(directory: Path, store: Path | None) -> ValidationData | None:
    """The latest validation rows for the report of matrix directory ``directory`` (module docstring)."""
    for cand in (lambda: _from_json(directory / "validation.json"),
                 lambda: _from_store(directory / "results.sqlite"),
                 lambda: _from_store(store) if store is not None else None):
        v = cand()
        if v is not None:
            return v
    return None


def _fmt(v) -> str:
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "-"
    if isinstance(v, float):
        return f"{v:.4g}"
    return str(v)


def section(page, data: ValidationData | None, store: Path | None, verdicts=None) -> None:
    """The "Validation" section: one row per check and body, the checks judged on the matrix's own cases
    (``verdicts``, a ``scorecard_verdicts.PairVerdicts``), then the work-precision diagrams."""
    page.section("validation", "Validation")
    if data is None:
        page.p("No validation results: run `bench-myriapoda validate --quick --out DIR` (DIR: this matrix "
               "directory; the main job, `bench-myriapoda`, does it for reports/quick).", "note")
        _case_verdicts(page, verdicts)
        return
    counts = data.rows["verdict"].value_counts().to_dict()
    page.p(f"From {data.origin}{' (quick set)' if data.quick else ''}: "
           + ", ".join(f"{n} {v}" for v, n in sorted(counts.items())) + ". PASS: within the tolerance of the "
           "reference; FAIL: not; NOT APPLICABLE: cannot be checked here (reason given); INFO: shown against a "
           "reference that is not a pass/fail criterion.", "note")
    df = data.rows
    table = pd.DataFrame({
        "check": df["check"], "body": df["body"],
        "measured": [_fmt(m) + (f" {u}" if u and isinstance(m, (int, float)) else "") for m, u in
                     zip(df["measured"], df["unit"])],
        "reference": [_fmt(v) for v in df["reference"]], "source": df["source"], "tolerance": df["tolerance"],
        "verdict": df["verdict"], "detail": df["detail"].fillna("")})
    page.table(table, [ROW_CLASS.get(v, "") for v in df["verdict"]])
    _case_verdicts(page, verdicts)
    _work_precision(page, data)


def _case_verdicts(page, verdicts) -> None:
    """The checks judged on the matrix's own headline cases (``scorecard_verdicts``): with the rows above, what
    the scorecard's fidelity column counts."""
    if verdicts is None:
        return
    rows = verdicts.rows[verdicts.rows["kind"].isin(("figure", "case")) & (verdicts.rows["verdict"] != "NOT VALIDATED")]
    if rows.empty:
        return
    page.h3("Judged on this matrix's own cases")
    page.p("The same criteria as the checks, applied to the headline cases above (the verdicts printed under the "
           "reproduced figures); the scorecard's fidelity column counts these rows with the validate rows.", "note")
    table = pd.DataFrame({
        "pair": [f"{c}/{b}" for c, b in zip(rows["creature"], rows["body"])], "check": rows["check"],
        "measured": [_fmt(m) + (f" {u}" if u and isinstance(m, (int, float)) else "") for m, u in
                     zip(rows["measured"], rows["unit"])],
        "reference": [_fmt(v) for v in rows["reference"]], "tolerance": rows["tolerance"],
        "verdict": rows["verdict"], "detail": rows["detail"].fillna("")})
    page.table(table.reset_index(drop=True), [ROW_CLASS.get(v, "") for v in rows["verdict"]])


def _work_precision(page, data: ValidationData) -> None:
    src = data.out_dir
    doc_path = src / "work_precision.json" if src is not None else None
    if doc_path is None or not doc_path.is_file():
        page.p("No work-precision diagrams: run `bench-myriapoda validate --work-precision`.", "note")
        return
    from ..core.errors import InputError
    from .inputs import read_json_file

    doc = read_json_file(doc_path, "work_precision.json")  # depth and size limits, a regular file
    if not (isinstance(doc, dict) and isinstance(doc.get("quantities", {}), dict) and all(
            isinstance(q, dict) and isinstance(q.get("title"), str) and isinstance(q.get("curves"), list)
            and all(isinstance(c, dict) and isinstance(c.get("body"), str) and "reference_kind" in c
                    and all(isinstance(c.get(k), (int, float, type(None))) for k in ("ref_change", "resolution_change"))
                    for c in q["curves"])
            for q in doc.get("quantities", {}).values())):
        raise InputError(str(doc_path), "quantities", "expected the object validate --work-precision writes "
                                                      "(per quantity a title and curves with a body and reference_kind each)")
    page.h3("Work-precision diagrams")
    for name, q in doc.get("quantities", {}).items():
        png = src / f"work_precision_{name}.png"
        if not png.is_file():
            continue
        dest = page.fig_dir / png.name
        shutil.copyfile(png, dest)
        refs = "; ".join(f"{c['body']}: {c['reference_kind']}"
                         + ("" if c.get("ref_change") is None else f" (last dt halving changed it "
                            f"{100 * c['ref_change']:.2g} %)")
                         + ("" if c.get("resolution_change") is None else f", resolution + 1 changes it "
                            f"{100 * c['resolution_change']:.2g} %") for c in q["curves"])
        page.figure(dest, f"{q['title']}: relative error against the reference vs CPU seconds per simulated "
                          f"second, log-log; one curve per body model over dt (open squares: mesh resolution). "
                          f"References: {refs}.")


# --------------------------------------------------------------------------- per-figure verdicts

def case_outcome(fig, row, res) -> tuple[Outcome | None, str]:
    """The verdict of one reproduced-figure case from its own metrics and recording, and which check it mirrors.

    Returns (None, reason) when no check covers the figure.
    """
    from ..harness.recorder import series_from_recording
    from ..validation import miller as M
    from ..validation import paper as P

    m = row["metrics"] if "metrics" in row and isinstance(row["metrics"], dict) else _metrics(row)
    try:  # a run too short for its locomotion metrics: the judges say NOT APPLICABLE with this reason
        too_short = json.loads(row.get("labels_json") or "{}").get("too_short")
    except (TypeError, ValueError, AttributeError):
        too_short = None
    if too_short:
        m = {**m, "too_short": too_short}
    case = res.case(row.case_hash)
    duration = float(case.get("duration", row.get("duration", math.nan)))
    rec = res.recording(row.case_hash)
    scen = fig.scenario
    if scen == "hang" and rec is not None and "leg_states" in rec:
        return P.judge_hang(rec["leg_t"], rec["leg_states"], m.get("hanging_elongation_m", math.nan)), \
            "paper.fig10a-hang"
    if scen in ("walk", "drop-adjust"):
        return P.judge_walk_cycle(m, duration), "paper.fig10d-walk"
    if scen == "control" and rec is not None:
        s = series_from_recording(rec)
        return P.judge_control(s.t, s.head, m.get("heading_error_deg", math.nan)), "paper.control-turn"
    if scen in ("foraging", "fig13-cylinders", "fig12-water-foraging"):
        return P.judge_avoidance(m, min_contacts=1), "paper.avoidance"
    if scen == "fig4-drop":
        strain = m.get("max_strain", math.nan)
        if not (isinstance(strain, (int, float)) and math.isfinite(strain)):  # a body without links (the lattice)
            return (Outcome(NA, None, P.IMPACT_STRAIN_MIN, f">= {P.IMPACT_STRAIN_MIN:g}", "no link strain measured "
                            "on this body (max_strain is not a number): the impact criterion has nothing to judge"),
                    "paper.fig4-drop")
        return (Outcome(PASS if strain >= P.IMPACT_STRAIN_MIN else FAIL, round(strain, 4), P.IMPACT_STRAIN_MIN,
                        f">= {P.IMPACT_STRAIN_MIN:g}", "largest link strain during the drop (recovery: see the "
                        "validate row)"), "paper.fig4-drop")
    if scen == "cliff" and rec is not None:
        from ..core.config import resolve_case
        sc = resolve_case(case["creature"]["name"], case["body"]["name"], "cliff").scenario
        return M.judge_worm_book(series_from_recording(rec).com, sc), "miller.image1-worm-book"
    if scen == "flat" and fig.gait == "lateral-undulation":
        return M.judge_snake_coils(m), "miller.image2-snake-coils"
    if scen == "flat" and fig.gait == "sidewinding":
        return M.judge_sidewinder(m), "miller.image3-sidewinder"
    if scen == "slope" and rec is not None:
        s = series_from_recording(rec)
        period = 1.0 / float(case["gait"]["frequency_hz"])
        slope = float(case["scenario"].get("slope_deg", 30.0))
        return M.judge_caterpillar_slope(s.t, s.com, period, slope, m.get("speed_bl_per_cycle", math.nan)), \
            "miller.image4-caterpillar-slope"
    return None, "no validation check covers this figure (the scene is drawn; nothing is measured against it)"


def _metrics(row) -> dict:
    out = {}
    for k, v in row.items():
        if isinstance(k, str) and k.startswith("metric."):
            out[k[len("metric."):]] = v
    for k in ("speed_bl_per_cycle", "speed_m_per_s", "path_following_error_bl", "travel_angle_deg"):
        if k in row and k not in out:
            out[k] = row[k]
    return {k: (float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else v) for k, v in out.items()}


def figure_verdict(page, fig, row, res, data: ValidationData | None, verdicts=None) -> str:
    """Write the verdict paragraph under a reproduced figure's caption; return the verdict.

    ``verdicts``: the report's ``scorecard_verdicts.PairVerdicts``: the verdict is its row of this case (the
    row the scorecard's fidelity column counts), not judged again here."""
    if verdicts is not None and verdicts.for_case(row.case_hash) is not None:
        v = verdicts.for_case(row.case_hash)
        out = None if v["verdict"] == "NOT VALIDATED" else \
            Outcome(v["verdict"], v["measured"], v["reference"], v["tolerance"], v["detail"] or "", v["unit"] or "")
        check = v["check"] if out is not None else v["detail"]
    else:
        try:
            out, check = case_outcome(fig, row, res)
        except Exception as exc:  # a recording without what the criterion needs: say so, never break the report
            out, check = None, f"could not judge this case: {type(exc).__name__}: {exc}"
    if out is None:
        verdict, text = "NOT VALIDATED", check
    else:
        verdict = out.verdict
        unit = f" {out.unit}" if out.unit and isinstance(out.measured, (int, float)) else ""
        text = (f"this case: measured {_fmt(out.measured)}{unit} against "
                f"{_fmt(out.reference)} ({out.tolerance})" + (f"; {out.detail}" if out.detail else ""))
        if verdict == FAIL:
            text = "DOES NOT REPRODUCE the figure: " + text
        v = data.lookup(check, str(row.body)) if data is not None else None
        if v is not None:
            text += f". validate {check} on {row.body}: {v['verdict']} (measured {_fmt(v['measured'])})"
    color = COLORS.get(verdict, "#666")
    weight = "700" if verdict == FAIL else "600"
    checked = f' data-check="{html.escape(check)}"' if out is not None else ""
    page.html.append(f'<p class="verdict" data-verdict="{html.escape(verdict)}"{checked} style="color:{color};'
                     f'font-weight:{weight}">Verdict: {html.escape(verdict)} -- {html.escape(text)}</p>')
    page.md.append(f"**Verdict: {verdict}** -- {text}\n")
    return verdict
