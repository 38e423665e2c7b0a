"""The fem body's dynamic stance on constructed cases (``bodies.fem.pushed_blocks``, docs/explanation/dynamic-stance.md,
"Where the force acts"): the legs' impulse goes to the pushed block's leg-attachment nodes only, as one rigid
velocity increment, with the momentum the feet transmit; the feet's friction cone bounds it; an unpushed block and
a swinging segment get nothing; the kinematic stance's penalty is off but for a held block."""
import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.core.leg_timeline import SF1, STANCE
from bench_myriapoda.harness.runner import Creature


def body_at_rest(*sets):
    case = resolve_case("centipede", "fem", "straight", overrides=["creature.segments=3", "legs.stance=dynamic", *sets])
    body = Creature(case, fused=False).body
    body.v[:] = 0.0
    body._f_work[:] = 0.0
    return body


def push(body, block, move, stance=True):
    """Push ``block`` toward its pose moved by ``move`` (3,) [m] with both its legs in STANCE (else SF1), its feet on
    the ground 0.2 m below its centre, beside its side faces; returns (v change (n_nodes, 3), tips after)."""
    c, R = body.segment_poses()
    n = body.n_blocks
    c_T, R_T = c.copy(), R.copy()
    c_T[block] += move
    states = np.full(2 * n, SF1, np.int64)
    if stance:
        states[2 * block:2 * block + 2] = STANCE
    tips = np.zeros((2 * n, 3))
    ground = c[block, 1] - 0.2
    for j, side in ((2 * block, -1.0), (2 * block + 1, 1.0)):
        tips[j] = (c[block, 0], ground, c[block, 2] + side * 0.6)
    supported = np.zeros(n, bool)
    supported[block] = True
    v0 = body.v.copy()
    body.push_support(supported, c_T, R_T, states, tips)
    return body.v - v0, tips


def test_the_push_goes_to_the_attachment_nodes_as_one_rigid_increment_with_the_feet_momentum():
    body = body_at_rest("legs.foot_mu=1000")
    dv, _ = push(body, 1, np.array([0.002, 0.0, 0.001]))
    att = body.att_nodes[body.att_block == 1]
    others = np.setdiff1d(np.arange(len(body.x)), att)
    assert np.all(dv[others] == 0.0)                  # only the pushed block's attachment nodes move
    assert np.abs(dv[att]).max() > 0.0
    # the momentum the nodes get is the impulse of the feet's forces (the foot scratch holds them)
    m = body.fem.mass[att]
    J = body.dt * body.stance.f.sum(axis=0)
    assert (m[:, None] * dv[att]).sum(axis=0) == pytest.approx(J, rel=1e-9, abs=1e-12)
    # forward and sideways as asked, up against gravity (the legs carry the weight)
    assert J[0] > 0.0 and J[2] > 0.0 and J[1] > 0.0
    # a rigid field over the attachment nodes: dv_p = a + alpha x r_p fits to round-off
    r = body.x[att] - body.x[att].mean(axis=0)
    rows = []
    for k in range(len(att)):
        rx = np.array([[0.0, r[k, 2], -r[k, 1]], [-r[k, 2], 0.0, r[k, 0]], [r[k, 1], -r[k, 0], 0.0]])
        rows.append(np.hstack([np.eye(3), rx]))   # alpha x r = -r x alpha
    A = np.vstack(rows)
    sol, *_ = np.linalg.lstsq(A, dv[att].ravel(), rcond=None)
    assert np.abs(A @ sol - dv[att].ravel()).max() < 1e-9 * np.abs(dv[att]).max()
    assert not body.support.any()                     # no penalty: the block is pushed, not carried
    assert body.stance.acc[0] == 2.0                  # two STANCE foot-steps pushed


def test_the_friction_cone_bounds_the_push_and_the_sliding_feet_move():
    # a big sideways move asks for more than mu times the normal force: the feet slide and the block gets only the
    # cone's tangential share
    body = body_at_rest("legs.foot_mu=0.1")
    dv, tips_after = push(body, 1, np.array([0.05, 0.0, 0.0]))
    att = body.att_nodes[body.att_block == 1]
    J = (body.fem.mass[att][:, None] * dv[att]).sum(axis=0)
    assert J[1] > 0.0 and abs(J[0]) <= 0.1 * J[1] * (1 + 1e-9)
    assert body.stance.acc[1] == 2.0                  # both feet slid ...
    c, _ = body.segment_poses()
    assert np.all(tips_after[2:4, 0] != c[1, 0])      # ... and moved from where they stood
    assert body.stance.acc[2] > 0.0


def test_a_swinging_segment_and_an_unsupported_block_get_nothing():
    body = body_at_rest()
    dv, _ = push(body, 1, np.array([0.01, 0.0, 0.0]), stance=False)
    assert np.all(dv == 0.0) and body.stance.acc[0] == 0.0


def test_the_held_head_keeps_the_penalty_and_is_not_pushed():
    case = resolve_case("centipede", "fem", "hang", overrides=["creature.segments=3", "legs.stance=dynamic"])
    body = Creature(case, fused=False).body
    assert body._held[0]
    v0 = body.v.copy()
    c, R = body.segment_poses()
    states = np.full(6, STANCE, np.int64)
    tips = c.repeat(2, axis=0) - np.array([0.0, 0.2, 0.0])
    body.push_support(np.array([True, False, False]), c, R, states, tips)
    assert body.support[0] and not body.support[1:].any()
    assert np.all(body.v == v0)
