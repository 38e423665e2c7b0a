"""Issues 28 (part 4) and 32: a result computed before a write fails is never lost.

A store that is fine before a run can fail its insert after the simulation (another program adds
a trigger, the disk fills, the store is replaced by something else).  The run was computed: it is
printed (``--json``: one JSON object on stdout), kept in a fallback file the one error line names,
and the exit code is 1 (a failure, not bad input).  The same store refused *before* the run starts
is exit 2 and nothing simulated.  ``matrix`` stops at such a case without leaving its recording
behind (a series file always has its row) and keeps the case's result the same way.  SIGTERM ends
a matrix as Ctrl-C does, and its workers print no BrokenPipeError after the main process is killed.

The simulations are the cheapest there are: the worm on the mass-spring body for 0.05 s.
"""
import json
import os
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.harness import store as store_mod
from bench_myriapoda.harness.store import connect

ROOT = Path(__file__).resolve().parents[1]
RUN = ["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "0.05", "--json"]
TRIGGER = "CREATE TRIGGER no_more BEFORE INSERT ON runs BEGIN SELECT RAISE(ABORT, 'refused by a trigger'); END;"


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))  # the second fallback folder, inside the test's directory
    (tmp_path / "tmp").mkdir()
    import tempfile
    monkeypatch.setattr(tempfile, "tempdir", None)  # re-read TMPDIR
    return work


def _rows(store: Path) -> int:
    con = sqlite3.connect(store)
    try:
        return con.execute("SELECT COUNT(*) FROM runs").fetchone()[0]
    finally:
        con.close()


def _after_the_run(monkeypatch, action):
    """Call ``action()`` once the simulation has finished, before the CLI stores its result."""
    from bench_myriapoda.harness import runner

    real = runner.run_case

    def run_then(*a, **k):
        result = real(*a, **k)
        action()
        return result
    monkeypatch.setattr(runner, "run_case", run_then)


def _trigger(store: Path):
    con = sqlite3.connect(store)
    con.executescript(TRIGGER)
    con.close()


def _disk_full(*a, **k):
    raise sqlite3.OperationalError("database or disk is full")


@pytest.mark.parametrize("how", ["trigger-added-during-the-run", "disk-full-on-insert", "store-replaced-by-a-directory"])
def test_a_store_that_fails_after_the_simulation_keeps_the_printed_result_in_a_fallback_file(how, fresh, capsys,
                                                                                             monkeypatch):
    store = fresh / "r.sqlite"
    connect(store).close()  # a good store before the run: the checks let it through
    if how == "trigger-added-during-the-run":
        _after_the_run(monkeypatch, lambda: _trigger(store))
    elif how == "disk-full-on-insert":
        monkeypatch.setattr(store_mod, "connect", _disk_full)  # what a full disk makes sqlite raise
    else:
        def replace():
            store.unlink()
            store.mkdir()
        _after_the_run(monkeypatch, replace)
    code = main([*RUN, "--store", str(store)])
    out = capsys.readouterr()
    assert code == 1, out.err
    printed = json.loads(out.out)  # exactly one JSON object on stdout: the computed result
    assert printed["status"] in ("ok", "unstable") and printed["timings"]["steps"] > 0
    assert out.err.count("\n") == 1 and out.err.startswith("bench-myriapoda: error: could not store the run in "), out.err
    assert "Traceback" not in out.err
    kept = Path(out.err.rsplit("the result is kept in ", 1)[1].strip())
    assert kept.is_file(), out.err
    doc = json.loads(kept.read_text())
    assert doc["result"] == printed and doc["store"] == str(store)
    if how == "store-replaced-by-a-directory":  # its folder is fine: the first fallback folder, beside it
        assert kept.parent == fresh / "unsaved"
    else:
        assert _rows(store) == 0


def test_a_full_file_system_after_the_run_falls_back_to_the_temporary_folder(fresh, tmp_path, capsys, monkeypatch):
    """A real full disk: the store on a small tmpfs that fills during the run; ``unsaved/`` beside the store
    cannot be written either, so the result goes to $TMPDIR (root only: mounting needs it)."""
    disk = tmp_path / "disk"
    disk.mkdir()
    if os.geteuid() != 0 or subprocess.run(["mount", "-t", "tmpfs", "-o", "size=2m", "tmpfs", str(disk)],
                                           capture_output=True).returncode != 0:
        pytest.skip("needs root to mount a small tmpfs")
    try:
        store = disk / "r.sqlite"
        connect(store).close()

        def fill():
            with open(disk / "filler", "wb") as fh:
                try:
                    while True:
                        fh.write(b"\0" * 65536)
                        fh.flush()
                except OSError:
                    pass
        _after_the_run(monkeypatch, fill)
        code = main([*RUN, "--store", str(store)])
        out = capsys.readouterr()
        assert code == 1, out.err
        printed = json.loads(out.out)
        assert out.err.count("\n") == 1 and "could not store the run" in out.err and "full" in out.err, out.err
        kept = Path(out.err.rsplit("the result is kept in ", 1)[1].strip())
        assert kept.parent == tmp_path / "tmp" / "bench-myriapoda-unsaved"
        assert json.loads(kept.read_text())["result"] == printed
    finally:
        subprocess.run(["umount", str(disk)], check=False)


