"""Issue 41, the Python API and the results store: the API is typed like the command line, refuses what
the command line refuses (a store that is not this suite's, an output folder that cannot take a matrix, a
case over the step budget) before anything runs or is written, and never loses a result computed before
its store failed.

Every refusal is checked the same way: ``InputError`` (or exit 2) with one line naming the argument, within
``BOUND_S`` (an interval timer in this process; for the command line, its CPU time, with a wall-time guard against
a hang: ``cli``), and nothing written in the test's folder.  The simulations are the cheapest there are: the worm
on the mass-spring body for 0.05 s.
"""
from __future__ import annotations

import contextlib
import json
import os
import pathlib
import resource
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import bench_myriapoda as bm
from bench_myriapoda.core.errors import InputError
from bench_myriapoda.harness import store as store_mod
from bench_myriapoda.harness.store import check_store, connect

ROOT = Path(__file__).resolve().parents[1]
CASE = ("worm", "massspring", "flat")
BOUND_S = 10
HANG_S = 60  # wall-time guard of a command line checked by its CPU time (``cli``)
TRIGGER = "CREATE TRIGGER no_more BEFORE INSERT ON runs BEGIN SELECT RAISE(ABORT, 'refused by a trigger'); END;"
RUN = ["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "0.05"]


# --------------------------------------------------------------------------- helpers

@contextlib.contextmanager
def within(seconds: float = BOUND_S):
    """Fail the block (TimeoutError) if it runs longer than ``seconds``: a refusal must come up front."""
    def expired(signum, frame):
        raise TimeoutError(f"not finished within {seconds} s")

    old = signal.signal(signal.SIGALRM, expired)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def snapshot(folder: Path) -> dict[str, tuple[int, int]]:
    """Every file and folder under ``folder``: (size, mtime_ns); what "nothing written" compares."""
    out = {}
    for dirpath, dirnames, filenames in os.walk(folder):
        for name in dirnames + filenames:
            p = Path(dirpath) / name
            st = p.lstat()
            out[str(p.relative_to(folder))] = (st.st_size if not p.is_dir() else 0, st.st_mtime_ns)
    return out


def refused(call, arg: str, match: str | None = None) -> str:
    """``call()`` raises InputError within BOUND_S, as one line starting with ``arg``; its text."""
    with within():
        with pytest.raises(InputError) as exc:
            call()
    text = str(exc.value)
    assert "\n" not in text and text.startswith(f"{arg}"), text
    if match is not None:
        assert match in text, text
    return text


def no_simulation(monkeypatch):
    """Make any simulation fail the test: a refusal comes before the run."""
    from bench_myriapoda.harness import runner

    def never(*a, **k):
        raise AssertionError("the case ran; it should have been refused before the run")
    monkeypatch.setattr(runner, "run_case", never)


def after_the_run(monkeypatch, action):
    """Call ``action()`` once the simulation has finished, before the result is stored."""
    from bench_myriapoda.harness import runner

    real = runner.run_case

    def run_then(*a, **k):
        result = real(*a, **k)
        action()
        return result
    monkeypatch.setattr(runner, "run_case", run_then)


def cli(args: list, cwd: Path, timeout: float | None = None, env: dict | None = None) -> subprocess.CompletedProcess:
    """The command line in a fresh interpreter, bytes out (a non-UTF-8 name stays as it is).

    Without ``timeout``: the command's CPU time (user + system) must stay within BOUND_S, and its wall time within
    HANG_S, a guard against a hang.  CPU time, because a loaded machine (three test workers on two cores, other
    jobs beside them) stretched the interpreter's start-up alone past 10 s of wall time; a refusal before the run
    costs about 1 CPU s.  With ``timeout`` [s]: a wall-time limit only (a command that runs a simulation, or one
    whose fault was waiting: SQLite's 60 s busy timeout)."""
    code = "import sys; from bench_myriapoda.cli import main; sys.exit(main())"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run([sys.executable, "-c", code, *args], cwd=cwd, capture_output=True,
                       timeout=HANG_S if timeout is None else timeout, env={**os.environ, **(env or {})})
    if timeout is None:  # this worker runs its tests one at a time: the only child reaped in between is this one
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        assert cpu <= BOUND_S, f"{args[:3]}: {cpu:.1f} CPU s, over {BOUND_S} s"
    return p


def one_error_line(p: subprocess.CompletedProcess, code: int, *words: str) -> str:
    err = p.stderr.decode("utf-8", "backslashreplace")
    assert p.returncode == code, err
    assert err.count("\n") == 1 and err.startswith("bench-myriapoda: error: ") and "Traceback" not in err, err
    for w in words:
        assert w in err, err
    return err


def rows(store: Path) -> int:
    con = sqlite3.connect(store)
    try:
        return con.execute("SELECT COUNT(*) FROM runs").fetchone()[0]
    finally:
        con.close()


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    """A working folder and a temporary folder (the second fallback) inside the test's own directory."""
    work = tmp_path / "work"
    work.mkdir()
    (tmp_path / "tmp").mkdir()
    monkeypatch.chdir(work)
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    import tempfile
    monkeypatch.setattr(tempfile, "tempdir", None)  # re-read TMPDIR
    return work


@contextlib.contextmanager
def tmpfs(where: Path, size: str = "4m"):
    """A small tmpfs at ``where`` (root only; the test is skipped where it cannot be mounted)."""
    where.mkdir()
    if os.geteuid() != 0 or subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(where)],
                                           capture_output=True).returncode != 0:
        pytest.skip("needs root to mount a tmpfs")
    try:
        yield where
    finally:
        subprocess.run(["umount", "-l", str(where)], capture_output=True)


