"""Run one resolved case: build the body, step it in chunks, sample, measure.

The body's kernel runs many steps per call (one chunk per observation
sample), so Python is touched only at the sample rate.  A blow-up inside the
kernel comes back as a status code: the run ends with status ``unstable``
and ``t_fail_s``, and everything measured until then is kept.  An exception
anywhere in the run becomes status ``error`` with its message.
"""
from __future__ import annotations

import math
import time
import traceback
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from ..core import registry
from ..core.config import Case
from ..metrics.behaviour import series_behaviour_metrics
from ..metrics.locomotion import energy_metrics, locomotion_metrics
from ..world.water_coupling import WaterCoupling, has_water
from .recorder import Recorder, Series


@dataclass
class RunResult:
    case: Case
    status: str  # "ok" | "unstable" | "error"
    metrics: dict[str, float]
    timings: dict[str, float]
    message: str = ""
    series: Series | None = None
    extra: dict[str, Any] = field(default_factory=dict)

    def to_json_dict(self) -> dict[str, Any]:
        def clean(v):
            if isinstance(v, float) and not math.isfinite(v):
                return None
            return v
        return {"case": self.case.to_dict(), "status": self.status,
                "metrics": {k: clean(v) for k, v in self.metrics.items()},
                "timings": {k: clean(v) for k, v in self.timings.items()},
                **({"labels": self.extra["labels"]} if "labels" in self.extra else {}),
                **({"message": self.message} if self.message else {})}


def hanging_metrics(series: Series) -> dict[str, float]:
    """Elongation of a suspended body: head-to-tail segment distance at the end (mean over the
    last 10 % of samples) minus that at t = 0, when the body hangs at its rest length [m]."""
    d = np.linalg.norm(series.segment_centers[:, 0] - series.segment_centers[:, -1], axis=1)
    tail = max(1, len(d) // 10)
    return {"hanging_elongation_m": float(d[-tail:].mean() - d[0])}


def wave_speed(case: Case, body_length_m: float | None = None) -> float:
    """Speed of the muscle wave along the undeformed body [m/s]: wavelength * frequency."""
    L = case.creature.body_length_m if body_length_m is None else body_length_m
    return case.gait.wavelength_bl * L * case.gait.frequency_hz


def body_length(body, case: Case) -> float:
    """Rest length of the body from head to tail [m]: the body model's own figure when it has one."""
    return float(getattr(body, "body_length_m", case.creature.body_length_m))


def run_case(case: Case, progress: Callable[[float], None] | None = None, keep_nodes: bool = False,
             on_sample: Callable[[float, Any, Any], None] | None = None) -> RunResult:
    """Simulate ``case`` and return its status, metrics and timings.

    ``progress`` is called with the fraction done after each chunk.
    ``on_sample(t [s], body, water)`` is called at every observation sample, t = 0
    included, after the sample is recorded (e.g. ``report.animate.FrameRecorder``);
    ``water`` is the scenario's ``world.water_coupling.WaterCoupling`` or None.
    """
    wall0 = time.perf_counter()
    timings = {"steps": 0, "steps_per_s": float("nan"), "realtime_factor": float("nan"),
               "compile_s": float("nan"), "wall_s": float("nan")}
    try:
        registry.load_all()
        body = registry.BODIES[case.body.name].factory(case)
        c0 = time.perf_counter()
        body.compile()
        timings["compile_s"] = time.perf_counter() - c0
        recorder = Recorder(keep_nodes=keep_nodes)
        recorder.add(body.observe(0.0, keep_nodes))
        water = WaterCoupling(case.scenario) if has_water(case.scenario) else None
        if water is not None:
            water.start(body)
        if on_sample is not None:
            on_sample(0.0, body, water)
        total = case.steps
        chunk = max(1, int(round(1.0 / (case.record.sample_hz * case.dt))))
        done = 0
        status, t_fail, message = "ok", None, ""
        sim_wall = 0.0
        water_wall = 0.0  # the water layer's own time: not part of the body's steps/s
        while done < total:
            n = min(chunk, total - done)
            s0 = time.perf_counter()
            k, code = body.advance(done * case.dt, n)
            sim_wall += time.perf_counter() - s0
            done += k
            t = done * case.dt
            if code != 0:
                status, t_fail, message = "unstable", t, body.status_text(code)
                break
            recorder.add(body.observe(t, keep_nodes))
            if water is not None:
                w0 = time.perf_counter()
                water.advance(body, t, k * case.dt)
                water_wall += time.perf_counter() - w0
            if on_sample is not None:
                on_sample(t, body, water)
            if progress is not None:
                progress(done / total)
        series = recorder.series()
        metrics: dict[str, float] = {}
        length = body_length(body, case)
        metrics.update(locomotion_metrics(series, case, wave_speed(case, length), length))
        metrics.update(energy_metrics(series))
        metrics["contact_fraction"] = body.contact_fraction_mean()
        metrics["max_penetration_m"] = body.max_penetration()
        metrics["body_length_m"] = length
        metrics["wave_speed_m_per_s"] = wave_speed(case, length)
        metrics["t_fail_s"] = t_fail if t_fail is not None else float("nan")
        if case.scenario.suspended:
            metrics.update(hanging_metrics(series))
        metrics.update(series_behaviour_metrics(series, case))  # a legged body's own figures replace these
        if case.creature.legs_per_segment:
            # these refer to a muscle wave's period and speed; a legged gait has its own stride metrics
            for k in ("speed_bl_per_cycle", "displacement_per_cycle_m", "slip_ratio", "wave_speed_m_per_s",
                      "cycles_measured"):
                metrics[k] = float("nan")
        metrics.update(body.extra_metrics())
        if water is not None:
            metrics.update(water.metrics())
            timings["water_s"] = water_wall
        extra = {}
        if hasattr(body, "leg_timeline"):
            extra["leg_timeline"] = body.leg_timeline()
            extra["labels"] = body.labels_dict()
            extra["brain_timeline"] = body.controller.brain_timeline()
        timings["steps"] = done
        timings["steps_per_s"] = done / sim_wall if sim_wall > 0 else float("nan")
        timings["realtime_factor"] = done * case.dt / sim_wall if sim_wall > 0 else float("nan")
        timings["wall_s"] = time.perf_counter() - wall0
        return RunResult(case, status, metrics, timings, message, series, extra)
    except Exception as exc:  # a bug or an unforeseen failure: recorded, not raised
        timings["wall_s"] = time.perf_counter() - wall0
        msg = f"{type(exc).__name__}: {exc}"
        return RunResult(case, "error", {}, timings, msg, None, {"traceback": traceback.format_exc()})
