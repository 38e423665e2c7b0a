"""The behaviour sampler's chunk replay among obstacles (issue 30): the fused legged path hands a chunk's
timeline samples to ``LeggedMonitor.sample_many`` in one call, obstacles included; the obstacle penetration,
clearance, path and centre of mass must be the same doubles as one ``sample`` call per row."""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from bench_myriapoda.harness.legged import LeggedMonitor
from bench_myriapoda.metrics.behaviour import BehaviourSampler
from bench_myriapoda.world import terrain_kernels as TK


def monitor(f, n_seg):
    m = LeggedMonitor.__new__(LeggedMonitor)
    m.body = SimpleNamespace(segment_half_extents=np.full((n_seg, 3), 0.3))
    m._com = []
    m.behaviour = BehaviourSampler(TK.PLANE, f, False)
    return m


@pytest.mark.parametrize("n_seg", [1, 6, 18])
def test_chunk_replay_among_obstacles_equals_per_sample_calls(n_seg):
    rng = np.random.default_rng(n_seg)
    recs = [TK.cylinder_record(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(0.3, 0.8), -1.0,
                               rng.uniform(0.1, 0.6)) for _ in range(30)]
    f = TK.with_obstacles(TK.header(0.0), recs)
    k = 13
    c = rng.normal(size=(k, n_seg, 3)) * [2.0, 0.3, 2.0] + [0.0, 0.5, 0.0]   # some points inside cylinders
    R = rng.normal(size=(k, n_seg, 3, 3))
    centres = rng.normal(size=(k, 2 * n_seg - 1, 3)) * [2.0, 0.3, 2.0] + [0.0, 0.4, 0.0]
    tips = rng.normal(size=(k, 2 * n_seg, 3)) * [2.0, 0.2, 2.0]
    one, many = monitor(f, n_seg), monitor(f, n_seg)
    for r in range(k):
        one.sample(c[r], R[r], centres[r], tips[r])
    many.sample_many(c[:5], R[:5], centres[:5], tips[:5])  # two chunks
    many.sample_many(c[5:], R[5:], centres[5:], tips[5:])
    many.sample_many(c[:0], R[:0], centres[:0], tips[:0])  # an empty chunk changes nothing
    assert np.array_equal(np.array(one._com), np.array(many._com))
    a, b = one.behaviour.metrics(), many.behaviour.metrics()
    assert a == b
    assert a["obstacle_penetration_body_max_m"] > 0 and a["obstacle_penetration_legs_max_m"] > 0
