"""The fixed throughput suite of ``bench-myriapoda regress`` and the scenes the benchmarks time.

Scene builders (``snake_body``, ``fem_chain``, ``fem_worm_body``, ``hybrid_chain``,
``walking_centipede``, ``rigid_scene``) are shared with ``tests/benchmarks/``, so the
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

# --------------------------------------------------------------------------- scenes (shared with the benchmarks)

SNAKE_SETTLE_STEPS = 20000  # the snake's gait has formed: the timed steps see contacts, friction and muscles


def snake_body(settle_steps: int = SNAKE_SETTLE_STEPS):
    """Miller's 50-segment snake (lateral undulation, anisotropic Coulomb friction), compiled and settled.

    Returns (case, body, t) with t [s] the time reached.
    """
    from ..core.config import resolve_case
    from .runner import Creature

    case = resolve_case("snake", "massspring", "flat")
    body = Creature(case)
    body.compile()
    done, status = advance_in_chunks(body, 0.0, settle_steps)
    if status != 0:
        raise RuntimeError(f"snake settle stopped after {done} steps: {body.status_text(status)}")
    return case, body, settle_steps * case.dt


FEM_CHAIN_SEGMENTS = 17
FEM_CHAIN_SPIN = 2.0  # [rad/s] about the vertical
FEM_CHAIN_LIFT = 0.05  # [m]


def fem_terrain():
    """The plane y = 0 as the FEMSystem's ``terrain`` argument."""
    from ..world import terrain_kernels as T
    return (T.PLANE, np.zeros(T.N_TERRAIN_PARAMS))


def fem_chain(resolution: int = 3, unit: str = "nodes"):
    """A 17-segment deformable chain (paper presets, segments 1 x 1 x 1) 5 cm above the plane, spinning at 2 rad/s.

    Returns (system, x0, v0): the FEMSystem (not compiled) and its start state.
    """
    from ..bodies.fem.mesh import chain_grid
    from ..bodies.fem.system import FEMSystem

    nodes, tets, _seg = chain_grid(FEM_CHAIN_SEGMENTS, 1.0, cross_section=(1.0, 1.0),
                                   resolution=resolution, resolution_unit=unit)
    system = FEMSystem(nodes, tets)
    centre = nodes.mean(axis=0)
    x0 = nodes + [0.0, FEM_CHAIN_LIFT, 0.0]
    v0 = np.cross([0.0, FEM_CHAIN_SPIN, 0.0], nodes - centre)
    return system, x0, v0


def fem_worm_body():
    """The FEM worm (``worm`` / ``fem`` / ``flat``, rectilinear muscle wave), compiled, at t = 0."""
    from ..core.config import resolve_case
    from .runner import Creature

    case = resolve_case("worm", "fem", "flat")
    body = Creature(case)
    body.compile()
    return case, body


HYBRID_RIGID = 18
HYBRID_SPIN = np.array([0.0, 0.2, 0.0])  # [rad/s] about the vertical through the centre of mass


def hybrid_chain():
    """``models/chain.toml`` lengthened to 18 boxes (density 1) and 17 FEM links, 1 cm above the plane,
    turning at 0.2 rad/s (not compiled)."""
    from ..core.config import resolve_case
    from .runner import build_body

    case = resolve_case("chain", "hybrid", "flat", overrides=[
        f"creature.segments={HYBRID_RIGID}", "body.rigid_density_kg_m3=1.0", "scenario.start_height_m=0.01"])
    body = build_body(case)
    com = body.observe(0.0).com
    body.rigid.v[:] = np.cross(HYBRID_SPIN, body.rigid.c - com)
    body.rigid.w[:] = HYBRID_SPIN
    body.v[body.free] = np.cross(HYBRID_SPIN, body.x[body.free] - com)
    body.sync_attached()
    return body


def hybrid_state_fields(body) -> list[np.ndarray]:
    """The arrays that hold a BodyHybrid's whole dynamic state (restore them to restart)."""
    rb = body.rigid
    return [body.x, body.v, body.fem.q_ws, rb.c, rb.q, rb.v, rb.w, rb.impulse_cache, body.acc]


CENTIPEDE_WALK_IN_STEPS = 4500  # 1.5 s: ADJUSTMENT is over and the leg wave has formed


