"""The verdict rows of every creature x body pair: one table that both the scorecard's fidelity column and
the report's "Reproduced paper figures" read, so that the two cannot disagree.

Two kinds of rows, each with its creature, body, check, measured, reference, tolerance, verdict, detail,
unit and origin:

``validate``     the rows of a ``validate`` run (``report.validation.ValidationData``): a check that concerns
                 one creature (``scorecard.check_creature``) is a row of that creature on its body; a check
                 of the body model itself (``scorecard.BODY_CHECKS``) is a row of every creature on that body;
                 cross-body rows (body ``all``) belong to no pair;
``matrix case``  the verdicts judged on the matrix's own headline cases, with the criteria the checks use
                 (``report.validation.case_outcome`` for a case that reproduces a paper figure, and the wave
                 direction of a walk and eps * Lambda for the rectilinear worm): ``case_hash`` names the case.
                 The figure verdict under a reproduced figure is this row.

Plain Python; :func:`pair_verdicts` builds the table once per report (it reads recordings).
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass

import pandas as pd

COLUMNS = ("creature", "body", "check", "measured", "reference", "tolerance", "verdict", "detail", "unit", "origin",
           "kind", "case_hash")
# kind: "validate" (a validate run's row), "figure" (the verdict of a matrix case that reproduces a paper figure:
# the verdict the report prints under that figure), "case" (another check judged on a matrix case)
NOT_VALIDATED = "NOT VALIDATED"


@dataclass
class PairVerdicts:
    """The verdict table (``COLUMNS``) and where its validate rows came from (``origin``; None: no validate run)."""

    rows: pd.DataFrame
    origin: str | None = None

    def for_pair(self, creature: str, body: str) -> pd.DataFrame:
        r = self.rows
        return r[(r["creature"] == creature) & (r["body"] == body)]

    def for_case(self, case_hash: str) -> pd.Series | None:
        """The matrix-case row of a case (its figure verdict), or None."""
        r = self.rows[(self.rows["case_hash"] == case_hash) & (self.rows["kind"] == "figure")]
        return None if r.empty else r.iloc[0]

    def validate_row(self, check: str, body: str) -> pd.Series | None:
        """The validate run's row of ``check`` on ``body`` (not a matrix-case row), or None."""
        r = self.rows
        m = r[(r["check"] == check) & (r["body"] == body) & (r["kind"] == "validate")]
        return None if m.empty else m.iloc[0]


# validate checks that concern one creature (by name prefix); the others test a body model as such
CHECK_CREATURE = (("analytic.worm", "worm"), ("miller.image1", "worm"), ("cross_body.worm", "worm"),
                  ("analytic.slithering", "snake"), ("miller.image2", "snake"), ("miller.image3", "snake"),
                  ("miller.image4", "caterpillar"), ("paper.fig4", "chain"), ("paper.wave-millipede", "millipede"),
                  ("paper.kinematic-shortcut-millipede", "millipede"),
                  ("paper.", "centipede"), ("cross_body.centipede", "centipede"), ("cross_body.hang", "centipede"),
                  ("throughput.", "centipede"))
BODY_CHECKS = ("analytic.hanging-bar", "analytic.cantilever", "analytic.rigid-rotation",
               "analytic.free-fall-momentum", "analytic.stable-dt", "analytic.damping-pure-mode",
               "analytic.damping-oscillating-mode")


def check_creature(check: str) -> str | None:
    """The creature a validate check concerns (None: a check of the body model itself)."""
    if check in BODY_CHECKS:
        return None
    for prefix, creature in CHECK_CREATURE:
        if check.startswith(prefix):
            return creature
    return None


def row_labels(row) -> dict:
    """A stored row's coded labels (``labels_json``), {} when absent or unreadable."""
    try:
        return json.loads(row.get("labels_json") or "{}")
    except (TypeError, ValueError):
        return {}


def _empty() -> pd.DataFrame:
    return pd.DataFrame({c: pd.Series(dtype=object) for c in COLUMNS})


def validate_rows(vdata, creatures_on: dict[str, set[str]] | None = None) -> pd.DataFrame:
    """The validate rows of ``vdata`` as pair rows.  ``creatures_on``: body -> the creatures a body check is
    a row of (None: the creature column of a body check is None, matched by every creature)."""

    if vdata is None or vdata.rows.empty:
        return _empty()
    out = []
    for _, v in vdata.rows.iterrows():
        body = str(v.get("body"))
        concerns = check_creature(str(v["check"]))
        creatures = [concerns] if concerns is not None else (sorted(creatures_on.get(body, ())) if creatures_on
                                                             is not None else [None])
        for c in creatures:
            out.append({"creature": c, "body": body, "check": v["check"], "measured": v.get("measured"),
                        "reference": v.get("reference"), "tolerance": v.get("tolerance"), "verdict": v["verdict"],
                        "detail": v.get("detail"), "unit": v.get("unit"), "origin": vdata.origin, "kind": "validate",
                        "case_hash": None})
    return pd.DataFrame(out, columns=list(COLUMNS)) if out else _empty()


