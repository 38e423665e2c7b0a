"""Issue 31: cases scheduled by predicted cost (longest first), the schedule simulator, the efficiency figure."""
import json
import math

import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness import schedule as S
from bench_myriapoda.harness.executors import CompileScheduler, compile_first_order, compile_group


def test_longest_first_orders_by_cost_and_keeps_ties_in_order():
    assert S.longest_first([1.0, 5.0, 3.0, 5.0, 0.5]) == [1, 3, 2, 0, 4]
    assert S.longest_first([]) == []


def test_compile_first_order_with_known_costs_compiles_each_group_on_its_cheapest_case_then_runs_longest_first():
    worm = [resolve_case("worm", "massspring", "flat", duration=d) for d in (1.0, 4.0, 2.0)]
    fem = [resolve_case("worm", "fem", "flat", duration=d) for d in (3.0, 0.5)]
    cases = worm + fem
    costs = [1.0, 4.0, 2.0, 30.0, 5.0]  # the FEM group holds the most work: it starts compiling first
    order = [i for i, _ in compile_first_order(cases, costs)]
    assert order == [4, 0, 3, 1, 2]  # heads: FEM's cheapest, the worm's cheapest; then 30, 4, 2
    # without costs: today's order (first case of each group, then the file order)
    assert [i for i, _ in compile_first_order(cases)] == [0, 3, 1, 2, 4]
    assert compile_group(worm[0]) != compile_group(fem[0])


def test_the_compile_scheduler_hands_out_warm_cases_longest_first_and_a_warmed_group_unblocks_at_once():
    cases = [resolve_case("worm", "massspring", "flat", duration=d) for d in (1.0, 4.0, 2.0, 3.0)]
    s = CompileScheduler(cases, costs=[1.0, 4.0, 2.0, 3.0])
    assert s.next_job()[0] == 0  # the cheapest case compiles the group
    assert s.next_job() is None  # the others wait for its kernels ...
    s.warmed(0)  # ... which are in the cache once its first chunk has run (not when the whole case ends)
    assert [s.next_job()[0] for _ in range(3)] == [1, 3, 2]  # longest first
    assert s.next_job() is None and not s.pending


def test_cost_model_sources_in_order_store_scaled_suite_default():
    worm = resolve_case("worm", "massspring", "flat", duration=2.0)
    key = S.cost_key(worm)
    # (key, steps, wall, compile, stepping time): the third run compiled cold, with kernels compiled lazily after
    # ``compile`` too; its stepping time is still clean
    obs = [S.Observed(key, 1000, 1.5, 0.5, 0.9), S.Observed(key, 1000, 2.5, 0.5, 1.9),
           S.Observed(key, 2000, 31.0, 29.0, 1.8)]
    model = S.CostModel(obs)
    p = model.predict(worm)
    assert p.source == "store"
    assert p.per_step_s == pytest.approx(0.9e-3)  # median of 0.9e-3, 1.9e-3, 0.9e-3
    assert p.fixed_s == pytest.approx(0.1)  # median of what the runs took besides compile and steps
    assert p.seconds == pytest.approx(0.1 + worm.steps * 0.9e-3)
    # without a stepping time: (wall - compile) / steps
    assert S.Observed(key, 1000, 2.5, 0.5).per_step_s == pytest.approx(2e-3)
    # the same case seen before ran fewer steps (it went unstable): predicted to stop there again
    seen = S.CostModel(obs + [S.Observed(key, 10, 0.5, 0.4, 0.01, worm.case_hash())]).predict(worm)
    assert seen.seconds == pytest.approx(seen.fixed_s + 10 * seen.per_step_s)
    # the same creature and body at twice the segments: scaled by size
    bigger = resolve_case("worm", "massspring", "flat", duration=2.0, overrides=[f"creature.segments={2 * key[2]}"])
    q = model.predict(bigger)
    assert q.source == "store-scaled" and q.per_step_s == pytest.approx(1.8e-3)
    # nothing stored: the throughput suite's figure, scaled from its scene's size
    snake = resolve_case("snake", "massspring", "flat", duration=1.0)
    r = S.CostModel(obs, suite={"massspring-snake": 10_000.0}).predict(snake)
    assert r.source == "suite"
    assert r.per_step_s == pytest.approx(1e-4 * S.size_of(S.cost_key(snake)) / 50.0)
    assert S.CostModel().predict(snake).source == "default"
    # a dict (a stored row's case_json) gives the same key as the Case
    assert S.cost_key(json.loads(json.dumps(worm.to_dict()))) == key


def test_predicted_costs_rank_a_long_fem_case_above_a_short_lattice_case_with_no_history():
    model = S.CostModel()
    long_fem = resolve_case("worm", "fem", "flat", duration=4.0)
    short_ms = resolve_case("worm", "massspring", "flat", duration=0.5)
    assert model.predict(long_fem).seconds > 10 * model.predict(short_ms).seconds


