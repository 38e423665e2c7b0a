"""The Targeter (Sec. 4.1, footnote 2, Sec. 4.3): Follower, Balancer (with the
restoring height sign of PAPER-NOTES.md), head motion, support, and the whole
step against a numpy/scipy reference."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bench_myriapoda.controllers.myriapod import targeter as T
from bench_myriapoda.controllers.myriapod.switcher import SF1, SF2, STANCE
from bench_myriapoda.world.terrain_kernels import PLANE, SLOPE

DT = 1.0 / 300.0  # [s]
REF_TOL = 1e-12  # kernel vs numpy/scipy reference
ORTHO_TOL = 1e-14  # |R^T R - I| after orthonormalize
ALIGN_TOL = 1e-6  # [rad] the Targeter's alignment tolerance in these tests
CIRCLE_TOL = 1e-9  # [m] a turning head's centres lie on the analytic circle

FLAT = np.zeros(8)  # ground plane y = 0
SLOPE_ANGLE = 0.3  # [rad]
TILTED = np.array([0.0, SLOPE_ANGLE] + [0.0] * 6)


def params(**kw):
    kw.setdefault("align_tol", ALIGN_TOL)
    return T.targeter_params(**kw)


def rot(axis, angle):
    v = np.zeros(3)
    v[axis] = angle
    return Rotation.from_rotvec(v).as_matrix()


def angle_between(a, b):
    return math.acos(np.clip(np.dot(a, b) / (np.linalg.norm(a) * np.linalg.norm(b)), -1.0, 1.0))


def run_step(c, R, kinematic, kind, f, p, link_rest, height_target, speed=0.0, rate=0.0, turn=0):
    c_T, R_T = np.empty_like(c), np.empty_like(R)
    T.targeter_step(c, R, np.asarray(kinematic, bool), kind, f, p, link_rest, height_target, speed, rate,
                    turn, DT, c_T, R_T)
    return c_T, R_T


def two_segments(distance, R1=None, height=1.0):
    """The head at the origin at height ``height`` and segment 1 behind it at ``distance``."""
    c = np.array([[0.0, height, 0.0], [-distance, height, 0.0]])
    R = np.stack([np.eye(3), np.eye(3) if R1 is None else R1])
    return c, R


# --------------------------------------------------------------------------
# small kernels
# --------------------------------------------------------------------------

def test_rotate_about_own_axis_matches_scipy():
    rng = np.random.default_rng(0)
    for axis in range(3):
        R = Rotation.random(random_state=rng).as_matrix()
        a = rng.uniform(-3.0, 3.0)
        got = R.copy()
        T.rotate_about_own_axis(got, axis, a)
        np.testing.assert_allclose(got, R @ rot(axis, a), rtol=0, atol=REF_TOL)


def test_orthonormalize_restores_a_rotation():
    rng = np.random.default_rng(1)
    R0 = Rotation.random(random_state=rng).as_matrix()
    R = R0 + 1e-6 * rng.normal(size=(3, 3))
    T.orthonormalize(R)
    assert np.max(np.abs(R.T @ R - np.eye(3))) < ORTHO_TOL
    assert abs(np.linalg.det(R) - 1.0) < ORTHO_TOL
    assert np.max(np.abs(R - R0)) < 1e-5


def test_limited_turn():
    assert T.limited_turn(0.5, 0.1, 1e-6) == 0.1
    assert T.limited_turn(-0.5, 0.1, 1e-6) == -0.1
    assert T.limited_turn(0.05, 0.1, 1e-6) == 0.05  # never overshoots
    assert T.limited_turn(1e-7, 0.1, 1e-6) == 0.0  # within tolerance: still


def test_turn_toward_equals_limited_turn_of_atan2_bit_for_bit():
    """The shortcut (no atan2 where the turn is surely 0) gives the full form's double, also at the
    threshold |y| = tol x / 2, around |atan2| = tol and for x <= 0."""
    rng = np.random.default_rng(5)
    tol, step = 1e-6, 2.0 / 3000.0
    xs = np.concatenate([rng.uniform(-1.0, 2.0, 4000), [0.0, -0.0, 1.0, 1.0, 1.0, 1.0]])
    ys = np.concatenate([rng.uniform(-1.0, 1.0, 4000) * 10.0 ** rng.uniform(-9, 0, 4000),
                         [1e-7, -1e-7, 0.5e-6, np.nextafter(0.5e-6, 1.0), 1e-6, np.nextafter(1e-6, 1.0)]])
    hits = 0
    for x, y in zip(xs, ys):
        want = T.limited_turn(math.atan2(y, x), step, tol)
        got = T.turn_toward(y, x, step, tol)
        assert np.float64(got).tobytes() == np.float64(want).tobytes(), (x, y)
        hits += x > 0.0 and abs(y) <= 0.5 * tol * x
    assert hits > 100



# --------------------------------------------------------------------------
# Follower
# --------------------------------------------------------------------------

@pytest.mark.parametrize("distance", [1.5, 0.6])
def test_follower_restores_the_link_length(distance):
    p = params(k1=5.0)
    c, R = two_segments(distance)
    link_rest, h_T = np.array([0.0, 1.0]), np.array([1.0, 1.0])  # at target height: no Balancer motion
    c_T, R_T = run_step(c, R, [False, True], PLANE, FLAT, p, link_rest, h_T)
    l = c[0] - c[1]
    np.testing.assert_allclose(c_T[1] - c[1], 5.0 * (distance - 1.0) * l * DT, rtol=0, atol=REF_TOL)
    new_length = np.linalg.norm(c[0] - c_T[1])
    assert (new_length < distance) if distance > 1.0 else (new_length > distance)
    # iterated with the segment carried to its target, the link settles at l0
    for _ in range(3000):
        c[1], R[1] = c_T[1], R_T[1]
        c_T, R_T = run_step(c, R, [False, True], PLANE, FLAT, p, link_rest, h_T)
    assert abs(np.linalg.norm(c[0] - c[1]) - 1.0) < 1e-6


def test_follower_at_rest_length_and_aligned_stays_still():
    c, R = two_segments(1.0)
    c_T, R_T = run_step(c, R, [True, True], PLANE, FLAT, params(), np.array([0.0, 1.0]), np.array([1.0, 1.0]))
    np.testing.assert_array_equal(c_T[1], c[1])
    np.testing.assert_allclose(R_T[1], R[1], rtol=0, atol=1e-15)


@pytest.mark.parametrize("yaw", [0.5, -0.5])
def test_follower_turns_x_toward_the_link_and_stops_when_aligned(yaw):
    """yaw > 0 (about +y) turns x toward -z: the link (along +x) then lies to the
    segment's right, and the Follower must turn back about -y."""
    omega = 2.0
    p = params(omega_follow=omega)
    c, R = two_segments(1.0, rot(1, yaw))
    link_rest, h_T = np.array([0.0, 1.0]), np.array([1.0, 1.0])
    errors, still_steps = [], 0
    for _ in range(200):
        c_T, R_T = run_step(c, R, [False, True], PLANE, FLAT, p, link_rest, h_T)
        if np.array_equal(R_T[1], R[1]):
            still_steps += 1
        R[1] = R_T[1]
        errors.append(angle_between(R[1][:, 0], c[0] - c[1]))
    errors = np.array(errors)
    n_turn = math.ceil((abs(yaw) - ALIGN_TOL) / (omega * DT))
    # turns toward the link at omega per step until aligned ...
    np.testing.assert_allclose(errors[:n_turn - 1], abs(yaw) - omega * DT * np.arange(1, n_turn),
                               rtol=0, atol=1e-9)
    assert errors[n_turn - 1] <= ALIGN_TOL
    # ... then holds still: no chatter
    assert still_steps >= 200 - n_turn
    np.testing.assert_allclose(R[1][:, 1], [0.0, 1.0, 0.0], atol=1e-12)  # a pure turn about y