def _outcome_row(creature, body, check, out, origin, kind, case_hash) -> dict:
    return {"creature": creature, "body": body, "check": check, "measured": out.measured, "reference": out.reference,
            "tolerance": out.tolerance, "verdict": out.verdict, "detail": out.detail, "unit": out.unit,
            "origin": origin, "kind": kind, "case_hash": case_hash}


def case_rows(res) -> pd.DataFrame:
    """The verdicts judged on the matrix's headline cases (module docstring)."""
    from ..validation.core import Outcome
    from .paper_figures import figure_for
    from .sweeps import sweep_mask
    from .validation import case_outcome

    df = res.df
    if df.empty:
        return _empty()
    main = df[~sweep_mask(df, res.grid_keys)]
    out = []
    for _, r in main.iterrows():
        if r["status"] == "error":
            continue
        creature, body = str(r["creature"]), str(r["body"])
        origin = f"this matrix's case {r.get('label', r['case_hash'])}"
        fig = figure_for(str(r["scenario"]), str(r["gait"]))
        if fig is not None:
            rec = res.recording(r.case_hash)
            if rec is not None and len(rec["t"]) >= 2:  # the report draws (and judges) only a recorded case
                try:
                    o, check = case_outcome(fig, r, res)
                except Exception as exc:  # a recording without what the criterion needs: said, never raised
                    o, check = None, f"could not judge this case: {type(exc).__name__}: {exc}"
                if o is None:
                    o, check = Outcome(NOT_VALIDATED, None, None, "-", check), "-"
                out.append(_outcome_row(creature, body, check, o, origin, "figure", r.case_hash))
        for check, o in _extra_outcomes(r, row_labels(r), creature):
            out.append(_outcome_row(creature, body, check, o, origin, "case", r.case_hash))
    return pd.DataFrame(out, columns=list(COLUMNS)) if out else _empty()


def _metrics(row) -> dict:
    out = {}
    for k, v in row.items():
        if isinstance(k, str) and k.startswith("metric."):
            try:
                out[k[len("metric."):]] = float(v)
            except (TypeError, ValueError):
                pass
    return out


def _extra_outcomes(row, labels: dict, creature: str):
    """Checks judged on a headline case beyond its figure: the leg wave's direction of a walk
    (``paper.wave-centipede`` / ``paper.wave-millipede``) and eps * Lambda of the rectilinear worm on flat
    ground (``analytic.worm-eps-lambda``), each with its check's own criterion and tolerance."""
    from ..validation import paper as P
    from ..validation.core import FAIL, Outcome, relative

    scenario, gait = str(row["scenario"]), str(row["gait"])
    m = _metrics(row)
    # a run that blew up reproduces nothing (as validation.core.failed_run)
    bad = Outcome(FAIL, None, None, "-", f"run {row['status']}: {row.get('message', '')}")
    if scenario == "walk" and creature in ("centipede", "millipede"):
        expected = "retrograde" if creature == "centipede" else "direct"
        yield f"paper.wave-{creature}", (P.judge_wave(m, labels, expected) if row["status"] == "ok" else bad)
    if creature == "worm" and gait == "rectilinear" and scenario == "flat":
        from ..validation.analytic import WORM_REL_TOL
        from ..validation.references import worm_displacement_per_cycle
        case = json.loads(row["case_json"]) if isinstance(row.get("case_json"), str) else {}
        g, c = case.get("gait", {}), case.get("creature", {})
        try:
            ref = worm_displacement_per_cycle(float(g["amplitude"]), float(g["wavelength_bl"]) * int(c["segments"])
                                              * float(c["segment_length_m"]))
        except (KeyError, TypeError, ValueError):
            return
        if row["status"] != "ok":
            yield "analytic.worm-eps-lambda", bad
            return
        d = m.get("displacement_per_cycle_m", math.nan)
        if not math.isfinite(d):
            from ..validation.core import not_applicable
            yield "analytic.worm-eps-lambda", not_applicable(labels.get("too_short") or "no displacement per cycle "
                                                             "measured", ref, f"{100 * WORM_REL_TOL:g} % relative")
            return
        yield "analytic.worm-eps-lambda", relative(d, ref, WORM_REL_TOL, "m")


def pair_verdicts(res, vdata) -> PairVerdicts:
    """The verdict table of matrix results ``res`` (``report.matrix_data.MatrixResults``) and validate data
    ``vdata`` (``report.validation.ValidationData`` or None): the validate rows, then the matrix-case rows."""
    creatures_on: dict[str, set[str]] = {}
    if not res.df.empty:
        for c, b in zip(res.df["creature"], res.df["body"]):
            creatures_on.setdefault(str(b), set()).add(str(c))
    parts = [p for p in (validate_rows(vdata, creatures_on), case_rows(res)) if not p.empty]
    rows = pd.concat(parts, ignore_index=True) if parts else _empty()
    return PairVerdicts(rows, vdata.origin if vdata is not None else None)