def read_only(mount: Path) -> None:
    """Remount ``mount`` read-only: a real read-only file system, which root cannot write either."""
    subprocess.run(["mount", "-o", "remount,ro", str(mount)], check=True, capture_output=True)


# --------------------------------------------------------------------------- the API is typed like the CLI

@pytest.mark.parametrize("args, kwargs, arg", [
    ((123, "massspring", "flat"), {}, "creature"),
    ((None, "massspring", "flat"), {}, "creature"),
    (("worm", ["massspring"], "flat"), {}, "body"),
    (("worm", "massspring", 5), {}, "scenario"),
    (CASE, {"gait": ["rectilinear"]}, "gait"),
    (CASE, {"gait": 5}, "gait"),
    (CASE, {"set": "abc"}, "set"),
    (CASE, {"set": 5}, "set"),
    (CASE, {"duration": "1"}, "duration"),
    (CASE, {"dt": [0.001]}, "dt"),
    (CASE, {"seed": 1.5}, "seed"),
    (CASE, {"seed": True}, "seed"),
    (CASE, {"keep_nodes": "yes"}, "keep_nodes"),
    (CASE, {"store": 5}, "store"),
    (CASE, {"max_steps": "1e9"}, "max_steps"),
    (CASE, {"duration": 1e300}, "run: duration"),  # the command line's step budget
    (CASE, {"duration": 20.0, "max_steps": 100}, "run: duration"),
])
def test_run_refuses_a_wrong_type_naming_the_argument_before_anything_runs(args, kwargs, arg, fresh, monkeypatch):
    no_simulation(monkeypatch)
    before = snapshot(fresh)
    refused(lambda: bm.run(*args, **kwargs), arg)
    assert snapshot(fresh) == before


def test_the_step_budget_names_the_api_keywords():
    text = refused(lambda: bm.run(*CASE, duration=1e300), "run: duration")
    assert "max_steps=" in text and "force=True" in text and "--" not in text


def test_a_path_numpy_scalars_and_a_TOML_suffix_are_valid_input(fresh):
    worm = ROOT / "models" / "worm.toml"
    assert bm.resolve(pathlib.Path(worm), "massspring", pathlib.Path(ROOT / "scenarios" / "flat.toml")).creature.name \
        == "worm"
    case = bm.resolve(*CASE, duration=np.float32(0.5), dt=np.float64(0.001), seed=np.int64(3))
    assert case.seed == 3 and isinstance(case.seed, int) and case.duration == float(np.float32(0.5))
    (fresh / "W.TOML").write_bytes(worm.read_bytes())
    assert bm.resolve("W.TOML", "massspring", "flat").case_hash() == bm.resolve(*CASE).case_hash()
    r = bm.run(pathlib.Path(worm), "massspring", "flat", duration=np.float32(0.05), seed=np.int64(1))
    assert r.status in ("ok", "unstable") and r.timings["steps"] > 0


