"""Fixtures shared by test files: the quick matrix's output, run once per test session."""
from __future__ import annotations

import fcntl
import json
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import pytest


def pytest_configure(config):
    """Each kernel compiled once across the test processes (pytest-xdist's workers share numba's on-disk cache):
    the matrix workers' compile lock (``jit.compile_lock``), so that the second worker needing a kernel the
    first is compiling waits and loads it instead of compiling it again (a cold test run compiles every kernel)."""
    from bench_myriapoda.jit import compile_lock

    compile_lock.install()


_compile_ahead: list = []  # the background compile this process started (tests/compile_ahead.py), at most one


def pytest_collection_finish(session):
    """On a test session that runs the main job (the ``quick_run`` fixture) under pytest-xdist, the first worker to
    finish collecting starts ``tests/compile_ahead.py`` in the background: one process per core compiles the quick
    matrix's kernels while the tests start (the module says why and what it saves).  Once per session: the workers
    share a marker file in their common temporary directory."""
    import os
    import subprocess
    import sys

    from compile_ahead import enabled
    from newcomer_venv import shared_tmp

    config = session.config
    if not hasattr(config, "workerinput") or not enabled():
        return
    if not any("quick_run" in getattr(item, "fixturenames", ()) for item in session.items):
        return
    shared = shared_tmp(config._tmp_path_factory, config)
    try:
        os.close(os.open(shared / "compile-ahead.started", os.O_CREAT | os.O_EXCL | os.O_WRONLY))
    except FileExistsError:
        return
    log = open(shared / "compile-ahead.log", "w")
    script = Path(__file__).with_name("compile_ahead.py")
    _compile_ahead.append(subprocess.Popen([sys.executable, str(script), str(len(os.sched_getaffinity(0)))],
                                           stdout=log, stderr=subprocess.STDOUT, start_new_session=True))
    log.close()


def pytest_unconfigure(config):
    """The background compile ends with the worker that started it (its pool with it: its own process group)."""
    import os
    import signal

    for proc in _compile_ahead:
        if proc.poll() is None:
            try:
                os.killpg(proc.pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
            proc.wait(timeout=30)


def pytest_xdist_auto_num_workers(config):
    """``-n auto``: one test process more than the CPUs this process may use.  A cold run's workers wait for
    each other's compiles (``jit.compile_lock``: a second worker needing a kernel the first is compiling
    waits to load it), for the main job's record, and for subprocesses; a third process fills those waits on
    two cores.  Measured on the 2-core machine, cold JIT cache, tests/test_hybrid.py, test_myriapod_bodies.py,
    test_controllers.py and test_worm_bodies.py (66 tests): 2 workers waited 44 s for compiles and took 254 s
    (297 CPU s), 3 workers 165 s (290 CPU s), other jobs running on the machine for both."""
    import os

    try:
        n = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        n = os.cpu_count() or 1
    return n + 1


@dataclass
class QuickRun:
    """The main job's output directory, its exit code, what it printed, the command and its working directory."""

    out: Path
    code: int
    stdout: str
    stderr: str = ""
    argv: list = field(default_factory=list)
    work: Path | None = None


@pytest.fixture(scope="session")
def quick_run(tmp_path_factory, request) -> QuickRun:
    """The main job as a newcomer runs it: the session venv's ``bench-myriapoda`` with no arguments, in an
    empty working directory (tests/newcomer_venv.py); its report is ``WORK/reports/quick``.  Once per test run.

    The most expensive fixture of the suite (about 2 minutes on 2 cores with warm JIT caches): every test
    of the main job's output shares it, and the main journey (tests/test_journeys.py) takes it as its first
    step and goes on in a copy of its working directory.  Under pytest-xdist each worker has its own session,
    so the first worker that asks runs the main job under a file lock in the directory all workers share,
    and the others wait for it and read its record (exit code, stdout and stderr kept beside it as JSON).
    """
    from newcomer_venv import newcomer_env, session_venv, shared_tmp

    shared = shared_tmp(tmp_path_factory, request.config)
    work = shared / "quick-main-job"
    out = work / "reports" / "quick"
    record = shared / "quick-main-job.json"
    with open(shared / "quick-main-job.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)   # released when the file closes, also if the main job raises
        if not record.is_file():
            bindir = session_venv(tmp_path_factory, request.config)
            argv = [str(bindir / "bench-myriapoda")]
            work.mkdir(parents=True, exist_ok=True)
            proc = subprocess.run(argv, cwd=work, env=newcomer_env(bindir), capture_output=True, text=True,
                                  timeout=3600)
            record.write_text(json.dumps({"code": proc.returncode, "stdout": proc.stdout, "stderr": proc.stderr,
                                          "argv": argv}))
        doc = json.loads(record.read_text())
    return QuickRun(out, doc["code"], doc["stdout"], doc["stderr"], doc["argv"], work)
