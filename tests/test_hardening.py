"""Issue 15: every malformed input gets exit code 2 and one line, nothing is lost, nothing runs away.

One regression test per fault the issue's fuzzer found (grouped by how it showed: a traceback, bad
input caught only at run time, silently accepted, a resource runaway, Dask, temporary directories).
Each bad-input test asserts: exit code 2, exactly one line on stderr naming the flag or file, no
traceback, and nothing written to a fresh directory.  The fuzz test is in test_hardening_fuzz.py.
"""
import json
import os
import shutil
import sqlite3
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.harness.store import connect
from bench_myriapoda.world.world import build_world
from matrix_toml import tiny_worm_matrix

ROOT = Path(__file__).resolve().parents[1]
RUN = ["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "0.05"]
SD = ["stable-dt", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "0.05"]


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    """An empty working directory: the default store (reports/results.sqlite) would land here."""
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    return work


def files(d: Path) -> dict[str, tuple[int, int]]:
    """Every file and directory under ``d`` with its size and mtime (to tell 'nothing written')."""
    out = {}
    for p in sorted(Path(d).rglob("*")):
        st = p.stat()
        out[str(p.relative_to(d))] = (st.st_size if p.is_file() else -1, st.st_mtime_ns)
    return out


def bad(capsys, argv, *words, where: Path | None = None):
    """Run the CLI in-process on ``argv``; assert exit 2, one line naming ``words``, nothing written in ``where``."""
    before = files(where) if where is not None else None
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    assert code == 2, (code, out.err)
    assert out.err.count("\n") == 1 and out.err.startswith("bench-myriapoda: error: "), out.err
    assert "Traceback" not in out.err
    for w in words:
        assert w in out.err, (w, out.err)
    if where is not None:
        assert files(where) == before, "something was written"
    return out.err


def write(d: Path, name: str, text: str | bytes) -> Path:
    p = Path(d) / name
    if isinstance(text, bytes):
        p.write_bytes(text)
    else:
        p.write_text(textwrap.dedent(text))
    return p


def creature_copy(d: Path, name="worm", edit=lambda t: t) -> Path:
    return write(d, f"my{name}.toml", edit((ROOT / "models" / f"{name}.toml").read_text()))


# =========================================================================== tracebacks before

@pytest.mark.parametrize("kind", ["creature", "scenario", "matrix"])
def test_a_non_utf8_byte_in_a_toml_file_is_one_line(kind, fresh, capsys):
    if kind == "creature":
        p = write(fresh, "c.toml", (ROOT / "models" / "worm.toml").read_bytes() + b"\n# caf\xe9\n")
        argv = ["run", "--creature", p, "--body", "massspring", "--scenario", "flat"]
    elif kind == "scenario":
        p = write(fresh, "s.toml", b'[scenario]\ndescription = "caf\xe9"\n')
        argv = ["run", "--creature", "worm", "--body", "massspring", "--scenario", p]
    else:
        p = write(fresh, "m.toml", b'[matrix]\ndescription = "\xff"\ncreatures = ["worm"]\n')
        argv = ["matrix", p]
    bad(capsys, argv, str(p), "not UTF-8", where=fresh)


@pytest.mark.parametrize("text", ["x = " + "[" * 5000 + "]" * 5000, "x = " + "{a = " * 3000 + "1" + "}" * 3000,
                                  "[creature]\n[bodies.massspring]\n" + "a." * 40 + "b = 1\n"])
def test_deeply_nested_toml_is_one_line(text, fresh, capsys):
    p = write(fresh, "c.toml", text)
    bad(capsys, ["run", "--creature", p, "--body", "massspring", "--scenario", "flat"], str(p), where=fresh)


@pytest.mark.parametrize("line", ['bodies = 5', 'gaits = "rectilinear"', 'bodies = [1, 2]'])
def test_top_level_bodies_or_gaits_that_is_not_a_table(line, fresh, capsys):
    p = write(fresh, "c.toml", f'{line}\n[creature]\ndefault_gait = "rectilinear"\n')
    bad(capsys, ["run", "--creature", p, "--body", "massspring", "--scenario", "flat"], str(p),
        line.split()[0], where=fresh)


def _schema_store(p: Path) -> None:
    con = sqlite3.connect(p)
    con.execute("CREATE TABLE runs (id INTEGER, something TEXT)")
    con.commit()
    con.close()


@pytest.mark.parametrize("make,words", [
    (lambda p: p.mkdir(), "not a file"),
    (lambda p: p.write_bytes(b"this is not a database at all" * 10), "not a SQLite"),
    (_schema_store, "lacks columns"),
    (None, "not a directory"),  # unwritable: its folder is a file
])
@pytest.mark.parametrize("cmd", ["run", "stable-dt", "regress"])
def test_store_that_is_a_directory_garbage_another_schema_or_unwritable_is_refused_before_the_run(
        cmd, make, words, fresh, capsys, monkeypatch):
    ran = []
    monkeypatch.setattr("bench_myriapoda.harness.runner.run_case", lambda *a, **k: ran.append(1))
    monkeypatch.setattr("bench_myriapoda.harness.stable_dt.find_stable_dt", lambda *a, **k: ran.append(1))
    monkeypatch.setattr("bench_myriapoda.harness.regress.run_suite", lambda *a, **k: ran.append(1))
    if make is None:
        (fresh / "afile").write_text("x")
        store = fresh / "afile" / "r.sqlite"
    else:
        store = fresh / "r.sqlite"
        make(store)
    argv = {"run": RUN, "stable-dt": SD, "regress": ["regress", "--repeats", "3"]}[cmd]
    bad(capsys, [*argv, "--store", store], "--store", words, where=fresh)
    assert not ran  # refused before anything was simulated or timed


@pytest.mark.parametrize("flag", ["--record", "--animate"])
@pytest.mark.parametrize("how", ["directory", "unwritable"])
def test_record_or_animate_to_a_directory_or_unwritable_path_is_refused_before_the_store_row(
        flag, how, fresh, capsys, monkeypatch):
    ran = []
    monkeypatch.setattr("bench_myriapoda.harness.runner.run_case", lambda *a, **k: ran.append(1))
    suffix = ".npz" if flag == "--record" else ".gif"
    if how == "directory":
        target = fresh / f"out{suffix}"
        target.mkdir()
        words = "is a directory"
    else:
        (fresh / "afile").write_text("x")
        target = fresh / "afile" / f"out{suffix}"
        words = "not a directory"
    bad(capsys, [*RUN, flag, target, "--store", fresh / "r.sqlite"], flag, words, where=fresh)
    assert not ran and not (fresh / "r.sqlite").exists()


# ---------------------------------------------------------------- report on a corrupt matrix directory

@pytest.fixture(scope="module")
def matrix_dir(tmp_path_factory):
    """A real (tiny) matrix output directory: two short worm runs with their recordings."""
    d = tmp_path_factory.mktemp("mx")
    m = write(d, "m.toml", tiny_worm_matrix(0.1, {"friction.mu_transverse": [0.3, 0.5]}, name="tiny"))
    out = d / "out"
    assert main(["matrix", str(m), "--out", str(out), "--workers", "1"]) == 0
    return out


def _copy(matrix_dir, tmp_path) -> Path:
    d = tmp_path / "copy"
    shutil.copytree(matrix_dir, d)
    return d


def _garbage_store(d):
    (d / "results.sqlite").write_bytes(b"\x00garbage" * 100)


def _empty_store(d):
    (d / "results.sqlite").write_bytes(b"")


def _no_runs_table(d):
    (d / "results.sqlite").unlink()
    con = sqlite3.connect(d / "results.sqlite")
    con.execute("CREATE TABLE other (x)")
    con.commit()
    con.close()


def _manifest(doc):
    def f(d):
        (d / "matrix.json").write_text(json.dumps(doc))
    return f


def _bad_row_json(d):
    con = sqlite3.connect(d / "results.sqlite")
    con.execute("UPDATE runs SET metrics_json = '{not json' WHERE id = (SELECT MIN(id) FROM runs)")
    con.commit()
    con.close()


def _bad_npz(d):
    for p in (d / "series").glob("*.npz"):
        p.write_bytes(b"PK\x03\x04 truncated zip")


def _npz_missing_series(d):
    for p in (d / "series").glob("*.npz"):
        np.savez(p, t=np.zeros(3))


@pytest.mark.parametrize("corrupt,words", [
    (_garbage_store, "results.sqlite"), (_empty_store, "empty"), (_no_runs_table, "no runs table"),
    (_manifest([1, 2, 3]), "JSON object"), (_manifest({"name": 5, "cases": {}}), "name"),
    (_manifest({"name": "tiny", "cases": {"abc": 7}}), "cases.abc"),
    (lambda d: (d / "matrix.json").write_text("{oops"), "unreadable matrix manifest"),
    (_bad_row_json, "unreadable row"), (_bad_npz, "unreadable recording"), (_npz_missing_series, "no com"),
])
def test_report_on_a_corrupt_matrix_directory_is_one_line_and_writes_nothing(matrix_dir, tmp_path, capsys,
                                                                              corrupt, words):
    d = _copy(matrix_dir, tmp_path)
    corrupt(d)
    bad(capsys, ["report", d], words, where=d)


def test_report_when_index_html_is_a_directory_swaps_nothing_and_leaves_no_temporary(matrix_dir, tmp_path, capsys):
    d = _copy(matrix_dir, tmp_path)
    (d / "index.html").mkdir()
    bad(capsys, ["report", d], "index.html", "not a file", where=d)
    assert not list(d.glob(".report-*")) and not (d / "figures").exists()


def test_report_writes_into_place_and_cleans_stale_temporaries(matrix_dir, tmp_path, capsys):
    d = _copy(matrix_dir, tmp_path)
    stale = [d / ".report-99999999-abcd", d / ".report-oldstyle", d / ".figures-old-99999999"]
    for s in stale:
        (s / "figures").mkdir(parents=True)
    assert main(["report", str(d)]) == 0
    capsys.readouterr()
    assert (d / "index.html").is_file() and (d / "figures").is_dir()
    assert not any(s.exists() for s in stale)
    assert not list(d.glob(".report-*")) and not list(d.glob(".figures-old-*"))


@pytest.mark.parametrize("content", [b"garbage" * 50, None])
def test_corrupt_regress_store_and_report_history_store(matrix_dir, tmp_path, capsys, content, monkeypatch):
    monkeypatch.setattr("bench_myriapoda.harness.regress.run_suite", lambda *a, **k: 1 / 0)
    store = tmp_path / "h.sqlite"
    if content is None:
        _schema_store(store)
        con = sqlite3.connect(store)
        con.execute("CREATE TABLE regress_history (run_id INTEGER)")
        con.commit()
        con.close()
    else:
        store.write_bytes(content)
    bad(capsys, ["regress", "--store", store], "--store", where=tmp_path)
    d = _copy(matrix_dir, tmp_path / "r")
    bad(capsys, ["report", d, "--history-store", store], "--history-store", where=d)


# ---------------------------------------------------------------- stable-dt, timeouts, scheduler, --out

def test_stable_dt_trial_that_errors_is_recorded_without_a_traceback(fresh, capsys, monkeypatch):
    from bench_myriapoda.harness import stable_dt
    from bench_myriapoda.harness.runner import RunResult

    def failing(case, **kw):
        return RunResult(case, "error", {}, {}, "ValueError: the body could not be built")

    monkeypatch.setattr(stable_dt, "run_case", failing)
    store = fresh / "r.sqlite"
    code = main([*SD, "--store", str(store)])
    out = capsys.readouterr()
    assert code == 1
    assert out.err.count("\n") == 1 and "Traceback" not in out.err and "could not be built" in out.err
    row = sqlite3.connect(store).execute("SELECT command, status, message FROM runs").fetchall()
    assert row == [("stable-dt", "error", "the run at dt = 0.00166667 s failed: ValueError: the body could not be built")]


@pytest.mark.parametrize("value", ["inf", "nan", "-1", "0"])
def test_timeout_per_case_must_be_finite_and_positive(value, fresh, capsys):
    bad(capsys, ["matrix", "quick", "--timeout-per-case", value, "--out", fresh / "o"], "--timeout-per-case",
        where=fresh)


def test_unreachable_scheduler_is_one_line_within_the_connect_timeout(fresh, capsys, monkeypatch):
    pytest.importorskip("dask.distributed")
    from bench_myriapoda.harness import executors

    monkeypatch.setattr(executors, "DASK_CONNECT_TIMEOUT_S", 2.0)
    bad(capsys, ["matrix", "quick", "--executor", "dask", "--scheduler", "tcp://127.0.0.1:9", "--out", fresh / "o"],
        "--scheduler", "cannot reach", where=fresh)


def test_unwritable_matrix_out_is_refused_before_any_case_runs(fresh, capsys, monkeypatch):
    ran = []
    monkeypatch.setattr("bench_myriapoda.harness.executors.run_matrix", lambda *a, **k: ran.append(1))
    (fresh / "afile").write_text("x")
    bad(capsys, ["matrix", "quick", "--out", fresh / "afile" / "sub"], "--out", "not a directory", where=fresh)
    (fresh / "o").mkdir()
    (fresh / "o" / "results.sqlite").write_bytes(b"garbage" * 40)
    bad(capsys, ["matrix", "quick", "--out", fresh / "o"], "--out", "not a SQLite", where=fresh)
    assert not ran


def test_a_closed_stdout_is_no_traceback(tmp_path):
    """The reader of stdout goes away (``bench-myriapoda list | head -0``): no traceback."""
    proc = subprocess.Popen([sys.executable, "-m", "bench_myriapoda.cli", "list"], cwd=ROOT, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    proc.stdout.close()  # nobody reads: the first write that reaches the pipe gets EPIPE
    err = proc.stderr.read()
    proc.wait(timeout=120)
    assert "Traceback" not in err and "Exception ignored" not in err and err.count("\n") <= 1, err


# =========================================================================== caught only at run time before

@pytest.mark.parametrize("table,line,key", [
    ("[bodies.massspring]", 'name = "fem"', "bodies.massspring.name"),
    ("[gaits.rectilinear]", 'name = "leg-wave"', "gaits.rectilinear.name"),
])
def test_a_name_key_inside_a_body_or_gait_table_cannot_override_the_choice(table, line, key, fresh, capsys):
    p = creature_copy(fresh, edit=lambda t: t.replace(table, f"{table}\n{line}", 1))
    assert table in p.read_text()
    bad(capsys, ["run", "--creature", p, "--body", "massspring", "--scenario", "flat"], str(p), key, where=fresh)


@pytest.mark.parametrize("where_,value", [("set", "[0.0, nan]"), ("set", "[inf]"), ("file", "[0.0, nan, 1.0]"),
                                          ("file", "[-inf, 0.0, 0.0]")])
def test_nan_or_inf_inside_a_list_value(where_, value, fresh, capsys):
    if where_ == "set":
        argv = [*RUN, "--set", f"scenario.mesh_translate_m={value}"]
        words = ["--set", "scenario.mesh_translate_m", "finite"]
    else:
        p = write(fresh, "s.toml", f"[scenario]\nmesh_translate_m = {value}\n")
        argv = ["run", "--creature", "worm", "--body", "massspring", "--scenario", p]
        words = [str(p), "scenario.mesh_translate_m", "finite"]
    bad(capsys, argv, *words, where=fresh)


@pytest.mark.parametrize("creature,body,sets,key", [
    ("centipede", "massspring", ["creature.segments=1"], "creature.segments"),
    ("centipede", "fem", ["creature.segments=1"], "creature.segments"),
    ("centipede", "hybrid", ["creature.segments=1"], "creature.segments"),
    ("chain", "hybrid", ["creature.segments=1"], "creature.segments"),
    ("centipede", "massspring", ["creature.mass_kg=0.01"], "creature.mass_kg"),
    ("centipede", "fem", ["creature.mass_kg=0.01", "body.block_density_kg_m3=-1"], "creature.mass_kg"),
    ("chain", "hybrid", ["creature.mass_kg=0.9"], "creature.mass_kg"),  # the free link nodes weigh 1 kg
    ("chain", "hybrid", ["body.link_width_m=5.0"], "body.link_width_m"),
    ("centipede", "massspring", ["body.link_height_m=9.0"], "body.link_height_m"),
])
def test_geometry_a_body_cannot_build_is_refused_before_the_run(creature, body, sets, key, fresh, capsys,
                                                                 monkeypatch):
    ran = []
    monkeypatch.setattr("bench_myriapoda.harness.runner.run_case", lambda *a, **k: ran.append(1))
    argv = ["run", "--creature", creature, "--body", body, "--scenario", "flat", "--duration", "0.05"]
    for s in sets:
        argv += ["--set", s]
    bad(capsys, argv, key, f"{creature}/{body}", where=fresh)
    assert not ran


def test_the_geometry_checks_accept_what_the_bodies_build():
    """At the limit: the chain's free link nodes weigh exactly 1 kg, so 1.01 kg builds (and check_buildable agrees)."""
    from bench_myriapoda.core import registry
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.core.feasibility import check_buildable

    for creature, body in (("chain", "hybrid"), ("centipede", "massspring"), ("centipede", "fem"),
                           ("worm", "fem"), ("worm", "massspring")):
        check_buildable(resolve_case(creature, body, "flat"), "test")
    case = resolve_case("chain", "hybrid", "flat", overrides=["creature.mass_kg=1.01"])
    check_buildable(case, "test")
    registry.BODIES["hybrid"].factory(case, build_world(case))  # builds


def test_obstacles_that_cannot_be_placed_are_refused_before_the_run(fresh, capsys):
    bad(capsys, [*RUN, "--set", "scenario.obstacle_cylinders=3", "--set", "scenario.obstacle_region_m=[-1, 1, -1, 1]",
                 "--set", "scenario.obstacle_clear_radius_m=5"], "scenario.obstacle_clear_radius_m", "no room",
        where=fresh)
    bad(capsys, [*RUN, "--set", "food.count=3", "--set", "food.region_m=[-1, 1, -1, 1]",
                 "--set", "food.clear_radius_m=5"], "food.count", "no room", where=fresh)


@pytest.mark.parametrize("argv,words", [
    (["--duration", "1e308"], ["duration", "steps", "--max-steps"]),
    (["--dt", "1e-13"], ["duration", "steps"]),
    (["--duration", "1e9"], ["duration", "steps"]),
])
def test_no_run_beyond_the_step_budget(argv, words, fresh, capsys):
    bad(capsys, [*RUN[:-2], *argv, "--no-store"], *words, where=fresh)


def test_duration_in_a_scenario_file_beyond_the_budget(fresh, capsys):
    p = write(fresh, "s.toml", "[scenario]\nduration_s = 1e9\n")
    bad(capsys, ["run", "--creature", "worm", "--body", "massspring", "--scenario", p], "steps", where=fresh)


# =========================================================================== silently accepted before

@pytest.mark.parametrize("argv,flag", [
    ([*RUN, "--store", ""], "--store"), ([*RUN, "--record", ""], "--record"),
    ([*RUN, "--export-frames", ""], "--export-frames"), ([*RUN, "--store", "  "], "--store"),
    ([*SD, "--store", ""], "--store"), (["matrix", "quick", "--out", ""], "--out"),
    (["report", "x", "--history-store", ""], "--history-store"), (["regress", "--store", ""], "--store"),
])
def test_empty_path_flags_are_refused(argv, flag, fresh, capsys):
    bad(capsys, argv, flag, "empty path", where=fresh)


@pytest.mark.parametrize("sets,key", [
    (['creature.gaits=["rectilinear", "nonesuch"]'], "creature.gaits"),
    (['creature.gaits=["lateral-undulation"]'], "creature.gaits"),
    (["scenario.control_times_s=[0, 1, 2]"], "scenario.control_"),
    (["scenario.control_speed_m_s=[0.5, 0.5]", "scenario.control_times_s=[0, 1]",
      "scenario.control_turn_rate_deg_s=[1, 2, 3]"], "scenario.control_"),
])
def test_gait_names_and_control_list_lengths_given_through_set(sets, key, fresh, capsys):
    argv = list(RUN)
    for s in sets:
        argv += ["--set", s]
    bad(capsys, argv, "--set", key, where=fresh)


@pytest.mark.parametrize("rule,key", [
    ('creature = 5', "exclude[0].creature"), ('seed = "zero"', "exclude[0].seed"),
    ('"friction.mu_transverse" = "high"', "exclude[0].friction.mu_transverse"),
    ('body = ["fem", 3]', "exclude[0].body"), ('body = []', "exclude[0].body"),
    ('"friction.mu_transverse" = true', "exclude[0].friction.mu_transverse"),
    ('"friction.mu_transverse" = nan', "exclude[0].friction.mu_transverse"),
    ('"friction.mu_transverse" = [0.2, inf]', "exclude[0].friction.mu_transverse"),
])
def test_exclude_values_are_type_checked(rule, key, fresh, capsys):
    p = write(fresh, "m.toml", f"""
        [matrix]
        creatures = ["worm"]
        bodies = ["massspring"]
        scenarios = ["flat"]
        seeds = [0]
        grid = {{ "friction.mu_transverse" = [0.2, 0.5] }}
        [[exclude]]
        {rule}
    """)
    bad(capsys, ["matrix", p, "--out", fresh / "o"], str(p), key, where=fresh)


@pytest.mark.parametrize("value", ["nan", "inf", "0", "-0.1"])
def test_stable_dt_rel_tol_must_be_a_finite_positive_number(value, fresh, capsys):
    bad(capsys, [*SD, "--rel-tol", value], "--rel-tol", where=fresh)


@pytest.mark.parametrize("name", ["/tmp/evil", "../escape", "..", "a/b", "", "-rf", "x" * 101, "tab\there"])
def test_matrix_name_must_be_one_safe_path_component(name, fresh, capsys):
    p = write(fresh, "m.toml", f"""
        [matrix]
        name = {json.dumps(name)}
        creatures = ["worm"]
        bodies = ["massspring"]
        scenarios = ["flat"]
    """)
    bad(capsys, ["matrix", p], str(p), "matrix.name", where=fresh)
    assert not Path("/tmp/evil").exists() or name != "/tmp/evil"


# =========================================================================== resource runaways

# Peak memory of the refusing process itself: VmHWM of /proc/self/status belongs to the process image
# (reset by exec), while getrusage's ru_maxrss survives exec and so would include the forked pytest's size.
REFUSE = """
import resource, sys, time
t0 = time.perf_counter()
from bench_myriapoda.cli import main
code = main(sys.argv[1:])
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
try:
    peak = next(int(l.split()[1]) for l in open("/proc/self/status") if l.startswith("VmHWM:")) / 1024
except (OSError, StopIteration):
    pass
print(code, time.perf_counter() - t0, peak, flush=True)
"""


@pytest.mark.parametrize("creature,body,res", [("worm", "fem", 50), ("centipede", "hybrid", 64)])
def test_an_oversized_mesh_is_refused_by_its_estimate_in_a_small_process(creature, body, res, tmp_path):
    proc = subprocess.run([sys.executable, "-c", REFUSE, "run", "--creature", creature, "--body", body,
                           "--scenario", "flat", "--set", f"body.resolution={res}", "--store", str(tmp_path / "r.sqlite")],
                          cwd=ROOT, capture_output=True, text=True, timeout=300)
    code, wall, maxrss_mb = proc.stdout.split()
    assert int(code) == 2
    assert proc.stderr.count("\n") == 1 and "case too large" in proc.stderr and "body.resolution" in proc.stderr
    assert "tets" in proc.stderr and "GB" in proc.stderr  # the estimate is in the message
    assert float(maxrss_mb) < 500  # the process that refused never came near the mesh's size
    assert not (tmp_path / "r.sqlite").exists()
    print(f"{creature}/{body} resolution {res}: refused in {float(wall):.2f} s at {float(maxrss_mb):.0f} MB peak RSS")


def test_the_estimate_refuses_without_building_any_mesh(fresh, capsys, monkeypatch):
    def no(*a, **k):
        raise AssertionError("a mesh was built")

    for target in ("bench_myriapoda.bodies.fem.mesh.box_grid", "bench_myriapoda.bodies.fem.mesh.chain_grid",
                   "bench_myriapoda.bodies.fem.body.chain_grid", "bench_myriapoda.bodies.hybrid.body.box_grid",
                   "bench_myriapoda.bodies.hybrid.body.build_mesh"):
        monkeypatch.setattr(target, no)
    bad(capsys, ["run", "--creature", "worm", "--body", "fem", "--scenario", "flat", "--set", "body.resolution=50"],
        "case too large", where=fresh)
    bad(capsys, ["run", "--creature", "centipede", "--body", "hybrid", "--scenario", "flat",
                 "--set", "body.resolution=64"], "case too large", where=fresh)


def test_memory_budget_and_max_steps_flags_and_force(fresh, capsys, monkeypatch):
    bad(capsys, [*RUN, "--memory-budget", "0.1"], "case too large", "--memory-budget", where=fresh)
    bad(capsys, [*RUN, "--max-steps", "10"], "case too large", "--max-steps", where=fresh)
    bad(capsys, [*RUN, "--memory-budget", "nan"], "--memory-budget", where=fresh)
    ran = []
    monkeypatch.setattr("bench_myriapoda.harness.runner.run_case", lambda *a, **k: ran.append(1) or 1 / 0)
    with pytest.raises(ZeroDivisionError):  # --force lets it through to the (stubbed) run
        main([*RUN, "--max-steps", "10", "--force", "--no-store"])
    assert ran == [1]


@pytest.mark.parametrize("key", ["scenario.heightfield_count", "scenario.obstacle_cylinders"])
def test_huge_bump_or_cylinder_counts_are_refused_by_a_bound(key, fresh, capsys):
    bad(capsys, [*RUN, "--set", f"{key}=100000"], key, "<= 2000", where=fresh)


# =========================================================================== Dask, resume, temporaries

BLOCKED_WORKER = """
import asyncio, sys
sys.modules["bench_myriapoda"] = None  # this worker cannot import the package
from distributed import Scheduler, Worker

async def main():
    async with Scheduler(host="127.0.0.1", port=0, dashboard_address=None) as s:
        async with Worker(s.address, nthreads=1):
            print(s.address, flush=True)
            await asyncio.sleep(300)

asyncio.run(main())
"""


def test_dask_workers_that_cannot_import_the_package_fail_within_a_timeout(fresh, capsys):
    pytest.importorskip("dask.distributed")
    proc = subprocess.Popen([sys.executable, "-c", BLOCKED_WORKER], stdout=subprocess.PIPE, text=True,
                            stderr=subprocess.DEVNULL, cwd="/")
    try:
        address = proc.stdout.readline().strip()
        assert address.startswith("tcp://")
        t0 = time.monotonic()
        err = bad(capsys, ["matrix", "quick", "--executor", "dask", "--scheduler", address, "--dask-timeout", "10",
                           "--out", fresh / "o"], "--scheduler", where=fresh)
        assert time.monotonic() - t0 < 120  # bounded (10 s probe + connect), not forever
        assert "cannot run cases" in err or "bench_myriapoda" in err
    finally:
        proc.kill()
        proc.wait()


def test_resume_retry_failed_reruns_error_and_timeout_cases(tmp_path, capsys):
    from bench_myriapoda.harness.executors import done_hashes
    from bench_myriapoda.harness.matrix import expand_matrix

    p = write(tmp_path, "m.toml", tiny_worm_matrix(0.05, {"friction.mu_transverse": [0.2, 0.3, 0.4]}, name="retry"))
    out = tmp_path / "out"
    assert main(["matrix", str(p), "--out", str(out), "--workers", "1"]) == 0
    store = out / "results.sqlite"
    hashes = [m.case.case_hash() for m in expand_matrix(p).cases]
    con = sqlite3.connect(store)
    con.execute("UPDATE runs SET status = 'error' WHERE case_hash = ?", (hashes[0],))
    con.execute("UPDATE runs SET status = 'timeout' WHERE case_hash = ?", (hashes[1],))
    con.commit()
    con.close()
    assert done_hashes(store, "retry") == set(hashes)
    assert done_hashes(store, "retry", retry_failed=True) == {hashes[2]}
    capsys.readouterr()
    assert main(["matrix", str(p), "--out", str(out), "--resume"]) == 1  # nothing rerun: still failed
    assert main(["matrix", str(p), "--out", str(out), "--resume", "--retry-failed", "--workers", "1"]) == 0
    rows = sqlite3.connect(store).execute("SELECT case_hash, status FROM runs ORDER BY id").fetchall()
    assert len(rows) == 5 and [h for h, _ in rows[3:]] and {h for h, _ in rows[3:]} == set(hashes[:2])
    assert all(st == "ok" for _, st in rows[3:])
    bad(capsys, ["matrix", str(p), "--out", str(out), "--retry-failed"], "--retry-failed", "--resume")


# =========================================================================== determinism over every body

def _metrics(case):
    from bench_myriapoda.harness.runner import run_case
    r = run_case(case)
    assert r.status in ("ok", "unstable"), r.message
    return r.metrics


@pytest.mark.parametrize("creature,body", [("worm", "massspring"), ("worm", "fem"), ("chain", "hybrid"),
                                           ("centipede", "massspring"), ("centipede", "fem"),
                                           ("centipede", "hybrid")])
def test_same_seed_gives_bitwise_identical_metrics_on_every_body(creature, body):
    from bench_myriapoda.core.config import resolve_case
    case = resolve_case(creature, body, "flat", duration=0.05, seed=7,
                        overrides=["scenario.perturbation_m=0.001"])
    a, b = _metrics(case), _metrics(case)
    assert a.keys() == b.keys()
    same = {k: (np.float64(a[k]).tobytes() == np.float64(b[k]).tobytes()) for k in a if isinstance(a[k], float)}
    assert all(same.values()), [k for k, v in same.items() if not v]
