"""Run one resolved case: compose a body, a controller and the world; step in chunks; sample; measure.

The runner builds the world once (``world.world.build_world``: terrain, obstacles, food, the water's bed)
and hands it to the body (every body factory takes it: ``factory(case, world)``), the controller (when its
gait declares ``GaitSpec.takes_world``) and the metrics; nothing else in a run builds the terrain from the
scenario again (``run_world`` is the one place outside ``world/`` that builds a world), builds the
body (``catalog``: ``BODIES[case.body.name].factory``) and the gait's
controller (``GAITS[case.gait.name].controller``, or one given by the caller), and passes data
between them (``core.protocols``): the body fills an ``Observation``, the controller writes an
``Actuation``.  An open-loop controller (Miller's muscle waves) fills the actuation for a whole
chunk of steps and the body's kernel runs the chunk in one call, so Python is touched only at
the sample rate.  A closed-loop controller (the paper's leg controller, a user's policy) ticks
at ``rate_hz`` (every step when 0) and the body runs the steps between ticks in one call.  A
blow-up inside the
kernel comes back as a status code: the run ends with status ``unstable``
and ``t_fail_s``, and everything measured until then is kept.  An exception
anywhere in the run becomes status ``error`` with its message.
"""
from __future__ import annotations

import copy
import math
import time
import traceback
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from ..core import registry
from ..core.config import Case
from ..core.protocols import LEGS, SEGMENTS, Actuation, Observation, controller_settings
from ..metrics.behaviour import series_behaviour_metrics
from ..metrics.legless import legless_metrics
from ..metrics.locomotion import blank_too_short, energy_metrics, locomotion_metrics, too_short_reason
from ..metrics.shape_tracking import shape_flag_reason
from ..world.water_coupling import WaterCoupling, has_water
from ..world.world import World, build_world
from ..fused import legged_walk
from .calibration import calibrated_body_info
from .legged import LeggedMonitor, LeggedView
from .recorder import Recorder, Series


@dataclass
class RunResult:
    case: Case
    status: str  # "ok" | "unstable" | "controller_unstable" | "error" | "timeout"
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
    """Rest length of the body from head to tail [m], the body model's own (links included)."""
    return float(body.body_length_m)


class UnsupportedCombination(ValueError):
    """A controller requires a capability the body does not have."""


def run_world(case: Case, controller=None, world: World | None = None) -> World:
    """The one world of a run: ``world`` when given, else the world a controller passed in already built
    holds (its ``world`` attribute), else ``case``'s, built here: the one place outside ``world/`` where a
    world is built from a scenario (``tests/test_world_built_once.py`` checks it statically)."""
    if world is None and isinstance(getattr(controller, "world", None), World):
        world = controller.world
    return build_world(case) if world is None else world


def compose(case: Case, controller=None, world: World | None = None):
    """(body, controller) for ``case``: the catalog's body and the gait's controller (or ``controller``),
    the controller reset for that body, both in ``world`` (``world.world.World``, built from the case here
    when None).  Raises UnsupportedCombination when the body cannot honour it."""
    registry.load_all()
    world = run_world(case, controller, world)
    body = build_body(case, world)
    if controller is None:
        gait = registry.GAITS[case.gait.name]
        controller = gait.controller(case, world=world) if gait.takes_world else gait.controller(case)
    elif getattr(controller, "world", False) is None:
        # a controller built without a world (it would build its own at reset) is handed the run's one
        controller.world = world
    requires, _, _ = controller_settings(controller)
    missing = requires - body.capabilities
    if missing:
        raise UnsupportedCombination(f"body {case.body.name!r} cannot honour this controller: it lacks "
                                     f"{', '.join(sorted(missing))}")
    controller.reset(case, calibrated_body_info(body, case, world), np.random.default_rng(case.seed))
    return body, controller


def build_body(case: Case, world: World | None = None):
    """The catalog's body of ``case`` (``BodySpec.factory``) in ``world`` (``run_world``: built here when
    None), for a body used outside a run (validation, benchmarks) as inside one."""
    registry.load_all()
    return registry.BODIES[case.body.name].factory(case, run_world(case, None, world))


