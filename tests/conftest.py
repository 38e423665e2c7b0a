"""Fixtures shared by test files: the quick matrix's output, run once per test session."""
from __future__ import annotations

import contextlib
import fcntl
import io
import json
import os
from dataclasses import dataclass
from pathlib import Path

import pytest


@dataclass
class QuickRun:
    """The main job's output directory, its exit code and what it printed on stdout."""

    out: Path
    code: int
    stdout: str


@pytest.fixture(scope="session")
def quick_run(tmp_path_factory) -> QuickRun:
    """``bench-myriapoda quick --workers 2 --out DIR``: the main job (quick matrix and report), once per test run.

    The most expensive fixture of the suite (about 1.5 minutes on 2 cores with warm JIT caches): every
    test of the quick matrix's output shares it. Under pytest-xdist each worker has its own session, so the
    first worker that asks runs the main job under a file lock in the directory all workers share, and
    the others wait for it and read its output (the exit code and stdout are kept beside it as JSON).
    """
    from bench_myriapoda.cli import main

    base = tmp_path_factory.getbasetemp()
    shared = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base
    out = shared / "quick-main-job" / "quick"
    record = shared / "quick-main-job.json"
    with open(shared / "quick-main-job.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)   # released when the file closes, also if the main job raises
        if record.is_file():
            doc = json.loads(record.read_text())
            return QuickRun(out, doc["code"], doc["stdout"])
        out.parent.mkdir(parents=True, exist_ok=True)
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            code = main(["quick", "--workers", "2", "--out", str(out)])
        record.write_text(json.dumps({"code": code, "stdout": buf.getvalue()}))
    return QuickRun(out, code, buf.getvalue())