def test_observed_runs_read_ok_and_unstable_rows_of_a_store(tmp_path):
    from bench_myriapoda.harness.runner import RunResult
    from bench_myriapoda.harness.store import record_run

    case = resolve_case("worm", "massspring", "flat", duration=1.0)
    db = tmp_path / "s.sqlite"
    for status, wall in (("ok", 2.0), ("unstable", 3.0), ("error", 99.0)):
        record_run(db, RunResult(case, status, {}, {"steps": 100, "steps_per_s": 1.0, "realtime_factor": 1.0,
                                                     "compile_s": 1.0, "wall_s": wall}), command="matrix", matrix="m")
    obs = S.observed_runs([db, tmp_path / "missing.sqlite"])
    assert sorted(o.wall_s for o in obs) == [2.0, 3.0]
    assert S.cost_model_for([db]).predict(case).source == "store"


def test_simulate_is_lpt_list_scheduling():
    # Graham's example: LPT gives 7 on two workers where 6 is possible; file order gives 8 here
    costs = [2.0, 2.0, 2.0, 3.0, 3.0]
    assert S.simulate(costs, 2).wall_s == pytest.approx(7.0)
    assert S.simulate(costs, 2, longest_first_order=False).wall_s == pytest.approx(7.0)
    assert S.simulate([1.0, 1.0, 1.0, 1.0, 4.0], 2, longest_first_order=False).wall_s == pytest.approx(6.0)
    assert S.simulate([1.0, 1.0, 1.0, 1.0, 4.0], 2).wall_s == pytest.approx(4.0)
    one = S.simulate(costs, 1, worker_start_s=0.5, per_case_s=0.1)
    assert one.wall_s == pytest.approx(0.5 + 12.0 + 0.5)
    assert one.busy_s == pytest.approx(12.5) and one.critical_s == pytest.approx(3.1)
    many = S.simulate(costs, 16)
    assert many.wall_s == pytest.approx(3.0) and many.workers == 16
    with pytest.raises(ValueError):
        S.simulate(costs, 0)


def test_efficiency_line_and_correlation():
    e = S.efficiency({"a": 3.0, "b": 1.0, "c": float("nan")}, workers=2, matrix_wall_s=4.0, labels={"a": "worm/fem"})
    assert e.parallel_efficiency == pytest.approx(0.5)
    assert e.critical_s == 3.0 and e.critical_case == "worm/fem" and e.cases == 3
    assert "parallel efficiency 50%" in e.line() and "critical path 3.0 s (worm/fem)" in e.line()
    assert S.correlation([1, 2, 3], [2, 4, 6]) == pytest.approx(1.0)
    assert math.isnan(S.correlation([1, 1], [2, 3]))


def test_write_run_summary_adds_a_schedule_section_and_keeps_the_manifest(tmp_path):
    m = tmp_path / "matrix.json"
    m.write_text(json.dumps({"name": "x", "cases": {"h": {}}}))
    S.write_run_summary(m, {"line": "parallel efficiency 50%"})
    doc = json.loads(m.read_text())
    assert doc["name"] == "x" and doc["cases"] == {"h": {}} and doc["schedule"]["line"].startswith("parallel")


class _Page:
    def __init__(self):
        self.sections, self.paras, self.tables = [], [], []

    def section(self, sid, title):
        self.sections.append(sid)

    def p(self, text, cls=""):
        self.paras.append(text)

    def table(self, df, *a, **k):
        self.tables.append(df)


def test_the_report_section_shows_the_recorded_schedule_or_says_there_is_none(tmp_path):
    from bench_myriapoda.report import schedule_section

    page = _Page()
    schedule_section.section(page, tmp_path)  # no matrix.json
    assert page.sections == ["schedule"] and "No schedule recorded" in page.paras[0] and not page.tables
    eff = S.efficiency({"a": 3.0, "b": 1.0}, workers=2, matrix_wall_s=4.0, labels={"a": "worm/fem"})
    S.write_run_summary(tmp_path / "matrix.json", {"efficiency": eff.to_dict(), "line": eff.line(),
                                                   "predicted_vs_measured_r": 0.9, "cost_sources": {"store": 2}})
    page = _Page()
    schedule_section.section(page, tmp_path)
    assert page.paras == [eff.line()]
    table = dict(zip(page.tables[0]["quantity"], page.tables[0]["value"]))
    assert table["parallel efficiency"] == "0.5" and table["critical case"] == "worm/fem"
    assert table["predicted vs measured case cost (Pearson r)"] == "0.9" and table["cost sources"] == "store: 2"
