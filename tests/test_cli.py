"""The command line: JSON output, bad input (exit 2, one line, nothing written), instability, recording."""
import json
import os
import sqlite3
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.harness.progress import ProgressBar

RUN = ["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "1.0"]


def cli(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_run_json_prints_exactly_one_object_with_the_documented_keys(capsys, tmp_path):
    # a 1 s run is too short for its speeds (issue 26: they would be null, with labels.too_short): pinned to
    # metrics.min_steady_cycles = 0, so that the documented keys are checked on a run whose metrics are numbers
    code, out, err = cli(capsys, *RUN, "--json", "--set", "metrics.min_steady_cycles=0",
                         "--store", str(tmp_path / "r.sqlite"))
    assert code == 0
    d = json.loads(out)  # exactly one JSON document: json.loads fails on trailing output
    assert set(d) == {"case", "status", "metrics", "timings"}
    assert d["status"] == "ok"
    assert set(d["timings"]) == {"steps", "steps_per_s", "realtime_factor", "compile_s", "wall_s"}
    for name in ("speed_bl_per_cycle", "speed_m_per_s", "lateral_speed_m_per_s", "displacement_per_cycle_m",
                 "travel_angle_deg", "path_following_error_bl", "slip_ratio", "contact_fraction",
                 "max_penetration_m", "energy_drift_rel", "t_fail_s"):
        assert name in d["metrics"], name
    assert d["case"]["creature"]["name"] == "worm" and d["case"]["gait"]["name"] == "rectilinear"
    assert d["timings"]["steps"] == round(1.0 / d["case"]["dt"])
    assert err == ""  # no progress bar with --json


def test_set_overrides_reach_the_resolved_case(capsys, tmp_path):
    code, out, _ = cli(capsys, *RUN, "--json", "--no-store", "--set", "friction.mu_transverse=0.2",
                       "--set", "friction.model=coulomb", "--set", "gait.frequency_hz=1", "--dt", "0.001", "--seed", "3")
    d = json.loads(out)
    assert d["case"]["friction"]["mu_transverse"] == 0.2
    assert d["case"]["friction"]["model"] == "coulomb"
    assert d["case"]["gait"]["frequency_hz"] == 1.0
    assert d["case"]["dt"] == 0.001 and d["case"]["seed"] == 3


def test_results_store_records_one_row_per_run_readable_with_pandas(capsys, tmp_path):
    db = tmp_path / "results.sqlite"
    for _ in range(2):
        assert cli(capsys, *RUN, "--json", "--store", str(db))[0] == 0
    con = sqlite3.connect(db)
    runs = pd.read_sql("SELECT * FROM runs", con)
    metrics = pd.read_sql("SELECT * FROM metrics", con)
    assert len(runs) == 2 and runs.case_hash.nunique() == 1
    assert set(runs.status) == {"ok"}
    assert runs.cpu_count.iloc[0] == os.cpu_count()
    assert runs.numba_version.notna().all() and runs.python_version.notna().all()
    assert json.loads(runs.case_json.iloc[0])["creature"]["name"] == "worm"
    assert set(metrics.run_id) == set(runs.id)
    assert "speed_bl_per_cycle" in set(metrics.name)


def test_store_transaction_leaves_no_partial_row(tmp_path, monkeypatch):
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.harness import store
    from bench_myriapoda.harness.runner import run_case

    result = run_case(resolve_case("worm", "massspring", "flat", duration=0.5))
    result.metrics["bad"] = object()  # sqlite cannot bind this: the metrics insert fails mid-transaction
    db = tmp_path / "r.sqlite"
    with pytest.raises(Exception):
        store.record_run(db, result)
    con = sqlite3.connect(db)
    assert con.execute("SELECT COUNT(*) FROM runs").fetchone()[0] == 0
    assert con.execute("SELECT COUNT(*) FROM metrics").fetchone()[0] == 0


def test_a_blow_up_is_recorded_as_unstable_not_a_crash(capsys, tmp_path):
    db = tmp_path / "r.sqlite"
    # a time step far beyond the explicit stability limit of the stiff snake lattice
    args = ["run", "--creature", "snake", "--body", "massspring", "--scenario", "flat", "--duration", "2",
            "--dt", "0.01", "--json", "--store", str(db)]
    code, out, _ = cli(capsys, *args)
    d = json.loads(out)
    assert code == 0
    assert d["status"] == "unstable"
    assert 0 < d["metrics"]["t_fail_s"] < 2.0
    assert d["timings"]["steps"] < 200
    assert "message" in d
    assert cli(capsys, *args, "--strict")[0] == 1
    con = sqlite3.connect(db)
    assert [r[0] for r in con.execute("SELECT status FROM runs")] == ["unstable", "unstable"]


def test_record_writes_an_npz_with_the_series(capsys, tmp_path):
    path = tmp_path / "rec.npz"
    assert cli(capsys, *RUN, "--no-store", "--record", str(path))[0] == 0
    with np.load(path) as z:
        assert z["nodes"].shape[0] == z["t"].shape[0] > 10
        assert z["nodes"].shape[1:] == (84, 3)  # 20 segments -> 21 faces of 4 masses
        assert json.loads(str(z["case_json"]))["creature"]["name"] == "worm"


# Bad command lines: (argv, what the message names, what it says is allowed).  Unknown names and combinations:
BAD_NAMES = [
    (["run", "--creature", "dragon", "--body", "massspring", "--scenario", "flat"], "--creature", "worm"),
    (["run", "--creature", "worm", "--body", "jelly", "--scenario", "flat"], "--body", "massspring"),
    (["run", "--creature", "worm", "--body", "massspring", "--scenario", "moon"], "--scenario", "flat"),
    (["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--gait", "hop"], "--gait", "rectilinear"),
    (["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--gait", "sidewinding"],
     "--gait", "unsupported combination"),
]
# bad ``--set KEY=VALUE`` overrides of RUN: (the override, the key named, what is allowed)
BAD_SETS = [("friction.mu_sideways=0.2", "friction.mu_sideways", "mu_transverse"),
            ("planet.gravity=1", "planet.gravity", "friction"),
            ("friction.mu_forward=abc", "friction.mu_forward", "expected a number"),
            ("creature.segments=2.5", "creature.segments", "expected an integer"),
            ("creature.segments=0", "creature.segments", ">= 1"), ("body.stiffness=-1", "body.stiffness", ">= 0"),
            ("friction.model=ice", "friction.model", "miller, coulomb, stick"),
            ("creature.name=snake", "creature.name", "--creature"), ("noequals", "--set", "KEY=VALUE")]
BAD_INPUTS = BAD_NAMES + [(RUN + ["--set", kv], key, allowed) for kv, key, allowed in BAD_SETS] + [
    (RUN + ["--dt", "0"], "--dt", "> 0.0"),
    (RUN + ["--dt", "-0.001"], "--dt", "> 0.0"),
    (RUN + ["--record", "out.txt"], "--record", ".npz"),
    (["run", "--creature", "worm"], "bench-myriapoda", "required"),
    (["frobnicate"], "bench-myriapoda", "invalid choice"),
]


@pytest.mark.parametrize("argv,where,allowed", BAD_INPUTS, ids=[" ".join(a[0][-2:]) for a in BAD_INPUTS])
def test_bad_input_gives_one_line_exit_2_and_writes_nothing(capsys, tmp_path, monkeypatch, argv, where, allowed):
    monkeypatch.chdir(tmp_path)  # the default store would be created here
    code, out, err = cli(capsys, *argv)
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert where in lines[0] and allowed in lines[0], lines[0]
    assert "Traceback" not in err
    assert not (tmp_path / "reports").exists()
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("content,expected", [
    ("[creature\nname = 'x'", "malformed TOML"),
    ("[creature]\nsegments = 'ten'\n[bodies.massspring]\n", "creature.segments: expected an integer"),
    ("[creature]\nsegments = 5\nwings = 2\n[bodies.massspring]\n", "creature.wings: unknown key"),
    ("[creature]\nsegments = 5\ndefault_gait = 'rectilinear'\n[bodies.massspring]\nstiffness = -2\n",
     "bodies.massspring.stiffness"),
    ("[creature]\nsegments = 5\n[skeleton]\n", "skeleton: unknown table"),
    # a gait's own body keys ([gaits.<gait>.bodies.<body>], models/snake.toml's sidewinder) are checked too
    ("[creature]\nsegments = 5\n[gaits.sidewinding.bodies.massspring]\nstiffness = -2\n[bodies.massspring]\n",
     "gaits.sidewinding.bodies.massspring.stiffness"),
    ("[creature]\nsegments = 5\n[gaits.sidewinding.bodies.rubber]\n[bodies.massspring]\n",
     "gaits.sidewinding.bodies.rubber: unknown body model"),
])
def test_bad_creature_file_names_the_file_and_key(capsys, tmp_path, monkeypatch, content, expected):
    monkeypatch.chdir(tmp_path)
    f = tmp_path / "bad.toml"
    f.write_text(content)
    code, out, err = cli(capsys, "run", "--creature", str(f), "--body", "massspring", "--scenario", "flat")
    assert code == 2 and out == ""
    assert str(f) in err and expected in err, err
    assert not (tmp_path / "reports").exists()


def test_unreadable_scenario_file(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    missing = tmp_path / "nope.toml"
    code, _, err = cli(capsys, "run", "--creature", "worm", "--body", "massspring", "--scenario", str(missing))
    assert code == 2 and str(missing) in err and "file not found" in err


def test_list_json_names_everything(capsys):
    code, out, _ = cli(capsys, "list", "--json")
    d = json.loads(out)
    assert code == 0
    assert set(d["creatures"]) >= {"worm", "snake", "caterpillar"}
    assert "massspring" in d["bodies"]
    assert set(d["gaits"]) >= {"rectilinear", "lateral-undulation", "sidewinding", "arching"}
    assert set(d["scenarios"]) >= {"flat", "drop", "cliff", "slope"}
    assert {"creature": "snake", "body": "massspring", "gait": "sidewinding"} in d["supported"]
    assert {"creature": "worm", "body": "massspring", "gait": "sidewinding"} not in d["supported"]


def test_console_script_exit_code_for_bad_input():
    p = subprocess.run([sys.executable, "-m", "bench_myriapoda.cli", "run", "--creature", "dragon", "--body",
                        "massspring", "--scenario", "flat"], capture_output=True, text=True)
    assert p.returncode == 2 and p.stdout == "" and "dragon" in p.stderr


def test_progress_bar_draws_only_when_enabled():
    import io
    s = io.StringIO()
    ProgressBar(enabled=False, stream=s).update(0.5)
    assert s.getvalue() == ""
    bar = ProgressBar(enabled=True, label="worm", stream=s)
    bar.update(1.0)
    bar.close()
    assert "worm" in s.getvalue() and "100%" in s.getvalue()


def test_every_scenario_file_loads_and_runs_a_few_steps():
    # ARCHITECTURE habit 11: examples are tests
    from bench_myriapoda.core.config import resolve_case, scenario_paths
    from bench_myriapoda.harness.runner import run_case
    for name in scenario_paths():
        for creature in ("worm", "snake", "caterpillar"):
            case = resolve_case(creature, "massspring", name, duration=0.05)
            r = run_case(case)
            assert r.status == "ok", (name, creature, r.message)


def test_cliff_worm_slides_off_the_book():
    # Miller Image 1: lands on the slab, crawls to the edge and falls off
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.harness.runner import run_case
    case = resolve_case("worm", "massspring", "cliff")
    r = run_case(case)
    assert r.status == "ok"
    slab_top = case.scenario.slab_height_m
    assert r.series.com[0, 1] > slab_top            # starts above the book
    assert r.series.com[-1, 1] < 0.5 * slab_top     # ends on the floor below it
    assert r.series.com[-1, 0] > case.scenario.slab_edge_x_m


def test_a_store_from_before_later_columns_is_upgraded_on_open(tmp_path, capsys):
    import sqlite3 as sq
    db = tmp_path / "old.sqlite"
    con = sq.connect(db)
    con.executescript("CREATE TABLE runs (id INTEGER PRIMARY KEY AUTOINCREMENT, case_hash TEXT NOT NULL, creature TEXT,"
                      " body TEXT, gait TEXT, scenario TEXT, status TEXT NOT NULL, message TEXT, case_json TEXT NOT NULL,"
                      " metrics_json TEXT NOT NULL, timings_json TEXT NOT NULL, steps INTEGER, steps_per_s REAL,"
                      " realtime_factor REAL, compile_s REAL, wall_s REAL, git_commit TEXT, git_dirty INTEGER,"
                      " machine_json TEXT NOT NULL, cpu_model TEXT, cpu_count INTEGER, python_version TEXT,"
                      " numpy_version TEXT, numba_version TEXT, timestamp TEXT NOT NULL);")
    con.close()
    assert main([*RUN, "--json", "--store", str(db)]) == 0
    cols = {r[1] for r in sq.connect(db).execute("PRAGMA table_info(runs)")}
    assert {"command", "labels_json", "matrix"} <= cols


def test_the_command_line_package_imports_no_numba_before_main_checks_its_environment():
    """``bench_myriapoda.cli`` is a package of one module per subcommand (issue 42); importing it (the console
    script's entry point, ``cli:main``) must not import numba, which reads its NUMBA_* variables once, at import:
    ``main`` checks them first (core.numba_env), then imports the subcommands.  Each subcommand is one module
    with its parser and its command, and the table names every one ``--help`` lists."""
    code = ("import sys, bench_myriapoda.cli as cli; assert 'numba' not in sys.modules, 'numba imported'; "
            "from bench_myriapoda.cli import commands; assert 'numba' in sys.modules; "
            "names = [m.__name__.rsplit('.', 1)[1] for m in commands.SUBCOMMANDS]; "
            "assert all(callable(m.add_parser) for m in commands.SUBCOMMANDS); "
            "print(' '.join(names)); print(cli.build_parser is commands.build_parser)")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    names, same = p.stdout.split("\n")[:2]
    assert names.split() == ["catalogue", "run", "stable_dt", "quick", "matrix", "report", "regress", "scorecard",
                             "keys", "peers", "validate"]
    assert same == "True"
    bad = subprocess.run([sys.executable, "-m", "bench_myriapoda.cli", "list"], capture_output=True, text=True,
                         env={**os.environ, "NUMBA_OPT": "abc"})
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "NUMBA_OPT" in bad.stderr, bad.stderr
