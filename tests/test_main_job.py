"""The main job's second half (issue 40, ``report/main_job.py``): which pairs and checks it covers, and what a
rerun of the same code keeps.  No simulation: the bisection is replaced by a counter where it would run."""
from __future__ import annotations

import json

import pytest

from bench_myriapoda.report import main_job
from bench_myriapoda.harness import stable_dt as S
from bench_myriapoda.harness.matrix import expand_matrix, locate_matrix
from bench_myriapoda.report.scorecard import BODY_CHECKS, check_creature

PAIRS = {(c, b) for c in ("worm", "snake", "caterpillar", "centipede", "millipede", "chain")
         for b in ("massspring", "fem", "hybrid")}


def test_the_quick_matrix_has_one_headline_case_per_supported_pair_at_headline_length():
    exp = expand_matrix(locate_matrix("quick"))
    heads = main_job.headline_cases(exp)
    assert {(c.creature.name, c.body.name) for c in heads} == PAIRS and len(heads) == 18
    for c in heads:
        assert c.duration == (2.0 if c.creature.name == "chain" else 10.0), (c.creature.name, c.body.name)


def test_the_checks_that_apply_give_every_body_a_verdict_and_skip_what_the_matrix_answers():
    checks = main_job.main_job_checks({c for c, _ in PAIRS}, ("massspring", "fem", "hybrid"))
    assert {b for _, b in checks} == {"massspring", "fem", "hybrid"}  # every pair gets at least a body check
    for name, body in checks:
        assert name in BODY_CHECKS or check_creature(name) in {c for c, _ in PAIRS}, name
        assert name not in main_job.ANSWERED_BY_MATRIX and body != "all"
    # a matrix of worms only runs no snake or centipede check
    worms = main_job.main_job_checks({"worm"}, ("massspring",))
    assert all(check_creature(n) in (None, "worm") for n, _ in worms) and ("analytic.worm-eps-lambda",
                                                                          "massspring") in worms


def test_brackets_are_kept_by_case_and_source_hash(tmp_path, monkeypatch):
    from bench_myriapoda.core.config import resolve_case

    cases = [resolve_case("worm", "massspring", "flat", duration=10.0), resolve_case("chain", "fem", "fig4-drop")]
    calls = []

    def fake(case):
        calls.append(case.case_hash())
        return {"case_hash": case.case_hash(), "creature": case.creature.name, "body": case.body.name,
                "stable_dt_max_s": 2 * case.dt, "unstable_dt_min_s": 2.1 * case.dt, "trials": [],
                "timed_cpu_s_per_sim_s": [1.0, 1.1, 0.9]}

    monkeypatch.setattr(S, "bracket_entry", fake)
    monkeypatch.setattr(S, "source_hash", lambda: "code-1")
    first = S.brackets_for_cases(cases, tmp_path)
    assert len(calls) == 2 and set(first) == {c.case_hash() for c in cases}
    assert S.brackets_for_cases(cases, tmp_path) == first and len(calls) == 2  # a rerun bisects nothing
    assert S.brackets_by_case(tmp_path)[cases[0].case_hash()]["stable_dt_max_s"] == pytest.approx(2 * cases[0].dt)
    monkeypatch.setattr(S, "source_hash", lambda: "code-2")  # an edited source file: bisect again
    S.brackets_for_cases(cases[:1], tmp_path)
    assert len(calls) == 3
    kept = json.loads((tmp_path / S.BRACKETS_NAME).read_text())["entries"]
    assert len(kept) == 3 and {e["code"] for e in kept.values()} == {"code-1", "code-2"}


def test_the_bisected_trial_is_the_headline_case_cut_to_one_second():
    from bench_myriapoda.core.config import resolve_case

    case = resolve_case("centipede", "fem", "walk", duration=10.0)
    trial = S.bracket_case(case)
    assert trial.duration == S.BRACKET_DURATION_S == 1.0 and trial.dt == case.dt
    assert trial.creature == case.creature and trial.body == case.body
    assert S.BRACKET_REL_TOL == 0.10 and S.TIMED_REPEATS >= 3


def test_a_rerun_keeps_the_cases_only_of_the_same_code(tmp_path, monkeypatch):
    monkeypatch.setattr(S, "source_hash", lambda: "code-1")
    assert not main_job.same_code_rerun(tmp_path, "quick")
    main_job.write_marker(tmp_path, "quick")
    assert not main_job.same_code_rerun(tmp_path, "quick")  # no results.sqlite: nothing to keep
    (tmp_path / "results.sqlite").write_bytes(b"")
    assert main_job.same_code_rerun(tmp_path, "quick") and not main_job.same_code_rerun(tmp_path, "paper")
    monkeypatch.setattr(S, "source_hash", lambda: "code-2")
    assert not main_job.same_code_rerun(tmp_path, "quick")


def test_a_bisection_that_raises_is_an_entry_with_its_error_never_a_crash_and_not_kept(tmp_path, monkeypatch):
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.report.scorecard import bracket_group

    case = resolve_case("worm", "massspring", "flat", duration=10.0)

    def broken(case):
        raise RuntimeError("a kernel failed")

    monkeypatch.setattr(S, "_bracket_entry", broken)
    got = S.brackets_for_cases([case], tmp_path)[case.case_hash()]
    assert got["error"] == "RuntimeError: a kernel failed" and got["stable_dt_max_s"] is None
    assert S.read_brackets(tmp_path) == {}  # the next run tries again
    g = bracket_group(got, case.dt)
    assert g.value is None and "a kernel failed" in g.reason and "bench-myriapoda stable-dt" in g.reason