# --------------------------------------------------------------------------
# Balancer
# --------------------------------------------------------------------------

@pytest.mark.parametrize("height,moves_up", [(1.3, False), (0.7, True)])
def test_balancer_restores_the_target_height(height, moves_up):
    """PAPER-NOTES: footnote 2 prints (h - h_T); the restoring sign is (h_T - h)."""
    p = params(k2=4.0)
    c, R = two_segments(1.0, height=height)
    h_T = np.array([1.0, 1.0])
    c_T, _ = run_step(c, R, [False, True], PLANE, FLAT, p, np.array([0.0, 1.0]), h_T)
    dy = c_T[1, 1] - c[1, 1]
    assert (dy > 0.0) == moves_up
    assert abs(dy - 4.0 * (1.0 - height) * DT) < REF_TOL
    for _ in range(2000):
        c[1] = c_T[1]
        c_T, _ = run_step(c, R, [False, True], PLANE, FLAT, p, np.array([0.0, 1.0]), h_T)
    assert abs(c[1, 1] - 1.0) < 1e-6


@pytest.mark.parametrize("yaw", [0.0, 0.7, -2.0])
def test_balancer_turns_y_toward_a_tilted_normal_and_stops(yaw):
    """On a slope (normal tilted toward -x) at several headings, so the normal
    has components along the segment's x and z axes."""
    omega = 1.5
    p = params(omega_balance=omega, k2=0.0)
    normal = np.array([-math.sin(SLOPE_ANGLE), math.cos(SLOPE_ANGLE), 0.0])
    c = np.array([[0.0, 1.0, 0.0]])
    R = rot(1, yaw)[None]
    errors = []
    for _ in range(300):
        _, R_T = run_step(c, R, [True], SLOPE, TILTED, p, np.zeros(1), np.ones(1))
        R = R_T
        errors.append(angle_between(R[0][:, 1], normal))
    errors = np.array(errors)
    assert errors[0] < SLOPE_ANGLE
    assert np.all(np.diff(errors) <= 1e-12)  # monotone approach
    assert errors[-1] < 2 * ALIGN_TOL
    # a settled segment stays still
    _, R_T = run_step(c, R, [True], SLOPE, TILTED, p, np.zeros(1), np.ones(1))
    np.testing.assert_allclose(R_T, R, rtol=0, atol=1e-15)


