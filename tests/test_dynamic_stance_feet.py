"""The dynamic stance's foot model (``bodies.dynamic_stance``) on constructed cases: the friction cone, the
sliding foot, the implicit spring-damper's stiff limit (docs/explanation/dynamic-stance.md)."""
import math

import numpy as np
import pytest

from bench_myriapoda.bodies import dynamic_stance as DS
from bench_myriapoda.core.leg_timeline import STANCE, SF1
from bench_myriapoda.world import terrain_kernels as TK

G = np.array([0.0, -9.81, 0.0])


def flat_terrain():
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.world.world import world_of
    case = resolve_case("centipede", "hybrid", "straight", overrides=["creature.segments=2"])
    return world_of(case, None).terrain


def feet(*rows):
    r = np.zeros((2, 3))
    n = np.zeros((2, 3))
    for j, row in enumerate(rows):
        r[j] = row
        n[j] = (0.0, 1.0, 0.0)
    return r, n


def test_foot_force_inside_the_cone_is_transmitted_whole():
    r, n = feet((0.1, -0.5, 0.6), (0.1, -0.5, -0.6))
    f, slide = np.zeros((2, 3)), np.zeros(2)
    out = DS.foot_forces(3.0, 20.0, 1.0, 0.0, 0.5, 0.0, r, n, 2, 0.5, -1.0, f, slide)
    # each foot: normal 10 N, tangential sqrt(1.5^2 + 0.5^2 + yaw part) < 0.5 x 10
    assert np.all(slide == 0.0)
    assert np.allclose(out, (3.0, 20.0, 1.0, 0.0, 0.5, 0.0), atol=1e-12)
    for j in range(2):
        ft = math.hypot(f[j, 0], f[j, 2])
        assert ft <= 0.5 * f[j, 1]


def test_foot_force_beyond_the_cone_is_cut_to_it_and_slides():
    r, n = feet((0.0, -0.5, 0.6))
    f, slide = np.zeros((2, 3)), np.zeros(2)
    Fx, Fy, Fz, *_ = DS.foot_forces(8.0, 10.0, 0.0, 0.0, 0.0, 0.0, r, n, 1, 0.5, -1.0, f, slide)
    assert Fy == pytest.approx(10.0)
    assert Fx == pytest.approx(5.0)            # mu f_n, along the demanded direction
    assert slide[0] == pytest.approx(1.0 - 5.0 / 8.0)
    # a leg pulling on the ground transmits nothing
    out = DS.foot_forces(1.0, -3.0, 0.0, 0.0, 0.0, 0.0, r, n, 1, 0.5, -1.0, f, slide)
    assert out == (0.0,) * 6 and slide[0] == 1.0
    # the actuator's bound scales the force, the foot does not slide for it
    out = DS.foot_forces(3.0, 4.0, 0.0, 0.0, 0.0, 0.0, r, n, 1, 1.0, 2.5, f, slide)
    assert math.hypot(out[0], out[1]) == pytest.approx(2.5) and slide[0] == 0.0


def one_segment(mu, omega=2 * math.pi * 10.0, zeta=1.0, max_force=-1.0):
    """A 1 kg box at rest at height 1 m with one STANCE foot below its left root, on flat ground."""
    kind, terr = flat_terrain()
    S = DS.stance_arrays(DS.StanceParams(1.0, omega, zeta, mu, max_force), np.array([1.0]),
                         np.array([[0.1, 0.1, 0.1]]), G, np.zeros((1, 3)), np.zeros((1, 3)), kind, terr)
    c = np.array([[0.0, 1.0, 0.0]])
    R = np.eye(3)[None].copy()
    v, w = np.zeros((1, 3)), np.zeros((1, 3))
    tips = np.array([[0.0, 0.0, 0.8], [0.0, 0.5, -0.8]])
    states = np.array([STANCE, SF1], np.int64)
    return S, c, R, v, w, tips, states


@pytest.mark.parametrize("speed, sticks", [(0.02, True), (5.0, False)])
def test_a_stance_foot_holds_while_the_cone_holds_and_slides_once_exceeded(speed, sticks):
    # the target one step ahead along +x at `speed`: the legs ask for m a / (1 + a) speed / dt forward (a = 0.0463
    # at dt = 1/3000 s, 10 Hz, zeta 1): 2.7 N at 0.02 m/s; the foot carries the 9.81 N weight, mu = 0.5 holds 4.9 N
    dt = 1.0 / 3000.0
    S, c, R, v, w, tips, states = one_segment(mu=0.5)
    c_T = c.copy()
    c_T[0, 0] += speed * dt
    before = tips.copy()
    DS.push_segments(c, v, w, R, np.array([True]), np.array([False]), c_T, R.copy(), states, tips, S, dt)
    assert v[0, 0] > 0.0
    if sticks:
        assert np.array_equal(tips, before)
        assert S.acc[DS.ACC_SLID_STEPS] == 0
    else:
        moved = tips[0] - before[0]
        assert moved[0] < 0.0 and moved[1] == 0.0   # swept back along the ground, not into it
        assert np.array_equal(tips[1], before[1])   # a swinging leg's tip is not the stance's business
        assert S.acc[DS.ACC_SLID_STEPS] == 1 and S.acc[DS.ACC_SLIP_M] == pytest.approx(np.linalg.norm(moved))
        # the force it got is the cone's: mu x the normal force
        assert v[0, 0] == pytest.approx(0.5 * v[0, 1], rel=1e-12)   # both dt f / m, the normal one the weight


def test_no_friction_no_horizontal_push():
    dt = 1.0 / 3000.0
    S, c, R, v, w, tips, states = one_segment(mu=0.0)
    c_T = c.copy()
    c_T[0, 0] += 1.0 * dt
    DS.push_segments(c, v, w, R, np.array([True]), np.array([False]), c_T, R.copy(), states, tips, S, dt)
    assert v[0, 0] == 0.0 and v[0, 2] == 0.0
    assert v[0, 1] == pytest.approx(9.81 * dt)  # the weight is still carried (the body's step adds gravity)


def test_stiff_legs_give_the_kinematic_stance_velocity():
    dt = 1.0 / 3000.0
    S, c, R, v, w, tips, states = one_segment(mu=math.inf, omega=1e9)
    c_T = c + np.array([[1.0, 0.2, -0.3]]) * dt
    v[0] = (0.3, -0.1, 0.2)
    DS.push_segments(c, v, w, R, np.array([True]), np.array([False]), c_T, R.copy(), states, tips, S, dt)
    # after the body's step adds gravity, v is (c_T - c) / dt, the kinematic stance's
    assert np.allclose(v[0] + G * dt, (c_T[0] - c[0]) / dt, rtol=1e-6, atol=1e-9)


def test_unsupported_or_held_segments_are_not_pushed():
    dt = 1.0 / 3000.0
    for supported, held in ((False, False), (True, True)):
        S, c, R, v, w, tips, states = one_segment(mu=1.0)
        c_T = c + 0.01
        DS.push_segments(c, v, w, R, np.array([supported]), np.array([held]), c_T, R.copy(), states, tips, S, dt)
        assert not v.any() and S.acc[DS.ACC_FOOT_STEPS] == 0
