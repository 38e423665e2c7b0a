"""``bench-myriapoda``: the command line.

    bench-myriapoda                      run scenarios/matrix/quick.toml, write reports/quick/index.html
    bench-myriapoda list [--json]        creatures, bodies, gaits, scenarios, supported combinations
    bench-myriapoda run --creature C --body B --scenario S [...]   one case
    bench-myriapoda stable-dt --creature C --body B --scenario S [...]   largest stable dt
    bench-myriapoda matrix FILE [--executor local|dask] [--resume] [...]  a whole scenario matrix
    bench-myriapoda report DIR [--baseline DIR2]   index.html and summary.md of a matrix run
    bench-myriapoda regress [--baseline COMMIT_OR_RUN] [...]   throughput suite vs. the stored history
    bench-myriapoda keys [SECTION] [--json]   every configuration key --set accepts, described
    bench-myriapoda peers [--repeats N] [--store PATH] [--json]   MuJoCo flex and PyElastica side by side (extra [peers])
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
from .cli_help import QUICK_SET_TIME, _para, help_text, validate_description
from .core.errors import InputError
from .harness.progress import MatrixProgress, ProgressBar

EXIT_OK, EXIT_FAIL, EXIT_BAD_INPUT = 0, 1, 2
EXIT_CLOSED_PIPE = 128 + 13  # what a shell reports for a process ended by SIGPIPE

# What no arguments do: this matrix, written (with its report) to this directory.
QUICK_MATRIX = "quick"
QUICK_OUT = Path("reports") / "quick"

MAIN_DESCRIPTION = """A research benchmark suite for simulated creatures: Miller's worms and snakes (SIGGRAPH 1988) and
    Fang, Jiang and Terzopoulos's myriapods (SCA 2013) on interchangeable body models (mass-spring lattice, FEM,
    rigid/FEM hybrid). It measures speed, gait quality, stability and throughput and stores every run. With no
    arguments it runs the quick matrix and writes reports/quick/index.html. `bench-myriapoda COMMAND --help`
    describes each command."""
MAIN_EPILOG = """examples:
  bench-myriapoda
  bench-myriapoda list
  bench-myriapoda run --creature worm --body massspring --scenario flat
  bench-myriapoda validate --quick
  bench-myriapoda run --help
"""

TABLE_METRICS = ("speed_bl_per_cycle", "speed_m_per_s", "travel_angle_deg", "slip_ratio",
                 "path_following_error_bl", "contact_fraction", "t_fail_s", "posture_fault")


class _Parser(argparse.ArgumentParser):
    """argparse that reports bad flags as an InputError (one line, exit 2, the program named once), with a
    suggestion for a misspelt subcommand or flag; ``describe`` fills the description when help is printed."""

    describe = None

    def parse_known_args(self, args=None, namespace=None):
        self._argv = list(sys.argv[1:] if args is None else args)
        return super().parse_known_args(args, namespace)

    def format_help(self) -> str:
        if self.describe is not None:
            self.description = self.describe()
        return super().format_help()

    def error(self, message: str):
        from .core.suggest import did_you_mean

        # the top-level parser's prog is the program itself, which the caller prints once already
        where = self.prog.removeprefix("bench-myriapoda").strip() or "arguments"
        if where == "arguments" and message.startswith("argument ") and ": " in message:
            where, message = message.split(": ", 1)
        commands = next((a.choices for a in self._actions if isinstance(a, argparse._SubParsersAction)), {})
        if "invalid choice" in message and commands:
            word = message.split("invalid choice: ", 1)[1].split(" (", 1)[0].strip("'\"")
            message += did_you_mean(word, commands)
        elif message.startswith("unrecognized arguments"):
            argv = getattr(self, "_argv", [])
            sub = commands.get(next((a for a in argv if a in commands), None), self)
            flags = [o for a in sub._actions for o in a.option_strings]
            word = next((w.split("=", 1)[0] for w in message.split(":", 1)[1].split() if w.startswith("-")), "")
            if sub is not self:
                where = sub.prog.removeprefix("bench-myriapoda").strip()
            message += did_you_mean(word, flags)
        raise InputError(where, None, message)


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="bench-myriapoda", description=_para(MAIN_DESCRIPTION), epilog=MAIN_EPILOG,
                formatter_class=argparse.RawDescriptionHelpFormatter)
    _version_argument(p)
    sub = p.add_subparsers(dest="command", parser_class=_Parser)

    ls = sub.add_parser("list", help="creatures, bodies, gaits, scenarios and supported combinations",
                        **help_text("list"))
    ls.add_argument("--json", action="store_true", help="print one JSON object")

    run = sub.add_parser("run", help="run one case", **_run_help_text())
    _case_arguments(run)
    run.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    run.add_argument("--record", metavar="FILE.npz", help="save the recorded time series (all node positions)")
    run.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    run.add_argument("--no-store", action="store_true", help="do not record the run in the results database")
    run.add_argument("--strict", action="store_true",
                     help="exit 1 when the run is unstable or controller_unstable or a legless body flipped or left "
                          "the ground (posture_fault)")
    run.add_argument("--plot-gait", metavar="FILE.png", help="draw the gait diagram (legs x time, paper Fig. 10)")
    run.add_argument("--animate", metavar="FILE", help="animation of the body from above and from the side "
                                                       "(.gif, or .mp4 with ffmpeg)")
    run.add_argument("--export-frames", metavar="DIR", help="one mesh per recorded sample (DIR/frame_00000.obj ...) "
                                                            "and DIR/frames.json, for Blender or Maya")
    run.add_argument("--frame-format", choices=("obj", "ply"), default=None,
                     help="mesh format of --export-frames (default obj)")
    run.add_argument("--size", metavar="WxH", default=None,
                     help="pixel size of the --animate picture, e.g. 1280x720 (default: 1040 px wide for the 2-D "
                          "view, 1040x720 for the 3-D view; even numbers for .mp4)")
    run.add_argument("--view", choices=("2d", "3d"), default=None,
                     help="--animate view: 2d = from above and from the side (default); 3d = a shaded perspective "
                          "view whose camera follows the creature")
    _budget_arguments(run)

    sd = sub.add_parser("stable-dt", help="largest time step for which a case stays stable (bisection)",
                        **help_text("stable-dt"))
    _case_arguments(sd)
    sd.add_argument("--rel-tol", type=float, default=0.05, help="stop when the bracket is tighter than this (default 0.05)")
    sd.add_argument("--max-runs", type=int, default=24, help="at most this many runs (default 24)")
    sd.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    sd.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    sd.add_argument("--no-store", action="store_true", help="do not record the result in the results database")
    _budget_arguments(sd)

    q = sub.add_parser("quick", help="run scenarios/matrix/quick.toml and write reports/quick/index.html "
                                     "(also what no arguments do)", **help_text("quick"))
    q.add_argument("--out", metavar="DIR", default=str(QUICK_OUT), help=f"output directory (default {QUICK_OUT})")
    q.add_argument("--workers", type=int, metavar="N", default=None, help="worker processes (default: CPU count)")

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
    _budget_arguments(mx)

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

    _scorecard_parser(sub)
    _keys_parser(sub)
    pe = sub.add_parser("peers", help="time MuJoCo flex and PyElastica's snake side by side with ours (extra [peers])",
                        **help_text("peers"))
    pe.add_argument("--repeats", type=int, metavar="N", default=5, help="timed repetitions per entry (default 5)")
    pe.add_argument("--store", metavar="PATH", default=None, help="results database (default reports/results.sqlite)")
    pe.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
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
    return p


def _fraction(text: str) -> float:
    """A number flag's value; one so small it reads as 0 (``5e-400``) is refused, not taken as 0."""
    value = float(text)  # ValueError: argparse says "invalid _fraction value"
    mantissa = text.strip().lower().split("e")[0]
    if value == 0.0 and any(ch in "123456789" for ch in mantissa):
        raise argparse.ArgumentTypeError(f"{text} is too small to tell from 0 (below 1e-308); give 0 or a "
                                         "larger number")
    return value


