"""``bench-myriapoda regress``: history, normalization, baselines, a slowed kernel flagged, bad input.

The suite is replaced by a tiny one (the rigid-box kernel, 1,000 steps per repetition, and a
shorter reference run) through the registry, so every regress run here takes well under a
second once the kernels are compiled.  No wall-clock time is asserted.
"""
from __future__ import annotations

import json
import math
import sqlite3
import statistics

import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.harness import throughput_suite as TS
from bench_myriapoda.harness.regress import Baseline, EntryResult, compare, load_history

TINY_STEPS = 1000
SLOWDOWN = 4  # the slowed entry runs its kernel this many times per step
ENTRY = "rigid-tiny"


def cli(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def tiny_entry(name: str = ENTRY, slowdown: int = 1, calls: list | None = None) -> TS.SuiteEntry:
    """The rigid-box kernel with few steps; ``slowdown`` > 1 runs the same kernel that many times per step."""
    def setup():
        if calls is not None:
            calls.append(name)
        step, steps = TS.setup_rigid_boxes(steps=TINY_STEPS)
        if slowdown == 1:
            return step, steps

        def slow(n: int) -> None:
            for _ in range(slowdown):
                step(n)

        return slow, steps

    return TS.SuiteEntry(name, f"rigid boxes, {TINY_STEPS} steps" + (f", {slowdown}x slowed" if slowdown > 1 else ""),
                         setup)


@pytest.fixture
def suite(monkeypatch):
    """A tiny registry in place of the real suite; tests add or replace entries in it."""
    reg = {ENTRY: tiny_entry()}
    monkeypatch.setattr(TS, "SUITE", reg)
    monkeypatch.setattr(TS, "REFERENCE_ITERATIONS", 60_000)
    return reg


def regress(capsys, store, *extra, repeats: int = 3):
    return cli(capsys, "regress", "--store", str(store), "--repeats", str(repeats), *extra)


def history_rows(store) -> int:
    con = sqlite3.connect(store)
    try:
        return con.execute("SELECT COUNT(*) FROM regress_history").fetchone()[0]
    finally:
        con.close()


def test_two_runs_are_stored_and_the_second_compares_against_the_first(suite, capsys, tmp_path):
    store = tmp_path / "results.sqlite"
    code, out, _ = regress(capsys, store, repeats=5)
    assert code == 0
    assert "no baseline yet" in out
    assert ENTRY in out

    code, out, _ = regress(capsys, store, "--json", "--threshold", "0.5", repeats=5)
    d = json.loads(out)  # exactly one JSON object: trailing output would fail here
    assert code == (1 if d["regressions"] else 0) == 0
    assert d["baseline"]["run_id"] == 1 and d["run_id"] == 2 and d["message"] is None
    (e,) = d["entries"]
    assert e["entry"] == ENTRY and e["verdict"] in ("ok", "faster")
    assert e["threshold"] >= 0.5
    assert e["change"] == pytest.approx(e["now"] / e["baseline"] - 1.0)

    hist = load_history(store)
    assert list(hist.run_id) == [1, 2] and set(hist.entry) == {ENTRY}
    assert (hist.repeats == 5).all() and (hist.steps_per_rep == TINY_STEPS).all()
    assert hist.machine_json.nunique() == 1 and json.loads(hist.machine_json[0])["cpu_count"] >= 1
    assert e["baseline"] == pytest.approx(hist.normalized[0], rel=1e-12)
    assert e["now"] == pytest.approx(hist.normalized[1], rel=1e-12)


def test_a_slowed_kernel_is_flagged_as_a_regression(suite, capsys, tmp_path):
    store = tmp_path / "results.sqlite"
    assert regress(capsys, store, repeats=5)[0] == 0
    suite[ENTRY] = tiny_entry(slowdown=SLOWDOWN)  # same name, SLOWDOWN x the work per step
    code, out, _ = regress(capsys, store, "--json", repeats=5)  # default --threshold 0.10
    d = json.loads(out)
    (e,) = d["entries"]
    assert e["verdict"] == "regression" and d["regressions"] == [ENTRY]
    assert code == 1
    assert e["change"] < -0.5  # about 1 / SLOWDOWN - 1 = -75 %
    assert history_rows(store) == 2  # a regressed run is still recorded

    code, out, _ = regress(capsys, store, "--baseline", "1")  # the table names the verdict too
    assert code == 1
    line = next(s for s in out.splitlines() if s.startswith(ENTRY))
    assert line.split()[-1] == "regression"


def test_a_new_entry_has_no_verdict_and_does_not_fail(suite, capsys, tmp_path):
    store = tmp_path / "results.sqlite"
    assert regress(capsys, store)[0] == 0
    suite["rigid-tiny-2"] = tiny_entry("rigid-tiny-2")
    code, out, _ = regress(capsys, store, "--json", "--threshold", "0.5")
    verdicts = {e["entry"]: e["verdict"] for e in json.loads(out)["entries"]}
    assert verdicts["rigid-tiny-2"] == "new" and verdicts[ENTRY] in ("ok", "faster")
    assert code == 0
    code, out, _ = regress(capsys, store, "--json", "--suite", "rigid-tiny-2", "--threshold", "0.5")
    d = json.loads(out)
    assert [e["entry"] for e in d["entries"]] == ["rigid-tiny-2"] and d["baseline"]["run_id"] == 2


def test_bad_input_exits_2_before_anything_is_timed_or_written(suite, capsys, tmp_path):
    calls: list = []
    suite[ENTRY] = tiny_entry(calls=calls)
    store = tmp_path / "results.sqlite"

    code, _, err = regress(capsys, store, "--baseline", "1")  # no history yet: nothing to compare against
    assert code == 2 and "--baseline" in err
    assert not store.exists()  # not even an empty database

    assert regress(capsys, store)[0] == 0
    rows, n_setups = history_rows(store), len(calls)
    for bad in (["--baseline", "999"], ["--baseline", "deadbeefdeadbeef"], ["--baseline", "no-such-ref"],
                ["--repeats", "1"], ["--repeats", "x"], ["--suite", "no-such-entry"], ["--threshold", "1.5"]):
        code, out, err = regress(capsys, store, *bad)
        assert code == 2, bad
        assert out == "" and err.startswith("bench-myriapoda: error: ") and len(err.strip().splitlines()) == 1, bad
    assert history_rows(store) == rows and len(calls) == n_setups


def test_the_normalized_figure_is_the_median_rate_over_the_reference_rate(suite, capsys, tmp_path):
    store = tmp_path / "results.sqlite"
    code, out, _ = regress(capsys, store, "--json")
    assert code == 0
    d = json.loads(out)
    assert d["baseline"] is None and d["message"] == "no baseline yet"
    (e,) = d["entries"]
    con = sqlite3.connect(store)
    row = con.execute("SELECT steps_per_s, spread, reference_ops_per_s, reference_spread, normalized, samples_json,"
                      " run_id, entry FROM regress_history").fetchone()
    con.close()
    sps, spread, ref, ref_spread, norm, samples, run_id, entry = row
    assert (run_id, entry) == (d["run_id"], ENTRY)
    assert norm == pytest.approx(sps / ref, rel=1e-12)
    assert e["now"] == pytest.approx(norm, rel=1e-12) and e["steps_per_s"] == pytest.approx(sps, rel=1e-12)
    s = json.loads(samples)
    assert len(s["steps_per_s"]) == len(s["reference_ops_per_s"]) == 3
    assert sps == pytest.approx(statistics.median(s["steps_per_s"]), rel=1e-12)
    assert ref == pytest.approx(statistics.median(s["reference_ops_per_s"]), rel=1e-12)
    med = statistics.median(s["steps_per_s"])
    assert spread == pytest.approx(statistics.median([abs(v - med) for v in s["steps_per_s"]]) / med, rel=1e-9)
    assert ref_spread >= 0.0 and math.isfinite(ref_spread)


def test_the_baseline_by_commit_and_by_default_on_the_same_machine(suite, capsys, tmp_path):
    store = tmp_path / "results.sqlite"
    assert regress(capsys, store)[0] == 0
    commit = load_history(store).git_commit[0]
    # a later run from another machine: the default baseline skips it
    con = sqlite3.connect(store)
    with con:
        con.execute("INSERT INTO regress_history (run_id, entry, git_commit, git_dirty, machine_json, timestamp,"
                    " steps_per_rep, repeats, steps_per_s, spread, reference_ops_per_s, reference_spread, normalized)"
                    " SELECT 7, entry, 'ffffffffffffffffffffffffffffffffffffffff', 0, '{\"cpu_model\": \"other\"}',"
                    " timestamp, steps_per_rep, repeats, steps_per_s, spread, reference_ops_per_s, reference_spread,"
                    " normalized FROM regress_history WHERE run_id = 1")
    con.close()
    code, out, _ = regress(capsys, store, "--json", "--threshold", "0.5")
    assert json.loads(out)["baseline"]["run_id"] == 1 and json.loads(out)["run_id"] == 8
    code, out, _ = regress(capsys, store, "--json", "--threshold", "0.5", "--baseline", "7")
    assert json.loads(out)["baseline"]["run_id"] == 7
    code, out, _ = regress(capsys, store, "--json", "--threshold", "0.5", "--baseline", "ffffffff")
    assert json.loads(out)["baseline"]["run_id"] == 7
    if commit is None:
        pytest.skip("not a git checkout: no commit recorded")
    code, out, _ = regress(capsys, store, "--json", "--threshold", "0.5", "--baseline", commit[:8])
    assert json.loads(out)["baseline"]["run_id"] == 10  # the latest run at that commit on this machine


def _result(normalized: float, spread: float) -> EntryResult:
    return EntryResult("k", 100, 7, steps_per_s=normalized * 1e8, spread=spread, reference_ops_per_s=1e8,
                       reference_spread=0.0)


def _base(normalized: float, spread: float) -> Baseline:
    return Baseline(1, "abc", False, "t", {"k": {"normalized": normalized, "steps_per_s": normalized * 1e8,
                                                 "spread": spread, "reference_spread": 0.0}})


def test_the_threshold_rises_with_the_measured_noise():
    quiet = compare([_result(0.8, 0.01)], _base(1.0, 0.01), threshold=0.10)[0]
    assert quiet["verdict"] == "regression" and quiet["threshold"] == pytest.approx(0.10)
    noisy = compare([_result(0.8, 0.06)], _base(1.0, 0.06), threshold=0.10)[0]
    assert noisy["threshold"] == pytest.approx(3.0 * math.hypot(0.06, 0.06))
    assert noisy["verdict"] == "ok"  # a 20 % drop within 3 x the combined spread (25 %)
    assert compare([_result(1.3, 0.01)], _base(1.0, 0.01))[0]["verdict"] == "faster"
    assert compare([_result(1.0, 0.01)], None)[0]["verdict"] == "new"


def test_history_frame_and_plot(suite, capsys, tmp_path):
    from bench_myriapoda.report.regress_history import plot_regress_history

    missing = tmp_path / "none.sqlite"
    assert load_history(missing).empty and not missing.exists()
    store = tmp_path / "results.sqlite"
    for _ in range(2):
        regress(capsys, store, "--threshold", "0.5")
    hist = load_history(store)
    assert len(hist) == 2 and {"run_id", "entry", "normalized", "git_commit", "label"} <= set(hist.columns)
    png = plot_regress_history(hist, tmp_path / "fig" / "history.png")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert plot_regress_history(load_history(missing), tmp_path / "empty.png").stat().st_size > 0