@pytest.mark.parametrize("kwargs, arg", [
    ({"workers": "2"}, "workers"),
    ({"workers": 1.5}, "workers"),
    ({"workers": 0}, "workers"),
    ({"workers": True}, "workers"),
    ({"timeout_per_case": float("inf")}, "timeout_per_case"),
    ({"timeout_per_case": float("nan")}, "timeout_per_case"),
    ({"timeout_per_case": "10"}, "timeout_per_case"),
    ({"out": "/"}, "out"),
    ({"out": ""}, "out"),
    ({"out": 5}, "out"),
    ({"executor": 5}, "executor"),
    ({"resume": "no"}, "resume"),
])
def test_run_matrix_refuses_bad_arguments_before_writing(kwargs, arg, fresh):
    before = snapshot(fresh)
    root_files = {n: os.path.lexists(f"/{n}") for n in ("matrix.json", "results.sqlite", "series")}
    refused(lambda: bm.run_matrix("quick", **kwargs), arg)
    assert snapshot(fresh) == before
    assert {n: os.path.lexists(f"/{n}") for n in root_files} == root_files  # nothing written into /


def test_run_matrix_refuses_a_garbage_store_in_out_and_leaves_it_as_it_was(fresh):
    out = fresh / "m"
    out.mkdir()
    (out / "results.sqlite").write_bytes(b"not a database at all" * 10)
    before = snapshot(fresh)
    refused(lambda: bm.run_matrix("quick", out=out), "out", "not a SQLite database")
    assert snapshot(fresh) == before


def test_run_matrix_refuses_a_read_only_file_system(fresh, tmp_path):
    with tmpfs(tmp_path / "ro") as disk:
        read_only(disk)
        refused(lambda: bm.run_matrix("quick", out=disk / "m"), "out", "not writable")
        assert not os.listdir(disk)


@pytest.mark.parametrize("manifest, words", [
    ("[1, 2]", "expected a JSON object, got list"),
    ("null", "expected a JSON object, got NoneType"),
    ("[" * 100_000 + "]" * 100_000, "nested too deeply"),
    ('{"cases": "abc"}', "cases"),
    ('{"cases": {"h": 5}}', "cases.h"),
    ('{"cases": {}, "grid_keys": [1]}', "grid_keys"),
    ("{", "not JSON"),
])
def test_load_results_refuses_a_corrupt_manifest_in_one_line(manifest, words, fresh):
    d = fresh / "m"
    d.mkdir()
    (d / "matrix.json").write_text(manifest)
    connect(d / "results.sqlite").close()
    refused(lambda: bm.load_results(d), str(d / "matrix.json"), words)


@pytest.mark.parametrize("column, value, words", [
    ("case_json", "{", "case_json"),
    ("case_json", "[1]", "expected a JSON object"),
    ("case_json", '{"creature": {"name": "worm"}}', "no body table"),
    ("metrics_json", "[" * 100_000 + "]" * 100_000, "nested too deeply"),
    ("labels_json", "5", "labels_json"),
])
def test_load_results_refuses_a_corrupt_row_naming_the_run(column, value, words, fresh):
    store = fresh / "r.sqlite"
    r = bm.run(*CASE, duration=0.05, store=store)
    con = sqlite3.connect(store)
    with con:
        con.execute(f"UPDATE runs SET {column} = ? WHERE id = ?", (value, r.run_id))
    con.close()
    refused(lambda: bm.load_results(store), str(store), words)
    assert f"run {r.run_id}" in refused(lambda: bm.load_results(store), str(store))


# --------------------------------------------------------------------------- stores refused before the run

def foreign_with_trigger(p: Path) -> None:
    con = sqlite3.connect(p)
    con.executescript("CREATE TABLE users (name TEXT); CREATE TABLE log (t TEXT);"
                      "CREATE TRIGGER t AFTER INSERT ON users BEGIN INSERT INTO log VALUES ('x'); END;")
    con.close()


@pytest.mark.parametrize("kind", ["garbage", "foreign-with-trigger", "empty-string", "directory", "dev-full",
                                  "number"])
def test_bm_run_checks_its_store_before_the_run_and_changes_nothing(kind, fresh, monkeypatch):
    p = fresh / "s.sqlite"
    if kind == "garbage":
        p.write_bytes(b"\x00garbage" * 64)
        store = p
    elif kind == "foreign-with-trigger":
        foreign_with_trigger(p)
        store = p
    elif kind == "directory":
        p.mkdir()
        store = p
    else:
        store = {"empty-string": "", "dev-full": "/dev/full", "number": 5}[kind]
    no_simulation(monkeypatch)
    before = snapshot(fresh)
    refused(lambda: bm.run(*CASE, duration=0.05, store=store), "store")
    assert snapshot(fresh) == before
    if kind == "foreign-with-trigger":  # no table of the suite's was added
        con = sqlite3.connect(p)
        assert {n for (n,) in con.execute("SELECT name FROM sqlite_master")} == {"users", "log", "t"}
        con.close()