def _case_arguments(p: argparse.ArgumentParser) -> None:
    """The flags that select and configure one case (shared by run and stable-dt)."""
    p.add_argument("--creature", required=True, help="creature name (models/NAME.toml) or a .toml path")
    p.add_argument("--body", required=True, help="body model: " + ", ".join(sorted(_bodies())))
    p.add_argument("--scenario", required=True, help="scenario name (scenarios/NAME.toml) or a .toml path")
    p.add_argument("--gait", help="gait (default: the creature's default gait)")
    p.add_argument("--duration", type=float, metavar="SECONDS",
                   help="simulated time [s] (default: the scenario's scenario.duration_s)")
    p.add_argument("--dt", type=float, metavar="SECONDS", help="time step [s] (default: the body model's)")
    p.add_argument("--seed", type=int, metavar="N", help="random seed (default 0)")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="override a configuration key by dotted path, e.g. friction.mu_transverse=0.2 "
                        "(repeatable; `bench-myriapoda keys` lists them all)")


def _budget_arguments(p: argparse.ArgumentParser) -> None:
    """The resource budget a case must fit before it runs (core/feasibility.py)."""
    p.add_argument("--force", action="store_true", help="run a case even when its resource estimate exceeds "
                                                        "the budget below")
    p.add_argument("--memory-budget", type=float, metavar="GB", default=None,
                   help="refuse a case estimated to need more memory (default: half of this machine's)")
    p.add_argument("--max-steps", type=float, metavar="N", default=None,
                   help="refuse a case of more time steps (duration / dt; default 1e9)")


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
    for section, width in (("bodies", 14), ("gaits", 20), ("scenarios", 14)):
        print(f"{section}:")
        for n, entry in cat[section].items():
            print(f"  {n:<{width}} {entry['description']}")
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
    labels = d.get("labels", {})  # a coded metric (brain_mode_final) prints its label, as the JSON has it
    names = sorted(set(d["metrics"]) | set(labels))
    width = max(len(k) for k in names) if names else 10
    short = set(too_short_metrics(result)) if labels.get("too_short") else set()
    for k in names:
        v = labels[k] if k in labels else ("too short" if k in short else _fmt(d["metrics"][k]))
        print(f"  {k:<{width}}  {v}")
    t = d["timings"]
    print(f"  {'steps':<{width}}  {t['steps']}   steps/s {_fmt(t['steps_per_s'])}   realtime x{_fmt(t['realtime_factor'])}"
          f"   compile {_fmt(t['compile_s'])} s   wall {_fmt(t['wall_s'])} s")


def too_short_metrics(result) -> tuple[str, ...]:
    """The metrics a too-short run leaves NaN (``metrics.locomotion.STEADY_METRICS``, ``metrics.walk``)."""
    from .metrics.locomotion import STEADY_METRICS
    from .metrics.walk import EMERGENT_WALK_METRICS
    return EMERGENT_WALK_METRICS if result.case.creature.legs_per_segment else STEADY_METRICS


