"""What the harness's benchmarks time of the hybrid body (``BodySpec.benchmarks``, issue 42): its coupled step on
a turning chain of boxes and FEM links, and the walking centipede, fused and on the Python path, in the
throughput suite of ``bench-myriapoda regress``.

The suite builds and times each scene (``harness.throughput_suite``); the entry names are those of the
results store's history and never change.
"""
from __future__ import annotations

import numpy as np

from ...core.specs import BARE, WALK_ON, BodyBenchmarks, SuiteCase

HYBRID_RIGID = 18
HYBRID_SPIN = np.array([0.0, 0.2, 0.0])  # [rad/s] about the vertical through the centre of mass
CENTIPEDE_WALK_IN_STEPS = 4500  # 1.5 s: ADJUSTMENT is over and the leg wave has formed


def spin_chain(body) -> None:
    """Set the chain turning at ``HYBRID_SPIN`` about the vertical through its centre of mass: boxes and free
    nodes moving as one rigid body, the attached nodes carried with their boxes."""
    com = body.observe(0.0).com
    body.rigid.v[:] = np.cross(HYBRID_SPIN, body.rigid.c - com)
    body.rigid.w[:] = HYBRID_SPIN
    body.v[body.free] = np.cross(HYBRID_SPIN, body.x[body.free] - com)
    body.sync_attached()


def chain_state(body) -> dict:
    """The arrays that hold a built hybrid body's whole dynamic state, by name (restoring them restarts it):
    node positions x and velocities v (n_nodes, 3) [m, m/s], the links' tet rotation state fem_q_ws, the boxes'
    centres rigid_c (n, 3) [m], orientations rigid_q (n, 4), velocities rigid_v [m/s] and rigid_w [rad/s] and
    contact impulse cache rigid_impulse_cache, and acc, the step's status accumulators."""
    rb = body.rigid
    return {"x": body.x, "v": body.v, "fem_q_ws": body.fem.q_ws, "rigid_c": rb.c, "rigid_q": rb.q, "rigid_v": rb.v,
            "rigid_w": rb.w, "rigid_impulse_cache": rb.impulse_cache, "acc": body.acc}


CHAIN = SuiteCase("hybrid-chain", "hybrid coupled step, 18 boxes + 17 FEM links", steps=1500, run=BARE,
                  # models/chain.toml lengthened to 18 boxes (density 1) and 17 FEM links, 1 cm above the plane
                  creature="chain", scenario="flat",
                  overrides=(f"creature.segments={HYBRID_RIGID}", "body.rigid_density_kg_m3=1.0",
                             "scenario.start_height_m=0.01"),
                  prepare=spin_chain, restart_state=chain_state)
CENTIPEDE = SuiteCase("hybrid-centipede", "walking 18-segment hybrid centipede (controller + coupled step, fused)",
                      steps=1500, run=WALK_ON, creature="centipede", scenario="walk",
                      overrides=("creature.segments=18",), settle_steps=CENTIPEDE_WALK_IN_STEPS,
                      scaling_settle_steps=900)
CENTIPEDE_PYTHON = SuiteCase("hybrid-centipede-python",
                             "the same centipede, controller sequenced from Python every step", steps=1500,
                             run=WALK_ON, creature="centipede", scenario="walk", overrides=("creature.segments=18",),
                             settle_steps=CENTIPEDE_WALK_IN_STEPS, fused=False)

BENCHMARKS = BodyBenchmarks(suite=(CHAIN, CENTIPEDE, CENTIPEDE_PYTHON))

# creature -> (suite entry, its scene's size in harness.schedule.size_of's units): the scheduler's rate of it
SUITE_SCENES = {"chain": (CHAIN.entry, 18.0 * 27.0),  # 18 boxes, 17 links at resolution 3
                "centipede": (CENTIPEDE.entry, 18.0 * 27.0)}