class Stepper:
    """Advances a composed body and controller: ``advance(t0, n) -> (steps done, status)``.

    Open loop: the controller fills n + 1 actuation rows (row n is the actuation at the chunk's
    end, which the body keeps as its current one) and the body runs the chunk in one call.
    Closed loop: the controller ticks every ``steps_per_tick`` steps on a fresh observation
    (``body.sense``); a body with SEGMENTS takes the new support at once (``apply_support``,
    paper Sec. 4.1: supported segments are moved kinematically), then runs to the next tick.

    Fused: when ``fused`` is True and the pair has a compiled composition (``bench_myriapoda.fused``:
    today the three legged bodies with the leg controller, ``fused.legged_walk`` says which cases), the
    closed loop runs in one compiled call per ``advance`` instead, with the same result step for
    step; ``fused_reason`` says why a pair runs on the Python path (None when fused).  ``world``: the run's
    ``world.world.World`` (the body was built in it), which the fused walk hands the body's step.
    """

    def __init__(self, case: Case, body, controller, monitor: LeggedMonitor | None = None, fused: bool = True, *,
                 world: World):
        self.body, self.controller, self.monitor = body, controller, monitor
        self.dt = case.dt
        _, self.open_loop, rate = controller_settings(controller)
        self.steps_per_tick = 1 if rate <= 0 else max(1, int(round(1.0 / (rate * case.dt))))
        self.act = Actuation.for_body(body)
        self.obs = Observation()
        self.supports = SEGMENTS in body.capabilities
        self.step_index = 0
        self.fused = None
        self.fused_reason: str | None = "the open-loop path is already one call per chunk" if self.open_loop \
            else "fused path switched off"
        if fused and not self.open_loop:
            self.fused_reason = legged_walk.unsupported_reason(body, controller, self.steps_per_tick, self.act)
            if self.fused_reason is None:
                self.fused = legged_walk.FusedLeggedWalk(body, controller, self.act, monitor, world=world)

    def start(self) -> None:
        """The actuation at t = 0 (a body's energy at the first sample uses it); loads the fused kernel."""
        if self.open_loop:
            self.controller.fill(0.0, self.dt, 1, self.act)
            self.body.advance(0.0, 0, self.act)
        if self.fused is not None:
            self.fused.compile()

    def advance(self, t0: float, n: int) -> tuple[int, int]:
        body, ctrl, act, dt = self.body, self.controller, self.act, self.dt
        if self.open_loop:
            ctrl.fill(t0, dt, n + 1, act)
            k, code = body.advance(t0, n, act)
            self.step_index += k
            return k, code
        if self.fused is not None:
            k, code = self.fused.advance(t0, n)
            self.step_index += k
            return k, code
        k = 0
        while k < n:
            t = t0 + k * dt
            if self.step_index % self.steps_per_tick == 0:
                body.sense(self.obs, t)
                ctrl.step(self.obs, t, act)
                if self.supports:
                    body.apply_support(act)
                if self.monitor is not None:
                    self.monitor.after_control(self.obs)
            m = min(n - k, self.steps_per_tick - self.step_index % self.steps_per_tick)
            d, code = body.advance(t, m, act)
            k += d
            self.step_index += d
            if code != 0:
                return k, code
        return n, 0


def compile_controller(body, controller, open_loop: bool) -> None:
    """JIT-compile (or load) a controller's kernels: one step of a throw-away copy on a scratch
    actuation, so neither the controller's state nor the body's changes."""
    probe = copy.deepcopy(controller)
    act = Actuation.for_body(body)
    if open_loop:
        probe.fill(0.0, 0.0, 1, act)
    else:
        obs = Observation()
        body.sense(obs, 0.0)
        probe.step(obs, 0.0, act)


