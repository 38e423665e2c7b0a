"""Scenario matrices: expansion, bad files, local vs Dask, fault isolation, kill and resume."""
import json
import math
import signal
import sqlite3
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pandas as pd
import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.core.errors import InputError
from bench_myriapoda.harness.executors import run_matrix
from bench_myriapoda.harness.matrix import expand_matrix
from matrix_toml import tiny_worm_matrix

ROOT = Path(__file__).resolve().parents[1]


def write(tmp_path, text, name="m.toml"):
    p = tmp_path / name
    p.write_text(textwrap.dedent(text))
    return p


# --------------------------------------------------------------------------- expansion

def test_expansion_is_the_product_minus_exclusions_duplicates_and_unsupported(tmp_path):
    p = write(tmp_path, """
        [matrix]
        creatures = ["worm", "snake"]
        bodies = ["massspring", "fem"]
        gaits = ["rectilinear", "sidewinding"]
        scenarios = ["flat"]
        seeds = [0, 1]
        duration = 0.05
        [matrix.grid]
        "friction.mu_transverse" = [0.2, 0.5]
        "dt" = [0.001, 0.001]          # a duplicated value: each case resolves twice to the same hash

        [[exclude]]
        creature = "snake"
        body = "fem"
        "friction.mu_transverse" = 0.5

        [[exclude]]
        seed = 1
        gait = ["sidewinding"]
    """)
    exp = expand_matrix(p)
    assert exp.name == "m"
    # worm: only rectilinear (sidewinding unsupported) -> 2 bodies x 2 seeds x 2 mu = 8
    # snake: 2 gaits x 2 bodies x 2 seeds x 2 mu = 16, minus fem & mu 0.5 (2 gaits x 2 seeds = 4),
    #        minus seed 1 & sidewinding among the rest (massspring: 2 mu, fem: mu 0.2 only -> 3) = 9
    axes = [m.axes for m in exp.cases]
    assert len(exp.cases) == 8 + 9
    assert exp.duplicates == len(exp.cases) + exp.excluded  # each case's second dt value
    assert exp.excluded == 4 + 3
    assert not any(a["creature"] == "snake" and a["body"] == "fem" and a["friction.mu_transverse"] == 0.5 for a in axes)
    assert not any(a["seed"] == 1 and a["gait"] == "sidewinding" for a in axes)
    assert len({m.case.case_hash() for m in exp.cases}) == len(exp.cases)
    assert all(m.case.dt == 0.001 and m.case.duration == 0.05 for m in exp.cases)
    assert {m.case.friction.mu_transverse for m in exp.cases} == {0.2, 0.5}
    # the worm's sidewinding is listed once per (creature, body, gait, scenario), never run
    unsup = {(u.creature, u.body, u.gait) for u in exp.unsupported}
    assert unsup == {("worm", "massspring", "sidewinding"), ("worm", "fem", "sidewinding")}
    assert all("unsupported combination" in u.reason for u in exp.unsupported)
    assert not any(a["creature"] == "worm" and a["gait"] == "sidewinding" for a in axes)


def test_body_grid_key_missing_from_a_body_model_is_unsupported_and_blocks_union(tmp_path):
    p = write(tmp_path, """
        [matrix]
        scenarios = ["flat"]
        duration = 0.05
        [[block]]
        creatures = ["worm"]
        bodies = ["massspring", "fem"]
        grid = { "body.resolution" = [2, 3] }
        [[block]]
        creatures = ["chain"]
        bodies = ["hybrid", "massspring"]
    """)
    exp = expand_matrix(p)
    labels = sorted((m.axes["creature"], m.axes["body"], m.axes.get("body.resolution")) for m in exp.cases)
    # since every creature runs on every body (issue 10) the chain runs on massspring too; the worm's
    # body.resolution grid still has no massspring key, so only that pair is unsupported
    assert labels == [("chain", "hybrid", None), ("chain", "massspring", None), ("worm", "fem", 2), ("worm", "fem", 3)]
    assert {(u.creature, u.body) for u in exp.unsupported} == {("worm", "massspring")}
    assert {m.case.body.resolution for m in exp.cases if m.axes["body"] == "fem"} == {2, 3}


