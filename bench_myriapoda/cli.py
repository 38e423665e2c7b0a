"""``bench-myriapoda``: the command line.

    bench-myriapoda                      run the default quick set of cases, print a table, store results
    bench-myriapoda list [--json]        creatures, bodies, gaits, scenarios, supported combinations
    bench-myriapoda run --creature C --body B --scenario S [...]   one case
    bench-myriapoda stable-dt --creature C --body B --scenario S [...]   largest stable dt
    bench-myriapoda matrix FILE [--executor local|dask] [--resume] [...]  a whole scenario matrix

Bad input gives one line on stderr naming the file or flag, the key and what
is allowed, and exit code 2, before anything is written.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any, Sequence

from .core import registry
from .core.config import creature_names, load_creature_file, resolve_case, scenario_paths
from .core.errors import InputError
from .harness.progress import ProgressBar

EXIT_OK, EXIT_FAIL, EXIT_BAD_INPUT = 0, 1, 2

# The default quick set: Miller's gaits on the lattice, the FEM worm, and the paper's centipede.
QUICK_CASES = (
    ("worm", "massspring", "flat", "rectilinear", 20.0),
    ("worm", "massspring", "cliff", "rectilinear", 30.0),
    ("snake", "massspring", "flat", "lateral-undulation", 16.0),
    ("snake", "massspring", "flat", "sidewinding", 16.0),
    ("caterpillar", "massspring", "slope", "arching", 16.0),
    ("worm", "fem", "flat", "rectilinear", 20.0),
    ("centipede", "hybrid", "walk", "leg-wave", 6.0),
)

TABLE_METRICS = ("speed_bl_per_cycle", "speed_m_per_s", "travel_angle_deg", "slip_ratio",
                 "path_following_error_bl", "contact_fraction", "t_fail_s")


class _Parser(argparse.ArgumentParser):
    """argparse that reports bad flags as an InputError (one line, exit 2)."""

    def error(self, message: str):
        raise InputError(self.prog, None, message)


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="bench-myriapoda", description="Benchmark suite for simulated myriapods, worms and snakes.")
    sub = p.add_subparsers(dest="command", parser_class=_Parser)

    ls = sub.add_parser("list", help="creatures, bodies, gaits, scenarios and supported combinations")
    ls.add_argument("--json", action="store_true", help="print one JSON object")

    run = sub.add_parser("run", help="run one case")
    _case_arguments(run)
    run.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    run.add_argument("--record", metavar="FILE.npz", help="save the recorded time series (all node positions)")
    run.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    run.add_argument("--no-store", action="store_true", help="do not record the run in the results database")
    run.add_argument("--strict", action="store_true", help="exit 1 when the run is unstable")
    run.add_argument("--plot-gait", metavar="FILE.png", help="draw the gait diagram (legs x time, paper Fig. 10)")

    sd = sub.add_parser("stable-dt", help="largest time step for which a case stays stable (bisection)")
    _case_arguments(sd)
    sd.add_argument("--rel-tol", type=float, default=0.05, help="stop when the bracket is tighter than this (default 0.05)")
    sd.add_argument("--max-runs", type=int, default=24, help="at most this many runs (default 24)")
    sd.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    sd.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    sd.add_argument("--no-store", action="store_true", help="do not record the result in the results database")

    q = sub.add_parser("quick", help="run the default quick set of cases (also what no arguments do)")
    q.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    q.add_argument("--json", action="store_true", help="print one JSON object per case, one per line")

    mx = sub.add_parser("matrix", help="run a scenario matrix (scenarios/matrix/NAME.toml) on a process pool or Dask")
    mx.add_argument("file", metavar="FILE", help="matrix file (.toml) or a name in scenarios/matrix/")
    mx.add_argument("--executor", choices=("local", "dask"), default="local",
                    help="local: a process pool on this machine (default); dask: a dask.distributed cluster")
    mx.add_argument("--workers", type=int, metavar="N", default=None, help="worker processes (default: CPU count)")
    mx.add_argument("--scheduler", metavar="ADDRESS", default=None,
                    help="dask scheduler address (default: start a LocalCluster)")
    mx.add_argument("--resume", action="store_true", help="run only the cases without a result in the store")
    mx.add_argument("--timeout-per-case", type=float, metavar="SECONDS", default=None,
                    help="record a case that runs longer as status timeout and stop its worker")
    mx.add_argument("--out", metavar="DIR", default=None,
                    help="results.sqlite and results.csv go here (default reports/matrix/NAME)")
    return p


def _case_arguments(p: argparse.ArgumentParser) -> None:
    """The flags that select and configure one case (shared by run and stable-dt)."""
    p.add_argument("--creature", required=True, help="creature name (models/NAME.toml) or a .toml path")
    p.add_argument("--body", required=True, help="body model: " + ", ".join(sorted(_bodies())))
    p.add_argument("--scenario", required=True, help="scenario name (scenarios/NAME.toml) or a .toml path")
    p.add_argument("--gait", help="gait (default: the creature's default gait)")
    p.add_argument("--duration", type=float, metavar="SECONDS", help="simulated time [s]")
    p.add_argument("--dt", type=float, metavar="SECONDS", help="time step [s]")
    p.add_argument("--seed", type=int, metavar="N", help="random seed")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="override a configuration key by dotted path, e.g. friction.mu_transverse=0.2")


def _resolve(args):
    return resolve_case(args.creature, args.body, args.scenario, args.gait, duration=args.duration, dt=args.dt,
                        seed=args.seed, overrides=args.set)


def _bodies() -> list[str]:
    registry.load_all()
    return list(registry.BODIES)


# --------------------------------------------------------------------------- list

def catalogue() -> dict[str, Any]:
    """Everything ``list`` reports, as plain data."""
    registry.load_all()
    creatures, combos = {}, []
    for name in creature_names():
        path, data = load_creature_file(name)
        c = data["creature"]
        gaits = list(c.get("gaits", [c.get("default_gait")]))
        bodies = sorted(data.get("bodies", {}))
        creatures[name] = {"description": c.get("description", ""), "default_gait": c.get("default_gait"),
                           "gaits": gaits, "bodies": bodies, "file": str(path)}
        for b in bodies:
            for g in gaits:
                if not (registry.GAITS[g].requires - registry.BODIES[b].capabilities):
                    combos.append({"creature": name, "body": b, "gait": g})
    scenarios = {}
    from .core.config import read_toml
    for name, path in scenario_paths().items():
        scenarios[name] = {"description": read_toml(path).get("scenario", {}).get("description", ""), "file": str(path)}
    return {
        "creatures": creatures,
        "bodies": {n: {"description": s.description, "capabilities": sorted(s.capabilities)}
                   for n, s in sorted(registry.BODIES.items())},
        "gaits": {n: {"description": s.description, "requires": sorted(s.requires)} for n, s in sorted(registry.GAITS.items())},
        "scenarios": scenarios,
        "supported": combos,
    }


def cmd_list(args) -> int:
    cat = catalogue()
    if args.json:
        print(json.dumps(cat, indent=2))
        return EXIT_OK
    print("creatures:")
    for n, c in cat["creatures"].items():
        print(f"  {n:<14} gaits: {', '.join(c['gaits'])} (default {c['default_gait']}); bodies: {', '.join(c['bodies'])}")
    print("bodies:")
    for n, b in cat["bodies"].items():
        print(f"  {n:<14} {b['description']}")
    print("gaits:")
    for n, g in cat["gaits"].items():
        print(f"  {n:<20} {g['description']}")
    print("scenarios:")
    for n, s in cat["scenarios"].items():
        print(f"  {n:<14} {s['description']}")
    print("supported (creature, body, gait):")
    for c in cat["supported"]:
        print(f"  {c['creature']}, {c['body']}, {c['gait']}")
    return EXIT_OK


# --------------------------------------------------------------------------- run

def _fmt(v: Any) -> str:
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "-"
    if isinstance(v, float):
        return f"{v:.4g}"
    return str(v)


def print_result_table(result) -> None:
    d = result.to_json_dict()
    c = d["case"]
    print(f"case {result.case.case_hash()}: {c['creature']['name']} / {c['body']['name']} / {c['gait']['name']} / "
          f"{c['scenario']['name']}  dt={c['dt']:.3g} s  duration={c['duration']:.3g} s")
    print(f"status: {d['status']}" + (f" ({result.message})" if result.message else ""))
    width = max(len(k) for k in d["metrics"]) if d["metrics"] else 10
    for k in sorted(d["metrics"]):
        print(f"  {k:<{width}}  {_fmt(d['metrics'][k])}")
    t = d["timings"]
    print(f"  {'steps':<{width}}  {t['steps']}   steps/s {_fmt(t['steps_per_s'])}   realtime x{_fmt(t['realtime_factor'])}"
          f"   compile {_fmt(t['compile_s'])} s   wall {_fmt(t['wall_s'])} s")


def cmd_run(args) -> int:
    from .harness.recorder import save_npz
    from .harness.runner import run_case
    from .harness.store import DEFAULT_STORE, record_run

    if args.record and not args.record.endswith(".npz"):
        raise InputError("--record", None, f"{args.record!r}: the file name must end in .npz")
    if args.plot_gait and not args.plot_gait.endswith(".png"):
        raise InputError("--plot-gait", None, f"{args.plot_gait!r}: the file name must end in .png")
    case = _resolve(args)
    if args.plot_gait and not case.creature.legs_per_segment:
        raise InputError("--plot-gait", None, f"creature {case.creature.name!r} has no legs: no gait diagram")
    bar = ProgressBar(enabled=not args.json and sys.stdout.isatty(), label=f"{args.creature}/{args.body}")
    result = run_case(case, progress=bar.update, keep_nodes=bool(args.record))
    bar.close()
    if not args.no_store:
        record_run(args.store or DEFAULT_STORE, result, command="run")
    if args.record and result.series is not None:
        extra = {}
        if "leg_timeline" in result.extra:
            extra = dict(zip(("leg_t", "leg_states", "leg_tips"), result.extra["leg_timeline"]))
        save_npz(Path(args.record), result.series, case.to_dict(), extra)
    if args.plot_gait and "leg_timeline" in result.extra:
        from .report.gait_diagram import plot_gait_diagram
        t, states, _ = result.extra["leg_timeline"]
        if len(t):
            plot_gait_diagram(t, states, Path(args.plot_gait), last_seconds=1.0,
                              title=f"{case.creature.name} / {case.body.name} / {case.scenario.name}")
    if args.json:
        print(json.dumps(result.to_json_dict()))
    else:
        print_result_table(result)
    if result.status == "error":
        print(f"bench-myriapoda: run failed: {result.message}", file=sys.stderr)
        return EXIT_FAIL
    if result.status == "unstable" and args.strict:
        return EXIT_FAIL
    return EXIT_OK


def cmd_stable_dt(args) -> int:
    from .harness.runner import RunResult
    from .harness.stable_dt import find_stable_dt
    from .harness.store import DEFAULT_STORE, record_run

    if args.rel_tol <= 0:
        raise InputError("--rel-tol", None, f"{args.rel_tol} is out of range; must be > 0")
    if args.max_runs < 2:
        raise InputError("--max-runs", None, f"{args.max_runs} is out of range; must be >= 2")
    case = _resolve(args)
    show = not args.json and sys.stdout.isatty()

    def progress(dt, status):
        if show:
            print(f"  dt = {dt:.4g} s: {status}", file=sys.stderr)

    res = find_stable_dt(case, rel_tol=args.rel_tol, max_runs=args.max_runs, progress=progress)
    metrics = {"stable_dt_max_s": res.stable_dt_max_s, "unstable_dt_min_s": res.unstable_dt_min_s,
               "stable_dt_runs": float(len(res.trials))}
    result = RunResult(case, "ok", metrics, {"steps": 0, "steps_per_s": float("nan"), "realtime_factor": float("nan"),
                                             "compile_s": float("nan"), "wall_s": float("nan")})
    if not args.no_store:
        record_run(args.store or DEFAULT_STORE, result, command="stable-dt")
    if args.json:
        d = result.to_json_dict()
        d["trials"] = [{"dt": dt, "status": st, "t_fail_s": None if math.isnan(tf) else tf} for dt, st, tf in res.trials]
        print(json.dumps(d))
    else:
        for dt, st, tf in res.trials:
            print(f"  dt = {dt:.4g} s  {st}" + ("" if math.isnan(tf) else f" (failed at t = {tf:.3g} s)"))
        print(f"stable_dt_max_s = {_fmt(res.stable_dt_max_s)}   (smallest unstable dt: {_fmt(res.unstable_dt_min_s)})")
    return EXIT_OK


def cmd_quick(args) -> int:
    from .harness.runner import run_case
    from .harness.store import DEFAULT_STORE, record_run

    cases = [resolve_case(c, b, s, g, duration=d) for c, b, s, g, d in QUICK_CASES]  # validate all first
    store = args.store or DEFAULT_STORE
    rows, worst = [], EXIT_OK
    for case in cases:
        bar = ProgressBar(enabled=not args.json and sys.stdout.isatty(),
                          label=f"{case.creature.name}/{case.gait.name}/{case.scenario.name}")
        result = run_case(case, progress=bar.update)
        bar.close()
        record_run(store, result, command="quick")
        if args.json:
            print(json.dumps(result.to_json_dict()))
        rows.append(result)
        if result.status == "error":
            worst = EXIT_FAIL
    if not args.json:
        head = ["creature", "body", "gait", "scenario", "status", *TABLE_METRICS, "steps_per_s"]
        table = [head]
        for r in rows:
            m = r.to_json_dict()["metrics"]
            table.append([r.case.creature.name, r.case.body.name, r.case.gait.name, r.case.scenario.name, r.status,
                          *(_fmt(m.get(k)) for k in TABLE_METRICS), _fmt(r.timings.get("steps_per_s"))])
        widths = [max(len(str(row[i])) for row in table) for i in range(len(head))]
        for row in table:
            print("  ".join(str(v).ljust(w) for v, w in zip(row, widths)))
        print(f"results stored in {store}")
    return worst


def cmd_matrix(args) -> int:
    """Expand a matrix file, list what is not supported, run the rest, store and tabulate the results.

    Exit 0 when every case ran to a status ok or unstable, 1 when any case of the matrix (this run or an
    earlier one that --resume kept) is error or timeout, 2 for bad input (nothing written).
    """
    import time

    from .harness.executors import matrix_rows, run_matrix
    from .harness.matrix import expand_matrix, locate_matrix

    if args.workers is not None and args.workers < 1:
        raise InputError("--workers", None, f"{args.workers} is out of range; must be >= 1")
    if args.timeout_per_case is not None and not args.timeout_per_case > 0:
        raise InputError("--timeout-per-case", None, f"{args.timeout_per_case} is out of range; must be > 0")
    if args.scheduler and args.executor != "dask":
        raise InputError("--scheduler", None, "only meaningful with --executor dask")
    if args.executor == "dask":
        try:
            import dask.distributed  # noqa: F401
        except ImportError:
            raise InputError("--executor", None, "dask is not installed; pip install 'dask[distributed]'") from None
    exp = expand_matrix(locate_matrix(args.file))
    out = Path(args.out) if args.out else Path("reports") / "matrix" / exp.name
    if out.exists() and not out.is_dir():
        raise InputError("--out", None, f"{out} exists and is not a directory")
    store = out / "results.sqlite"
    print(f"matrix {exp.name}: {len(exp.cases)} cases ({exp.excluded} excluded, {exp.duplicates} duplicates, "
          f"{len(exp.unsupported)} unsupported combinations)")
    if exp.unsupported:
        print("unsupported combinations (not run):")
        for u in exp.unsupported:
            print(f"  {u}")
    if not exp.cases:
        raise InputError(str(exp.path), None, "no case left to run after exclusions and unsupported combinations")
    labels = {m.case.case_hash(): m.label for m in exp.cases}
    tty = sys.stderr.isatty()
    t0, failed = time.perf_counter(), 0

    def on_result(result, done, total):
        nonlocal failed
        failed += result.status in ("error", "timeout")
        if tty:
            el = time.perf_counter() - t0
            eta = el / done * (total - done)
            print(f"[{done}/{total}] failed {failed}  eta {eta:.0f}s  {labels[result.case.case_hash()]}: {result.status}"
                  + (f" ({result.message})" if result.message else ""), file=sys.stderr)

    cases = [m.case for m in exp.cases]
    run_matrix(cases, executor=args.executor, workers=args.workers, scheduler=args.scheduler,
               timeout_per_case=args.timeout_per_case, store_path=store, on_result=on_result, matrix=exp.name,
               resume=args.resume)
    rows = matrix_rows(store, exp.name).drop_duplicates("case_hash", keep="last")
    rows = rows[rows.case_hash.isin(labels)]
    table = []
    for _, r in rows.iterrows():
        m = json.loads(r.metrics_json)
        case = json.loads(r.case_json)
        axes = next(mc.axes for mc in exp.cases if mc.case.case_hash() == r.case_hash)
        table.append({"case_hash": r.case_hash, **{k: v for k, v in axes.items()}, "dt": case["dt"],
                      "duration": case["duration"], "status": r.status, "message": r.message or "",
                      **{k: m.get(k) for k in TABLE_METRICS}, "steps_per_s": r.steps_per_s, "wall_s": r.wall_s,
                      **{f"metric.{k}": v for k, v in sorted(m.items())}})
    import pandas as pd
    df = pd.DataFrame(table)
    df.to_csv(out / "results.csv", index=False)
    try:
        df.to_parquet(out / "results.parquet", index=False)
    except ImportError:  # pyarrow (or fastparquet) not installed: CSV only
        pass
    head = ["creature", "body", "gait", "scenario", "status", *TABLE_METRICS[:3], "steps_per_s"]
    lines = [head] + [[_fmt(t.get(k)) for k in head] for t in table]
    widths = [max(len(str(row[i])) for row in lines) for i in range(len(head))]
    for row in lines:
        print("  ".join(str(v).ljust(w) for v, w in zip(row, widths)))
    missing = set(labels) - set(rows.case_hash)
    bad = sum(t["status"] in ("error", "timeout") for t in table)
    print(f"{len(table)} of {len(labels)} cases stored in {store}; {bad} error or timeout; table in {out / 'results.csv'}")
    return EXIT_FAIL if bad or missing else EXIT_OK


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        parser = build_parser()
        args = parser.parse_args(argv or ["quick"])
        if args.command is None:
            args = parser.parse_args(["quick", *argv])
        return {"list": cmd_list, "run": cmd_run, "quick": cmd_quick, "stable-dt": cmd_stable_dt,
                "matrix": cmd_matrix}[args.command](args)
    except InputError as exc:
        print(f"bench-myriapoda: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("bench-myriapoda: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