class Creature:
    """A body composed with its controller (``compose``), stepped like one body.

    ``advance(t0, n) -> (steps done, status)`` runs the controller and the body together
    (``Stepper``); ``scene()`` draws the legs too; every other attribute is the body's.
    ``compile()`` compiles both (a fused run: its chunk kernel, which holds both) and sets the actuation
    of t = 0.  ``world``: the ``world.world.World`` both live in (built from the case when not given).
    """

    def __init__(self, case: Case, controller=None, fused: bool = True, world: World | None = None):
        self.case = case
        self.own_controller = controller is None
        self.world = run_world(case, controller, world)
        self.body, self.controller = compose(case, controller, self.world)
        requires, self.open_loop, _ = controller_settings(self.controller)
        legged = LEGS in requires and SEGMENTS in requires
        # the behaviour metrics sample the run's one world (issue 30 item 1)
        self.monitor = LeggedMonitor(case, self.body, self.controller, self.world.terrain) \
            if legged else None
        self.view = LeggedView(self.body, self.controller) if legged else self.body
        self.stepper = Stepper(case, self.body, self.controller, self.monitor, fused=fused, world=self.world)

    def __getattr__(self, name):
        return getattr(self.body, name)

    def compile(self) -> None:
        # A fused run (``Stepper.fused``) steps only through its chunk kernel, so only the chunk is compiled
        # here: the kernels it shares with the Python path are compiled once either way, but those only the
        # Python path calls (the controller's Python-side checks: ``legs_penetration``, ``stance_knees_inside``,
        # its stance IK) each cost their own compile, LLVM optimisation, machine code and cache entry on a
        # cold start (issue 13, README Development notes).  The chunk's callees compile as it is typed, the
        # controller's first (they need only the terrain's kernels, so on a cold start one matrix worker compiles
        # them while another compiles the body's: compile_lock); per-sample kernels (``observe``, the monitor's)
        # compile at their first call.
        if self.stepper.fused is not None:
            self.stepper.start()
            return
        # the controller first, for the reason above; both compiles leave the body's and the controller's state
        # as they were, so the order changes no result
        if self.own_controller:
            compile_controller(self.body, self.controller, self.open_loop)
        self.body.compile()
        self.stepper.start()

    def advance(self, t0: float, n_steps: int) -> tuple[int, int]:
        return self.stepper.advance(t0, n_steps)

    def scene(self):
        return self.view.scene()


def _has_gait(case: Case) -> bool:
    """A body that moves by a gait: not a passive body (dropped, muscles off) or one hanging by its head."""
    return case.gait.name != "passive" and not case.scenario.passive and not case.scenario.suspended


def _walk_metrics(series, case, metrics: dict, monitor, length: float):
    """A legged run's emergent measures (``metrics.walk``) over its gait window, and the too-short reason."""
    from ..metrics.walk import walk_emergent_metrics

    start = monitor.gait_window_start(float(series.t[0]))  # as LeggedMonitor.metrics
    return walk_emergent_metrics(series.t, series.com, series.head, series.tail, series.energy, start,
                                 case.controller.head_speed_m_s, metrics.get("stride_frequency_hz", math.nan),
                                 length, case.creature.mass_kg, case.scenario.gravity_m_s2,
                                 case.metrics.min_steady_cycles)