def test_the_shipped_matrices_expand_without_unsupported_combinations():
    quick = expand_matrix(ROOT / "scenarios" / "matrix" / "quick.toml")
    # issue 40: every creature on every body model, the 18 pairs `bench-myriapoda list` supports
    assert {(m.axes["creature"], m.axes["body"]) for m in quick.cases} == {
        (c, b) for c in ("worm", "snake", "caterpillar", "centipede", "millipede", "chain")
        for b in ("massspring", "fem", "hybrid")}
    # the report's stability and scaling sections need these sweeps
    assert {"dt", "body.stiffness", "body.youngs_modulus_pa", "creature.segments", "body.resolution"} <= set(
        quick.grid_keys)
    assert {m.axes["body"] for m in quick.cases if "dt" in m.axes} == {"massspring", "fem", "hybrid"}
    miller = expand_matrix(ROOT / "scenarios" / "matrix" / "miller.toml")
    paper = expand_matrix(ROOT / "scenarios" / "matrix" / "paper.toml")
    assert {m.axes["scenario"] for m in paper.cases} == {
        "fig4-drop", "hang", "drop-adjust", "walk", "control",
        "fig1-mesh", "terrain", "fig13-cylinders", "foraging", "fig12-water-foraging"}
    assert len(miller.cases) == 10 and not quick.unsupported and not miller.unsupported and not paper.unsupported


# --------------------------------------------------------------------------- bad files

BASE = """
    [matrix]
    creatures = ["worm"]
    bodies = ["massspring"]
    scenarios = ["flat"]
    duration = 0.05
"""


@pytest.mark.parametrize("extra, key, words", [
    ('colour = "red"\n', "matrix.colour", "unknown key"),
    ('seeds = "0"\n', "matrix.seeds", "list"),
    ('[matrix.grid]\n"friction.mu_transverse" = 0.2\n', "matrix.grid.friction.mu_transverse", "list"),
    ('[matrix.grid]\n"friction.mu_transverse" = ["a"]\n', "matrix.grid.friction.mu_transverse", "expected a number"),
    ('[matrix.grid]\n"friction.mu_sideways" = [0.1]\n', "matrix.grid.friction.mu_sideways", "unknown key"),
    ('[matrix.grid]\n"dt" = [0.0]\n', "matrix.grid.dt", "out of range"),
    ('[matrix.grid]\n"body.resolutoin" = [3]\n', "matrix.grid.body.resolutoin", "unknown key"),
    ('[[exclude]]\ncolour = "red"\n', "exclude[0].colour", "not an axis"),
])
def test_bad_matrix_file_names_the_file_and_the_key(tmp_path, extra, key, words):
    text = textwrap.dedent(BASE)
    if extra.startswith("[") or extra.startswith("[["):
        text += extra
    else:  # a key of [matrix]
        text = text.replace("[matrix]\n", "[matrix]\n" + extra)
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(InputError) as ei:
        expand_matrix(p)
    assert ei.value.source == str(p) and ei.value.key == key
    assert words in ei.value.message


def test_unknown_creature_via_cli_exits_2_and_writes_nothing(tmp_path, capsys):
    p = write(tmp_path, BASE.replace('"worm"', '"wurm"'))
    out = tmp_path / "out"
    assert main(["matrix", str(p), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and str(p) in err and "matrix.creatures" in err and "wurm" in err
    assert not out.exists()
    assert main(["matrix", str(p).replace("bad", "x"), "--workers", "0", "--out", str(out)]) == 2
    assert not out.exists()


# --------------------------------------------------------------------------- executors

def small_cases(tmp_path):
    p = write(tmp_path, tiny_worm_matrix(0.3, {"friction.mu_transverse": [0.2, 0.6],
                                               "scenario.perturbation_m": [0.0, 0.001]}), "small.toml")
    return [m.case for m in expand_matrix(p).cases]


def same(a, b):
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))


def test_local_and_dask_give_identical_metrics(tmp_path):
    pytest.importorskip("dask.distributed")
    cases = small_cases(tmp_path)
    local = run_matrix(cases, "local", workers=2, store_path=tmp_path / "l.sqlite", matrix="small")
    dask = run_matrix(cases, "dask", workers=2, store_path=tmp_path / "d.sqlite", matrix="small", dask_processes=False)
    by_hash = {r.case.case_hash(): r for r in dask}
    assert len(local) == len(dask) == 4
    for r in local:
        d = by_hash[r.case.case_hash()]
        assert r.status == d.status == "ok"
        assert r.metrics.keys() == d.metrics.keys()
        diff = {k: (v, d.metrics[k]) for k, v in r.metrics.items() if not same(v, d.metrics[k])}
        assert not diff  # tolerance 0: the same kernels on the same machine are bit-identical
    # the perturbation seed matters: the perturbed and unperturbed cases differ, so equality above is not vacuous
    speeds = {r.case.scenario.perturbation_m: r.metrics["max_penetration_m"] for r in local
              if r.case.friction.mu_transverse == 0.2}
    assert speeds[0.0] != speeds[0.001]


