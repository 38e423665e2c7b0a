"""``bench-myriapoda validate``: verdicts against the papers and analytic references (exit 1 on a FAIL)."""
from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

from ..harness.store import DEFAULT_STORE, check_store, check_writable_dir, check_writable_file, record_validation_run
from .checks import check_path_flags, store_after_the_run
from .exits import EXIT_FAIL, EXIT_OK
from .help_text import QUICK_SET_TIME, help_text, validate_description


def add_parser(sub) -> None:
    va = sub.add_parser("validate", help="verdicts against the papers and analytic references (exit 1 on a FAIL)",
                        **help_text("validate"))
    va.describe = validate_description
    va.add_argument("--body", nargs="+", action="extend", metavar="B", default=None,
                    help="only these body models (default: all)")
    va.add_argument("--check", nargs="+", action="extend", metavar="NAME", default=None,
                    help="only these checks or families (analytic, miller, paper, cross_body, throughput)")
    va.add_argument("--quick", action="store_true", help=f"the quick set: small sizes, {QUICK_SET_TIME}")
    va.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    va.add_argument("--out", metavar="DIR", default=None,
                    help="validation.json and the work-precision PNGs go here (default reports/validation)")
    va.add_argument("--work-precision", action="store_true",
                    help="also sweep dt and resolution per body model and draw work-precision diagrams")
    va.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    va.add_argument("--no-store", action="store_true", help="do not record the rows in the results database")


class stdout_to_stderr:
    """Point file descriptor 1 at stderr inside the block (and restore it), Python's and C's writes alike."""

    def __enter__(self):
        sys.stdout.flush()
        try:
            self.saved = os.dup(1)
            os.dup2(2, 1)
        except OSError:  # no real descriptors (an embedding host): nothing to redirect
            self.saved = None
        return self

    def __exit__(self, *exc):
        if self.saved is not None:
            sys.stdout.flush()
            os.dup2(self.saved, 1)
            os.close(self.saved)
        return False


def check_outputs(args, store: Path, out_dir: Path, json_name: str) -> None:
    """``validate``: its store is opened and schema-checked and ``--out`` (with its ``json_name``,
    validation.json) can be written, before any check runs."""
    if not args.no_store:
        check_store(store, "--store")
    check_writable_dir(out_dir, "--out")
    check_writable_file(out_dir / json_name, "--out")


def cmd_validate(args) -> int:
    """Run the validation checks; exit 1 when any check FAILs, 0 otherwise, 2 for bad input (nothing run)."""
    # the checks' registry imports every check module (validation.registry: about 25 ms (CPU, measured after the body models load: python -c, time.process_time)):
    # only this command pays for it
    from ..validation import run as V
    from ..validation.core import clean

    pairs, bodies = V.select(args.check, args.body, args.quick)
    check_path_flags(args, "--store", "--out")
    store = Path(args.store) if args.store else DEFAULT_STORE
    out_dir = Path(args.out) if args.out else V.DEFAULT_OUT
    check_outputs(args, store, out_dir, V.JSON_NAME)
    tty = not args.json and sys.stderr.isatty()
    t0 = time.perf_counter()
    # compiled libraries (LAPACK on a blown-up run's NaNs) print to file descriptor 1 directly: while the
    # checks run, fd 1 points at stderr, so that --json's stdout holds exactly one JSON object
    with stdout_to_stderr():
        rows = V.run_checks(pairs, args.quick, bodies,
                            progress=(lambda m: print(f"validate: {m}", file=sys.stderr)) if tty else None)
        wp = None
        if args.work_precision:
            from ..report.work_precision import run_work_precision  # matplotlib (about 0.35 s of CPU): this flag only
            wp = run_work_precision(out_dir, bodies, args.quick, progress=(
                lambda m: print(f"work-precision: {m}", file=sys.stderr)) if tty else None)
    wall = time.perf_counter() - t0
    dicts = [r.to_dict() for r in rows]
    counts = V.summary(rows)
    doc = clean({"quick": bool(args.quick), "bodies": list(bodies), "wall_s": wall, "counts": counts,
                 "rows": dicts, "work_precision": wp})
    run_id = unstored = None
    if not args.no_store:
        run_id, unstored = store_after_the_run(store, "validation run",
                                               lambda: record_validation_run(store, dicts, args.quick, str(out_dir)),
                                               lambda: doc)
    doc["run_id"] = run_id
    try:
        V.write_json(out_dir, doc)
    except OSError as exc:
        unstored = unstored or f"could not write {out_dir / V.JSON_NAME} ({exc.strerror or exc})"
    failed = counts.get("FAIL", 0) > 0
    if args.json:
        print(json.dumps(doc, allow_nan=False))
    else:
        for line in V.format_table(rows):
            print(line)
        print(", ".join(f"{n} {v}" for v, n in sorted(counts.items())) + f"; {wall:.0f} s"
              + (f"; stored as validation run {run_id} in {store}" if run_id else "") + f"; {out_dir / V.JSON_NAME}")
        if wp:
            print("work-precision diagrams: " + ", ".join(wp["figures"]))
    if unstored:
        print(f"bench-myriapoda: error: {unstored}", file=sys.stderr)
    return EXIT_FAIL if failed or unstored else EXIT_OK