def test_the_same_store_refused_before_the_run_starts_is_exit_2_and_nothing_simulated(fresh, capsys, monkeypatch):
    """The counterpart: the trigger already there when the run is asked for is found by the store check."""
    ran = []
    monkeypatch.setattr("bench_myriapoda.harness.runner.run_case", lambda *a, **k: ran.append(1))
    store = fresh / "r.sqlite"
    connect(store).close()
    _trigger(store)
    before = store.stat().st_mtime_ns
    code = main([*RUN, "--store", str(store)])
    out = capsys.readouterr()
    assert code == 2 and not ran and out.out == ""
    assert out.err.count("\n") == 1 and "--store" in out.err and "trigger" in out.err
    assert store.stat().st_mtime_ns == before and not (fresh / "unsaved").exists()


def test_a_matrix_whose_store_fails_mid_run_stops_with_its_case_kept_and_no_orphan_recording(fresh, capsys,
                                                                                             monkeypatch):
    from bench_myriapoda.harness import executors

    (fresh / "m.toml").write_text('[matrix]\ncreatures = ["worm"]\nbodies = ["massspring"]\nscenarios = ["flat"]\n'
                                  "seeds = [0, 1]\nduration = 0.05\n")
    out_dir = fresh / "o"
    real = executors.record_run
    calls = []

    def record_then_break(path, result, **k):
        calls.append(1)
        if len(calls) == 2:  # the second case: another program put a trigger on the store meanwhile
            _trigger(Path(path))
        return real(path, result, **k)
    monkeypatch.setattr(executors, "record_run", record_then_break)
    code = main(["matrix", str(fresh / "m.toml"), "--out", str(out_dir), "--workers", "1"])
    out = capsys.readouterr()
    assert code == 1, out.err
    err = [line for line in out.err.splitlines() if line.startswith("bench-myriapoda: ")]
    assert len(err) == 1 and "matrix stopped: could not store the matrix case" in err[0], out.err
    assert "Traceback" not in out.err
    kept = Path(err[0].split("the result is kept in ", 1)[1].split("; the cases stored")[0])
    assert json.loads(kept.read_text())["result"]["status"] in ("ok", "unstable")
    stored = sqlite3.connect(out_dir / "results.sqlite").execute("SELECT case_hash FROM runs").fetchall()
    series = sorted(p.stem for p in (out_dir / "series").glob("*.npz"))
    assert len(stored) == 1 and series == [stored[0][0]]  # the failed case left no recording without its row


def test_report_on_a_full_disk_is_one_line_without_a_traceback(fresh, capsys, monkeypatch):
    import errno

    def full(*a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr("bench_myriapoda.report.build.build_report", full)
    code = main(["report", str(fresh)])
    out = capsys.readouterr()
    assert code == 1
    assert out.err.count("\n") == 1 and "No space left on device" in out.err and "Traceback" not in out.err


def _matrix_process(fresh: Path, seeds: int, duration: float):
    (fresh / "m.toml").write_text('[matrix]\ncreatures = ["worm"]\nbodies = ["massspring"]\nscenarios = ["flat"]\n'
                                  f"seeds = {list(range(seeds))}\nduration = {duration}\n")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.Popen([sys.executable, "-m", "bench_myriapoda.cli", "matrix", str(fresh / "m.toml"), "--out",
                             str(fresh / "o"), "--workers", "1"], cwd=fresh, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


def _wait_for(pred, timeout: float) -> bool:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if pred():
            return True
        time.sleep(0.2)
    return False


def _stored(fresh: Path) -> int:
    store = fresh / "o" / "results.sqlite"
    try:
        return _rows(store) if store.is_file() else 0
    except sqlite3.Error:
        return 0


def test_sigterm_ends_a_matrix_like_ctrl_c_and_it_resumes(fresh):
    p = _matrix_process(fresh, seeds=4, duration=10.0)  # still running when SIGTERM comes
    try:
        assert _wait_for(lambda: _stored(fresh) >= 1, 300), "no case stored"
        p.send_signal(signal.SIGTERM)
        out, err = p.communicate(timeout=120)
    finally:
        if p.poll() is None:
            p.kill()
    assert p.returncode == 130, err
    assert "bench-myriapoda: interrupted" in err and "Traceback" not in err and "BrokenPipeError" not in err, err
    done = _stored(fresh)
    assert 1 <= done < 4
    code = main(["matrix", str(fresh / "m.toml"), "--out", str(fresh / "o"), "--workers", "1", "--resume"])
    assert code == 0 and _stored(fresh) == 4


def test_workers_print_no_broken_pipe_after_the_main_process_is_killed(fresh):
    p = _matrix_process(fresh, seeds=3, duration=20.0)  # the second case still runs when the kill comes
    try:
        assert _wait_for(lambda: _stored(fresh) >= 1, 300), "no case stored"
        os.kill(p.pid, signal.SIGKILL)
        # the worker finishes its case, finds the pipe closed and ends; its stderr is the same pipe,
        # so communicate() returns once it has ended
        out, err = p.communicate(timeout=120)
    finally:
        if p.poll() is None:
            p.kill()

    assert "BrokenPipeError" not in err and "Traceback" not in err, err