# --------------------------------------------------------------------------
# head
# --------------------------------------------------------------------------

def test_head_moves_along_its_x_axis_at_the_commanded_speed():
    speed = 0.8
    yaw = 0.4
    c = np.array([[0.0, 1.0, 0.0]])
    R = rot(1, yaw)[None]
    start = c[0].copy()
    for _ in range(300):
        c, R = run_step(c, R, [True], PLANE, FLAT, params(), np.zeros(1), np.ones(1), speed=speed)
    x_axis = np.array([math.cos(yaw), 0.0, -math.sin(yaw)])
    np.testing.assert_allclose(c[0] - start, speed * 300 * DT * x_axis, rtol=0, atol=1e-12)


@pytest.mark.parametrize("turn", [T.TURN_LEFT, T.TURN_RIGHT])
def test_head_turns_at_the_commanded_rate_on_a_circle(turn):
    speed, rate, n = 0.5, 0.9, 600
    c = np.array([[0.0, 1.0, 0.0]])
    R = np.eye(3)[None]
    centres = []
    for _ in range(n):
        c, R = run_step(c, R, [True], PLANE, FLAT, params(), np.zeros(1), np.ones(1), speed=speed,
                        rate=rate, turn=turn)
        centres.append(c[0].copy())
    heading = math.atan2(-R[0][2, 0], R[0][0, 0])  # positive = turned left (x toward -z)
    assert abs(heading - turn * rate * n * DT) < 1e-12
    # each step is a chord of length speed dt turning by rate dt: a circle of
    # radius speed dt / (2 sin(rate dt / 2)), centred on the inner side
    radius = speed * DT / (2.0 * math.sin(0.5 * rate * DT))
    pts = np.vstack([[0.0, 1.0, 0.0], centres])  # with the start
    assert np.ptp(pts[:, 1]) == 0.0  # stays at its height on flat ground
    centre = _circle_centre(pts[:, [0, 2]])
    dist = np.hypot(pts[:, 0] - centre[0], pts[:, 2] - centre[1])
    assert np.max(np.abs(dist - radius)) < CIRCLE_TOL
    assert np.sign(centre[1]) == -turn  # left turn: centre on the -z (left) side


def _circle_centre(xy):
    """Least-squares circle centre of 2D points (algebraic fit)."""
    A = np.column_stack([2 * xy[:, 0], 2 * xy[:, 1], np.ones(len(xy))])
    b = (xy ** 2).sum(axis=1)
    sol, *_ = np.linalg.lstsq(A, b, rcond=None)
    return sol[:2]


