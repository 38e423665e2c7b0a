"""``bench-myriapoda regress``: the fixed throughput suite timed, stored, compared with a baseline run."""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from ..harness import regress as R
from ..harness.machine import git_commit, machine_fingerprint
from ..harness.store import DEFAULT_STORE, check_store, record_regress_run
from .checks import check_path_flags, store_after_the_run
from .exits import EXIT_FAIL, EXIT_OK
from .help_text import help_text


def _fraction(text: str) -> float:
    """A number flag's value; one so small it reads as 0 (``5e-400``) is refused, not taken as 0.  (Its name is
    argparse's word for it: "invalid _fraction value".)"""
    value = float(text)  # ValueError: argparse says "invalid _fraction value"
    mantissa = text.strip().lower().split("e")[0]
    if value == 0.0 and any(ch in "123456789" for ch in mantissa):
        raise argparse.ArgumentTypeError(f"{text} is too small to tell from 0 (below 1e-308); give 0 or a "
                                         "larger number")
    return value


def add_parser(sub) -> None:
    rg = sub.add_parser("regress", help="time the fixed throughput suite, store it, compare with a baseline run",
                        **help_text("regress"))
    rg.add_argument("--baseline", metavar="COMMIT_OR_RUN", default=None,
                    help="a regress run id or a git commit (prefix) with a run in the store "
                         "(default: the latest earlier run on this machine)")
    rg.add_argument("--repeats", type=int, metavar="N", default=7, help="timed repetitions per entry (default 7)")
    rg.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    rg.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    rg.add_argument("--threshold", type=_fraction, metavar="FRACTION", default=0.10,
                    help="smallest drop of the normalized figure that counts as a regression (default 0.10; "
                         "raised to 3x the measured noise when that is larger)")
    rg.add_argument("--suite", nargs="+", action="extend", metavar="NAME", default=None,
                    help="run only these entries of the suite (default: all)")


def cmd_regress(args) -> int:
    """Time the throughput suite, store it in ``regress_history``, compare with the baseline run.

    Exit 1 when any entry's normalized figure dropped beyond the noise-aware threshold, 0 otherwise
    (also with no baseline yet), 2 for bad input (nothing timed, nothing written).
    """
    repeats = R.check_repeats(args.repeats)
    threshold = R.check_threshold(args.threshold)
    names = R.check_suite_names(args.suite)
    check_path_flags(args, "--store", "--baseline")
    store = Path(args.store) if args.store else DEFAULT_STORE
    check_store(store, "--store")
    machine = json.dumps(machine_fingerprint(), sort_keys=True)
    base = R.resolve_baseline(store, args.baseline, machine, names)
    tty = not args.json and sys.stderr.isatty()

    def progress(msg: str) -> None:
        if tty:
            print(f"regress: {msg}", file=sys.stderr)

    try:
        results = R.run_suite(names, repeats, progress=progress)
    except RuntimeError as exc:  # a kernel stopped early: no figure to store
        print(f"bench-myriapoda: regress failed: {exc}", file=sys.stderr)
        return EXIT_FAIL
    rows = R.compare(results, base, threshold)
    run_id, unstored = store_after_the_run(store, "regress run",
                                           lambda: record_regress_run(store, [r.row() for r in results]),
                                           lambda: {"entries": [r.row() for r in results], "comparison": rows})
    regressed = [r["entry"] for r in rows if r["verdict"] == "regression"]
    commit, dirty = git_commit()
    if args.json:
        print(json.dumps({
            "run_id": run_id, "git_commit": commit, "git_dirty": dirty, "store": str(store), "repeats": repeats,
            "threshold": threshold, "noise_k": R.NOISE_K,
            "baseline": None if base is None else {"run_id": base.run_id, "git_commit": base.git_commit,
                                                   "git_dirty": base.git_dirty, "timestamp": base.timestamp},
            "message": "no baseline yet" if base is None else None,
            "entries": rows, "regressions": regressed}))
    else:
        here = f"regress run {run_id} at {(commit or '?')[:7]}{'+' if dirty else ''}"
        print(here + (f" vs. baseline {base.describe()}" if base else "") + f"; {repeats} repetitions per entry")
        for line in R.format_table(rows):
            print(line)
        ref = sorted(r.reference_ops_per_s for r in results)[len(results) // 2]
        print(f"normalized = steps/s / reference ops/s (reference kernel: {ref:.3g} ops per CPU second); "
              f"stored in {store}")
        if base is None:
            print("no baseline yet")
        elif regressed:
            print(f"{len(regressed)} regression(s): {', '.join(regressed)}")
    if unstored:
        print(f"bench-myriapoda: error: {unstored}", file=sys.stderr)
    return EXIT_FAIL if regressed or unstored else EXIT_OK