def test_dask_worker_processes_get_the_compile_lock_and_the_threaded_cluster_leaves_this_process_alone():
    # issue 13: the local executor's workers compile a shared kernel once (compile_lock); Dask worker processes
    # on one machine share numba's cache the same way and must wait for each other too
    pytest.importorskip("dask.distributed")
    import gc

    from bench_myriapoda.harness import executors

    before = executors.worker_process_state()
    client, cluster = executors.dask_client(None, workers=1, processes=True)
    try:
        state = client.run(executors.worker_process_state)
        assert len(state) == 1
        assert [tuple(v) for v in state.values()] == [(True, executors.WORKER_GC_THRESHOLDS)]
        # a restarted worker (a timed-out case's) gets them again
        client.restart_workers(list(state))
        again = client.run(executors.worker_process_state)
        assert [tuple(v) for v in again.values()] == [(True, executors.WORKER_GC_THRESHOLDS)]
    finally:
        client.close()
        cluster.close()
    client, cluster = executors.dask_client(None, workers=1, processes=False)
    try:
        assert list(client.run(executors.worker_process_state).values()) == [before]
    finally:
        client.close()
        cluster.close()
    assert executors.worker_process_state() == before
    assert gc.get_threshold() == before[1]


def test_a_case_that_raises_blows_up_or_outruns_its_timeout_is_recorded_and_the_others_complete(tmp_path, capsys):
    p = write(tmp_path, """
        [matrix]
        name = "faults"
        scenarios = ["flat"]
        duration = 0.05
        [[block]]                        # outruns the timeout: ~500 s of wall time
        creatures = ["worm"]
        bodies = ["fem"]
        duration = 3000.0
        [[block]]                        # ok
        creatures = ["worm"]
        bodies = ["massspring"]
        set = { "creature.segments" = 4 }
        [[block]]                        # blows up: dt far beyond the lattice's stability limit
        creatures = ["worm"]
        bodies = ["massspring"]
        duration = 2.0
        grid = { "dt" = [0.05] }
        [[block]]                        # raises in the body: links wider than the boxes
        creatures = ["chain"]
        bodies = ["hybrid"]
        set = { "body.link_width_m" = 5.0 }
        [[block]]                        # ok, queued behind the others
        creatures = ["worm"]
        bodies = ["massspring"]
        set = { "creature.segments" = 5 }
    """)
    out = tmp_path / "out"
    t0 = time.monotonic()
    code = main(["matrix", str(p), "--workers", "2", "--timeout-per-case", "20", "--out", str(out)])
    wall = time.monotonic() - t0
    assert code == 1  # an error and a timeout among the results
    assert wall < 90  # the timed-out worker was stopped, not waited for (the fem case alone needs ~500 s)
    runs = pd.read_sql("SELECT * FROM runs", sqlite3.connect(out / "results.sqlite"))
    assert len(runs) == 5 and runs.case_hash.is_unique and set(runs.matrix) == {"faults"}
    assert set(runs.command) == {"matrix"}
    st = sorted((r.creature, r.body, r.status) for r in runs.itertuples())
    assert st == [("chain", "hybrid", "error"), ("worm", "fem", "timeout"), ("worm", "massspring", "ok"),
                  ("worm", "massspring", "ok"), ("worm", "massspring", "unstable")]
    msg = dict(zip(runs.status, runs.message))
    assert "ValueError" in msg["error"] and "link cross-section" in msg["error"]
    assert "timeout of 20 s" in msg["timeout"]
    assert msg["unstable"]
    csv = pd.read_csv(out / "results.csv")
    assert len(csv) == 5 and sorted(csv.status) == sorted(runs.status)


# --------------------------------------------------------------------------- kill and resume