# --------------------------------------------------------------------------
# support
# --------------------------------------------------------------------------

def test_segments_supported():
    states = np.array([STANCE, STANCE, STANCE, SF1, SF2, SF1], dtype=np.int64)
    out = np.zeros(3, bool)
    T.segments_supported(states, 2, out)
    assert list(out) == [True, False, False]
    T.segments_supported(states, 1, out)
    assert list(out) == [True, True, False]


def test_unsupported_segments_keep_their_current_pose():
    rng = np.random.default_rng(2)
    c = rng.normal(size=(4, 3))
    R = np.stack([Rotation.random(random_state=rng).as_matrix() for _ in range(4)])
    c_T, R_T = run_step(c, R, [False, True, False, False], SLOPE, TILTED, params(), np.ones(4), np.ones(4),
                        speed=1.0, rate=1.0, turn=1)
    for i in (0, 2, 3):
        np.testing.assert_array_equal(c_T[i], c[i])
        np.testing.assert_array_equal(R_T[i], R[i])
    assert not np.array_equal(c_T[1], c[1])


# --------------------------------------------------------------------------
# the whole step against a numpy/scipy reference
# --------------------------------------------------------------------------

def _limit(remaining, step, tol):
    return 0.0 if abs(remaining) <= tol else math.copysign(min(abs(remaining), step), remaining)


def targeter_reference(c, R, kinematic, kind, f, p, link_rest, height_target, speed, rate, turn, dt):
    """Sec. 6 steps 2-3 and footnote 2 written with scipy rotations."""
    c_T, R_T = c.copy(), R.copy()
    for i in range(len(c)):
        if not kinematic[i]:
            continue
        if kind == PLANE:
            h, n = c[i, 1] - f[0], np.array([0.0, 1.0, 0.0])
        else:
            s, co = math.sin(f[1]), math.cos(f[1])
            h, n = -s * c[i, 0] + co * (c[i, 1] - f[0]), np.array([-s, co, 0.0])
        c_T[i] = c_T[i] + p[T.K2] * (height_target[i] - h) * n * dt
        nl = R_T[i].T @ n
        step = p[T.OMEGA_BALANCE] * dt
        a = -_limit(math.atan2(nl[0], nl[1]), step, p[T.ALIGN_TOL])
        b = _limit(math.atan2(nl[2], nl[1]), step, p[T.ALIGN_TOL])
        R_T[i] = R_T[i] @ rot(2, a) @ rot(0, b)
        if i == 0:
            c_T[0] = c_T[0] + speed * dt * R_T[0][:, 0]
            R_T[0] = R_T[0] @ rot(1, turn * rate * dt)
        else:
            l = c_T[i - 1] - c[i]
            c_T[i] = c_T[i] + p[T.K1] * (np.linalg.norm(l) - link_rest[i]) * l * dt
            ll = R_T[i].T @ l
            turn = _limit(math.atan2(ll[2], ll[0]), p[T.OMEGA_FOLLOW] * dt, p[T.ALIGN_TOL])
            R_T[i] = R_T[i] @ rot(1, -turn)
        u, _, vt = np.linalg.svd(R_T[i])
        R_T[i] = u @ vt
    return c_T, R_T


@pytest.mark.parametrize("kind,f", [(PLANE, FLAT), (SLOPE, TILTED)])
def test_targeter_step_matches_reference(kind, f):
    rng = np.random.default_rng(3)
    n = 6
    p = params(k1=3.0, k2=5.0, omega_follow=40.0, omega_balance=30.0)
    for trial in range(20):
        c = np.cumsum(rng.normal(scale=0.5, size=(n, 3)), axis=0) + [0.0, 1.0, 0.0]
        R = np.stack([Rotation.random(random_state=rng).as_matrix() for _ in range(n)])
        kinematic = rng.random(n) < 0.7
        link_rest = rng.uniform(0.3, 1.0, n)
        height_target = rng.uniform(0.5, 1.5, n)
        args = (kind, f, p, link_rest, height_target, 0.7, 1.3, [1, -1, 0][trial % 3])
        got = run_step(c, R, kinematic, *args)
        want = targeter_reference(c, R, kinematic, *args, DT)
        np.testing.assert_allclose(got[0], want[0], rtol=0, atol=REF_TOL)
        np.testing.assert_allclose(got[1], want[1], rtol=0, atol=REF_TOL)