def test_bm_run_refuses_a_store_on_a_read_only_file_system(fresh, tmp_path, monkeypatch):
    with tmpfs(tmp_path / "ro") as disk:
        connect(disk / "r.sqlite").close()
        read_only(disk)
        no_simulation(monkeypatch)
        refused(lambda: bm.run(*CASE, duration=0.05, store=disk / "r.sqlite"), "store", "not writable")


def damaged_store(p: Path) -> None:
    """A store whose runs table's root page is overwritten: SQLite opens it and reads its schema, only
    ``PRAGMA quick_check`` (or a query of runs) finds the damage."""
    r = bm.run(*CASE, duration=0.05, store=p)
    assert r.run_id == 1
    con = sqlite3.connect(p)
    page = con.execute("PRAGMA page_size").fetchone()[0]
    root = con.execute("SELECT rootpage FROM sqlite_master WHERE name = 'runs'").fetchone()[0]
    con.close()
    with open(p, "r+b") as fh:
        fh.seek((root - 1) * page + 8)
        fh.write(bytes(range(256)) * 4)


def test_a_store_with_damaged_pages_fails_check_store_and_every_writer_refuses_it(fresh):
    store = fresh / "r.sqlite"
    damaged_store(store)
    text = refused(lambda: check_store(store, "--store"), "--store")
    assert "damaged" in text or "malformed" in text, text
    before = store.read_bytes()
    refused(lambda: bm.run(*CASE, duration=0.05, store=store), "store")
    one_error_line(cli([*RUN, "--store", str(store)], fresh), 2, "--store")
    one_error_line(cli(["validate", "--quick", "--check", "analytic.rigid-rotation", "--body", "massspring", "--store",
                        str(store), "--out", str(fresh / "v")], fresh), 2, "--store")
    one_error_line(cli(["regress", "--store", str(store)], fresh), 2, "--store")
    assert store.read_bytes() == before and not (fresh / "v").exists()