def test_killed_matrix_resumes_with_every_case_stored_exactly_once(tmp_path):
    p = write(tmp_path, """
        [matrix]
        name = "resume"
        creatures = ["worm"]
        bodies = ["massspring"]
        scenarios = ["flat"]
        duration = 100.0
        seeds = [0]
        [matrix.grid]
        "scenario.perturbation_m" = [0.0, 0.0001, 0.0002, 0.0003, 0.0004, 0.0005, 0.0006, 0.0007]
    """)
    # each case must outlast the 50 ms poll by a wide margin on any machine: a warm 1.5 s worm case takes
    # ~15 ms here, and CI (warm cache, faster CPU) once stored all 8 between two polls; 100 s takes ~1 s
    out = tmp_path / "out"
    db = out / "results.sqlite"
    cmd = [sys.executable, "-m", "bench_myriapoda.cli", "matrix", str(p), "--workers", "1", "--out", str(out)]
    proc = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    n_before = 0
    deadline = time.monotonic() + 90
    while time.monotonic() < deadline and proc.poll() is None:
        if db.exists():
            try:
                n_before = sqlite3.connect(db).execute("SELECT COUNT(*) FROM runs").fetchone()[0]
            except sqlite3.OperationalError:  # the table is being created
                n_before = 0
            if n_before >= 1:
                break
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    assert 1 <= n_before < 8, "the kill must land mid-run"
    n_killed = sqlite3.connect(db).execute("SELECT COUNT(*) FROM runs").fetchone()[0]
    assert n_killed < 8
    res = subprocess.run(cmd + ["--resume"], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr
    con = sqlite3.connect(db)
    runs = pd.read_sql("SELECT id, case_hash, status FROM runs", con)
    assert len(runs) == 8 and runs.case_hash.is_unique and set(runs.status) == {"ok"}
    # no partial row: every run has its metric rows, and no metric row lacks a run
    per_run = pd.read_sql("SELECT run_id, COUNT(*) AS n FROM metrics GROUP BY run_id", con)
    assert set(per_run.run_id) == set(runs.id) and per_run.n.nunique() == 1 and per_run.n.iloc[0] > 10
    assert "8 of 8 cases stored" in res.stdout


class _Interrupt(Exception):
    pass


@pytest.mark.parametrize("executor", ["local", "dask"])
def test_an_interrupted_cost_scheduled_matrix_resumes_with_every_case_stored_once(tmp_path, executor):
    # issue 31: cases start longest predicted first; an interrupted matrix still resumes with each case once
    if executor == "dask":
        pytest.importorskip("dask.distributed")
    cases = small_cases(tmp_path)
    db = tmp_path / "r.sqlite"
    kw = dict(store_path=db, matrix="small", schedule="cost")
    if executor == "dask":
        kw["dask_processes"] = False

    def stop_after_two(result, done, total):
        if done == 2:
            raise _Interrupt()

    stats: dict = {}
    with pytest.raises(_Interrupt):
        run_matrix(cases, executor, workers=2, on_result=stop_after_two, stats=stats, **kw)
    assert set(stats["predicted_s"]) == {c.case_hash() for c in cases}  # every case had a cost before it ran
    first = pd.read_sql("SELECT case_hash FROM runs", sqlite3.connect(db))
    assert 2 <= len(first) < 4 and first.case_hash.is_unique
    again = run_matrix(cases, executor, workers=2, resume=True, **kw)
    assert {r.case.case_hash() for r in again}.isdisjoint(set(first.case_hash))
    runs = pd.read_sql("SELECT case_hash, status FROM runs", sqlite3.connect(db))
    assert len(runs) == 4 and runs.case_hash.is_unique and set(runs.status) == {"ok"}
    assert set(runs.case_hash) == {c.case_hash() for c in cases}
    assert run_matrix(cases, executor, workers=2, resume=True, **kw) == []  # nothing left to run


def test_the_order_cases_start_in_does_not_change_their_results(tmp_path):
    # longest-first (cost) and file order, and the cases given in reverse: bit-identical metrics per case
    cases = small_cases(tmp_path)
    runs = [run_matrix(cases, "local", workers=2, store_path=tmp_path / "c.sqlite", matrix="small", schedule="cost"),
            run_matrix(cases, "local", workers=2, store_path=tmp_path / "f.sqlite", matrix="small", schedule="file"),
            run_matrix(cases[::-1], "local", workers=1, store_path=tmp_path / "r.sqlite", matrix="small")]
    by_hash = [{r.case.case_hash(): r for r in rs} for rs in runs]
    assert all(len(b) == 4 for b in by_hash)
    for h, r in by_hash[0].items():
        for other in by_hash[1:]:
            o = other[h]
            assert r.status == o.status == "ok" and r.metrics.keys() == o.metrics.keys()
            assert not {k: (v, o.metrics[k]) for k, v in r.metrics.items() if not same(v, o.metrics[k])}


def test_a_matrix_run_ends_with_its_parallel_efficiency_and_critical_path(tmp_path, capsys):
    p = write(tmp_path, tiny_worm_matrix(0.3, {"friction.mu_transverse": [0.2, 0.6]}, name="eff"))
    out = tmp_path / "out"
    assert main(["matrix", str(p), "--workers", "2", "--out", str(out)]) == 0
    line = [ln for ln in capsys.readouterr().out.splitlines() if ln.startswith("parallel efficiency")]
    assert len(line) == 1 and "critical path" in line[0] and "on 2 worker(s)" in line[0]
    sched = json.loads((out / "matrix.json").read_text())["schedule"]
    eff = sched["efficiency"]
    assert eff["cases"] == 2 and eff["workers"] == 2 and 0 < eff["parallel_efficiency"] <= 1
    walls = [c["wall_s"] for c in sched["cases"].values()]
    assert eff["critical_path_s"] == max(walls) and eff["case_wall_sum_s"] == pytest.approx(sum(walls))
    assert eff["matrix_wall_s"] >= max(walls)
    assert all(c["predicted_s"] > 0 for c in sched["cases"].values())
