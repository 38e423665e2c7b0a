"""What the harness's benchmarks time of the FEM body (``BodySpec.benchmarks``, issue 42): its advance kernel on
a spinning 17-segment chain, the muscle-driven worm and the walking legged chain in the throughput suite of
``bench-myriapoda regress``, and the chain resting on the plane in ``bench-myriapoda peers`` (against
MuJoCo's flex blocks).

The chain scenes are kernels of the FEM's own (``FEMSystem`` on a mesh, no case): ``fem_chain`` builds
them, shared with ``tests/benchmarks/test_bench_fem.py``.  The entry names are those of the results store's
history and never change.
"""
from __future__ import annotations

import numpy as np

from ...core.specs import KERNEL, RESTART, WALK_ON, BodyBenchmarks, PeerCase, SuiteCase
from ...world import terrain_kernels as T
from .mesh import chain_grid
from .system import DT_PAPER, FEMSystem

FEM_CHAIN_SEGMENTS = 17
FEM_CHAIN_SPIN = 2.0  # [rad/s] about the vertical
FEM_CHAIN_LIFT = 0.05  # [m]
CENTIPEDE_WALK_IN_STEPS = 4500  # 1.5 s: ADJUSTMENT is over and the leg wave has formed
RESTING_SETTLE_STEPS = 3000  # the resting chain of the peers' comparison settles on the plane first
RESTING_FRICTION = 0.5  # Coulomb friction of the chain scenes


def fem_terrain():
    """The plane y = 0 as the FEMSystem's ``terrain`` argument."""
    return (T.PLANE, np.zeros(T.N_TERRAIN_PARAMS))


def fem_chain(resolution: int = 3, unit: str = "nodes"):
    """A 17-segment deformable chain (paper presets, segments 1 x 1 x 1) 5 cm above the plane, spinning at 2 rad/s.

    Returns (system, x0, v0): the FEMSystem (not compiled) and its start state.
    """
    nodes, tets, _seg = chain_grid(FEM_CHAIN_SEGMENTS, 1.0, cross_section=(1.0, 1.0),
                                   resolution=resolution, resolution_unit=unit)
    system = FEMSystem(nodes, tets)
    centre = nodes.mean(axis=0)
    x0 = nodes + [0.0, FEM_CHAIN_LIFT, 0.0]
    v0 = np.cross([0.0, FEM_CHAIN_SPIN, 0.0], nodes - centre)
    return system, x0, v0


def _check(what: str, n: int, steps: int, status: int) -> None:
    if status != 0 or steps != n:
        raise RuntimeError(f"throughput suite entry {what!r}: {steps} of {n} steps, status {status}")


def setup_chain(steps: int):
    """The FEM advance kernel on the 17-segment chain (816 tets), restarted from the drop at every call."""
    system, x0, v0 = fem_chain()
    terrain = fem_terrain()
    system.advance(1, dt=DT_PAPER, terrain=terrain)  # JIT compile or cache load, and the factorization
    q0 = system.q_ws.copy()

    def step(n: int) -> None:
        system.x[:] = x0
        system.v[:] = v0
        system.q_ws[:] = q0
        r = system.advance(n, dt=DT_PAPER, terrain=terrain, friction=RESTING_FRICTION)
        _check(CHAIN.entry, n, r.steps, r.status)

    return step, steps


def setup_chain_resting(resolution: int, steps: int):
    """The chain (resolution nodes per edge) settled on the plane, restarted at every call: (step, steps)."""
    system, x0, _v0 = fem_chain(resolution=resolution)
    terrain = fem_terrain()
    system.x[:] = x0 - [0.0, x0[:, 1].min(), 0.0]  # underside on the plane, at rest
    r = system.advance(RESTING_SETTLE_STEPS, dt=DT_PAPER, terrain=terrain, friction=RESTING_FRICTION)
    if r.status != 0:
        raise RuntimeError("our FEM chain went unstable while settling")
    state = [a.copy() for a in (system.x, system.v, system.q_ws)]

    def step(n: int) -> None:
        for dst, src in zip((system.x, system.v, system.q_ws), state):
            dst[...] = src
        r = system.advance(n, dt=DT_PAPER, terrain=terrain, friction=RESTING_FRICTION)
        if r.status != 0 or r.steps != n:
            raise RuntimeError("our FEM chain stopped early")

    return step, steps


def worm_state(body) -> dict:
    """The arrays a timed repetition of the worm restores, by name: node positions x and velocities v
    (n_nodes, 3) [m, m/s], each tet's rotation state q_ws (``kernels`` module docstring) and acc, the step's
    status accumulators."""
    return {"x": body.x, "v": body.v, "q_ws": body.system.q_ws, "acc": body.acc}


CHAIN = SuiteCase("fem-chain", "FEM advance kernel, 17-segment chain, 816 tets", steps=3000, run=KERNEL,
                  kernel=setup_chain)
WORM = SuiteCase("fem-worm", "FEM worm body kernel (muscles, friction)", steps=3000, run=RESTART,
                 creature="worm", scenario="flat", restart_state=worm_state)
CENTIPEDE = SuiteCase("fem-centipede", "walking 18-segment FEM centipede (controller + step, fused)", steps=1000,
                      run=WALK_ON, creature="centipede", scenario="walk", overrides=("creature.segments=18",),
                      settle_steps=CENTIPEDE_WALK_IN_STEPS)


def _resting(resolution: int, tets_per_segment: int, steps: int) -> PeerCase:
    """Our entry of the peers' soft-body group of that many tets: the chain resting on the plane."""
    n = tets_per_segment * FEM_CHAIN_SEGMENTS

    def kernel(k: int):
        return setup_chain_resting(resolution, k)

    return PeerCase(f"ours:fem-chain-{n}", f"our FEM chain resting on the plane, {n} tets", group=f"soft-{n}",
                    elements=n, element_kind="tet", dt=DT_PAPER,
                    case=SuiteCase(f"ours:fem-chain-{n}", "resting chain", steps=steps, run=KERNEL, kernel=kernel))


BENCHMARKS = BodyBenchmarks(
    suite=(CHAIN, WORM, CENTIPEDE),
    # resolution 3 and 4 nodes per edge: 48 and 162 tets per segment, ten times the peer's steps per repetition
    peers=(_resting(3, 48, 6000), _resting(4, 162, 2000)))

# creature -> (suite entry, its scene's size in harness.schedule.size_of's units): the scheduler's rate of it
SUITE_SCENES = {"worm": (WORM.entry, 20.0 * 27.0),  # the default 20-segment worm, resolution 3
                "centipede": (CENTIPEDE.entry, 18.0 * 27.0)}
