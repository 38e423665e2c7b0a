"""``bench-myriapoda``: the command line.

    bench-myriapoda                      run scenarios/matrix/quick.toml, write reports/quick/index.html
    bench-myriapoda list [--json]        creatures, bodies, gaits, scenarios, supported combinations
    bench-myriapoda run --creature C --body B --scenario S [...]   one case
    bench-myriapoda stable-dt --creature C --body B --scenario S [...]   largest stable dt
    bench-myriapoda matrix FILE [--executor local|dask] [--resume] [...]  a whole scenario matrix
    bench-myriapoda report DIR [--baseline DIR2]   index.html and summary.md of a matrix run
    bench-myriapoda regress [--baseline COMMIT_OR_RUN] [...]   throughput suite vs. the stored history
    bench-myriapoda validate [--body B ...] [--check NAME ...] [--quick] [--json] [--out DIR] [--work-precision]

Bad input gives one line on stderr naming the file or flag, the key and what
is allowed, and exit code 2, before anything is written.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
from pathlib import Path
from typing import Any, Sequence

from .core import registry
from .core.config import creature_names, load_creature_file, resolve_case, scenario_paths
from .core.errors import InputError
from .harness.progress import ProgressBar

EXIT_OK, EXIT_FAIL, EXIT_BAD_INPUT = 0, 1, 2

# What no arguments do: this matrix, written (with its report) to this directory.
QUICK_MATRIX = "quick"
QUICK_OUT = Path("reports") / "quick"

TABLE_METRICS = ("speed_bl_per_cycle", "speed_m_per_s", "travel_angle_deg", "slip_ratio",
                 "path_following_error_bl", "contact_fraction", "t_fail_s", "posture_fault")


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
    run.add_argument("--strict", action="store_true",
                     help="exit 1 when the run is unstable or a legless body flipped or left the ground (posture_fault)")
    run.add_argument("--plot-gait", metavar="FILE.png", help="draw the gait diagram (legs x time, paper Fig. 10)")
    run.add_argument("--animate", metavar="FILE", help="animation of the body from above and from the side "
                                                       "(.gif, or .mp4 with ffmpeg)")
    run.add_argument("--export-frames", metavar="DIR", help="one mesh per recorded sample (DIR/frame_00000.obj ...) "
                                                            "and DIR/frames.json, for Blender or Maya")
    run.add_argument("--frame-format", choices=("obj", "ply"), default=None,
                     help="mesh format of --export-frames (default obj)")

    sd = sub.add_parser("stable-dt", help="largest time step for which a case stays stable (bisection)")
    _case_arguments(sd)
    sd.add_argument("--rel-tol", type=float, default=0.05, help="stop when the bracket is tighter than this (default 0.05)")
    sd.add_argument("--max-runs", type=int, default=24, help="at most this many runs (default 24)")
    sd.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    sd.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    sd.add_argument("--no-store", action="store_true", help="do not record the result in the results database")

    q = sub.add_parser("quick", help="run scenarios/matrix/quick.toml and write reports/quick/index.html "
                                     "(also what no arguments do)")
    q.add_argument("--out", metavar="DIR", default=str(QUICK_OUT), help=f"output directory (default {QUICK_OUT})")
    q.add_argument("--workers", type=int, metavar="N", default=None, help="worker processes (default: CPU count)")

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
                    help="results.sqlite, results.csv, matrix.json and series/ go here (default reports/matrix/NAME)")
    mx.add_argument("--report", action="store_true", help="write DIR/index.html and DIR/summary.md when done")

    rp = sub.add_parser("report", help="write DIR/index.html and DIR/summary.md from a matrix output directory")
    rp.add_argument("dir", metavar="DIR", help="a directory written by `bench-myriapoda matrix FILE --out DIR`")
    rp.add_argument("--baseline", metavar="DIR2", default=None,
                    help="another matrix output directory to compare against; regressions are highlighted")
    rp.add_argument("--threshold", type=float, default=0.10, metavar="FRACTION",
                    help="relative change of a metric that counts (default 0.10; throughput: 0.15)")
    rp.add_argument("--history-store", metavar="PATH", default=None,
                    help="results store with the regress history to plot (default reports/results.sqlite)")
    rp.add_argument("--strict", action="store_true", help="exit 1 when the baseline comparison finds a regression")

    rg = sub.add_parser("regress", help="time the fixed throughput suite, store it, compare with a baseline run")
    rg.add_argument("--baseline", metavar="COMMIT_OR_RUN", default=None,
                    help="a regress run id or a git commit (prefix) with a run in the store "
                         "(default: the latest earlier run on this machine)")
    rg.add_argument("--repeats", type=int, metavar="N", default=7, help="timed repetitions per entry (default 7)")
    rg.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    rg.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    rg.add_argument("--threshold", type=float, metavar="FRACTION", default=0.10,
                    help="smallest drop of the normalized figure that counts as a regression (default 0.10; "
                         "raised to 3x the measured noise when that is larger)")
    rg.add_argument("--suite", nargs="+", action="extend", metavar="NAME", default=None,
                    help="run only these entries of the suite (default: all)")

    va = sub.add_parser("validate", help="verdicts against the papers and analytic references (exit 1 on a FAIL)")
    va.add_argument("--body", nargs="+", action="extend", metavar="B", default=None,
                    help="only these body models (default: all)")
    va.add_argument("--check", nargs="+", action="extend", metavar="NAME", default=None,
                    help="only these checks or families (analytic, miller, paper, cross_body, throughput)")
    va.add_argument("--quick", action="store_true", help="the quick set: small sizes, within 3 minutes on 2 cores")
    va.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    va.add_argument("--out", metavar="DIR", default=None,
                    help="validation.json and the work-precision PNGs go here (default reports/validation)")
    va.add_argument("--work-precision", action="store_true",
                    help="also sweep dt and resolution per body model and draw work-precision diagrams")
    va.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    va.add_argument("--no-store", action="store_true", help="do not record the rows in the results database")
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
    _check_frame_outputs(args)
    case = _resolve(args)
    if args.plot_gait and not case.creature.legs_per_segment:
        raise InputError("--plot-gait", None, f"creature {case.creature.name!r} has no legs: no gait diagram")
    frames, anim_stride = _frame_recorder(args, case)
    bar = ProgressBar(enabled=not args.json and sys.stdout.isatty(), label=f"{args.creature}/{args.body}")
    result = run_case(case, progress=bar.update, keep_nodes=bool(args.record), on_sample=frames)
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
    written = _write_frame_outputs(args, case, frames, anim_stride)
    if args.json:
        print(json.dumps(result.to_json_dict()))
    else:
        print_result_table(result)
    if result.status == "error":
        print(f"bench-myriapoda: run failed: {result.message}", file=sys.stderr)
        return EXIT_FAIL
    if not written:
        return EXIT_FAIL
    if args.strict and (result.status == "unstable" or result.metrics.get("posture_fault") == 1.0):
        if result.metrics.get("posture_fault") == 1.0:
            print("bench-myriapoda: posture fault: the body flipped over or left the ground "
                  "(metrics roll_max_deg, airborne_max_s)", file=sys.stderr)
        return EXIT_FAIL
    return EXIT_OK


def _check_frame_outputs(args) -> None:
    """Validate --animate, --export-frames and --frame-format before anything runs or is written."""
    if args.animate:
        from matplotlib.animation import FFMpegWriter

        from .report.animate import SUFFIXES

        suffix = Path(args.animate).suffix.lower()
        if suffix not in SUFFIXES:
            raise InputError("--animate", None, f"{args.animate!r}: the file name must end in .gif or .mp4")
        if suffix == ".mp4" and not FFMpegWriter.isAvailable():
            raise InputError("--animate", None, f"{args.animate!r}: writing .mp4 needs ffmpeg, which is not on PATH; "
                                                "install ffmpeg or write a .gif")
    if args.frame_format and not args.export_frames:
        raise InputError("--frame-format", None, "only meaningful with --export-frames")
    if args.export_frames:
        from .report.export_frames import check_out_dir

        try:
            check_out_dir(args.export_frames)
        except ValueError as exc:
            raise InputError("--export-frames", None, str(exc)) from None


def _frame_recorder(args, case):
    """(the runner's on_sample hook or None, every how many recorded frames the animation keeps one)."""
    if not (args.animate or args.export_frames):
        return None, 1
    from .report.animate import FrameRecorder, expected_samples, frame_stride, sample_period

    anim_stride = frame_stride(expected_samples(case), sample_period(case))
    if args.export_frames:  # the export wants every sample; the animation takes every anim_stride-th of them
        return FrameRecorder(1), anim_stride
    return FrameRecorder(anim_stride), 1


def _write_frame_outputs(args, case, frames, anim_stride: int) -> bool:
    """Write the animation and the exported frames of what was recorded (up to a blow-up, if any).

    Returns False (after one line on stderr) when a file could not be written; nothing half-written
    is left (both writers write to a temporary name and rename at the end).
    """
    if frames is None:
        return True
    note = sys.stderr if args.json else sys.stdout  # --json keeps stdout to exactly one JSON object
    if not frames.frames:
        print("bench-myriapoda: no frame was recorded; nothing animated or exported", file=sys.stderr)
        return False
    import subprocess

    try:
        if args.animate:
            from .report.animate import write_animation
            from .world.terrain import terrain_from_scenario

            terrain = None if case.scenario.terrain == "none" else terrain_from_scenario(case.scenario)
            title = f"{case.creature.name} / {case.body.name} / {case.gait.name} / {case.scenario.name}"
            water = frames.water()
            if water is not None:
                water = (water[0][::anim_stride], water[1])
            info = write_animation(frames.frames[::anim_stride], frames.times[::anim_stride], terrain,
                                   Path(args.animate), title=title, water=water)
            print(f"animation: {info['path']} ({info['frames']} frames at {info['fps']:.3g} fps)", file=note)
        if args.export_frames:
            from .report.export_frames import export_frames

            meta = export_frames(frames.frames, frames.times, case.to_dict(), Path(args.export_frames),
                                 args.frame_format or "obj")
            print(f"frames: {args.export_frames} ({meta['n_frames']} {meta['format']} files and frames.json)",
                  file=note)
    except (OSError, ValueError, subprocess.SubprocessError) as exc:  # full disk, ffmpeg failing, DIR filled
        print(f"bench-myriapoda: could not write the animation or frames: {exc}", file=sys.stderr)
        return False
    return True


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
    """The main job: the quick matrix on a local process pool, then its report."""
    ns = argparse.Namespace(file=QUICK_MATRIX, executor="local", workers=args.workers, scheduler=None, resume=False,
                            timeout_per_case=None, out=args.out, report=True)
    return cmd_matrix(ns)


def cmd_report(args) -> int:
    from .harness.store import DEFAULT_STORE
    from .report.build import build_report

    if not 0 < args.threshold < 10:
        raise InputError("--threshold", None, f"{args.threshold} is out of range; must be in (0, 10)")
    history = Path(args.history_store) if args.history_store else DEFAULT_STORE
    summary = build_report(args.dir, baseline=args.baseline, history_store=history, threshold=args.threshold)
    print(f"report written to {summary.index} and {summary.summary} ({len(summary.figures)} figures)")
    if args.baseline:
        print(f"{summary.regressions} regression(s) against {args.baseline}")
    return EXIT_FAIL if args.strict and summary.regressions else EXIT_OK


def cmd_matrix(args) -> int:
    """Expand a matrix file, list what is not supported, run the rest, store and tabulate the results.

    Exit 0 when every case ran to a status ok or unstable, 1 when any case of the matrix (this run or an
    earlier one that --resume kept) is error or timeout, 2 for bad input (nothing written).
    """
    import time

    from .harness.executors import matrix_rows, run_matrix
    from .harness.matrix import expand_matrix, locate_matrix, write_matrix_manifest

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
    write_matrix_manifest(out, exp)
    run_matrix(cases, executor=args.executor, workers=args.workers, scheduler=args.scheduler,
               timeout_per_case=args.timeout_per_case, store_path=store, on_result=on_result, matrix=exp.name,
               resume=args.resume, series_dir=out / "series")
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
    if args.report:
        from .harness.store import DEFAULT_STORE
        from .report.build import build_report
        summary = build_report(out, history_store=DEFAULT_STORE)
        print(f"report written to {summary.index} ({len(summary.figures)} figures)")
    return EXIT_FAIL if bad or missing else EXIT_OK


def cmd_regress(args) -> int:
    """Time the throughput suite, store it in ``regress_history``, compare with the baseline run.

    Exit 1 when any entry's normalized figure dropped beyond the noise-aware threshold, 0 otherwise
    (also with no baseline yet), 2 for bad input (nothing timed, nothing written).
    """
    from .harness import regress as R
    from .harness.machine import git_commit, machine_fingerprint
    from .harness.store import DEFAULT_STORE, record_regress_run

    repeats = R.check_repeats(args.repeats)
    threshold = R.check_threshold(args.threshold)
    names = R.check_suite_names(args.suite)
    store = Path(args.store) if args.store else DEFAULT_STORE
    if store.exists() and not store.is_file():
        raise InputError("--store", None, f"{store} exists and is not a file")
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
    run_id = record_regress_run(store, [r.row() for r in results])
    rows = R.compare(results, base, threshold)
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
    return EXIT_FAIL if regressed else EXIT_OK


class _stdout_to_stderr:
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


def cmd_validate(args) -> int:
    """Run the validation checks; exit 1 when any check FAILs, 0 otherwise, 2 for bad input (nothing run)."""
    import time

    from .harness.store import DEFAULT_STORE, record_validation_run
    from .validation import run as V
    from .validation.core import clean

    pairs, bodies = V.select(args.check, args.body, args.quick)
    store = Path(args.store) if args.store else DEFAULT_STORE
    if not args.no_store and store.exists() and not store.is_file():
        raise InputError("--store", None, f"{store} exists and is not a file")
    out_dir = Path(args.out) if args.out else V.DEFAULT_OUT
    if out_dir.exists() and not out_dir.is_dir():
        raise InputError("--out", None, f"{out_dir} exists and is not a directory")
    tty = not args.json and sys.stderr.isatty()
    t0 = time.perf_counter()
    # compiled libraries (LAPACK on a blown-up run's NaNs) print to file descriptor 1 directly: while the
    # checks run, fd 1 points at stderr, so that --json's stdout holds exactly one JSON object
    with _stdout_to_stderr():
        rows = V.run_checks(pairs, args.quick, bodies,
                            progress=(lambda m: print(f"validate: {m}", file=sys.stderr)) if tty else None)
        wp = None
        if args.work_precision:
            from .validation.work_precision import run_work_precision
            wp = run_work_precision(out_dir, bodies, args.quick, progress=(
                lambda m: print(f"work-precision: {m}", file=sys.stderr)) if tty else None)
    wall = time.perf_counter() - t0
    dicts = [r.to_dict() for r in rows]
    counts = V.summary(rows)
    doc = clean({"quick": bool(args.quick), "bodies": list(bodies), "wall_s": wall, "counts": counts,
                 "rows": dicts, "work_precision": wp})
    run_id = None
    if not args.no_store:
        run_id = record_validation_run(store, dicts, args.quick, str(out_dir))
    doc["run_id"] = run_id
    V.write_json(out_dir, doc)
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
    return EXIT_FAIL if failed else EXIT_OK


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        parser = build_parser()
        args = parser.parse_args(argv or ["quick"])
        if args.command is None:
            args = parser.parse_args(["quick", *argv])
        return {"list": cmd_list, "run": cmd_run, "quick": cmd_quick, "stable-dt": cmd_stable_dt,
                "matrix": cmd_matrix, "report": cmd_report, "regress": cmd_regress,
                "validate": cmd_validate}[args.command](args)
    except InputError as exc:
        print(f"bench-myriapoda: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("bench-myriapoda: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