def test_targeter_params_validation():
    with pytest.raises(ValueError):
        T.targeter_params(k1=-1.0)
    with pytest.raises(ValueError):
        T.targeter_params(omega_follow=float("nan"))


@pytest.mark.parametrize("kind,f", [(PLANE, FLAT), (SLOPE, TILTED)])
def test_targeter_step_equals_one_pass_of_the_kernels_bit_for_bit(kind, f):
    """``targeter_step`` runs its segments in two passes (centres, then turns and Gram-Schmidt): the same
    doubles as one head-to-tail pass of balance, head_motion / follow and orthonormalize per segment
    (Sec. 6 order), with segments left to the dynamics among them, turning and misaligned poses."""
    from bench_myriapoda.world.terrain_kernels import signed_distance, surface_normal
    rng = np.random.default_rng(4)
    n = 9
    c = np.cumsum(np.c_[-0.3 + 0.05 * rng.normal(size=n), 0.02 * rng.normal(size=n), 0.05 * rng.normal(size=n)], 0)
    c[:, 1] += 1.0
    R = np.stack([Rotation.from_rotvec(0.2 * rng.normal(size=3)).as_matrix() for _ in range(n)])
    kinematic = np.ones(n, bool)
    kinematic[[3, 4]] = False
    p = params()
    link_rest, height_target = np.full(n, 0.28), np.full(n, 0.9)
    got_c, got_R = run_step(c, R, kinematic, kind, f, p, link_rest, height_target, 0.4, 0.8, 1)
    c_T, R_T = c.copy(), R.copy()
    for i in range(n):
        if not kinematic[i]:
            continue
        h = signed_distance(kind, f, *c[i])
        nx, ny, nz = surface_normal(kind, f, *c[i])
        T.balance(c_T[i], R_T[i], h, nx, ny, nz, height_target[i], p[T.K2], p[T.OMEGA_BALANCE], p[T.ALIGN_TOL], DT)
        if i == 0:
            T.head_motion(c_T[0], R_T[0], 0.4, 0.8, 1, DT)
        else:
            T.follow(c_T[i], R_T[i], c[i], c_T[i - 1], link_rest[i], p[T.K1], p[T.OMEGA_FOLLOW], p[T.ALIGN_TOL], DT)
        T.orthonormalize(R_T[i])
    assert not np.array_equal(R_T[kinematic], R[kinematic])
    np.testing.assert_array_equal(got_c, c_T)
    np.testing.assert_array_equal(got_R, R_T)


# --------------------------------------------------------------------------- walls (keep_clear_of_walls)

HALF = np.array([0.5, 0.25, 0.5])  # [m] a segment's box: 1 m long, 0.5 m high, 1 m wide
WALL_TOL = 1e-12  # [m] a probe pushed out of a wall ends on its surface, up to round-off


def walls_of(*cylinders):
    """A wall-only terrain array of tall cylinders (x, z, radius) from y = -1 to y = 5 m."""
    from bench_myriapoda.world import terrain_kernels as TK
    return TK.with_obstacles(TK.header(), [TK.cylinder_record(x, z, r, -1.0, 5.0) for x, z, r in cylinders])


def probes_world(c, R, half):
    return np.array([c + R @ (np.array(p) * half) for p in T.WALL_PROBES])


def min_wall_phi(walls, c, R, half):
    from bench_myriapoda.world.terrain_kernels import obstacles_phi
    return min(obstacles_phi(walls, *p)[0] for p in probes_world(c, R, half))


def test_a_carried_box_reaching_into_a_wall_is_moved_out_along_its_normal():
    # a cylinder of radius 0.6 m centred 0.9 m to the right (+z) of the centre: the box's right side (z = 0.5)
    # is 0.2 m inside it at x = 0
    walls = walls_of((0.0, 0.9, 0.6))
    R = rot(1, 0.0)
    c_T = np.array([[0.0, 0.3, 0.0]])
    R_T = R[None].copy()
    assert min_wall_phi(walls, c_T[0], R, HALF) == pytest.approx(-0.2)
    pushes = T.keep_clear_of_walls(c_T, R_T, np.array([True]), walls, HALF[None])
    assert pushes >= 1
    assert min_wall_phi(walls, c_T[0], R, HALF) >= -WALL_TOL
    # straight away from the axis at the deepest probe (z = 0.5 at x = 0): along -z, height unchanged
    np.testing.assert_allclose(c_T[0], [0.0, 0.3, -0.2], atol=1e-12)
    np.testing.assert_array_equal(R_T[0], R)  # the turn is left alone


