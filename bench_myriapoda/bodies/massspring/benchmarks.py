"""What the harness's benchmarks time of the mass-spring body (``BodySpec.benchmarks``, issue 42): Miller's
snake and the walking legged chain in the throughput suite of ``bench-myriapoda regress``, the snake again in
``bench-myriapoda peers`` (against PyElastica's), and the worker-cost probe's case.

The suite builds and times each scene (``harness.throughput_suite``); the entry names are those of the
results store's history and never change.
"""
from __future__ import annotations

from ...core.specs import RESTART, WALK_ON, BodyBenchmarks, PeerCase, SuiteCase

SNAKE_SETTLE_STEPS = 20000  # the snake's gait has formed: the timed steps see contacts, friction and muscles
CENTIPEDE_WALK_IN_STEPS = 4500  # 1.5 s: ADJUSTMENT is over and the leg wave has formed


def snake_state(body) -> dict:
    """The arrays a timed repetition of the snake restores, by name: positions x and velocities v (n_nodes, 3)
    [m, m/s], and acc, the step's status accumulators."""
    return {"x": body.x, "v": body.v, "acc": body.acc}


SNAKE = SuiteCase("massspring-snake", "Miller's 50-segment snake, lattice step loop", steps=10000, run=RESTART,
                  creature="snake", scenario="flat", settle_steps=SNAKE_SETTLE_STEPS, restart_state=snake_state,
                  scaling_settle_steps=3000)
CENTIPEDE = SuiteCase("massspring-centipede", "walking 18-segment mass-spring centipede (controller + step, fused)",
                      steps=3000, run=WALK_ON, creature="centipede", scenario="walk",
                      overrides=("creature.segments=18",), settle_steps=CENTIPEDE_WALK_IN_STEPS)

BENCHMARKS = BodyBenchmarks(
    suite=(SNAKE, CENTIPEDE),
    # compared with PyElastica's continuum snake: the same work as the regress entry (the snake's own dt)
    peers=(PeerCase("ours:massspring-snake", f"Miller's 50-segment snake ({SNAKE.entry})", group="snake",
                    elements=50, element_kind="segment", case=SNAKE),),
    # a short worm of the lattice loads the cheapest kernels of the catalog's bodies
    probe_scene=("worm", "flat"))

# creature -> (suite entry, its scene's size in harness.schedule.size_of's units): the scheduler's rate of it
SUITE_SCENES = {"snake": (SNAKE.entry, 50.0),  # Miller's 50-segment snake
                "centipede": (CENTIPEDE.entry, 18.0)}
