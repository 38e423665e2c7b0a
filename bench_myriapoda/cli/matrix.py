"""``bench-myriapoda matrix``: a scenario matrix on a local process pool or Dask, stored and tabulated (and, for
``quick``, the main job's stable-dt brackets and validate checks after it)."""
from __future__ import annotations

import json
import math
import os
import sys
from pathlib import Path

from ..core.errors import InputError
from ..harness.matrix import check_matrix_outputs, expand_matrix, locate_matrix, write_matrix_manifest
from ..harness.progress import MatrixProgress
from ..harness.schedule import run_summary, write_run_summary
from ..harness.store import DEFAULT_STORE, UnstoredError
from ..harness.terminal_table import closing_line, matrix_table_lines
from ..jit.worker_start import prestart
from ..report.main_job import fidelity_phase, same_code_rerun, write_marker
from .case_flags import budget_arguments, check_case_fits
from .checks import check_path_flags, check_workers
from .exits import EXIT_FAIL, EXIT_OK
from .help_text import help_text
from .signals import sigterm_as_interrupt

TABLE_METRICS = ("speed_bl_per_cycle", "speed_m_per_s", "travel_angle_deg", "slip_ratio",
                 "path_following_error_bl", "contact_fraction", "t_fail_s", "posture_fault")


def add_parser(sub) -> None:
    mx = sub.add_parser("matrix", help="run a scenario matrix (scenarios/matrix/NAME.toml) on a process pool or Dask",
                        **help_text("matrix"))
    mx.add_argument("file", metavar="FILE", help="matrix file (.toml) or a name in scenarios/matrix/")
    mx.add_argument("--executor", choices=("local", "dask"), default="local",
                    help="local: a process pool on this machine (default); dask: a dask.distributed cluster")
    mx.add_argument("--workers", type=int, metavar="N", default=None, help="worker processes (default: CPU count)")
    mx.add_argument("--scheduler", metavar="ADDRESS", default=None,
                    help="dask scheduler address (default: start a LocalCluster)")
    mx.add_argument("--resume", action="store_true", help="run only the cases without a result in the store")
    mx.add_argument("--retry-failed", action="store_true",
                    help="with --resume: also rerun the cases stored as error or timeout")
    mx.add_argument("--dask-timeout", type=float, metavar="SECONDS", default=None,
                    help="--scheduler: how long a worker may take to run a test task before the matrix "
                         "is refused (default 60)")
    mx.add_argument("--timeout-per-case", type=float, metavar="SECONDS", default=None,
                    help="record a case that runs longer as status timeout and stop its worker")
    mx.add_argument("--out", metavar="DIR", default=None,
                    help="results.sqlite, results.csv, matrix.json and series/ go here (default reports/matrix/NAME)")
    mx.add_argument("--report", action="store_true", help="write DIR/index.html and DIR/summary.md when done")
    mx.add_argument("--schedule", choices=("cost", "file"), default="cost",
                    help="order the cases are started in: cost (longest predicted first, the default) or file "
                         "(the matrix file's order); results do not depend on it")
    budget_arguments(mx)


def check_matrix_flags(args) -> None:
    check_path_flags(args, "--out", "--scheduler")
    if args.retry_failed and not args.resume:
        raise InputError("--retry-failed", None, "only meaningful with --resume")
    if args.dask_timeout is not None:
        if not args.scheduler:
            raise InputError("--dask-timeout", None, "only meaningful with --scheduler")
        if not (math.isfinite(args.dask_timeout) and 0 < args.dask_timeout <= 3600):
            raise InputError("--dask-timeout", None, f"{args.dask_timeout} is out of range; must be > 0 and <= 3600")


