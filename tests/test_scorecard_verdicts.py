"""One source for the report's figure verdicts and the scorecard's fidelity column (issue 40):
``report.scorecard_verdicts.PairVerdicts``.  Constructed tables here; the quick matrix's own report is checked
in test_scorecard.py."""
from __future__ import annotations

import pandas as pd

from bench_myriapoda.report.scorecard import fidelity_group
from bench_myriapoda.report.scorecard_verdicts import COLUMNS, PairVerdicts, validate_rows
from bench_myriapoda.report.validation import ValidationData, figure_verdict


class _Page:
    def __init__(self):
        self.html, self.md = [], []


def _table(rows: list[dict]) -> PairVerdicts:
    full = [{c: r.get(c) for c in COLUMNS} for r in rows]
    return PairVerdicts(pd.DataFrame(full, columns=list(COLUMNS)), "test validate run")


def _figure_row(verdict: str, measured: float) -> dict:
    return {"creature": "centipede", "body": "fem", "check": "paper.fig10d-walk", "measured": measured,
            "reference": 0.5, "tolerance": ">= 0.5", "verdict": verdict, "detail": "10 s walk", "unit": "",
            "origin": "this matrix's case centipede/fem/leg-wave/walk", "kind": "figure", "case_hash": "abc"}


def _verdict_of_figure(pv: PairVerdicts) -> str:
    page = _Page()
    row = pd.Series({"case_hash": "abc", "body": "fem", "scenario": "walk", "gait": "leg-wave"})
    # res and fig are not read: the verdict is the table's row of this case, never judged a second time
    return figure_verdict(page, None, row, None, None, pv), page.html[0]


def test_the_figure_and_the_fidelity_cell_read_the_same_row():
    for verdict, measured in (("PASS", 0.69), ("FAIL", 0.2)):
        pv = _table([_figure_row(verdict, measured),
                     {"creature": None, "body": "fem", "check": "analytic.cantilever", "measured": 0.956,
                      "reference": 1.0, "tolerance": "5 % relative", "verdict": "PASS", "kind": "validate"}])
        shown, html = _verdict_of_figure(pv)
        assert shown == verdict and f'data-verdict="{verdict}"' in html and 'data-check="paper.fig10d-walk"' in html
        g = fidelity_group(pv, "centipede", "fem")
        assert {"check": "paper.fig10d-walk", "verdict": verdict, "kind": "figure"} in g.details["checks"]
        assert g.details["counts"].get(verdict, 0) >= 1
        if verdict == "FAIL":  # the figure's failure is the pair's worst check, with its measured value and reference
            assert g.details["worst_check"] == "paper.fig10d-walk" and g.value == 0.5
            assert "worst: paper.fig10d-walk" in g.text and "measured 0.2, reference 0.5" in g.text, g.text
    # another pair's figure row is not this pair's
    assert fidelity_group(_table([_figure_row("FAIL", 0.2)]), "centipede", "hybrid").text == "no check ran"


def test_a_figure_no_check_covers_is_not_validated_in_both_places():
    row = {**_figure_row("NOT VALIDATED", None), "check": "-", "detail": "no validation check covers this figure"}
    pv = _table([row])
    shown, html = _verdict_of_figure(pv)
    assert shown == "NOT VALIDATED" and "no validation check covers this figure" in html and "data-check" not in html
    g = fidelity_group(pv, "centipede", "fem")
    assert g.value is None and g.text == "no check ran"


def test_a_body_check_is_a_row_of_every_creature_on_that_body_and_a_creature_check_of_its_creature():
    rows = pd.DataFrame([
        {"check": "analytic.free-fall-momentum", "body": "hybrid", "measured": 1e-12, "reference": 0.0,
         "tolerance": "<= 1e-09", "verdict": "PASS"},
        {"check": "miller.image4-caterpillar-arch", "body": "massspring", "measured": "4/4", "reference": "all 4",
         "tolerance": "every described behaviour", "verdict": "PASS"},
        {"check": "cross_body.worm-speed", "body": "all", "measured": 0.1, "reference": 0.0, "verdict": "PASS"}])
    t = validate_rows(ValidationData(rows, "v"), {"hybrid": {"worm", "chain"}, "massspring": {"caterpillar"}})
    assert sorted(zip(t["creature"], t["body"], t["check"])) == [
        ("caterpillar", "massspring", "miller.image4-caterpillar-arch"),
        ("chain", "hybrid", "analytic.free-fall-momentum"), ("worm", "all", "cross_body.worm-speed"),
        ("worm", "hybrid", "analytic.free-fall-momentum")]  # the cross-body row: body "all", no pair's