def cmd_run(args) -> int:
    from .harness.recorder import save_npz
    from .harness.runner import run_case
    from .harness.store import DEFAULT_STORE, record_run

    _check_path_flags(args, "--store", "--record", "--plot-gait", "--animate", "--export-frames")
    if args.record and not args.record.endswith(".npz"):
        raise InputError("--record", None, f"{args.record!r}: the file name must end in .npz")
    if args.plot_gait and not args.plot_gait.endswith(".png"):
        raise InputError("--plot-gait", None, f"{args.plot_gait!r}: the file name must end in .png")
    _check_run_outputs(args)
    _check_frame_outputs(args)
    for flag in ("--plot-gait", "--animate"):
        if getattr(args, flag[2:].replace("-", "_")):
            _check_drawing(flag)
    case = _resolve(args)
    if args.plot_gait and not case.creature.legs_per_segment:
        raise InputError("--plot-gait", None, f"creature {case.creature.name!r} has no legs: no gait diagram")
    world = _check_case_fits(case, args, _case_source(args),
                             keep_nodes=bool(args.record or args.animate or args.export_frames))
    frames, anim_stride = _frame_recorder(args, case)
    bar = ProgressBar(enabled=not args.json and sys.stderr.isatty(), label=f"{case.creature.name}/{case.body.name}",
                      total_s=case.duration, dt=case.dt)
    result = run_case(case, progress=bar.update, keep_nodes=bool(args.record), on_sample=frames, world=world)
    bar.close()
    # From here on nothing may raise before the result is printed: a failed write keeps the result (stored
    # elsewhere, printed) and says so in a line; the exit code is then 1.
    failed: list[str] = []  # one line each: the store, --record, --plot-gait
    run_id = None
    if not args.no_store:
        store = args.store or DEFAULT_STORE
        run_id, unstored = _store_or_keep(store, "run", lambda: record_run(store, result, command="run"),
                                          result.to_json_dict)
        failed += [unstored] if unstored else []
    if args.record and result.series is not None:
        def record():
            extra = {}
            if "leg_timeline" in result.extra:
                extra = dict(zip(("leg_t", "leg_states", "leg_tips"), result.extra["leg_timeline"]))
            save_npz(Path(args.record), result.series, case.to_dict(), extra)
        failed += filter(None, [_write_after_the_run("--record", args.record, record)])
    if args.plot_gait and "leg_timeline" in result.extra:
        def plot():
            from .report.gait_diagram import plot_gait_diagram
            t, states, _ = result.extra["leg_timeline"]
            if len(t):
                plot_gait_diagram(t, states, Path(args.plot_gait), last_seconds=1.0,
                                  title=f"{case.creature.name} / {case.body.name} / {case.scenario.name}")
        failed += filter(None, [_write_after_the_run("--plot-gait", args.plot_gait, plot)])
    try:
        written = _write_frame_outputs(args, case, frames, anim_stride, world)
    except Exception as exc:  # anything _write_frame_outputs does not expect: the result is still printed
        print(f"bench-myriapoda: could not write the animation or frames ({type(exc).__name__}: {exc})",
              file=sys.stderr)
        written = False
    if args.json:
        print(json.dumps(result.to_json_dict()))
    else:
        print_result_table(result)
        if run_id is not None:  # where the result went (--json keeps stdout to the one object)
            print(f"stored in {args.store or DEFAULT_STORE} (run id {run_id})")
    for line in failed:
        print(f"bench-myriapoda: error: {line}", file=sys.stderr)
    if failed:
        return EXIT_FAIL
    if result.status == "error":
        print(f"bench-myriapoda: run failed: {result.message}", file=sys.stderr)
        return EXIT_FAIL
    if not written:
        return EXIT_FAIL
    if args.strict and (result.status in ("unstable", "controller_unstable") or result.metrics.get("posture_fault") == 1.0):
        if result.metrics.get("posture_fault") == 1.0:
            print("bench-myriapoda: posture fault: the body flipped over or left the ground "
                  "(metrics roll_max_deg, airborne_max_s)", file=sys.stderr)
        return EXIT_FAIL
    return EXIT_OK


def _write_after_the_run(flag: str, path: str, write) -> str | None:
    """``write()`` one output file of a finished run; None, or the line saying why it failed.  Any exception
    is caught: after the simulation a traceback would lose the computed result, which is printed and
    stored whatever happened to this file."""
    try:
        write()
        return None
    except Exception as exc:
        why = exc.strerror if isinstance(exc, OSError) and exc.strerror else f"{type(exc).__name__}: {exc}"
        return f"could not write {flag} {path} ({why})"


def _check_drawing(flag: str) -> None:
    """matplotlib can be imported before a run that draws (``--plot-gait``, ``--animate``): an ``MPLBACKEND``
    naming no backend makes its import raise, which after the run would have lost the result."""
    try:
        import matplotlib  # noqa: F401
    except ValueError as exc:
        if "backend" in str(exc).lower():
            raise InputError("MPLBACKEND", None, f"{os.environ.get('MPLBACKEND', '')!r} is not a matplotlib backend "
                                                 f"({flag} draws with matplotlib); unset it or set it to agg") from None
        raise InputError(flag, None, f"matplotlib cannot be imported ({exc})") from None
    except ImportError as exc:
        raise InputError(flag, None, f"matplotlib cannot be imported ({exc})") from None