def walking_centipede(segments: int = 18, body: str = "hybrid", walk_in_steps: int = CENTIPEDE_WALK_IN_STEPS,
                      fused: bool = True, sets: tuple[str, ...] = ()):
    """A centipede on the ``walk`` scenario, compiled and walked in; returns (case, creature).

    ``fused``: the runner's default, one compiled call per chunk where the body has a fused legged
    path (``fused.legged_walk``); False keeps the Python path (controller sequenced every step).
    ``sets``: more ``--set`` overrides (``legs.stance=dynamic``: tests/benchmarks/test_bench_dynamic_stance.py)."""
    from ..core.config import resolve_case
    from .runner import Creature

    case = resolve_case("centipede", body, "walk", overrides=[f"creature.segments={segments}", *sets])
    b = Creature(case, fused=fused)
    b.compile()
    done, status = b.advance(0.0, walk_in_steps)
    if status != 0:
        raise RuntimeError(f"centipede walk-in stopped after {done} steps: {b.status_text(status)}")
    return case, b


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


# --------------------------------------------------------------------------- cost against size

SCALING_SEGMENTS = (6, 12, 25, 50, 100, 200)
SCALING_KINDS = ("snake", "centipede")
SCALING_SETTLE_STEPS = {"snake": 3000, "centipede": 900}  # the gait / leg wave has started


def scaling_scene(kind: str, segments: int):
    """A compiled creature of ``segments`` segments for the cost-against-size fit, settled; returns (case, creature, t).

    ``snake``: Miller's snake on the mass-spring body; ``centipede``: the walking hybrid centipede."""
    from ..core.config import resolve_case
    from .runner import Creature

    if kind == "snake":
        case = resolve_case("snake", "massspring", "flat", overrides=[f"creature.segments={segments}"])
    elif kind == "centipede":
        case = resolve_case("centipede", "hybrid", "walk", overrides=[f"creature.segments={segments}"])
    else:
        raise ValueError(f"unknown scaling kind {kind!r}; known: {', '.join(SCALING_KINDS)}")
    body = Creature(case)
    body.compile()
    n = SCALING_SETTLE_STEPS[kind]
    done, status = advance_in_chunks(body, 0.0, n)
    if status != 0:
        raise RuntimeError(f"{kind} with {segments} segments stopped after {done} steps: {body.status_text(status)}")
    return case, body, n * case.dt


def time_per_step(kind: str, segments: int, steps: int, repeats: int = 3) -> float:
    """CPU seconds per step (the fastest of ``repeats`` runs of ``steps`` steps, each from the same state)."""
    import time

    case, body, t0 = scaling_scene(kind, segments)
    fields = [body.x, body.v, body.acc] if kind == "snake" else []
    start = [a.copy() for a in fields]
    best = math.inf
    t = t0
    for _ in range(repeats):
        for dst, src in zip(fields, start):
            dst[...] = src
        if kind == "snake":
            t = t0
        c0 = time.thread_time()
        done, status = advance_in_chunks(body, t, steps)
        best = min(best, time.thread_time() - c0)
        _check(f"scaling {kind} {segments}", steps, done, status)
        t += steps * case.dt
    return best / steps


def fit_exponent(segments, seconds_per_step) -> float:
    """Slope p of log(time per step) = p log(segments) + c (least squares)."""
    p, _c = np.polyfit(np.log(np.asarray(segments, float)), np.log(np.asarray(seconds_per_step, float)), 1)
    return float(p)


# --------------------------------------------------------------------------- the suite

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


def setup_massspring_snake(steps: int = 10000) -> tuple[Step, int]:
    """Miller's 50-segment snake step loop, restarted from the settled gait at every call."""
    _case, body, t0 = snake_body()
    start = [a.copy() for a in (body.x, body.v, body.acc)]

    def step(n: int) -> None:
        for dst, src in zip((body.x, body.v, body.acc), start):
            dst[...] = src
        done, status = advance_in_chunks(body, t0, n)
        _check("massspring-snake", n, done, status)

    return step, steps


def setup_fem_chain(steps: int = 3000) -> tuple[Step, int]:
    """The FEM advance kernel on the 17-segment chain (816 tets), restarted from the drop at every call."""
    from ..bodies.fem.system import DT_PAPER

    system, x0, v0 = fem_chain()
    terrain = fem_terrain()
    system.advance(1, dt=DT_PAPER, terrain=terrain)  # JIT compile or cache load, and the factorization
    q0 = system.q_ws.copy()

    def step(n: int) -> None:
        system.x[:] = x0
        system.v[:] = v0
        system.q_ws[:] = q0
        r = system.advance(n, dt=DT_PAPER, terrain=terrain, friction=0.5)
        _check("fem-chain", n, r.steps, r.status)

    return step, steps