def check_outputs(args, out: Path) -> None:
    """``matrix``: DIR can be written, its store is opened and schema-checked, its files are files
    (``harness.matrix.check_matrix_outputs``, which the API's ``run_matrix`` uses too)."""
    check_matrix_outputs(out, "--out")
    if args.report:
        # the report's modules import pandas and matplotlib (report.build: about 0.65 s (CPU, measured after the body models load: python -c, time.process_time)): only --report pays
        from ..report.build import check_report_outputs
        check_report_outputs(out)


def cmd_matrix(args) -> int:
    """Expand a matrix file, list what is not supported, run the rest, store and tabulate the results.

    Exit 0 when every case ran to a status ok or unstable, 1 when any case of the matrix (this run or an
    earlier one that --resume kept) is error or timeout, 2 for bad input (nothing written).
    """
    # the executors and the runner they start: about 60 ms of CPU at start-up (measured after the body models load,
    # python -c, time.process_time), which list, keys, report and --help do not pay
    from ..harness import executors

    check_workers(args.workers)
    if args.timeout_per_case is not None and not (math.isfinite(args.timeout_per_case) and args.timeout_per_case > 0):
        raise InputError("--timeout-per-case", None, f"{args.timeout_per_case} is out of range; must be a finite "
                                                     "number of seconds > 0")
    check_matrix_flags(args)
    if args.scheduler and args.executor != "dask":
        raise InputError("--scheduler", None, "only meaningful with --executor dask")
    if args.executor == "dask":
        try:
            import dask.distributed  # noqa: F401  (the optional extra [dask]: whether it is installed)
        except ImportError:
            raise InputError("--executor", None, "dask is not installed; pip install 'bench-myriapoda[dask]'") from None
    if args.executor == "local":  # the workers' fork server imports the package while the matrix expands
        prestart()
    exp = expand_matrix(locate_matrix(args.file))
    out = Path(args.out) if args.out else Path("reports") / "matrix" / exp.name
    if out.exists() and not out.is_dir():
        raise InputError("--out", None, f"{out} exists and is not a directory")
    store = out / "results.sqlite"
    check_outputs(args, out)
    for m in exp.cases:  # the budget only: a case its body cannot build is an error row, as any case that raises
        check_case_fits(m.case, args, f"{exp.path}: case {m.label}", buildable=False)
    if args.executor == "dask" and args.scheduler:
        executors.check_dask_scheduler(args.scheduler, probe_timeout=args.dask_timeout)
    print(f"matrix {exp.name}: {len(exp.cases)} cases ({exp.excluded} excluded, {exp.duplicates} duplicates, "
          f"{len(exp.unsupported)} unsupported combinations)")
    if exp.unsupported:
        print("unsupported combinations (not run):")
        for u in exp.unsupported:
            print(f"  {u}")
    if not exp.cases:
        raise InputError(str(exp.path), None, "no case left to run after exclusions and unsupported combinations")
    labels = {m.case.case_hash(): m.label for m in exp.cases}
    cases = [m.case for m in exp.cases]
    write_matrix_manifest(out, exp)
    main_job = bool(getattr(args, "main_job", False))
    reuse = False
    if main_job and not args.resume:  # the main job again on the same code: its stored cases are its results
        reuse = same_code_rerun(out, exp.name)
        if reuse:
            print(f"the cases this code ran into {out} before are kept (a rerun of the same code gives the same "
                  f"results); `bench-myriapoda matrix {exp.name} --out DIR` into a new DIR runs them all again")
    resume = args.resume or reuse
    todo = len(cases) - (len({c.case_hash() for c in cases} & executors.done_hashes(store, exp.name)) if resume else 0)
    bar = MatrixProgress(sys.stderr.isatty(), todo, label=f"matrix {exp.name}")

    def on_result(result, done, total):
        bar.case_done(labels[result.case.case_hash()], result.status, result.message)

    stats: dict = {}
    try:
        with sigterm_as_interrupt():  # SIGTERM ends a matrix as Ctrl-C does: workers stopped, resumable
            ran = executors.run_matrix(cases, executor=args.executor, workers=args.workers, scheduler=args.scheduler,
                                       timeout_per_case=args.timeout_per_case, store_path=store, on_result=on_result,
                                       matrix=exp.name, resume=resume, series_dir=out / "series",
                                       retry_failed=args.retry_failed, schedule=getattr(args, "schedule", "cost"),
                                       history_stores=[DEFAULT_STORE], stats=stats)
    except UnstoredError as exc:  # the cases stored so far stay; --resume runs the rest once the store is fixed
        bar.close()
        print(f"bench-myriapoda: error: matrix stopped: {exc}; the cases stored before it are kept "
              f"(rerun with --resume)", file=sys.stderr)
        return EXIT_FAIL
    finally:
        bar.close()
    if ran:
        sched = run_summary(stats, ran, labels)
        write_run_summary(out / "matrix.json", sched)
    rows = executors.matrix_rows(store, exp.name).drop_duplicates("case_hash", keep="last")
    rows = rows[rows.case_hash.isin(labels)]
    axes_of = {}
    for mc in exp.cases:  # the first case of a hash, as a search in order would find it
        axes_of.setdefault(mc.case.case_hash(), mc.axes)
    table = []
    for _, r in rows.iterrows():
        m = json.loads(r.metrics_json)
        case = json.loads(r.case_json)
        axes = axes_of[r.case_hash]
        table.append({"case_hash": r.case_hash, **{k: v for k, v in axes.items()}, "dt": case["dt"],
                      "duration": case["duration"], "status": r.status, "message": r.message or "",
                      "labels_json": r.labels_json or "{}",
                      **{k: m.get(k) for k in TABLE_METRICS}, "steps_per_s": r.steps_per_s, "wall_s": r.wall_s,
                      **{f"metric.{k}": v for k, v in sorted(m.items())}})
    import pandas as pd  # only a matrix's table needs it (about 0.19 s of CPU); matrix_rows above imported it
    df = pd.DataFrame(table)
    df.to_csv(out / "results.csv", index=False)
    try:
        df.to_parquet(out / "results.parquet", index=False)
    except ImportError:  # pyarrow (or fastparquet) not installed: CSV only
        pass
    shown = [{**t, "axes": axes_of[t["case_hash"]]} for t in table]  # the grid point of each case
    for line in matrix_table_lines(shown, exp.grid_keys):
        print(line)
    missing = set(labels) - set(rows.case_hash)
    bad = sum(t["status"] in ("error", "timeout") for t in table)
    print(f"{len(table)} of {len(labels)} cases stored in {store}; {bad} error or timeout; table in {out / 'results.csv'}")
    if ran:
        print(sched["line"])
    if main_job:
        done = fidelity_phase(exp, out, args.workers, progress=(lambda m: print(f"main job: {m}", file=sys.stderr))
                              if sys.stderr.isatty() else None)
        print(f"stable dt of {done['brackets']} pairs (bisection, {out / 'stable_dt.json'}); {done['checks']} "
              f"validate --quick checks {'kept' if done['validation_kept'] else 'run'} ({out / 'validation.json'}); "
              f"{done['wall_s']:.0f} s")
        if not (bad or missing):
            write_marker(out, exp.name)
    if args.report:
        from ..report import build  # pandas and matplotlib (about 0.65 s, check_outputs): only --report pays
        # the matrix's cores are free now: its --workers draw the figures (figure_pool; dask: this machine's)
        workers = args.workers or os.cpu_count() or 1
        summary = build.build_report(out, history_store=DEFAULT_STORE, workers=workers)
        print(f"report written to {summary.index} ({len(summary.figures)} figures)")
        print(closing_line(shown, exp.grid_keys, summary.index, summary.verdicts))
    else:
        print(closing_line(shown, exp.grid_keys, None) + f"; write the report with `bench-myriapoda report {out}`")
    return EXIT_FAIL if bad or missing else EXIT_OK