def run_case(case: Case, progress: Callable[[float], None] | None = None, keep_nodes: bool = False,
             on_sample: Callable[[float, Any, Any], None] | None = None, controller=None,
             world: World | None = None) -> RunResult:
    """Simulate ``case`` and return its status, metrics and timings.

    ``controller``: a controller object (``core.protocols.Controller``: ``reset`` and
    ``step(observation, t, actuation)``, optional ``requires``, ``open_loop``, ``rate_hz``) to
    drive the body instead of the gait's own.
    ``progress`` is called with the fraction done after each chunk.
    ``on_sample(t [s], body, water)`` is called at every observation sample, t = 0
    included, after the sample is recorded (e.g. ``report.animate.FrameRecorder``);
    ``water`` is the scenario's ``world.water_coupling.WaterCoupling`` or None.
    ``world``: the case's ``world.world.World`` when built already (the CLI's placement check builds it);
    built here when None.
    """
    wall0 = time.perf_counter()
    timings = {"steps": 0, "steps_per_s": float("nan"), "realtime_factor": float("nan"),
               "compile_s": float("nan"), "wall_s": float("nan")}
    try:
        creature = Creature(case, controller, world=world)
        body, monitor, stepper = creature.body, creature.monitor, creature.stepper
        view = creature.view  # what drawings and the water see: the body with its legs
        c0 = time.perf_counter()
        creature.compile()
        timings["compile_s"] = time.perf_counter() - c0
        recorder = Recorder(keep_nodes=keep_nodes)
        recorder.add(body.observe(0.0, keep_nodes))
        water = WaterCoupling(case.scenario, creature.world) if has_water(case.scenario) else None
        if water is not None:
            water.start(view)
        if on_sample is not None:
            on_sample(0.0, view, water)
        total = case.steps
        chunk = max(1, int(round(1.0 / (case.record.sample_hz * case.dt))))
        done = 0
        status, t_fail, message = "ok", None, ""
        sim_wall = 0.0
        water_wall = 0.0  # the water layer's own time: not part of the body's steps/s
        while done < total:
            n = min(chunk, total - done)
            s0 = time.perf_counter()
            k, code = stepper.advance(done * case.dt, n)
            sim_wall += time.perf_counter() - s0
            done += k
            t = done * case.dt
            if code != 0:
                status, t_fail, message = "unstable", t, body.status_text(code)
                break
            recorder.add(body.observe(t, keep_nodes))
            if water is not None:
                w0 = time.perf_counter()
                water.advance(view, t, k * case.dt)
                water_wall += time.perf_counter() - w0
            if on_sample is not None:
                on_sample(t, view, water)
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
        metrics.update(series_behaviour_metrics(series, case, creature.world))  # a legged body's own figures replace these
        if monitor is not None:
            # these refer to a muscle wave's period and speed; a legged gait has its own stride metrics
            for k in ("speed_bl_per_cycle", "displacement_per_cycle_m", "slip_ratio", "wave_speed_m_per_s",
                      "cycles_measured", "steady_cycles"):
                metrics[k] = float("nan")
        if monitor is None:  # shape, roll, contact and posture_fault of a legless body
            metrics.update(legless_metrics(series, case, length, creature.world))
        metrics.update(body.extra_metrics())
        controller_metrics = getattr(creature.controller, "metrics", None)  # e.g. the shape tracker's saturation
        if callable(controller_metrics):
            metrics.update(controller_metrics())
        if metrics.get("shape_not_achieved") == 1.0 and status == "ok":
            message = shape_flag_reason(metrics, case)
        controller_status = getattr(creature.controller, "run_status", None)  # e.g. the shape tracker's guard
        verdict = controller_status() if callable(controller_status) else None
        if verdict is not None and status == "ok":
            # the controller drove the body away (issue 44): its own status, the shape's reason kept in the message
            status, message = verdict[0], verdict[1] + (f"; {message}" if message else "")
        elif verdict is not None:  # a blow-up stays ``unstable`` (the body's); what the controller did is said too
            message = f"{message}; {verdict[1]}"
        extra = {}
        controller_labels = getattr(creature.controller, "labels", None)  # e.g. where the shape loop's gains came from
        if callable(controller_labels) and controller_labels():
            extra.setdefault("labels", {}).update(controller_labels())
        if monitor is not None:
            metrics.update(monitor.metrics())
            extra.update(monitor.extra())
        # a legless gait measured over under metrics.min_steady_cycles steady cycles: its locomotion metrics
        # are NaN and the reason travels with the result (JSON, store, report); a legged walk's emergent
        # measures (metrics.walk) are NaN under that many strides
        short = None
        if monitor is not None and len(series.t) >= 3:
            walk, short = _walk_metrics(series, case, metrics, monitor, length)
            metrics.update(walk)
        elif len(series.t) >= 3 and _has_gait(case):
            short = too_short_reason(float(series.t[-1]), case)
        if short:
            if monitor is None:
                blank_too_short(metrics)
            extra.setdefault("labels", {})["too_short"] = short
        if water is not None:
            metrics.update(water.metrics())
            timings["water_s"] = water_wall
        timings["steps"] = done
        timings["steps_per_s"] = done / sim_wall if sim_wall > 0 else float("nan")
        timings["realtime_factor"] = done * case.dt / sim_wall if sim_wall > 0 else float("nan")
        timings["wall_s"] = time.perf_counter() - wall0
        return RunResult(case, status, metrics, timings, message, series, extra)
    except Exception as exc:  # a bug or an unforeseen failure: recorded, not raised
        timings["wall_s"] = time.perf_counter() - wall0
        msg = f"{type(exc).__name__}: {exc}"
        return RunResult(case, "error", {}, timings, msg, None, {"traceback": traceback.format_exc()})