def setup_fem_worm(steps: int = 3000) -> tuple[Step, int]:
    """The FEM worm body kernel (muscles, friction, ground contact), restarted from t = 0 at every call."""
    _case, body = fem_worm_body()
    fields = [body.x, body.v, body.system.q_ws, body.acc]
    start = [a.copy() for a in fields]

    def step(n: int) -> None:
        for dst, src in zip(fields, start):
            dst[...] = src
        done, status = advance_in_chunks(body, 0.0, n)
        _check("fem-worm", n, done, status)

    return step, steps


def setup_hybrid_chain(steps: int = 1500) -> tuple[Step, int]:
    """The hybrid body's coupled step (18 boxes, 17 FEM links), restarted from the same state at every call."""
    body = hybrid_chain()
    fields = hybrid_state_fields(body)
    start = [a.copy() for a in fields]
    body.compile()

    def step(n: int) -> None:
        for dst, src in zip(fields, start):
            dst[...] = src
        done, status = body.advance(0.0, n)
        _check("hybrid-chain", n, done, status)

    return step, steps


def _centipede_setup(name: str, body_name: str, fused: bool, steps: int) -> tuple[Step, int]:
    """A walking 18-segment centipede on ``body_name``; walks on from call to call."""
    case, body = walking_centipede(18, body_name, fused=fused)
    if fused and body.stepper.fused is None:
        raise RuntimeError(f"{name}: the fused path does not apply: {body.stepper.fused_reason}")
    t = [CENTIPEDE_WALK_IN_STEPS * case.dt]

    def step(n: int) -> None:
        done, status = body.advance(t[0], n)
        t[0] += done * case.dt
        _check(name, n, done, status)

    return step, steps


def setup_hybrid_centipede(steps: int = 1500) -> tuple[Step, int]:
    """The walking 18-segment hybrid centipede, fused: leg controller and coupled step in one compiled call per chunk."""
    return _centipede_setup("hybrid-centipede", "hybrid", True, steps)


def setup_hybrid_centipede_python(steps: int = 1500) -> tuple[Step, int]:
    """The same centipede on the Python path (the controller sequenced from Python every step): the fused speed-up."""
    return _centipede_setup("hybrid-centipede-python", "hybrid", False, steps)


def setup_massspring_centipede(steps: int = 3000) -> tuple[Step, int]:
    """The walking 18-segment mass-spring centipede (boxes + spring-cube links), fused."""
    return _centipede_setup("massspring-centipede", "massspring", True, steps)


def setup_fem_centipede(steps: int = 1000) -> tuple[Step, int]:
    """The walking 18-segment FEM centipede (stiff blocks in one mesh), fused."""
    return _centipede_setup("fem-centipede", "fem", True, steps)


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


SUITE: dict[str, SuiteEntry] = {e.name: e for e in (
    SuiteEntry("massspring-snake", "Miller's 50-segment snake, lattice step loop", setup_massspring_snake),
    SuiteEntry("fem-chain", "FEM advance kernel, 17-segment chain, 816 tets", setup_fem_chain),
    SuiteEntry("fem-worm", "FEM worm body kernel (muscles, friction)", setup_fem_worm),
    SuiteEntry("hybrid-chain", "hybrid coupled step, 18 boxes + 17 FEM links", setup_hybrid_chain),
    SuiteEntry("hybrid-centipede", "walking 18-segment hybrid centipede (controller + coupled step, fused)",
               setup_hybrid_centipede),
    SuiteEntry("hybrid-centipede-python", "the same centipede, controller sequenced from Python every step",
               setup_hybrid_centipede_python),
    SuiteEntry("massspring-centipede", "walking 18-segment mass-spring centipede (controller + step, fused)",
               setup_massspring_centipede),
    SuiteEntry("fem-centipede", "walking 18-segment FEM centipede (controller + step, fused)", setup_fem_centipede),
    SuiteEntry("rigid-boxes", "rigid-box core, 18 boxes with contact and friction", setup_rigid_boxes),
)}

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