def _check_frame_outputs(args) -> None:
    """Validate --animate, --export-frames and --frame-format before anything runs or is written."""
    for flag, value in (("--size", args.size), ("--view", args.view)):
        if value is not None and not args.animate:
            raise InputError(flag, None, "only meaningful with --animate")
    if args.size is not None:
        from .report.animate import parse_size

        try:
            w, h = parse_size(args.size)
        except ValueError as exc:
            raise InputError("--size", None, str(exc)) from None
        if Path(args.animate).suffix.lower() == ".mp4" and (w % 2 or h % 2):
            raise InputError("--size", None, f"{args.size!r}: an .mp4 (H.264, yuv420p) needs an even width and height")
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
    from .report.animate import GIF_TICK_S, FrameRecorder, expected_samples, frame_stride, sample_period

    # a GIF shows frames for whole centiseconds: choose the stride so every frame interval is one
    tick = GIF_TICK_S if args.animate and Path(args.animate).suffix.lower() == ".gif" else None
    anim_stride = frame_stride(expected_samples(case), sample_period(case), tick_s=tick) if args.animate else 1
    if args.export_frames:  # the export wants every sample; the animation takes every anim_stride-th of them
        return FrameRecorder(1), anim_stride
    return FrameRecorder(anim_stride), 1


