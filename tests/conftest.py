"""Fixtures shared by test files: the quick matrix's output, run once per test session."""
from __future__ import annotations

import contextlib
import io
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
    """``bench-myriapoda quick --workers 2 --out DIR``: the main job (quick matrix and report), once per session.

    The most expensive fixture of the suite (about 1.5 minutes on 2 cores with warm JIT caches): every
    test of the quick matrix's output shares it.
    """
    from bench_myriapoda.cli import main

    out = tmp_path_factory.mktemp("quick") / "quick"
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        code = main(["quick", "--workers", "2", "--out", str(out)])
    return QuickRun(out, code, buf.getvalue())