@contextlib.contextmanager
def another_writer(store: Path, begin: str):
    """Another program holding ``store``'s lock (``BEGIN IMMEDIATE`` or ``BEGIN EXCLUSIVE``) until the block ends.

    A separate process: POSIX locks belong to a process, and any close of the file in this one (the header
    check reads the file) would drop a lock held by a connection of this process."""
    code = ("import sqlite3, sys; con = sqlite3.connect(sys.argv[1], isolation_level=None); "
            f"con.execute({begin!r}); print('held', flush=True); sys.stdin.read()")
    p = subprocess.Popen([sys.executable, "-c", code, str(store)], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    try:
        assert p.stdout.readline().strip() == b"held"
        yield
    finally:
        p.stdin.close()
        p.wait(timeout=30)


def test_a_store_locked_by_another_writer_is_refused_within_seconds(fresh, monkeypatch):
    store = fresh / "r.sqlite"
    connect(store).close()
    no_simulation(monkeypatch)
    with another_writer(store, "BEGIN IMMEDIATE"):  # for longer than any insert takes
        refused(lambda: bm.run(*CASE, duration=0.05, store=store), "store", "locked")
        # wall time: the fault was waiting out SQLite's 60 s busy timeout (no CPU), so the bound is on waiting
        one_error_line(cli([*RUN, "--store", str(store)], fresh, timeout=30), 2, "--store", "locked")
    with another_writer(store, "BEGIN EXCLUSIVE"):  # a writer committing: even reading waits; no check hangs
        refused(lambda: check_store(store, "--store", write=False), "--store", "locked")
    assert rows(store) == 0


def test_checking_a_store_keeps_a_lock_this_process_holds_on_it(fresh):
    """A notebook's own connection in a write transaction on the store, then a check of that store: the
    lock must survive (a plain open and close of the file drops every POSIX lock of the process on it, and
    another program could then write into the transaction's pages)."""
    store = fresh / "r.sqlite"
    connect(store).close()
    mine = sqlite3.connect(store, isolation_level=None)
    mine.execute("BEGIN IMMEDIATE")
    try:
        assert check_store(store, "--store", write=False) == store
        refused(lambda: check_store(store, "--store"), "--store", "locked")  # a writer would wait for it
        code = ("import sqlite3, sys; c = sqlite3.connect(sys.argv[1], timeout=0.2, isolation_level=None)\n"
                "try:\n    c.execute('BEGIN IMMEDIATE'); print('got the lock')\n"
                "except sqlite3.OperationalError as e:\n    print(e)")
        other = subprocess.run([sys.executable, "-c", code, str(store)], capture_output=True, text=True, timeout=60)
        assert other.stdout.strip() == "database is locked", other.stdout
    finally:
        mine.close()


def test_a_store_with_a_hot_journal_is_recovered_and_used(fresh):
    """A writer killed mid-transaction leaves a hot journal; SQLite rolls it back on the next read-write
    open and the store is as it was: valid input, for the command line and the API."""
    store = fresh / "r.sqlite"
    bm.run(*CASE, duration=0.05, store=store)
    code = ("import sqlite3, os, sys; con = sqlite3.connect(sys.argv[1], isolation_level=None); "
            "con.execute('PRAGMA cache_size=1'); con.execute('BEGIN'); "
            "[con.execute('INSERT INTO metrics VALUES (?, ?, 1.0)', (i + 10, 'x' * 500)) for i in range(2000)]; "
            "os._exit(0)")
    subprocess.run([sys.executable, "-c", code, str(store)], check=True, timeout=60)
    journal = Path(str(store) + "-journal")
    assert journal.is_file() and journal.stat().st_size > 0, "no hot journal was left"
    assert check_store(store, "--store") == store
    p = cli([*RUN, "--store", str(store), "--json"], fresh, timeout=300)
    assert p.returncode == 0, p.stderr.decode()
    r = bm.run(*CASE, duration=0.05, store=store)
    assert r.run_id == 3 and rows(store) == 3 and len(bm.load_results(store)) == 3


# --------------------------------------------------------------------------- results kept after the run

def kept_file(text: str) -> Path:
    return Path(text.rsplit("the result is kept in ", 1)[1].strip())


@pytest.mark.parametrize("how", ["trigger", "disk-full", "directory"])
def test_bm_run_keeps_the_result_when_its_store_fails_after_the_run(how, fresh, monkeypatch):
    store = fresh / "r.sqlite"
    connect(store).close()
    if how == "trigger":
        def fail():
            con = sqlite3.connect(store)
            con.executescript(TRIGGER)
            con.close()
        after_the_run(monkeypatch, fail)
    elif how == "disk-full":  # what a full disk makes SQLite raise (a real one: the tmpfs test below)
        def disk_full(*a, **k):
            raise sqlite3.OperationalError("database or disk is full")
        monkeypatch.setattr(store_mod, "connect", disk_full)
    else:
        def replace():
            store.unlink()
            store.mkdir()
        after_the_run(monkeypatch, replace)
    with pytest.warns(RuntimeWarning, match="could not store the run"):
        r = bm.run(*CASE, duration=0.05, store=store)
    assert r.run_id is None and r.status in ("ok", "unstable") and r.timings["steps"] > 0  # in memory
    assert r.series is not None and len(r.series) > 0
    kept = kept_file(r.unstored)
    assert kept.parent == fresh / "unsaved"
    doc = json.loads(kept.read_text())
    assert doc["result"] == json.loads(json.dumps(r.to_dict())) and doc["store"] == str(store)


@pytest.mark.parametrize("entry", ["cli", "api"])
@pytest.mark.parametrize("how", ["read-only", "disk-full"])
def test_a_real_read_only_or_full_file_system_after_the_run_keeps_the_result(how, entry, fresh, tmp_path,
                                                                               monkeypatch, capsys):
    """The store on a tmpfs that is remounted read-only, or filled, while the case runs: the insert fails,
    ``unsaved/`` beside the store cannot be written either, the result goes to $TMPDIR."""
    from bench_myriapoda.cli import main

    with tmpfs(tmp_path / "disk", "2m") as disk:
        store = disk / "r.sqlite"
        connect(store).close()

        def fill():
            with open(disk / "filler", "wb") as fh:
                with contextlib.suppress(OSError):
                    while True:
                        fh.write(b"\0" * 65536)
                        fh.flush()
        after_the_run(monkeypatch, (lambda: read_only(disk)) if how == "read-only" else fill)
        if entry == "cli":
            assert main([*RUN, "--store", str(store), "--json"]) == 1
            out = capsys.readouterr()
            printed = json.loads(out.out)
            assert out.err.count("\n") == 1 and "could not store the run" in out.err, out.err
            kept = kept_file(out.err)
        else:
            with pytest.warns(RuntimeWarning):
                r = bm.run(*CASE, duration=0.05, store=store)
            printed = json.loads(json.dumps(r.to_dict()))
            kept = kept_file(r.unstored)
        assert kept.parent == tmp_path / "tmp" / "bench-myriapoda-unsaved"
        assert json.loads(kept.read_text())["result"] == printed and printed["timings"]["steps"] > 0
        assert rows(store) == 0


def test_a_scenario_file_whose_name_is_not_utf8_is_run_stored_and_printed(fresh):
    name = os.fsdecode(b"\xfe.toml")
    text = (ROOT / "scenarios" / "flat.toml").read_text()
    (fresh / name).write_text("\n".join(ln for ln in text.splitlines() if not ln.startswith("name")))  # named by file
    p = cli(["run", "--creature", "worm", "--body", "massspring", "--scenario", name, "--duration", "0.05",
             "--store", "r.sqlite", "--json"], fresh, timeout=300)
    assert p.returncode == 0, p.stderr.decode()
    assert json.loads(p.stdout)["timings"]["steps"] > 0
    con = sqlite3.connect(fresh / "r.sqlite")
    assert con.execute("SELECT scenario FROM runs").fetchall() == [("\\xfe",)]  # the byte, escaped
    con.close()
    assert bm.load_results(fresh / "r.sqlite").scenario.tolist() == [os.fsdecode(b"\xfe")]  # from case_json
    r = bm.run("worm", "massspring", name, duration=0.05, store=fresh / "r.sqlite")
    assert r.run_id == 2 and r.unstored is None


def test_a_store_whose_name_is_not_utf8_is_stored_and_named_on_stdout(fresh):
    name = os.fsdecode(b"\xff.sqlite")
    p = cli([*RUN, "--store", name], fresh, timeout=300)
    assert p.returncode == 0, p.stderr.decode()
    assert b"stored in \xff.sqlite (run id 1)" in p.stdout  # the name's own bytes, as ls shows them
    assert rows(fresh / name) == 1
    assert bm.run(*CASE, duration=0.05, store=fresh / name).run_id == 2


def test_a_record_path_thousands_of_folders_deep_is_refused_before_the_run(fresh):
    deep = "a/" * 1400 + "x.npz"  # 2.8 kB: under PATH_MAX, but mkdir(parents=True) recursed out of stack
    one_error_line(cli([*RUN, "--no-store", "--record", deep], fresh), 2, "--record", "folders deep")
    assert not (fresh / "a").exists()


def test_a_bogus_mplbackend_is_refused_before_a_run_that_draws(fresh):
    one_error_line(cli(["run", "--creature", "centipede", "--body", "hybrid", "--scenario", "walk", "--duration",
                        "0.05", "--plot-gait", "g.png"], fresh, env={"MPLBACKEND": "bogus"}), 2, "MPLBACKEND")
    assert not os.listdir(fresh)


def test_a_write_that_raises_anything_after_the_run_keeps_the_printed_and_stored_result(fresh, capsys, monkeypatch):
    from bench_myriapoda.cli import main
    from bench_myriapoda.harness import recorder

    def deep(*a, **k):
        raise RecursionError("maximum recursion depth exceeded")
    monkeypatch.setattr(recorder, "save_npz", deep)
    assert main([*RUN, "--store", "r.sqlite", "--record", "x.npz", "--json"]) == 1
    out = capsys.readouterr()
    assert json.loads(out.out)["timings"]["steps"] > 0 and rows(fresh / "r.sqlite") == 1
    assert out.err.count("\n") == 1 and "could not write --record x.npz (RecursionError" in out.err, out.err


def test_a_store_and_a_record_that_both_fail_after_the_run_are_both_named(fresh, capsys, monkeypatch):
    from bench_myriapoda.cli import main

    def disk_full(*a, **k):
        raise sqlite3.OperationalError("database or disk is full")
    monkeypatch.setattr(store_mod, "connect", disk_full)
    after_the_run(monkeypatch, lambda: (fresh / "y").write_text(""))  # a file where the recording's folder goes
    code = main([*RUN, "--store", "r.sqlite", "--record", "y/x.npz", "--json"])
    out = capsys.readouterr()
    assert code == 1 and json.loads(out.out)["timings"]["steps"] > 0
    lines = out.err.splitlines()
    assert len(lines) == 2 and "could not store the run" in lines[0] and "could not write --record y/x.npz" in \
        lines[1], lines
    assert kept_file(lines[0]).is_file()


# --------------------------------------------------------------------------- timeouts and signals

def two_case_matrix(folder: Path) -> Path:
    m = folder / "m.toml"
    m.write_text('[matrix]\nname = "m"\ncreatures = ["worm"]\nbodies = ["massspring"]\nscenarios = ["flat"]\n'
                 "seeds = [0, 1]\nduration = 0.05\n")
    return m


@pytest.mark.parametrize("timeout", ["3e6", "1e300"])
def test_a_huge_timeout_per_case_runs_the_matrix(timeout, fresh):
    """select/poll overflowed on a wait of more than about 2.1e6 s; each wait is now at most an hour.  The
    output folder's name is not UTF-8 either: the closing lines name it."""
    m = two_case_matrix(fresh)
    out = os.fsdecode(b"\xffo")
    p = cli(["matrix", str(m), "--workers", "1", "--timeout-per-case", timeout, "--out", out], fresh, timeout=400)
    assert p.returncode == 0, p.stderr.decode("utf-8", "backslashreplace")
    assert b"2 of 2 cases stored in \xffo/results.sqlite" in p.stdout
    assert len(bm.load_results(fresh / out)) == 2


def test_an_infinite_timeout_is_refused_on_the_command_line_as_in_the_api(fresh):
    m = two_case_matrix(fresh)
    one_error_line(cli(["matrix", str(m), "--timeout-per-case", "inf", "--out", "o"], fresh), 2, "--timeout-per-case")
    refused(lambda: bm.run_matrix(m, out=fresh / "o", timeout_per_case=float("inf")), "timeout_per_case")
    assert not (fresh / "o").exists()


def sigterm_handled(pid: int) -> bool:
    """The process catches SIGTERM (bit 15 of SigCgt in /proc/PID/status): main() is running."""
    try:
        text = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return False
    mask = int(next(ln.split()[1] for ln in text.splitlines() if ln.startswith("SigCgt:")), 16)
    return bool(mask & (1 << (signal.SIGTERM - 1)))


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads /proc/PID/status")
@pytest.mark.parametrize("command", ["run", "matrix-start-up"])
def test_sigterm_ends_a_run_or_a_matrix_start_up_with_130(command, fresh):
    if command == "run":
        args = [*RUN[:-1], "3000", "--no-store"]  # far longer than the test waits
    else:
        args = ["matrix", str(two_case_matrix(fresh)), "--workers", "1", "--out", "o"]
    code = "import sys; from bench_myriapoda.cli import main; sys.exit(main())"
    p = subprocess.Popen([sys.executable, "-c", code, *args], cwd=fresh, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    try:
        for _ in range(600):  # until main() holds its SIGTERM handler (the interpreter's imports come first)
            if sigterm_handled(p.pid) or p.poll() is not None:
                break
            time.sleep(0.05)
        assert p.poll() is None, "ended before SIGTERM was sent"
        p.send_signal(signal.SIGTERM)
        _, err = p.communicate(timeout=120)
    finally:
        if p.poll() is None:
            p.kill()
    assert p.returncode == 130, err.decode()
    assert err.decode().strip().endswith("bench-myriapoda: interrupted") and b"Traceback" not in err, err.decode()


# An interrupt raised inside an import of a C extension comes out as that import's ImportError (numpy's
# "PyCapsule_Import could not import module ..."): a fresh-clone run on a loaded machine (f725d9b) sent SIGTERM to
# `run` while check_numba_env imported numba, and the command ended with that traceback and exit 1.  The import is
# played here: the signal arrives inside check_numba_env and the KeyboardInterrupt it raises is re-raised as an
# ImportError from it, as CPython's PyCapsule_Import does.
INTERRUPTED_IMPORT = """
import os, signal, sys, time
from bench_myriapoda.cli import program

def check_numba_env():
    interrupt = None
    try:
        os.kill(os.getpid(), signal.{sig})
        time.sleep(30)  # the handler raises before this ends
    except KeyboardInterrupt as exc:
        interrupt = exc
        if {chained}:
            raise ImportError('PyCapsule_Import could not import module "datetime"') from exc
    raise ImportError('PyCapsule_Import could not import module "datetime"')  # no trace of the interrupt

program.check_numba_env = check_numba_env
signal.signal(signal.SIGINT, signal.default_int_handler)  # as in a terminal (a pytest-xdist worker ignores SIGINT)
sys.exit(program.main(["list"]))
"""


@pytest.mark.parametrize("sig, chained", [("SIGTERM", True), ("SIGTERM", False), ("SIGINT", True)])
def test_an_interrupt_that_an_import_turns_into_an_import_error_still_ends_with_130(sig, chained, fresh):
    """SIGTERM inside main() ends with 130 whatever exception its KeyboardInterrupt became, even one that keeps
    no trace of it; Ctrl-C (no handler of ours) does when the KeyboardInterrupt is in the exception's chain."""
    code = INTERRUPTED_IMPORT.format(sig=sig, chained=chained)
    p = subprocess.run([sys.executable, "-c", code], cwd=fresh, capture_output=True, text=True, timeout=60)
    assert p.returncode == 130, p.stderr
    assert p.stderr.strip() == "bench-myriapoda: interrupted", p.stderr


# An interrupt whose handler runs inside a finalizer is printed and ignored by Python ("Exception ignored in: <function
# ZipFile.__del__ ...> KeyboardInterrupt"): a fresh-clone run of 6ab195c sent SIGTERM to a matrix while a ZipFile was
# collected, and the matrix went on with its cases and ended with 0.  Played here: the command's work collects an
# object whose finalizer receives the signal, then goes on for up to 30 s.
INTERRUPTED_FINALIZER = """
import os, signal, sys, time
from bench_myriapoda.cli import program

class Closes:
    def __del__(self):
        os.kill(os.getpid(), signal.{sig})
        sum(range(100000))  # the handler runs here, inside the finalizer

def command(name):
    def run(args):
        c = Closes()
        del c
        end = time.monotonic() + 30.0
        while time.monotonic() < end:  # a command's work after the finalizer
            sum(range(1000))
        print("finished")
        return 0
    return run

import bench_myriapoda.cli.commands as commands
commands.command = command
signal.signal(signal.SIGINT, signal.default_int_handler)  # as in a terminal (a pytest-xdist worker ignores SIGINT)
sys.exit(program.main(["list"]))
"""


@pytest.mark.parametrize("sig", ["SIGTERM", "SIGINT"])
def test_an_interrupt_that_lands_in_a_finalizer_still_ends_the_command_with_130(sig, fresh):
    """Python ignores an exception raised in a finalizer; the interrupt is delivered again, after it, so the command
    stops (well before its 30 s of work) with 130 and one line, and no "Exception ignored" traceback."""
    code = INTERRUPTED_FINALIZER.format(sig=sig)
    start = time.monotonic()
    p = subprocess.run([sys.executable, "-c", code], cwd=fresh, capture_output=True, text=True, timeout=90)
    assert p.returncode == 130, p.stderr
    assert p.stderr.strip() == "bench-myriapoda: interrupted" and "finished" not in p.stdout, p.stderr
    assert time.monotonic() - start < 25.0


def test_an_interrupt_sent_again_after_a_command_that_ended_at_once_lands_inside_main(fresh):
    """The finalizer's command returns at once, before the signal is sent again (a few milliseconds later): it
    still lands inside ``main`` (which waits for it before restoring the handlers), so main ends with 130 and its
    caller goes on; delivered after, with SIGTERM's default handler back, it killed the caller (exit 143)."""
    code = INTERRUPTED_FINALIZER.format(sig="SIGTERM").replace(
        "end = time.monotonic() + 30.0", "end = time.monotonic()").replace(
        'sys.exit(program.main(["list"]))',
        'code = program.main(["list"])\ntime.sleep(0.2)\nprint("caller goes on", code)\nsys.exit(code)')
    p = subprocess.run([sys.executable, "-c", code], cwd=fresh, capture_output=True, text=True, timeout=90)
    assert p.returncode == 130, (p.returncode, p.stderr)
    assert "caller goes on 130" in p.stdout and p.stderr.strip() == "bench-myriapoda: interrupted", p.stderr