def _write_frame_outputs(args, case, frames, anim_stride: int, world) -> bool:
    """Write the animation and the exported frames of what was recorded (up to a blow-up, if any), over the
    run's ``world`` (``world.world.World``, the one the placement check built).

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
            from .report.animate import parse_size, write_animation
            terrain = None if world.terrain_none else world.terrain
            title = f"{case.creature.name} / {case.body.name} / {case.gait.name} / {case.scenario.name}"
            water = frames.water()
            if water is not None:
                water = (water[0][::anim_stride], water[1])
            info = write_animation(frames.frames[::anim_stride], frames.times[::anim_stride], terrain,
                                   Path(args.animate), title=title, water=water,
                                   size=parse_size(args.size) if args.size else None, view=args.view or "2d")
            w, h = info["size"]
            print(f"animation: {info['path']} ({info['frames']} frames at {info['fps']:.3g} fps, {w}x{h} px)",
                  file=note)
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

    if not (math.isfinite(args.rel_tol) and 0 < args.rel_tol < 1):  # a relative bracket width: 1 would stop at once
        raise InputError("--rel-tol", None, f"{args.rel_tol} is out of range; must be a number > 0 and < 1 "
                                            "(the bracket's width relative to dt)")
    if not 2 <= args.max_runs <= 1000:
        raise InputError("--max-runs", None, f"{args.max_runs} is out of range; must be 2 to 1000")
    _check_path_flags(args, "--store")
    if not args.no_store:
        from .harness.store import DEFAULT_STORE, check_store
        check_store(args.store or DEFAULT_STORE, "--store")
    case = _resolve(args)
    world = _check_case_fits(case, args, _case_source(args))
    show = not args.json and sys.stdout.isatty()

    def progress(dt, status):
        if show:
            print(f"  dt = {dt:.4g} s: {status}", file=sys.stderr)

    res = find_stable_dt(case, rel_tol=args.rel_tol, max_runs=args.max_runs, progress=progress, world=world)
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
        _, unstored = _store_or_keep(store, "stable-dt result", lambda: record_run(store, result, command="stable-dt"),
                                     lambda: d)
    if args.json:
        print(json.dumps(d))
    else:
        for dt, st, tf in res.trials:
            print(f"  dt = {dt:.4g} s  {st}" + ("" if math.isnan(tf) else f" (failed at t = {tf:.3g} s)"))
        print(f"stable_dt_max_s = {_fmt(res.stable_dt_max_s)}   (smallest unstable dt: {_fmt(res.unstable_dt_min_s)})")
    if unstored:
        print(f"bench-myriapoda: error: {unstored}", file=sys.stderr)
        return EXIT_FAIL
    if res.error:
        print(f"bench-myriapoda: stable-dt stopped: {res.error.splitlines()[0]}", file=sys.stderr)
        return EXIT_FAIL
    return EXIT_OK


def cmd_quick(args) -> int:
    """The main job: the quick matrix on a local process pool, the stable-dt bracket of every headline pair and
    the validate --quick checks that apply to its pairs (``report.main_job``), then its report.  A rerun of
    the same code keeps the cases, brackets and verdicts of the last complete run in DIR (``main_job=True``)."""
    ns = argparse.Namespace(file=QUICK_MATRIX, executor="local", workers=args.workers, scheduler=None, resume=False,
                            schedule="cost",
                            timeout_per_case=None, out=args.out, report=True, retry_failed=False, dask_timeout=None,
                            force=False, memory_budget=None, max_steps=None, main_job=True)
    return cmd_matrix(ns)


def cmd_report(args) -> int:
    from .harness.store import DEFAULT_STORE
    from .report.build import build_report

    if not 0 < args.threshold < 10:
        raise InputError("--threshold", None, f"{args.threshold} is out of range; must be in (0, 10)")
    if args.workers is not None and not 1 <= args.workers <= MAX_WORKERS:
        raise InputError("--workers", None, f"{args.workers} is out of range; must be 1 to {MAX_WORKERS}")
    _check_path_flags(args, "--history-store", "--baseline")
    from .report.inputs import check_history_store
    check_history_store(args.history_store)  # the same check as scorecard's, the default store included
    history = Path(args.history_store) if args.history_store else DEFAULT_STORE
    try:
        summary = build_report(args.dir, baseline=args.baseline, history_store=history, threshold=args.threshold,
                               workers=args.workers or os.cpu_count() or 1)
    except OSError as exc:  # the disk filled while the figures were written: the old page stays as it was
        print(f"bench-myriapoda: error: report: could not write into {args.dir} ({exc.strerror or exc})",
              file=sys.stderr)
        return EXIT_FAIL
    print(f"report written to {summary.index} and {summary.summary} ({len(summary.figures)} figures)")
    if args.baseline:
        print(f"{summary.regressions} regression(s) against {args.baseline}")
    return EXIT_FAIL if args.strict and summary.regressions else EXIT_OK


def _scorecard_parser(sub) -> None:
    sc = sub.add_parser("scorecard", help="which body model for each creature: stability, fidelity, locomotion "
                                          "and cost per creature x body of a matrix output directory",
                        **help_text("scorecard"))
    sc.add_argument("dir", metavar="DIR", help="a directory written by `bench-myriapoda matrix FILE --out DIR`")
    sc.add_argument("--json", action="store_true", help="print exactly one JSON object on stdout")
    sc.add_argument("--history-store", metavar="PATH", default=None,
                    help="results store with validate and stable-dt results (default reports/results.sqlite)")


def cmd_scorecard(args) -> int:
    """The scorecard of a matrix output directory (``report.scorecard``), as text or one JSON object."""
    from .harness.store import DEFAULT_STORE
    from .report.scorecard import scorecard_for_dir, scorecard_lines

    _check_path_flags(args, "--history-store")
    from .report.inputs import check_history_store
    check_history_store(args.history_store)  # the same check as report's, the default store included
    card = scorecard_for_dir(args.dir, Path(args.history_store) if args.history_store else DEFAULT_STORE)
    if args.json:
        print(json.dumps(card.to_json()))
    else:
        for line in scorecard_lines(card):
            print(line)
    return EXIT_OK


def cmd_matrix(args) -> int:
    """Expand a matrix file, list what is not supported, run the rest, store and tabulate the results.

    Exit 0 when every case ran to a status ok or unstable, 1 when any case of the matrix (this run or an
    earlier one that --resume kept) is error or timeout, 2 for bad input (nothing written).
    """
    from .harness.executors import done_hashes, matrix_rows, run_matrix
    from .harness.matrix import expand_matrix, locate_matrix, write_matrix_manifest

    if args.workers is not None and not 1 <= args.workers <= MAX_WORKERS:
        raise InputError("--workers", None, f"{args.workers} is out of range; must be 1 to {MAX_WORKERS}")
    if args.timeout_per_case is not None and not (math.isfinite(args.timeout_per_case) and args.timeout_per_case > 0):
        raise InputError("--timeout-per-case", None, f"{args.timeout_per_case} is out of range; must be a finite "
                                                     "number of seconds > 0")
    _check_matrix_flags(args)
    if args.scheduler and args.executor != "dask":
        raise InputError("--scheduler", None, "only meaningful with --executor dask")
    if args.executor == "dask":
        try:
            import dask.distributed  # noqa: F401
        except ImportError:
            raise InputError("--executor", None, "dask is not installed; pip install 'bench-myriapoda[dask]'") from None
    if args.executor == "local":  # the workers' fork server imports the package while the matrix expands
        from .jit.worker_start import prestart
        prestart()
    exp = expand_matrix(locate_matrix(args.file))
    out = Path(args.out) if args.out else Path("reports") / "matrix" / exp.name
    if out.exists() and not out.is_dir():
        raise InputError("--out", None, f"{out} exists and is not a directory")
    store = out / "results.sqlite"
    _check_matrix_outputs(args, out, store)
    for m in exp.cases:  # the budget only: a case its body cannot build is an error row, as any case that raises
        _check_case_fits(m.case, args, f"{exp.path}: case {m.label}", buildable=False)
    if args.executor == "dask" and args.scheduler:
        from .harness.executors import check_dask_scheduler
        check_dask_scheduler(args.scheduler, probe_timeout=args.dask_timeout)
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
        from .report.main_job import same_code_rerun
        reuse = same_code_rerun(out, exp.name)
        if reuse:
            print(f"the cases this code ran into {out} before are kept (a rerun of the same code gives the same "
                  f"results); `bench-myriapoda matrix {exp.name} --out DIR` into a new DIR runs them all again")
    resume = args.resume or reuse
    todo = len(cases) - (len({c.case_hash() for c in cases} & done_hashes(store, exp.name)) if resume else 0)
    bar = MatrixProgress(sys.stderr.isatty(), todo, label=f"matrix {exp.name}")

    def on_result(result, done, total):
        bar.case_done(labels[result.case.case_hash()], result.status, result.message)

    from .harness.store import DEFAULT_STORE as history_store
    from .harness.store import UnstoredError
    stats: dict = {}
    try:
        with _sigterm_as_interrupt():  # SIGTERM ends a matrix as Ctrl-C does: workers stopped, resumable
            ran = run_matrix(cases, executor=args.executor, workers=args.workers, scheduler=args.scheduler,
                             timeout_per_case=args.timeout_per_case, store_path=store, on_result=on_result,
                             matrix=exp.name, resume=resume, series_dir=out / "series",
                             retry_failed=args.retry_failed, schedule=getattr(args, "schedule", "cost"),
                             history_stores=[history_store], stats=stats)
    except UnstoredError as exc:  # the cases stored so far stay; --resume runs the rest once the store is fixed
        bar.close()
        print(f"bench-myriapoda: error: matrix stopped: {exc}; the cases stored before it are kept "
              f"(rerun with --resume)", file=sys.stderr)
        return EXIT_FAIL
    finally:
        bar.close()
    if ran:
        from .harness.schedule import run_summary, write_run_summary
        sched = run_summary(stats, ran, labels)
        write_run_summary(out / "matrix.json", sched)
    rows = matrix_rows(store, exp.name).drop_duplicates("case_hash", keep="last")
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
    import pandas as pd
    df = pd.DataFrame(table)
    df.to_csv(out / "results.csv", index=False)
    try:
        df.to_parquet(out / "results.parquet", index=False)
    except ImportError:  # pyarrow (or fastparquet) not installed: CSV only
        pass
    from .harness.terminal_table import closing_line, matrix_table_lines
    shown = [{**t, "axes": axes_of[t["case_hash"]]} for t in table]  # the grid point of each case
    for line in matrix_table_lines(shown, exp.grid_keys):
        print(line)
    missing = set(labels) - set(rows.case_hash)
    bad = sum(t["status"] in ("error", "timeout") for t in table)
    print(f"{len(table)} of {len(labels)} cases stored in {store}; {bad} error or timeout; table in {out / 'results.csv'}")
    if ran:
        print(sched["line"])
    if main_job:
        from .report.main_job import fidelity_phase, write_marker
        done = fidelity_phase(exp, out, args.workers, progress=(lambda m: print(f"main job: {m}", file=sys.stderr))
                              if sys.stderr.isatty() else None)
        print(f"stable dt of {done['brackets']} pairs (bisection, {out / 'stable_dt.json'}); {done['checks']} "
              f"validate --quick checks {'kept' if done['validation_kept'] else 'run'} ({out / 'validation.json'}); "
              f"{done['wall_s']:.0f} s")
        if not (bad or missing):
            write_marker(out, exp.name)
    if args.report:
        from .harness.store import DEFAULT_STORE
        from .report.build import build_report
        # the matrix's cores are free now: its --workers draw the figures (figure_pool; dask: this machine's)
        workers = args.workers or os.cpu_count() or 1
        summary = build_report(out, history_store=DEFAULT_STORE, workers=workers)
        print(f"report written to {summary.index} ({len(summary.figures)} figures)")
        print(closing_line(shown, exp.grid_keys, summary.index, summary.verdicts))
    else:
        print(closing_line(shown, exp.grid_keys, None) + f"; write the report with `bench-myriapoda report {out}`")
    return EXIT_FAIL if bad or missing else EXIT_OK


class _sigterm_as_interrupt:
    """Inside the block SIGTERM raises KeyboardInterrupt (as SIGINT does), so that a terminated matrix
    stops its workers, keeps what it stored and prints "interrupted"; the old handler is restored after.
    ``main`` holds it around every command: a terminated ``run`` or matrix start-up ends with 130, as
    Ctrl-C does, not -15.  A process forked inside the block (the report's figure pool) dies of SIGTERM
    as it would without the handler."""

    def __enter__(self):
        import signal

        self.pid = os.getpid()
        try:
            self.saved = signal.signal(signal.SIGTERM, self._raise)
        except ValueError:  # not the main thread: leave SIGTERM as it is
            self.saved = None
        return self

    def _raise(self, signum, frame):
        import signal

        if os.getpid() != self.pid:  # a forked child inherited the handler: end as SIGTERM ends it
            signal.signal(signal.SIGTERM, signal.SIG_DFL)
            os.kill(os.getpid(), signal.SIGTERM)
            return
        raise KeyboardInterrupt

    def __exit__(self, *exc):
        import signal

        if self.saved is not None:
            signal.signal(signal.SIGTERM, self.saved)
        return False


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
    _check_path_flags(args, "--store", "--baseline")
    store = Path(args.store) if args.store else DEFAULT_STORE
    from .harness.store import check_store
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
    run_id, unstored = _store_or_keep(store, "regress run", lambda: record_regress_run(store, [r.row() for r in results]),
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


# --------------------------------------------------------------------------- validation of flags and outputs
# Everything here runs before a case is built or a file is written (issue 15): a bad flag or an output
# that cannot be written is one line and exit 2, not a traceback after the simulation ran.

MAX_WORKERS = 1024


def _check_path_flags(args, *flags: str) -> None:
    """A path flag given as an empty (or blank) string is an error, not 'use the default'."""
    from .core.userpaths import check_path_text

    for flag in flags:
        value = getattr(args, flag.lstrip("-").replace("-", "_"), None)
        if value is not None:  # empty, NUL, a name longer than the file system allows
            check_path_text(value, flag)


def _check_run_outputs(args) -> None:
    """``run``: the store is opened and schema-checked, every output file can be written (nothing is yet)."""
    from .harness.store import DEFAULT_STORE, check_store, check_writable_file

    if not args.no_store:
        check_store(args.store or DEFAULT_STORE, "--store")
    for flag in ("--record", "--plot-gait", "--animate"):
        value = getattr(args, flag.lstrip("-").replace("-", "_"))
        if value:
            check_writable_file(value, flag)
    if args.export_frames:
        from .harness.store import check_writable_dir
        check_writable_dir(args.export_frames, "--export-frames")


def _store_or_keep(store, what: str, write, doc) -> tuple[Any, str | None]:
    """(``write()``'s run id, None), or when the store refused the insert after the run (a full disk, a
    store changed meanwhile): (None, the line saying why and which fallback file keeps ``doc()``)."""
    from .harness.store import UnstoredError, store_or_keep

    try:
        return store_or_keep(store, what, write, doc), None
    except UnstoredError as exc:
        return None, str(exc)


def _check_validate_outputs(args, store: Path, out_dir: Path) -> None:
    """``validate``: its store is opened and schema-checked and ``--out`` (with its validation.json) can be
    written, before any check runs."""
    from .harness.store import check_store, check_writable_dir, check_writable_file
    from .validation.run import JSON_NAME

    if not args.no_store:
        check_store(store, "--store")
    check_writable_dir(out_dir, "--out")
    check_writable_file(out_dir / JSON_NAME, "--out")


def _case_source(args) -> str:
    """How a message names the case of run and stable-dt: CREATURE/BODY/SCENARIO as given."""
    return f"{args.creature}/{args.body}/{args.scenario}"


def _check_case_fits(case, args, source: str, keep_nodes: bool = False, buildable: bool = True):
    """(Unless --force) the case fits the resource budget and (``buildable``) its body can be built
    (core/feasibility.py) and its world too: returns that world (``world.world.World``, built once by
    ``world.buildable.check_placements``; the caller runs the case in it), None when not ``buildable``."""
    from .core.feasibility import check_budget, check_buildable
    from .world.buildable import check_placements

    budget = None
    if args.memory_budget is not None:
        if not (math.isfinite(args.memory_budget) and args.memory_budget > 0):
            raise InputError("--memory-budget", None, f"{args.memory_budget} is out of range; must be a number of GB > 0")
        budget = args.memory_budget * 1e9
    if args.max_steps is not None and not (math.isfinite(args.max_steps) and args.max_steps >= 1):
        raise InputError("--max-steps", None, f"{args.max_steps} is out of range; must be a number >= 1")
    if not args.force:
        check_budget(case, source, budget, args.max_steps, keep_nodes)
    elif not math.isfinite(case.duration / case.dt) or case.duration / case.dt > 2 ** 62:
        raise InputError(source, None, f"duration {case.duration:g} s / dt {case.dt:g} s: too many steps to count, "
                                       "even with --force")
    if not buildable:
        return None
    check_buildable(case, source)
    return check_placements(case, source)


def _check_matrix_flags(args) -> None:
    _check_path_flags(args, "--out", "--scheduler")
    if args.retry_failed and not args.resume:
        raise InputError("--retry-failed", None, "only meaningful with --resume")
    if args.dask_timeout is not None:
        if not args.scheduler:
            raise InputError("--dask-timeout", None, "only meaningful with --scheduler")
        if not (math.isfinite(args.dask_timeout) and 0 < args.dask_timeout <= 3600):
            raise InputError("--dask-timeout", None, f"{args.dask_timeout} is out of range; must be > 0 and <= 3600")


def _check_matrix_outputs(args, out: Path, store: Path) -> None:
    """``matrix``: DIR can be written, its store is opened and schema-checked, its files are files
    (``harness.matrix.check_matrix_outputs``, which the API's ``run_matrix`` uses too)."""
    from .harness.matrix import check_matrix_outputs

    check_matrix_outputs(out, "--out")
    if args.report:
        from .report.build import check_report_outputs
        check_report_outputs(out)
def cmd_peers(args) -> int:
    """Time the peers (MuJoCo flex, PyElastica's snake) and ours in one sitting; store and print the ratios.

    Exit 2 (one line, nothing timed or written) when the ``[peers]`` packages are missing."""
    from .harness import peers as P
    from .harness import regress as R
    from .harness.store import DEFAULT_STORE, record_regress_run

    missing = P.missing_packages()
    if missing:
        raise InputError("peers", None, f"needs the optional packages {', '.join(missing)}: "
                                        f"pip install {' '.join(missing)} (or the extra bench-myriapoda[peers])")
    repeats = R.check_repeats(args.repeats)
    _check_path_flags(args, "--store")
    store = Path(args.store) if args.store else DEFAULT_STORE
    from .harness.store import check_store
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
    run_id, unstored = _store_or_keep(store, "peers run", lambda: record_regress_run(store, [r.row() for r in results]),
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
    _check_path_flags(args, "--store", "--out")
    store = Path(args.store) if args.store else DEFAULT_STORE
    out_dir = Path(args.out) if args.out else V.DEFAULT_OUT
    _check_validate_outputs(args, store, out_dir)
    tty = not args.json and sys.stderr.isatty()
    t0 = time.perf_counter()
    # compiled libraries (LAPACK on a blown-up run's NaNs) print to file descriptor 1 directly: while the
    # checks run, fd 1 points at stderr, so that --json's stdout holds exactly one JSON object
    with _stdout_to_stderr():
        rows = V.run_checks(pairs, args.quick, bodies,
                            progress=(lambda m: print(f"validate: {m}", file=sys.stderr)) if tty else None)
        wp = None
        if args.work_precision:
            from .report.work_precision import run_work_precision
            wp = run_work_precision(out_dir, bodies, args.quick, progress=(
                lambda m: print(f"work-precision: {m}", file=sys.stderr)) if tty else None)
    wall = time.perf_counter() - t0
    dicts = [r.to_dict() for r in rows]
    counts = V.summary(rows)
    doc = clean({"quick": bool(args.quick), "bodies": list(bodies), "wall_s": wall, "counts": counts,
                 "rows": dicts, "work_precision": wp})
    run_id = unstored = None
    if not args.no_store:
        run_id, unstored = _store_or_keep(store, "validation run",
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


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        with _sigterm_as_interrupt():  # from the start: building the parser imports the body models (~1.3 s)
            from .core.numba_env import check_numba_env
            check_numba_env()  # before numba is imported: it reads these variables once, at import
            if "--version" in argv[:1] and len(argv) > 1:  # argparse would print the version and ignore the rest
                raise InputError("--version", None, f"takes no other arguments; got {' '.join(argv[1:])}")
            parser = build_parser()
            args = parser.parse_args(argv or ["quick"])
            if args.command is None:
                args = parser.parse_args(["quick", *argv])
            _print_any_file_name()
            code = {"list": cmd_list, "run": cmd_run, "quick": cmd_quick, "stable-dt": cmd_stable_dt,
                    "matrix": cmd_matrix, "report": cmd_report, "regress": cmd_regress, "keys": cmd_keys,
                    "peers": cmd_peers, "validate": cmd_validate, "scorecard": cmd_scorecard}[args.command](args)
            sys.stdout.flush()  # a closed pipe shows here, inside the handler, not at interpreter exit
        return code
    except BrokenPipeError:
        return _closed_pipe()
    except InputError as exc:
        print(f"bench-myriapoda: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("bench-myriapoda: interrupted", file=sys.stderr)
        return 130


PRINT_ERRORS = "bench_myriapoda_file_names"


def _print_any_file_name() -> None:
    """Let stdout print a file name that is not UTF-8 (``--store $'\\xff.sqlite'``, held by Python as a lone
    surrogate): as its own bytes, as ``ls`` would, and any other unencodable character as a backslash
    escape.  With strict UTF-8 the line naming the store raised UnicodeEncodeError after the run."""
    import codecs

    def write_bytes_or_escape(exc):
        try:
            return codecs.lookup_error("surrogateescape")(exc)
        except UnicodeError:
            return codecs.lookup_error("backslashreplace")(exc)

    try:
        codecs.lookup_error(PRINT_ERRORS)
    except LookupError:
        codecs.register_error(PRINT_ERRORS, write_bytes_or_escape)
    stream = sys.stdout
    if getattr(stream, "errors", None) == "strict" and hasattr(stream, "reconfigure"):
        try:
            stream.reconfigure(errors=PRINT_ERRORS)
        except (ValueError, OSError):  # a stream that cannot change now: leave it
            pass


def _closed_pipe() -> int:
    """stdout's reader went away (``bench-myriapoda run --json | head -c 10``): stop quietly.

    stdout is pointed at /dev/null so the interpreter's final flush does not raise again;
    the exit code is the shell's for a process ended by SIGPIPE (128 + 13).
    """
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # stdout without a file descriptor (e.g. captured in a test)
        pass
    return EXIT_CLOSED_PIPE


# --------------------------------------------------------------------------- help, version, keys

def _version_argument(p: argparse.ArgumentParser) -> None:
    from . import __version__

    p.add_argument("--version", action="version", version=f"bench-myriapoda {__version__}")


RUN_EXAMPLES = """examples:
  bench-myriapoda run --creature worm --body massspring --scenario flat
  bench-myriapoda run --creature snake --body fem --scenario flat --gait sidewinding --duration 5 --json
  bench-myriapoda run --creature snake --body massspring --scenario flat \\
      --set friction.mu_transverse=0.2 --set gait.frequency_hz=0.5 --record snake.npz
  bench-myriapoda run --creature centipede --body hybrid --scenario walk --plot-gait gait.png --animate walk.gif
  bench-myriapoda run --creature ./my-worm.toml --body massspring --scenario ./my-ground.toml   # your own files
"""


def _run_help_text() -> dict[str, Any]:
    """``run --help``: what can be chosen (creatures, bodies, gaits, scenarios) and examples at the end."""
    registry.load_all()
    creatures = creature_names()
    lines = [
        _para("Run one case (creature x body model x gait x scenario) and print its metrics: speed, direction, "
              "gait quality, stability and the body model's own figures, plus the throughput. The case is resolved "
              "from the built-in defaults, the creature file, the scenario file, --duration/--dt/--seed and then "
              "--set, later layers winning; the run is recorded in the results store unless --no-store. A run that "
              "blows up ends with status unstable (exit 0 unless --strict)."),
        "",
        f"creatures:  {', '.join(creatures) or '(none found)'}",
        f"bodies:     {', '.join(sorted(registry.BODIES))}",
        f"gaits:      {', '.join(sorted(registry.GAITS))} (default: the creature's default gait; "
        "`bench-myriapoda list` shows which creature has which)",
        f"scenarios:  {', '.join(scenario_paths()) or '(none found)'}",
        "",
        "Any other configuration key: --set SECTION.KEY=VALUE; `bench-myriapoda keys` lists them all with "
        "types, defaults, ranges and units.",
    ]
    return {"description": "\n".join(lines), "epilog": RUN_EXAMPLES,
            "formatter_class": argparse.RawDescriptionHelpFormatter}


def _keys_parser(sub) -> None:
    from .core.keys import sections

    k = sub.add_parser("keys", help="every configuration key --set accepts: type, default, range, unit, meaning",
                       **help_text("keys"))
    k.add_argument("section", nargs="?", metavar="SECTION", default=None,
                   help=f"only this section: {', '.join(sections())} (default: all)")
    k.add_argument("--json", action="store_true", help='print one JSON object {"keys": [...]}')


def cmd_keys(args) -> int:
    from .core.keys import config_keys

    rows = config_keys(args.section)
    if args.json:
        print(json.dumps({"keys": rows}, indent=1))
        return EXIT_OK
    section = None
    for r in rows:
        if r["section"] != section:
            section = r["section"]
            print(f"[{section}]" + ("  (dt, duration, seed: --dt, --duration, --seed or --set)" if section == "top"
                                    else ""))
        default = "-" if r["default"] is None else json.dumps(r["default"])
        bodies = (f"  ({', '.join(r['bodies'])})" if "bodies" in r
                  else f"  (gaits: {', '.join(r['gaits'])})" if "gaits" in r else "")
        print(f"  {r['key']}{bodies}")
        print(f"      {r['type']}; default {default}" + (f"; {r['allowed_text']}" if r["allowed_text"] else "")
              + (f"; unit {r['unit']}" if r["unit"] else ""))
        print(f"      {r['description']}")
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
