"""``bench-myriapoda peers``: MuJoCo flex and PyElastica's snake timed side by side with this suite's bodies."""
from __future__ import annotations

import json
import sys
from pathlib import Path

from ..core.errors import InputError
from ..harness import regress as R
from ..harness.store import DEFAULT_STORE, check_store, record_regress_run
from .checks import check_path_flags, store_after_the_run
from .exits import EXIT_FAIL, EXIT_OK
from .help_text import help_text


def add_parser(sub) -> None:
    pe = sub.add_parser("peers", help="time MuJoCo flex and PyElastica's snake side by side with ours (extra [peers])",
                        **help_text("peers"))
    pe.add_argument("--repeats", type=int, metavar="N", default=5, help="timed repetitions per entry (default 5)")
    pe.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    pe.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")


def cmd_peers(args) -> int:
    """Time the peers (MuJoCo flex, PyElastica's snake) and ours in one sitting; store and print the ratios.

    Exit 2 (one line, nothing timed or written) when the ``[peers]`` packages are missing."""
    # the peers' and the throughput suite's scenes: about 8 ms of CPU at start-up, which the other commands do not pay
    from ..harness import peers as P

    missing = P.missing_packages()
    if missing:
        raise InputError("peers", None, f"needs the optional packages {', '.join(missing)}: "
                                        f"pip install {' '.join(missing)} (or the extra bench-myriapoda[peers])")
    repeats = R.check_repeats(args.repeats)
    check_path_flags(args, "--store")
    store = Path(args.store) if args.store else DEFAULT_STORE
    check_store(store, "--store")
    entries = P.peer_entries()
    tty = not args.json and sys.stderr.isatty()
    try:
        results = R.run_suite(list(entries), repeats, suite={k: e.entry for k, e in entries.items()},
                              progress=(lambda m: print(f"peers: {m}", file=sys.stderr)) if tty else None)
    except RuntimeError as exc:
        print(f"bench-myriapoda: peers failed: {exc}", file=sys.stderr)
        return EXIT_FAIL
    rows = P.ratios(entries, results)
    run_id, unstored = store_after_the_run(store, "peers run",
                                           lambda: record_regress_run(store, [r.row() for r in results]),
                                           lambda: {"entries": [r.row() for r in results], "ratios": rows})
    if args.json:
        print(json.dumps({"run_id": run_id, "store": str(store), "repeats": repeats, "entries": rows}))
    else:
        for line in P.format_rows(rows):
            print(line)
        print(f"one process, one sitting, CPU time of the timing thread; stored as regress run {run_id} in {store}")
    if unstored:
        print(f"bench-myriapoda: error: {unstored}", file=sys.stderr)
        return EXIT_FAIL
    return EXIT_OK
