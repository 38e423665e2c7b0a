"""The fixed throughput suite of ``bench-myriapoda regress`` and the scenes the benchmarks time.

The bodies publish their own entries (``BodySpec.benchmarks.suite``, a ``core.specs.SuiteCase`` each, declared
in ``bodies/<name>/benchmarks.py``): the scene (creature, scenario, overrides) and how it is built and timed
(``run``).  This module builds and times them and names no body (issue 42); it adds the one entry that is no
body's, the rigid-box core (``rigid_scene``).  The builders (``settled_creature``, ``bare_body``,
``walked_in``, ``walking_centipede``, ``rigid_scene``) are shared with ``tests/benchmarks/``, so the
regression suite and the pytest-benchmark micro benchmarks time the same bodies.

``SUITE`` is a registry: entry name -> ``SuiteEntry`` whose ``setup()`` builds the scene,
compiles its kernels (or loads them from the numba cache) and returns ``(step, steps)``:
``step(n)`` runs n steps of the kernel (restarting from a fixed state where the scene
allows it, so every repetition does the same work) and ``steps`` is how many steps one
timed repetition runs.  A test can register or replace an entry (``SUITE[name] = ...``).

``reference_ops(n)`` is the fixed REFERENCE kernel timed in the same run: a small spring
chain in numba (multiply-adds and one sqrt per spring, 33 x 3 doubles: memory-light), so
``steps/s / reference ops/s`` is a figure that stays comparable on a slower, faster or
busier machine.  Its work never changes: editing it breaks every stored figure.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numba
import numpy as np

from ..core import registry
from ..core.config import resolve_case
from ..core.specs import BARE, KERNEL, RESTART, WALK_ON, SuiteCase
from .runner import Creature, build_body

Step = Callable[[int], None]


@dataclass(frozen=True)
class SuiteEntry:
    """One kernel of the suite.  ``setup()`` returns (step, steps per timed repetition)."""

    name: str
    description: str
    setup: Callable[[], tuple[Step, int]]


def _check(name: str, n: int, done: int, status: int) -> None:
    if status != 0 or done != n:
        raise RuntimeError(f"throughput suite entry {name!r}: {done} of {n} steps, status {status}")


def advance_in_chunks(creature, t0: float, n: int) -> tuple[int, int]:
    """Advance a ``runner.Creature`` n steps in the runner's chunks (one per observation sample), as a
    run does: an open-loop controller fills one chunk's actuation, the body's kernel runs it."""
    case = creature.case
    chunk = max(1, int(round(1.0 / (case.record.sample_hz * case.dt))))
    done = 0
    while done < n:
        k, status = creature.advance(t0 + done * case.dt, min(chunk, n - done))
        done += k
        if status != 0:
            return done, status
    return done, 0


# --------------------------------------------------------------------------- the bodies' published scenes

def suite_cases() -> dict[str, tuple[str, SuiteCase]]:
    """Entry -> (body, ``SuiteCase``) of every catalogued body's suite entries, in the catalog's order."""
    registry.load_all()
    return {c.entry: (name, c) for name, spec in registry.BODIES.items() for c in spec.benchmarks.suite}


def scene_case(body: str, sc: SuiteCase, overrides: tuple[str, ...] = ()):
    """The resolved case of a published scene of ``body``, with more ``--set`` overrides after its own."""
    return resolve_case(sc.creature, body, sc.scenario, overrides=[*sc.overrides, *overrides])


def settled_creature(body: str, sc: SuiteCase):
    """A ``RESTART`` scene: the creature built as a run builds it (its gait's controller), compiled and settled
    ``sc.settle_steps`` steps in the runner's chunks.  Returns (case, creature, t) with t [s] the time reached."""
    case = scene_case(body, sc)
    creature = Creature(case)
    creature.compile()
    done, status = advance_in_chunks(creature, 0.0, sc.settle_steps)
    if status != 0:
        raise RuntimeError(f"{sc.entry} settle stopped after {done} steps: {creature.status_text(status)}")
    return case, creature, sc.settle_steps * case.dt


def bare_body(body: str, sc: SuiteCase):
    """A ``BARE`` scene: the body alone (no controller) with its published start state (``sc.prepare``), not
    compiled.  Returns (case, body)."""
    case = scene_case(body, sc)
    built = build_body(case)
    if sc.prepare is not None:
        sc.prepare(built)
    return case, built


def walked_in(body: str, sc: SuiteCase, overrides: tuple[str, ...] = ()):
    """A ``WALK_ON`` scene: the creature with its controller (``sc.fused``: the fused legged path where the body
    has one, else the Python path), compiled and walked in ``sc.settle_steps`` steps in one call; returns
    (case, creature)."""
    case = scene_case(body, sc, overrides)
    creature = Creature(case, fused=sc.fused)
    creature.compile()
    done, status = creature.advance(0.0, sc.settle_steps)
    if status != 0:
        raise RuntimeError(f"{sc.entry} walk-in stopped after {done} steps: {creature.status_text(status)}")
    return case, creature


CENTIPEDE_WALK_IN_STEPS = 4500  # 1.5 s: ADJUSTMENT is over and the leg wave has formed


def walking_centipede(segments: int, body: str, walk_in_steps: int = CENTIPEDE_WALK_IN_STEPS,
                      fused: bool = True, sets: tuple[str, ...] = ()):
    """A centipede of ``segments`` segments on ``body`` on the ``walk`` scenario, compiled and walked in; returns
    (case, creature).

    ``fused``: the runner's default, one compiled call per chunk where the body has a fused legged
    path (``fused.legged_walk``); False keeps the Python path (controller sequenced every step).
    ``sets``: more ``--set`` overrides (``legs.stance=dynamic``: tests/benchmarks/test_bench_dynamic_stance.py)."""
    sc = SuiteCase("walking-centipede", "a walking centipede", steps=0, run=WALK_ON, creature="centipede",
                   scenario="walk", overrides=(f"creature.segments={segments}",), settle_steps=walk_in_steps,
                   fused=fused)
    return walked_in(body, sc, sets)


def _restored(fields: dict[str, np.ndarray]) -> Callable[[], None]:
    """A function that writes the arrays' present values back into them (their copies taken now)."""
    start = {name: a.copy() for name, a in fields.items()}

    def restore() -> None:
        for name, a in fields.items():
            a[...] = start[name]

    return restore


def _setup_restart(body: str, sc: SuiteCase) -> tuple[Step, int]:
    _case, creature, t0 = settled_creature(body, sc)
    restore = _restored(sc.restart_state(creature))

    def step(n: int) -> None:
        restore()
        done, status = advance_in_chunks(creature, t0, n)
        _check(sc.entry, n, done, status)

    return step, sc.steps


def _setup_bare(body: str, sc: SuiteCase) -> tuple[Step, int]:
    _case, built = bare_body(body, sc)
    restore = _restored(sc.restart_state(built))
    built.compile()

    def step(n: int) -> None:
        restore()
        done, status = built.advance(0.0, n)
        _check(sc.entry, n, done, status)

    return step, sc.steps


def _setup_walk_on(body: str, sc: SuiteCase) -> tuple[Step, int]:
    case, creature = walked_in(body, sc)
    if sc.fused and creature.stepper.fused is None:
        raise RuntimeError(f"{sc.entry}: the fused path does not apply: {creature.stepper.fused_reason}")
    t = [sc.settle_steps * case.dt]

    def step(n: int) -> None:
        done, status = creature.advance(t[0], n)
        t[0] += done * case.dt
        _check(sc.entry, n, done, status)

    return step, sc.steps


def _setup_kernel(_body: str, sc: SuiteCase) -> tuple[Step, int]:
    return sc.kernel(sc.steps)


SETUPS = {RESTART: _setup_restart, BARE: _setup_bare, WALK_ON: _setup_walk_on, KERNEL: _setup_kernel}


def setup_of(body: str, sc: SuiteCase) -> Callable[[], tuple[Step, int]]:
    """The ``setup()`` of a published scene: builds, compiles and returns (step, steps) as ``sc.run`` says."""
    if sc.run not in SETUPS:
        raise ValueError(f"suite entry {sc.entry!r} of {body}: unknown run {sc.run!r}; known: {', '.join(SETUPS)}")
    needs = {RESTART: "restart_state", BARE: "restart_state", KERNEL: "kernel"}.get(sc.run)
    if needs and getattr(sc, needs) is None:
        raise ValueError(f"suite entry {sc.entry!r} of {body}: a {sc.run!r} scene needs {needs}")
    return lambda: SETUPS[sc.run](body, sc)


# --------------------------------------------------------------------------- the rigid-box core (no body's)

RIGID_DT = 1.0 / 3000.0  # [s]
RIGID_BOXES = 18
RIGID_HALF = (0.1, 0.05, 0.08)  # [m]
RIGID_MASS = 0.5  # [kg]
RIGID_STATE_FIELDS = ("c", "q", "v", "w", "impulse_cache")


def rigid_contact_settings():
    from ..bodies.rigid import ContactSettings
    return ContactSettings(friction=0.5, restitution=0.0)


def rigid_scene():
    """18 segment-sized boxes on the plane: nine at rest, nine sliding at 1 m/s in different directions."""
    from ..bodies.rigid import RigidBoxes

    boxes = RigidBoxes([RIGID_HALF] * RIGID_BOXES, [RIGID_MASS] * RIGID_BOXES)
    for i in range(RIGID_BOXES):
        heading = 2.0 * np.pi * i / RIGID_BOXES
        speed = 1.0 if i % 2 else 0.0
        boxes.set_pose(i, c=[0.5 * i, RIGID_HALF[1] - 1e-6, 0.0],
                       v=[speed * np.cos(heading), 0.0, speed * np.sin(heading)])
    return boxes


def setup_rigid_boxes(steps: int = 6000) -> tuple[Step, int]:
    """The rigid-box core: 18 boxes on the plane, restarted from the same state at every call."""
    boxes = rigid_scene()
    settings = rigid_contact_settings()
    start = {k: getattr(boxes, k).copy() for k in RIGID_STATE_FIELDS}
    boxes.advance(1, RIGID_DT, contact=settings)  # JIT compile or cache load

    def step(n: int) -> None:
        for k, value in start.items():
            getattr(boxes, k)[...] = value
        done, status = boxes.advance(n, RIGID_DT, contact=settings)
        _check("rigid-boxes", n, done, status)

    return step, steps


# --------------------------------------------------------------------------- cost against size

SCALING_SEGMENTS = (6, 12, 25, 50, 100, 200)


def scaling_cases() -> dict[str, tuple[str, SuiteCase]]:
    """Creature -> (body, ``SuiteCase``) of the scenes the bodies publish for the cost-against-size fit
    (``SuiteCase.scaling_settle_steps`` > 0; the first body's where two publish one creature)."""
    out: dict[str, tuple[str, SuiteCase]] = {}
    for body, sc in suite_cases().values():
        if sc.scaling_settle_steps > 0:
            out.setdefault(sc.creature, (body, sc))
    return out


def scaling_scene(kind: str, segments: int):
    """A compiled creature of ``segments`` segments for the cost-against-size fit, settled; returns (case, creature, t).

    ``kind``: a creature of ``scaling_cases`` (``snake``: Miller's snake on the mass-spring body; ``centipede``:
    the walking hybrid centipede), built as its published scene with ``creature.segments`` set."""
    cases = scaling_cases()
    if kind not in cases:
        raise ValueError(f"unknown scaling kind {kind!r}; known: {', '.join(cases)}")
    body, sc = cases[kind]
    own = [o for o in sc.overrides if not o.startswith("creature.segments=")]
    case = resolve_case(sc.creature, body, sc.scenario, overrides=[*own, f"creature.segments={segments}"])
    creature = Creature(case)
    creature.compile()
    n = sc.scaling_settle_steps
    done, status = advance_in_chunks(creature, 0.0, n)
    if status != 0:
        raise RuntimeError(f"{kind} with {segments} segments stopped after {done} steps: "
                           f"{creature.status_text(status)}")
    return case, creature, n * case.dt


def time_per_step(kind: str, segments: int, steps: int, repeats: int = 3) -> float:
    """CPU seconds per step (the fastest of ``repeats`` runs of ``steps`` steps, each from the same state where the
    scene restarts, ``RESTART``; a walking scene walks on)."""
    import time

    body, sc = scaling_cases()[kind]
    case, creature, t0 = scaling_scene(kind, segments)
    restart = sc.run == RESTART
    restore = _restored(sc.restart_state(creature) if restart else {})
    best = math.inf
    t = t0
    for _ in range(repeats):
        restore()
        if restart:
            t = t0
        c0 = time.thread_time()
        done, status = advance_in_chunks(creature, t, steps)
        best = min(best, time.thread_time() - c0)
        _check(f"scaling {kind} {segments}", steps, done, status)
        t += steps * case.dt
    return best / steps


def fit_exponent(segments, seconds_per_step) -> float:
    """Slope p of log(time per step) = p log(segments) + c (least squares)."""
    p, _c = np.polyfit(np.log(np.asarray(segments, float)), np.log(np.asarray(seconds_per_step, float)), 1)
    return float(p)


# --------------------------------------------------------------------------- the suite

def suite() -> dict[str, SuiteEntry]:
    """Entry name -> ``SuiteEntry``: every catalogued body's published entries, in the catalog's order, then the
    rigid-box core."""
    entries = [SuiteEntry(sc.entry, sc.description, setup_of(body, sc)) for body, sc in suite_cases().values()]
    entries.append(SuiteEntry("rigid-boxes", "rigid-box core, 18 boxes with contact and friction", setup_rigid_boxes))
    return {e.name: e for e in entries}


SUITE: dict[str, SuiteEntry] = suite()

# --------------------------------------------------------------------------- the reference kernel

REFERENCE_NODES = 33           # a chain of 33 unit masses, 32 springs: 33 x 3 doubles, in L1
REFERENCE_ITERATIONS = 250000  # time steps of the chain per call: ops = 32 * 250000 spring updates


@numba.njit(cache=True)
def _reference_kernel(x, v, n_iter):  # pragma: no cover - compiled
    """Symplectic Euler on a stiff 3-D spring chain: per spring 3 subtractions, one sqrt, a few multiply-adds."""
    m = x.shape[0]
    k = 100.0
    dt = 1.0e-3
    f = np.zeros((m, 3))
    for _ in range(n_iter):
        for i in range(m):
            f[i, 0] = 0.0
            f[i, 1] = 0.0
            f[i, 2] = 0.0
        for i in range(m - 1):
            dx = x[i + 1, 0] - x[i, 0]
            dy = x[i + 1, 1] - x[i, 1]
            dz = x[i + 1, 2] - x[i, 2]
            L = math.sqrt(dx * dx + dy * dy + dz * dz)
            s = k * (L - 1.0) / L
            f[i, 0] += s * dx
            f[i, 1] += s * dy
            f[i, 2] += s * dz
            f[i + 1, 0] -= s * dx
            f[i + 1, 1] -= s * dy
            f[i + 1, 2] -= s * dz
        for i in range(m):
            v[i, 0] += dt * f[i, 0]
            v[i, 1] += dt * f[i, 1]
            v[i, 2] += dt * f[i, 2]
            x[i, 0] += dt * v[i, 0]
            x[i, 1] += dt * v[i, 1]
            x[i, 2] += dt * v[i, 2]
    return x[m - 1, 0]


def _reference_start() -> tuple[np.ndarray, np.ndarray]:
    i = np.arange(REFERENCE_NODES, dtype=np.float64)
    x = np.stack([1.05 * i, 0.02 * np.sin(i), 0.02 * np.cos(i)], axis=1)  # slightly stretched and bent
    return x, np.zeros_like(x)


def reference_ops(n_iter: int | None = None) -> int:
    """Run the reference kernel once (n_iter chain steps, default REFERENCE_ITERATIONS); return the ops done."""
    n_iter = REFERENCE_ITERATIONS if n_iter is None else n_iter
    x, v = _reference_start()
    r = _reference_kernel(x, v, n_iter)
    if not math.isfinite(r):
        raise RuntimeError("reference kernel diverged")
    return n_iter * (REFERENCE_NODES - 1)