def test_a_thin_wall_against_the_middle_of_the_box_side_is_caught():
    # radius 0.1 m touching the right side's middle 5 cm deep: no corner inside, the side's edge midpoints are
    walls = walls_of((0.0, 0.55, 0.1))
    c_T = np.array([[0.0, 0.3, 0.0]])
    R_T = np.eye(3)[None].copy()
    corners = probes_world(c_T[0], np.eye(3), HALF)[:8]
    from bench_myriapoda.world.terrain_kernels import obstacles_phi
    assert min(obstacles_phi(walls, *p)[0] for p in corners) > 0.0
    assert T.keep_clear_of_walls(c_T, R_T, np.array([True]), walls, HALF[None]) >= 1
    assert min_wall_phi(walls, c_T[0], np.eye(3), HALF) >= -WALL_TOL
    assert c_T[0, 2] == pytest.approx(-0.05, abs=1e-12)


def test_a_box_between_two_walls_is_pushed_out_of_both():
    walls = walls_of((0.0, 0.9, 0.6), (0.9, -0.8, 0.4))  # right of its middle, and left of its front corner
    yaw = rot(1, 0.2)
    c_T = np.array([[0.0, 0.3, 0.0]])
    R_T = yaw[None].copy()
    assert min_wall_phi(walls, c_T[0], yaw, HALF) < -0.1
    T.keep_clear_of_walls(c_T, R_T, np.array([True]), walls, HALF[None])
    assert min_wall_phi(walls, c_T[0], yaw, HALF) >= -WALL_TOL


def test_segments_not_carried_or_clear_of_the_walls_and_terrains_without_walls_are_left_alone():
    walls = walls_of((0.0, 0.9, 0.6), (10.0, 0.0, 0.5))
    c_T = np.array([[0.0, 0.3, 0.0], [10.0, 0.3, 1.2], [20.0, 0.3, 0.0]])  # inside (not carried), beside, far
    R_T = np.tile(np.eye(3), (3, 1, 1))
    half = np.tile(HALF, (3, 1))
    before = c_T.copy()
    assert T.keep_clear_of_walls(c_T, R_T, np.array([False, True, True]), walls, half) == 0
    np.testing.assert_array_equal(c_T, before)
    assert T.keep_clear_of_walls(c_T, R_T, np.ones(3, bool), FLAT, half) == 0  # no obstacle block
    np.testing.assert_array_equal(c_T, before)


def test_wall_terrain_holds_the_tall_obstacles_walkable_terrain_leaves_out():
    from bench_myriapoda.controllers.myriapod.controller import walkable_terrain, wall_terrain
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.world import terrain_kernels as TK
    from bench_myriapoda.world.terrain import terrain_from_scenario
    # a low cylinder (0.3 m, walked over) and a tall one (3 m, a wall); standing height 1 m
    case = resolve_case("centipede", "hybrid", "walk",
                        overrides=["scenario.obstacle_cylinder_list=[4.0, 0.0, 0.5, 0.3, 8.0, 2.0, 0.6, 3.0]"])
    kind, f = terrain_from_scenario(case.scenario)
    walk, walls = walkable_terrain(case.scenario, kind, f, 1.0), wall_terrain(case.scenario, kind, f, 1.0)
    np.testing.assert_array_equal(TK.obstacle_records(walk)[:, 1:4], [[4.0, 0.0, 0.5]])
    np.testing.assert_array_equal(TK.obstacle_records(walls)[:, 1:4], [[8.0, 2.0, 0.6]])
    flat = resolve_case("centipede", "hybrid", "walk")
    kind, f = terrain_from_scenario(flat.scenario)
    assert wall_terrain(flat.scenario, kind, f, 1.0) is f  # no obstacles: nothing to build
