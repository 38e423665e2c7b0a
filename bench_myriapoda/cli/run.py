"""``bench-myriapoda run``: one case, its metrics printed and stored, its recording, gait diagram, animation and
frames written after it (``frames``)."""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any

from ..core import registry
from ..core.config import creature_names, scenario_paths
from ..core.errors import InputError
from ..harness import recorder
from ..harness.progress import ProgressBar
from ..harness.store import DEFAULT_STORE, check_store, check_writable_dir, check_writable_file, record_run
from ..metrics.locomotion import STEADY_METRICS
from ..metrics.walk import EMERGENT_WALK_METRICS
from . import frames as F
from .case_flags import budget_arguments, case_arguments, case_source, check_case_fits, resolve
from .checks import check_path_flags, store_after_the_run
from .exits import EXIT_FAIL, EXIT_OK
from .help_text import para

RUN_EXAMPLES = """examples:
  bench-myriapoda run --creature worm --body massspring --scenario flat
  bench-myriapoda run --creature snake --body fem --scenario flat --gait sidewinding --duration 5 --json
  bench-myriapoda run --creature snake --body massspring --scenario flat \\
      --set friction.mu_transverse=0.2 --set gait.frequency_hz=0.5 --record snake.npz
  bench-myriapoda run --creature centipede --body hybrid --scenario walk --plot-gait gait.png --animate walk.gif
  bench-myriapoda run --creature ./my-worm.toml --body massspring --scenario ./my-ground.toml   # your own files
"""


def run_help_text() -> dict[str, Any]:
    """``run --help``: what can be chosen (creatures, bodies, gaits, scenarios) and examples at the end."""
    registry.load_all()
    creatures = creature_names()
    lines = [
        para("Run one case (creature x body model x gait x scenario) and print its metrics: speed, direction, "
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


def add_parser(sub) -> None:
    run = sub.add_parser("run", help="run one case", **run_help_text())
    case_arguments(run)
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
    budget_arguments(run)


def fmt(v: Any) -> str:
    """A metric's value as the tables print it: 4 significant digits, ``-`` for none or not finite."""
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
        v = labels[k] if k in labels else ("too short" if k in short else fmt(d["metrics"][k]))
        print(f"  {k:<{width}}  {v}")
    t = d["timings"]
    print(f"  {'steps':<{width}}  {t['steps']}   steps/s {fmt(t['steps_per_s'])}   realtime x{fmt(t['realtime_factor'])}"
          f"   compile {fmt(t['compile_s'])} s   wall {fmt(t['wall_s'])} s")


def too_short_metrics(result) -> tuple[str, ...]:
    """The metrics a too-short run leaves NaN (``metrics.locomotion.STEADY_METRICS``, ``metrics.walk``)."""
    return EMERGENT_WALK_METRICS if result.case.creature.legs_per_segment else STEADY_METRICS


def check_run_outputs(args) -> None:
    """``run``: the store is opened and schema-checked, every output file can be written (nothing is yet)."""
    if not args.no_store:
        check_store(args.store or DEFAULT_STORE, "--store")
    for flag in ("--record", "--plot-gait", "--animate"):
        value = getattr(args, flag.lstrip("-").replace("-", "_"))
        if value:
            check_writable_file(value, flag)
    if args.export_frames:
        check_writable_dir(args.export_frames, "--export-frames")


def write_after_the_run(flag: str, path: str, write) -> str | None:
    """``write()`` one output file of a finished run; None, or the line saying why it failed.  Any exception
    is caught: after the simulation a traceback would lose the computed result, which is printed and
    stored whatever happened to this file."""
    try:
        write()
        return None
    except Exception as exc:
        why = exc.strerror if isinstance(exc, OSError) and exc.strerror else f"{type(exc).__name__}: {exc}"
        return f"could not write {flag} {path} ({why})"


def cmd_run(args) -> int:
    # the runner (the metrics, the water layer, the fused walk): about 45 ms of CPU at start-up (measured after the
    # body models load, python -c, time.process_time), which list, keys, report and --help do not pay
    from ..harness import runner

    check_path_flags(args, "--store", "--record", "--plot-gait", "--animate", "--export-frames")
    if args.record and not args.record.endswith(".npz"):
        raise InputError("--record", None, f"{args.record!r}: the file name must end in .npz")
    if args.plot_gait and not args.plot_gait.endswith(".png"):
        raise InputError("--plot-gait", None, f"{args.plot_gait!r}: the file name must end in .png")
    check_run_outputs(args)
    F.check_frame_outputs(args)
    for flag in ("--plot-gait", "--animate"):
        if getattr(args, flag[2:].replace("-", "_")):
            F.check_drawing(flag)
    case = resolve(args)
    if args.plot_gait and not case.creature.legs_per_segment:
        raise InputError("--plot-gait", None, f"creature {case.creature.name!r} has no legs: no gait diagram")
    world = check_case_fits(case, args, case_source(args),
                            keep_nodes=bool(args.record or args.animate or args.export_frames))
    frames, anim_stride = F.frame_recorder(args, case)
    bar = ProgressBar(enabled=not args.json and sys.stderr.isatty(), label=f"{case.creature.name}/{case.body.name}",
                      total_s=case.duration, dt=case.dt)
    result = runner.run_case(case, progress=bar.update, keep_nodes=bool(args.record), on_sample=frames, world=world)
    bar.close()
    # From here on nothing may raise before the result is printed: a failed write keeps the result (stored
    # elsewhere, printed) and says so in a line; the exit code is then 1.
    failed: list[str] = []  # one line each: the store, --record, --plot-gait
    run_id = None
    if not args.no_store:
        store = args.store or DEFAULT_STORE
        run_id, unstored = store_after_the_run(store, "run", lambda: record_run(store, result, command="run"),
                                               result.to_json_dict)
        failed += [unstored] if unstored else []
    if args.record and result.series is not None:
        def record():
            extra = {}
            if "leg_timeline" in result.extra:
                extra = dict(zip(("leg_t", "leg_states", "leg_tips"), result.extra["leg_timeline"]))
            recorder.save_npz(Path(args.record), result.series, case.to_dict(), extra)
        failed += filter(None, [write_after_the_run("--record", args.record, record)])
    if args.plot_gait and "leg_timeline" in result.extra:
        def plot():
            # matplotlib, imported when a gait diagram is drawn (report.gait_diagram: about 0.43 s of CPU)
            from ..report.gait_diagram import plot_gait_diagram
            t, states, _ = result.extra["leg_timeline"]
            if len(t):
                plot_gait_diagram(t, states, Path(args.plot_gait), last_seconds=1.0,
                                  title=f"{case.creature.name} / {case.body.name} / {case.scenario.name}")
        failed += filter(None, [write_after_the_run("--plot-gait", args.plot_gait, plot)])
    try:
        written = F.write_frame_outputs(args, case, frames, anim_stride, world)
    except Exception as exc:  # anything write_frame_outputs does not expect: the result is still printed
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
