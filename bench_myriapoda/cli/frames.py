"""What ``run`` draws after the run: its flags checked before anything runs (``--animate``, ``--size``,
``--view``, ``--export-frames``, ``--frame-format``; matplotlib importable for ``--plot-gait`` and
``--animate``), the frames recorded during the run, and the animation and mesh frames written from them.

The animation module imports matplotlib; it is imported only when a run draws (``report.animate``: about 0.37 s
of CPU, measured after the body models load with python -c and time.process_time), which ``run`` without
``--animate``, and every other command, does not pay.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from ..core.errors import InputError
from ..report.export_frames import check_out_dir, export_frames


def check_drawing(flag: str) -> None:
    """matplotlib can be imported before a run that draws (``--plot-gait``, ``--animate``): an ``MPLBACKEND``
    naming no backend makes its import raise, which after the run would have lost the result."""
    try:
        import matplotlib  # noqa: F401  (the check itself: imported here to see whether it can be)
    except ValueError as exc:
        if "backend" in str(exc).lower():
            raise InputError("MPLBACKEND", None, f"{os.environ.get('MPLBACKEND', '')!r} is not a matplotlib backend "
                                                 f"({flag} draws with matplotlib); unset it or set it to agg") from None
        raise InputError(flag, None, f"matplotlib cannot be imported ({exc})") from None
    except ImportError as exc:
        raise InputError(flag, None, f"matplotlib cannot be imported ({exc})") from None


def check_frame_outputs(args) -> None:
    """Validate --animate, --export-frames and --frame-format before anything runs or is written."""
    for flag, value in (("--size", args.size), ("--view", args.view)):
        if value is not None and not args.animate:
            raise InputError(flag, None, "only meaningful with --animate")
    if args.size is not None:
        from ..report.animate import parse_size  # matplotlib (module docstring)

        try:
            w, h = parse_size(args.size)
        except ValueError as exc:
            raise InputError("--size", None, str(exc)) from None
        if Path(args.animate).suffix.lower() == ".mp4" and (w % 2 or h % 2):
            raise InputError("--size", None, f"{args.size!r}: an .mp4 (H.264, yuv420p) needs an even width and height")
    if args.animate:
        from matplotlib.animation import FFMpegWriter  # matplotlib (module docstring)

        from ..report.animate import SUFFIXES

        suffix = Path(args.animate).suffix.lower()
        if suffix not in SUFFIXES:
            raise InputError("--animate", None, f"{args.animate!r}: the file name must end in .gif or .mp4")
        if suffix == ".mp4" and not FFMpegWriter.isAvailable():
            raise InputError("--animate", None, f"{args.animate!r}: writing .mp4 needs ffmpeg, which is not on PATH; "
                                                "install ffmpeg or write a .gif")
    if args.frame_format and not args.export_frames:
        raise InputError("--frame-format", None, "only meaningful with --export-frames")
    if args.export_frames:
        try:
            check_out_dir(args.export_frames)
        except ValueError as exc:
            raise InputError("--export-frames", None, str(exc)) from None


def frame_recorder(args, case):
    """(the runner's on_sample hook or None, every how many recorded frames the animation keeps one)."""
    if not (args.animate or args.export_frames):
        return None, 1
    from ..report.animate import GIF_TICK_S, FrameRecorder, expected_samples, frame_stride, sample_period  # matplotlib

    # a GIF shows frames for whole centiseconds: choose the stride so every frame interval is one
    tick = GIF_TICK_S if args.animate and Path(args.animate).suffix.lower() == ".gif" else None
    anim_stride = frame_stride(expected_samples(case), sample_period(case), tick_s=tick) if args.animate else 1
    if args.export_frames:  # the export wants every sample; the animation takes every anim_stride-th of them
        return FrameRecorder(1), anim_stride
    return FrameRecorder(anim_stride), 1


def write_frame_outputs(args, case, frames, anim_stride: int, world) -> bool:
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
    try:
        if args.animate:
            from ..report.animate import parse_size, write_animation  # matplotlib (module docstring)
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
            meta = export_frames(frames.frames, frames.times, case.to_dict(), Path(args.export_frames),
                                 args.frame_format or "obj")
            print(f"frames: {args.export_frames} ({meta['n_frames']} {meta['format']} files and frames.json)",
                  file=note)
    except (OSError, ValueError, subprocess.SubprocessError) as exc:  # full disk, ffmpeg failing, DIR filled
        print(f"bench-myriapoda: could not write the animation or frames: {exc}", file=sys.stderr)
        return False
    return True
