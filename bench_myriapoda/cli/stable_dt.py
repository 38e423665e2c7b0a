"""``bench-myriapoda stable-dt``: the largest time step for which one case stays stable (bisection)."""
from __future__ import annotations

import json
import math
import sys

from ..core.errors import InputError
from ..harness.store import DEFAULT_STORE, check_store, record_run
from .case_flags import budget_arguments, case_arguments, case_source, check_case_fits, resolve
from .checks import check_path_flags, store_after_the_run
from .exits import EXIT_FAIL, EXIT_OK
from .help_text import help_text
from .run import fmt


def add_parser(sub) -> None:
    sd = sub.add_parser("stable-dt", help="largest time step for which a case stays stable (bisection)",
                        **help_text("stable-dt"))
    case_arguments(sd)
    sd.add_argument("--rel-tol", type=float, default=0.05, help="stop when the bracket is tighter than this (default 0.05)")
    sd.add_argument("--max-runs", type=int, default=24, help="at most this many runs (default 24)")
    sd.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    sd.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    sd.add_argument("--no-store", action="store_true", help="do not record the result in the results database")
    budget_arguments(sd)


def cmd_stable_dt(args) -> int:
    # the runner: about 45 ms of CPU at start-up (as ``run``'s), which list, keys, report and --help do not pay
    from ..harness import stable_dt
    from ..harness.runner import RunResult

    if not (math.isfinite(args.rel_tol) and 0 < args.rel_tol < 1):  # a relative bracket width: 1 would stop at once
        raise InputError("--rel-tol", None, f"{args.rel_tol} is out of range; must be a number > 0 and < 1 "
                                            "(the bracket's width relative to dt)")
    if not 2 <= args.max_runs <= 1000:
        raise InputError("--max-runs", None, f"{args.max_runs} is out of range; must be 2 to 1000")
    check_path_flags(args, "--store")
    if not args.no_store:
        check_store(args.store or DEFAULT_STORE, "--store")
    case = resolve(args)
    world = check_case_fits(case, args, case_source(args))
    show = not args.json and sys.stdout.isatty()

    def progress(dt, status):
        if show:
            print(f"  dt = {dt:.4g} s: {status}", file=sys.stderr)

    res = stable_dt.find_stable_dt(case, rel_tol=args.rel_tol, max_runs=args.max_runs, progress=progress, world=world)
    metrics = {"stable_dt_max_s": res.stable_dt_max_s, "unstable_dt_min_s": res.unstable_dt_min_s,
               "stable_dt_runs": float(len(res.trials))}
    result = RunResult(case, "error" if res.error else "ok", metrics,
                       {"steps": 0, "steps_per_s": float("nan"), "realtime_factor": float("nan"),
                        "compile_s": float("nan"), "wall_s": float("nan")}, res.error)
    d = result.to_json_dict()
    d["trials"] = [{"dt": dt, "status": st, "t_fail_s": None if math.isnan(tf) else tf} for dt, st, tf in res.trials]
    unstored = None
    if not args.no_store:
        store = args.store or DEFAULT_STORE
        _, unstored = store_after_the_run(store, "stable-dt result",
                                          lambda: record_run(store, result, command="stable-dt"), lambda: d)
    if args.json:
        print(json.dumps(d))
    else:
        for dt, st, tf in res.trials:
            print(f"  dt = {dt:.4g} s  {st}" + ("" if math.isnan(tf) else f" (failed at t = {tf:.3g} s)"))
        print(f"stable_dt_max_s = {fmt(res.stable_dt_max_s)}   (smallest unstable dt: {fmt(res.unstable_dt_min_s)})")
    if unstored:
        print(f"bench-myriapoda: error: {unstored}", file=sys.stderr)
        return EXIT_FAIL
    if res.error:
        print(f"bench-myriapoda: stable-dt stopped: {res.error.splitlines()[0]}", file=sys.stderr)
        return EXIT_FAIL
    return EXIT_OK
