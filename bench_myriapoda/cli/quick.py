"""``bench-myriapoda quick`` (and ``bench-myriapoda`` with no arguments): the main job, a preset of ``matrix``."""
from __future__ import annotations

import argparse
from pathlib import Path

from . import matrix
from .help_text import help_text

# What no arguments do: this matrix, written (with its report) to this directory.
QUICK_MATRIX = "quick"
QUICK_OUT = Path("reports") / "quick"


def add_parser(sub) -> None:
    q = sub.add_parser("quick", help="run scenarios/matrix/quick.toml and write reports/quick/index.html "
                                     "(also what no arguments do)", **help_text("quick"))
    q.add_argument("--out", metavar="DIR", default=str(QUICK_OUT), help=f"output directory (default {QUICK_OUT})")
    q.add_argument("--workers", type=int, metavar="N", default=None, help="worker processes (default: CPU count)")


def cmd_quick(args) -> int:
    """The main job: the quick matrix on a local process pool, the stable-dt bracket of every headline pair and
    the validate --quick checks that apply to its pairs (``report.main_job``), then its report.  A rerun of
    the same code keeps the cases, brackets and verdicts of the last complete run in DIR (``main_job=True``)."""
    ns = argparse.Namespace(file=QUICK_MATRIX, executor="local", workers=args.workers, scheduler=None, resume=False,
                            schedule="cost",
                            timeout_per_case=None, out=args.out, report=True, retry_failed=False, dask_timeout=None,
                            force=False, memory_budget=None, max_steps=None, main_job=True)
    return matrix.cmd_matrix(ns)
