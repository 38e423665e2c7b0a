"""``bench-myriapoda scorecard``: which body model for each creature, from a matrix output directory."""
from __future__ import annotations

import json
from pathlib import Path

from ..harness.store import DEFAULT_STORE
from ..report.inputs import check_history_store
from .checks import check_path_flags
from .exits import EXIT_OK
from .help_text import help_text


def add_parser(sub) -> None:
    sc = sub.add_parser("scorecard", help="which body model for each creature: stability, fidelity, locomotion "
                                          "and cost per creature x body of a matrix output directory",
                        **help_text("scorecard"))
    sc.add_argument("dir", metavar="DIR", help="a directory written by `bench-myriapoda matrix FILE --out DIR`")
    sc.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    sc.add_argument("--history-store", metavar="PATH", default=None,
                    help="results store with validate and stable-dt results (default reports/results.sqlite)")


def cmd_scorecard(args) -> int:
    """The scorecard of a matrix output directory (``report.scorecard``), as text or one JSON object."""
    # the scorecard reads the matrix with pandas and draws with matplotlib (report.scorecard: about 0.62 s
    # (CPU, measured after the body models load: python -c, time.process_time)): this command only
    from ..report.scorecard import scorecard_for_dir, scorecard_lines

    check_path_flags(args, "--history-store")
    check_history_store(args.history_store)  # the same check as report's, the default store included
    card = scorecard_for_dir(args.dir, Path(args.history_store) if args.history_store else DEFAULT_STORE)
    if args.json:
        print(json.dumps(card.to_json()))
    else:
        for line in scorecard_lines(card):
            print(line)
    return EXIT_OK
