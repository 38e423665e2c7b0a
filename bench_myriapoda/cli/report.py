"""``bench-myriapoda report``: DIR/index.html and DIR/summary.md of a matrix output directory."""
from __future__ import annotations

import os
import sys
from pathlib import Path

from ..core.errors import InputError
from ..harness.store import DEFAULT_STORE
from ..report.inputs import check_history_store
from .checks import check_path_flags, check_workers
from .exits import EXIT_FAIL, EXIT_OK
from .help_text import help_text


def add_parser(sub) -> None:
    rp = sub.add_parser("report", help="write DIR/index.html and DIR/summary.md from a matrix output directory",
                        **help_text("report"))
    rp.add_argument("dir", metavar="DIR", help="a directory written by `bench-myriapoda matrix FILE --out DIR`")
    rp.add_argument("--baseline", metavar="DIR2", default=None,
                    help="another matrix output directory to compare against; regressions are highlighted")
    rp.add_argument("--threshold", type=float, default=0.10, metavar="FRACTION",
                    help="relative change of a metric that counts (default 0.10; throughput: 0.15)")
    rp.add_argument("--history-store", metavar="PATH", default=None,
                    help="results store with the regress history to plot (default reports/results.sqlite)")
    rp.add_argument("--strict", action="store_true", help="exit 1 when the baseline comparison finds a regression")
    rp.add_argument("--workers", type=int, metavar="N", default=None,
                    help="processes drawing the figures (default: CPU count; the page is the same for any N)")


def cmd_report(args) -> int:
    # the report's modules import pandas and matplotlib (report.build: about 0.65 s (CPU, measured after the body models load: python -c, time.process_time)): this command only
    from ..report import build

    if not 0 < args.threshold < 10:
        raise InputError("--threshold", None, f"{args.threshold} is out of range; must be in (0, 10)")
    check_workers(args.workers)
    check_path_flags(args, "--history-store", "--baseline")
    check_history_store(args.history_store)  # the same check as scorecard's, the default store included
    history = Path(args.history_store) if args.history_store else DEFAULT_STORE
    try:
        summary = build.build_report(args.dir, baseline=args.baseline, history_store=history,
                                     threshold=args.threshold, workers=args.workers or os.cpu_count() or 1)
    except OSError as exc:  # the disk filled while the figures were written: the old page stays as it was
        print(f"bench-myriapoda: error: report: could not write into {args.dir} ({exc.strerror or exc})",
              file=sys.stderr)
        return EXIT_FAIL
    print(f"report written to {summary.index} and {summary.summary} ({len(summary.figures)} figures)")
    if args.baseline:
        print(f"{summary.regressions} regression(s) against {args.baseline}")
    return EXIT_FAIL if args.strict and summary.regressions else EXIT_OK
