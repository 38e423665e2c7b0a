"""The fused legged path against the Python path in dynamic stance (``legs.stance = "dynamic"``,
``bodies.dynamic_stance``): bit for bit, as tests/test_fused_walk.py checks it in kinematic stance, with the
feet that slide and the dynamic stance's statistics compared too."""
import numpy as np
import pytest

from test_fused_walk import assert_same_record, pair, walk_both


def assert_same_stance(fused, ref):
    assert np.array_equal(fused.body.stance.acc, ref.body.stance.acc)
    assert fused.body.extra_metrics() == ref.body.extra_metrics()


@pytest.mark.parametrize("body", ["hybrid", "massspring", "fem"])
def test_fused_equals_python_in_dynamic_stance(body):
    # mu = 0.3: the feet slide (the tips move in the body's support), ADJUSTMENT then RANDOM-WALK
    case, fused, ref = pair("walk", 6, "legs.stance=dynamic", "friction.mu_transverse=0.3", body=body)
    assert fused.body.dynamic_stance and ref.body.dynamic_stance
    walk_both(case, fused, ref, [1] * 40 + [50] * 30 + [7, 13, 993, 1])
    assert fused.controller.brain == 3
    assert fused.body.stance.acc[1] > 0          # feet slid
    assert_same_stance(fused, ref)
    assert_same_record(fused, ref)


def test_fused_equals_python_in_dynamic_stance_among_cylinders():
    # obstacles: the feet's normals from the terrain's obstacle search, feet standing on low cylinders
    case, fused, ref = pair("fig13-cylinders", 6, "legs.stance=dynamic")
    walk_both(case, fused, ref, [50] * 50)
    assert_same_stance(fused, ref)
    assert_same_record(fused, ref)
