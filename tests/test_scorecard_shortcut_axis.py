"""The myriapods' error axis (issue 43 item 4): the scorecard's centipede and millipede rows rank by validate's
kinematic-shortcut check (the deviation of the paper's kinematic stance from the dynamic stance, in body
lengths), and the recommendation names that axis.  Constructed matrix rows and recorded check rows, no
simulation."""
from __future__ import annotations

import json
from types import SimpleNamespace

import pandas as pd

from bench_myriapoda.report.scorecard import SHORTCUT_KIND, build_scorecard, shortcut_error
from bench_myriapoda.report.scorecard_verdicts import COLUMNS, PairVerdicts, check_creature

# CPU s per simulated s of each pair's three timed repeats
COSTS = {("centipede", "fem"): [2.0, 2.1, 1.9], ("centipede", "hybrid"): [1.0, 1.02, 0.98],
         ("centipede", "massspring"): [0.30, 0.31, 0.29], ("millipede", "hybrid"): [1.5, 1.52, 1.48],
         ("millipede", "massspring"): [0.5, 0.51, 0.49]}
# recorded validate --quick rows of the kinematic-shortcut checks: head path deviation [BL] (INFO), as the check
# writes them (validation/shortcut.py); none for fem here (a pair whose check was not run: no error axis)
SHORTCUT_ROWS = {("centipede", "hybrid"): 0.012, ("centipede", "massspring"): 0.030,
                 ("millipede", "hybrid"): 0.020, ("millipede", "massspring"): 0.008}


def _matrix() -> SimpleNamespace:
    rows = []
    for (creature, body), costs in COSTS.items():
        case = {"creature": {"legs_per_segment": 2}, "gait": {}}
        for seed, c in enumerate(costs):
            rows.append({"creature": creature, "body": body, "gait": "leg-wave", "scenario": "walk", "duration": 10.0,
                         "seed": seed, "status": "ok", "realtime_factor": 1.0 / c, "steps_per_s": 3000.0 / c,
                         "label": f"{creature}/{body}/leg-wave/walk", "case_json": json.dumps(case),
                         "labels_json": "{}", "dt": 1.0 / 3000, "case_hash": f"{creature}-{body}",
                         "metric.speed_m_per_s": 0.95, "metric.body_length_m": 25.0})
    return SimpleNamespace(df=pd.DataFrame(rows), grid_keys=(), directory="constructed")


def _verdicts(shortcut_rows) -> PairVerdicts:
    rows = []
    for (creature, body), dev in shortcut_rows.items():
        check = f"paper.kinematic-shortcut-{creature}"
        rows.append({"creature": check_creature(check), "body": body, "check": check, "measured": dev,
                     "reference": 0.0, "tolerance": "- (a measure of the shortcut, INFO)", "verdict": "INFO",
                     "detail": "", "unit": "BL", "origin": "recorded", "kind": "validate", "case_hash": None})
    return PairVerdicts(pd.DataFrame(rows, columns=list(COLUMNS)), "recorded")


def test_the_millipedes_shortcut_check_is_the_millipedes():
    assert check_creature("paper.kinematic-shortcut-millipede") == "millipede"
    assert check_creature("paper.kinematic-shortcut-centipede") == "centipede"


def test_centipede_and_millipede_rank_by_the_kinematic_shortcut_check_and_the_recommendation_names_it():
    card = build_scorecard(_matrix(), _verdicts(SHORTCUT_ROWS))
    rows = {(r.creature, r.body): r for r in card.rows}
    for pair, dev in SHORTCUT_ROWS.items():
        assert rows[pair].error == dev and rows[pair].error_kind == SHORTCUT_KIND
    assert rows[("centipede", "fem")].error is None   # no row for fem: no error axis
    cent, milli = card.recommendations["centipede"], card.recommendations["millipede"]
    # centipede: hybrid has less shortcut error, massspring costs less: a trade-off on the two axes, fem unranked
    assert SHORTCUT_KIND in cent and "trade-off" in cent and "fem: no " + SHORTCUT_KIND in cent, cent
    assert "hybrid (1.2 % " + SHORTCUT_KIND in cent and "massspring (3 % " + SHORTCUT_KIND in cent, cent
    # millipede: massspring is both cheaper and closer to its dynamic stance
    assert milli.startswith("millipede: massspring (0.8 % " + SHORTCUT_KIND), milli
    assert "decided by both error and cost" in milli, milli
    # without the check's rows the myriapods are ranked by cost alone, as before
    plain = build_scorecard(_matrix(), _verdicts({}))
    assert all(r.error is None for r in plain.rows)
    assert "decided by cost alone" in plain.recommendations["centipede"]


def test_a_failed_shortcut_check_gives_no_error_axis():
    v = _verdicts({("centipede", "hybrid"): 0.012})
    assert shortcut_error(v, "centipede", "hybrid") == 0.012
    v.rows.loc[0, "verdict"] = "FAIL"
    assert shortcut_error(v, "centipede", "hybrid") is None
    assert shortcut_error(None, "centipede", "hybrid") is None
    assert shortcut_error(v, "millipede", "hybrid") is None


def test_the_main_job_runs_the_kinematic_shortcut_checks_for_the_myriapods_on_the_bodies_with_a_dynamic_stance():
    # the four checks cost about 9 CPU s with a warm JIT (two 4 s walks each; validate --quick on 2 cores); fem has
    # a dynamic stance too now (bodies/fem/pushed_blocks.py; this test asserted it was left out before)
    from bench_myriapoda.report import main_job

    checks = set(main_job.main_job_checks({"centipede", "millipede"}, ("massspring", "fem", "hybrid")))
    for creature in ("centipede", "millipede"):
        name = f"paper.kinematic-shortcut-{creature}"
        assert {(name, "hybrid"), (name, "massspring"), (name, "fem")} <= checks
    worms = main_job.main_job_checks({"worm"}, ("massspring", "hybrid"))
    assert not any(n.startswith("paper.kinematic-shortcut") for n, _ in worms)


def test_the_fem_body_gets_the_error_axis_from_its_own_shortcut_check():
    # fem has a dynamic stance (bodies/fem/pushed_blocks.py), so validate records its check rows too: with them the
    # centipede's three bodies are all ranked on the shortcut error, none left unranked
    rows_in = {**SHORTCUT_ROWS, ("centipede", "fem"): 0.004}
    card = build_scorecard(_matrix(), _verdicts(rows_in))
    rows = {(r.creature, r.body): r for r in card.rows}
    assert rows[("centipede", "fem")].error == 0.004 and rows[("centipede", "fem")].error_kind == SHORTCUT_KIND
    assert shortcut_error(_verdicts(rows_in), "centipede", "fem") == 0.004
    cent = card.recommendations["centipede"]
    assert "fem (0.4 % " + SHORTCUT_KIND in cent and "fem: no " not in cent, cent
