"""Rigid boxes: kernels against slow references, free fall, loads, kinematic bodies, status.

Contact physics lives in test_rigid_contact.py, torque-free rotation in
test_rigid_rotation.py.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bench_myriapoda.bodies import rigid_kernels as rk
from bench_myriapoda.bodies.rigid import (
    STATUS_NONFINITE,
    STATUS_OK,
    STATUS_RUNAWAY,
    ContactSettings,
    RigidBoxes,
)

DT = 1.0 / 3000.0  # [s] the FEM time step of the myriapod paper
G = 9.81  # [m/s^2]
NO_GRAVITY = (0.0, 0.0, 0.0)
FAR_PLANE = [-1.0e6]  # terrain y = -1e6 m: no contact in these tests

QUAT_TOL = 1e-13  # quaternion / matrix ops vs scipy (round-off only)
STEP_TOL = 1e-12  # one kernel step vs the numpy re-implementation [m, m/s, rad/s]
INERTIA_REL_TOL = 1e-3  # box_inertia vs a midpoint-rule integral on a 60^3 grid
ENERGY_TOL = 1e-12  # [J] energy kernel vs numpy
LOAD_TOL = 1e-12  # [N, N m] accumulated force and torque vs numpy


def scipy_to_wxyz(r: Rotation) -> np.ndarray:
    return np.roll(r.as_quat(), 1, axis=-1)


def wxyz_to_scipy(q: np.ndarray) -> Rotation:
    return Rotation.from_quat(np.roll(q, -1, axis=-1))


def same_rotation(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """|q1 . q2| is 1 exactly when both quaternions are the same rotation (q ~ -q)."""
    return np.abs(np.sum(q1 * q2, axis=-1))


@pytest.fixture
def rng():
    return np.random.default_rng(20130627)


# ---------------------------------------------------------------- quaternions

def test_quat_multiply_matches_scipy_composition(rng):
    ra, rb = Rotation.random(50, random_state=1), Rotation.random(50, random_state=2)
    out = np.empty((50, 4))
    rk.quat_multiply(scipy_to_wxyz(ra), scipy_to_wxyz(rb), out)
    expected = scipy_to_wxyz(ra * rb)  # scipy: (a * b).apply(x) = a.apply(b.apply(x))
    np.testing.assert_allclose(same_rotation(out, expected), 1.0, atol=QUAT_TOL)
    # The Hamilton product itself (not only the rotation) on non-unit inputs:
    a = rng.normal(size=(20, 4))
    b = rng.normal(size=(20, 4))
    rk.quat_multiply(a, b, out[:20])
    w1, v1 = a[:, 0], a[:, 1:]
    w2, v2 = b[:, 0], b[:, 1:]
    ref_w = w1 * w2 - np.sum(v1 * v2, axis=1)
    ref_v = w1[:, None] * v2 + w2[:, None] * v1 + np.cross(v1, v2)
    np.testing.assert_allclose(out[:20, 0], ref_w, atol=QUAT_TOL * 10)
    np.testing.assert_allclose(out[:20, 1:], ref_v, atol=QUAT_TOL * 10)


def test_quat_to_matrix_and_normalize_match_scipy(rng):
    r = Rotation.random(50, random_state=3)
    scaled = scipy_to_wxyz(r) * rng.uniform(0.1, 10.0, size=(50, 1))
    unit = np.empty_like(scaled)
    rk.quat_normalize(scaled, unit)
    np.testing.assert_allclose(np.linalg.norm(unit, axis=1), 1.0, atol=QUAT_TOL)
    mats = np.empty((50, 3, 3))
    rk.quat_to_matrix(unit, mats)
    np.testing.assert_allclose(mats, r.as_matrix(), atol=QUAT_TOL * 10)
    zero = np.zeros((1, 4))
    rk.quat_normalize(zero, zero)
    np.testing.assert_array_equal(zero, [[1.0, 0.0, 0.0, 0.0]])


def test_quat_from_axis_angle_matches_scipy(rng):
    axis = rng.normal(size=(40, 3))
    angle = rng.uniform(-2 * np.pi, 2 * np.pi, size=40)
    out = np.empty((40, 4))
    rk.quat_from_axis_angle(axis, angle, out)
    unit_axis = axis / np.linalg.norm(axis, axis=1, keepdims=True)
    expected = scipy_to_wxyz(Rotation.from_rotvec(unit_axis * angle[:, None]))
    np.testing.assert_allclose(same_rotation(out, expected), 1.0, atol=QUAT_TOL)


@pytest.mark.parametrize("spin", [1e-7, 3.0, 400.0])  # [rad/s]: series branch, typical, fast
def test_quat_integrate_is_exact_for_constant_world_spin(rng, spin):
    r0 = Rotation.random(30, random_state=4)
    w = rng.normal(size=(30, 3))
    w *= spin / np.linalg.norm(w, axis=1, keepdims=True)
    out = np.empty((30, 4))
    rk.quat_integrate(scipy_to_wxyz(r0), w, DT, out)
    # World-frame spin: the increment is applied on the left.
    expected = scipy_to_wxyz(Rotation.from_rotvec(w * DT) * r0)
    np.testing.assert_allclose(same_rotation(out, expected), 1.0, atol=QUAT_TOL)
    np.testing.assert_allclose(np.linalg.norm(out, axis=1), 1.0, atol=QUAT_TOL)


# ---------------------------------------------------------------- body kernels

def test_box_inertia_matches_numerical_integral():
    h = np.array([[0.3, 0.2, 0.1], [0.05, 0.4, 0.25]])
    mass = np.array([2.0, 0.7])
    out = np.empty((2, 3))
    rk.box_inertia(mass, h, out)
    k = 60  # midpoint rule: relative error ~ 1 / (6 k^2) on x^2
    for b in range(2):
        axes = [(np.arange(k) + 0.5) / k * 2 * h[b, a] - h[b, a] for a in range(3)]
        x, y, z = np.meshgrid(*axes, indexing="ij")
        dm = mass[b] / x.size
        ref = dm * np.array([np.sum(y**2 + z**2), np.sum(x**2 + z**2), np.sum(x**2 + y**2)])
        np.testing.assert_allclose(out[b], ref, rtol=INERTIA_REL_TOL)


def test_accumulate_point_forces_matches_numpy(rng):
    n, k = 4, 25
    c = rng.normal(size=(n, 3))
    body = rng.integers(0, n, size=k)
    points = rng.normal(size=(k, 3))
    forces = rng.normal(size=(k, 3))
    f_acc = np.ones((n, 3))  # accumulates: starts from non-zero on purpose
    t_acc = np.ones((n, 3))
    rk.accumulate_point_forces(body, points, forces, c, f_acc, t_acc)
    f_ref = np.ones((n, 3))
    t_ref = np.ones((n, 3))
    np.add.at(f_ref, body, forces)
    np.add.at(t_ref, body, np.cross(points - c[body], forces))
    np.testing.assert_allclose(f_acc, f_ref, atol=LOAD_TOL)
    np.testing.assert_allclose(t_acc, t_ref, atol=LOAD_TOL)


def test_points_to_world_and_point_velocities_match_numpy(rng):
    boxes = RigidBoxes([[0.1, 0.2, 0.3]] * 3, [1.0, 2.0, 3.0])
    rots = Rotation.random(3, random_state=5)
    for i in range(3):
        boxes.set_pose(i, c=rng.normal(size=3), q=scipy_to_wxyz(rots[i]),
                       v=rng.normal(size=3), w=rng.normal(size=3))
    body = np.array([0, 2, 1, 2, 0])
    local = rng.normal(size=(5, 3))
    world = boxes.points_to_world(body, local)
    ref = boxes.c[body] + np.einsum("kij,kj->ki", rots[body].as_matrix(), local)
    np.testing.assert_allclose(world, ref, atol=STEP_TOL)
    np.testing.assert_allclose(boxes.world_points(2, local), boxes.c[2] + rots[2].apply(local),
                               atol=STEP_TOL)
    vel = boxes.point_velocities(body, world)
    np.testing.assert_allclose(vel, boxes.v[body] + np.cross(boxes.w[body], world - boxes.c[body]),
                               atol=STEP_TOL)


def test_point_velocities_are_the_rate_of_attached_points():
    """An FEM node fixed to a free body moves at v + w x r (finite-difference check)."""
    boxes = RigidBoxes([[0.2, 0.1, 0.05]], [1.0])
    boxes.set_pose(0, c=[0, 1, 0], v=[0.3, -0.2, 0.1], w=[2.0, -1.0, 3.0])
    local = np.array([[0.2, 0.1, 0.05], [-0.2, 0.0, 0.05]])
    p0 = boxes.world_points(0, local)
    u0 = boxes.point_velocities([0, 0], p0)
    boxes.advance(1, DT, gravity=NO_GRAVITY, terrain_params=FAR_PLANE)
    p1 = boxes.world_points(0, local)
    u1 = boxes.point_velocities([0, 0], p1)
    # Central difference of a smooth trajectory: error ~ |a| dt^2 / 6 with |a| ~ 5 m/s^2.
    np.testing.assert_allclose((p1 - p0) / DT, 0.5 * (u0 + u1), atol=1e-6)


def test_energy_kernel_matches_numpy(rng):
    boxes = RigidBoxes(rng.uniform(0.05, 0.3, size=(5, 3)), rng.uniform(0.5, 3.0, size=5))
    rots = Rotation.random(5, random_state=6)
    for i in range(5):
        boxes.set_pose(i, c=rng.normal(size=3), q=scipy_to_wxyz(rots[i]),
                       v=rng.normal(size=3), w=rng.normal(size=3))
    e = boxes.energy()
    R = rots.as_matrix()
    I_world = np.einsum("nij,nj,nkj->nik", R, boxes.inertia_body, R)
    np.testing.assert_allclose(e.kinetic_linear, 0.5 * boxes.mass * np.sum(boxes.v**2, axis=1),
                               atol=ENERGY_TOL)
    np.testing.assert_allclose(e.kinetic_rotational,
                               0.5 * np.einsum("ni,nij,nj->n", boxes.w, I_world, boxes.w),
                               atol=ENERGY_TOL)
    np.testing.assert_allclose(e.potential, boxes.mass * G * boxes.c[:, 1], atol=ENERGY_TOL)


# ---------------------------------------------------------------- one step vs numpy

def numpy_step(c, R, v, w, m, I, F, tau, dt, g):
    """Slow reference of one contact-free step, written with rotation matrices.

    Kick v and L = I_world w with F and tau; drift c with the new v; rotate by the
    Strang splitting x(dt/2) y(dt/2) z(dt) y(dt/2) x(dt/2) of the free rigid body,
    each piece a body-frame rotation about one principal axis with L fixed.
    """
    v = v + dt * (g + F / m)
    L = R @ (I * (R.T @ w)) + dt * tau
    c = c + dt * v
    rot = Rotation.from_matrix(R)
    for axis, h in [(0, 0.5), (1, 0.5), (2, 1.0), (1, 0.5), (0, 0.5)]:
        Lb = rot.inv().apply(L)
        e = np.zeros(3)
        e[axis] = h * dt * Lb[axis] / I[axis]
        rot = rot * Rotation.from_rotvec(e)
    R = rot.as_matrix()
    w = R @ ((R.T @ L) / I)
    return c, R, v, w


def test_one_step_without_contact_matches_numpy_reference(rng):
    n = 6
    boxes = RigidBoxes(rng.uniform(0.05, 0.4, size=(n, 3)), rng.uniform(0.2, 5.0, size=n))
    rots = Rotation.random(n, random_state=7)
    for i in range(n):
        boxes.set_pose(i, c=rng.normal(size=3), q=scipy_to_wxyz(rots[i]),
                       v=rng.normal(size=3), w=rng.normal(scale=20.0, size=3))
    boxes.force[:] = rng.normal(size=(n, 3))
    boxes.torque[:] = rng.normal(size=(n, 3))
    before = {k: getattr(boxes, k).copy() for k in ("c", "v", "w", "force", "torque")}
    g = np.array([0.0, -G, 0.0])
    n_done, status = boxes.advance(1, DT, gravity=g, terrain_params=FAR_PLANE)
    assert (n_done, status) == (1, STATUS_OK)
    for i in range(n):
        c, R, v, w = numpy_step(before["c"][i], rots[i].as_matrix(), before["v"][i],
                                before["w"][i], boxes.mass[i], boxes.inertia_body[i],
                                before["force"][i], before["torque"][i], DT, g)
        np.testing.assert_allclose(boxes.c[i], c, atol=STEP_TOL)
        np.testing.assert_allclose(boxes.v[i], v, atol=STEP_TOL)
        np.testing.assert_allclose(boxes.w[i], w, atol=STEP_TOL * 100)  # |w| ~ 30 rad/s
        np.testing.assert_allclose(boxes.rotation_matrices()[i], R, atol=STEP_TOL)
    # clear_forces=True (default) empties the accumulators after the call.
    assert not boxes.force.any() and not boxes.torque.any()


# ---------------------------------------------------------------- analytic motion

def test_free_fall_matches_kinematics_within_symplectic_euler_bound():
    """Semi-implicit Euler: c_n = c0 + v0 t - g t^2 / 2 - g t dt / 2 exactly.

    So the error against the exact parabola is bounded by g t dt / 2 (0.5 mm at
    t = 1 s) and, being a pure discretisation offset, matches that value to round-off.
    """
    c0 = np.array([0.5, 20.0, -1.0])
    v0 = np.array([1.0, 3.0, -2.0])
    boxes = RigidBoxes([[0.1, 0.1, 0.1]], [2.0])
    boxes.set_pose(0, c=c0, v=v0)
    n = 3000
    t = n * DT
    assert boxes.advance(n, DT) == (n, STATUS_OK)  # default plane y = 0 stays 5 m below
    g = np.array([0.0, -G, 0.0])
    exact_c = c0 + v0 * t + 0.5 * g * t**2
    bound = 0.5 * G * t * DT
    err = boxes.c[0] - exact_c
    assert np.all(np.abs(err) <= bound + 1e-12)
    np.testing.assert_allclose(err, 0.5 * g * t * DT, atol=1e-9)  # the offset itself
    np.testing.assert_allclose(boxes.v[0], v0 + g * t, atol=1e-10)
    np.testing.assert_allclose(boxes.w[0], 0.0, atol=0.0)


def test_force_off_centre_gives_torque_r_cross_f_and_spins_the_body():
    boxes = RigidBoxes([[0.2, 0.1, 0.05]], [1.5])
    boxes.set_pose(0, c=[0.0, 1.0, 0.0], q=scipy_to_wxyz(Rotation.from_rotvec([0.2, 0.4, -0.1])))
    point = np.array([0.1, 1.05, -0.02])
    force = np.array([0.0, 0.0, 3.0])
    boxes.apply_force_at_point(0, force, point)
    r = point - boxes.c[0]
    np.testing.assert_allclose(boxes.force[0], force, atol=LOAD_TOL)
    np.testing.assert_allclose(boxes.torque[0], np.cross(r, force), atol=LOAD_TOL)
    R = boxes.rotation_matrices()[0]
    I_world_inv = R @ np.diag(1.0 / boxes.inertia_body[0]) @ R.T
    boxes.advance(1, DT, gravity=NO_GRAVITY, terrain_params=FAR_PLANE)
    np.testing.assert_allclose(boxes.v[0], DT * force / boxes.mass[0], atol=STEP_TOL)
    # After one step w = R' I^-1 R'^T L with L = dt r x F: compare in the new frame.
    R1 = boxes.rotation_matrices()[0]
    L = DT * np.cross(r, force)
    np.testing.assert_allclose(boxes.w[0], R1 @ ((R1.T @ L) / boxes.inertia_body[0]),
                               atol=STEP_TOL)
    assert np.linalg.norm(boxes.w[0] - DT * I_world_inv @ np.cross(r, force)) < 1e-6


def test_force_through_centre_does_not_rotate():
    boxes = RigidBoxes([[0.2, 0.1, 0.05]], [1.5])
    q0 = scipy_to_wxyz(Rotation.from_rotvec([0.3, -0.2, 0.6]))
    boxes.set_pose(0, c=[0.0, 1.0, 0.0], q=q0)
    force = np.array([2.0, -1.0, 0.5])
    for _ in range(100):
        boxes.apply_force_at_point(0, force, boxes.c[0])
        boxes.advance(1, DT, gravity=NO_GRAVITY, terrain_params=FAR_PLANE)
    np.testing.assert_allclose(boxes.w[0], 0.0, atol=1e-14)
    np.testing.assert_allclose(same_rotation(boxes.q[0], q0), 1.0, atol=1e-14)
    np.testing.assert_allclose(boxes.v[0], 100 * DT * force / 1.5, rtol=1e-12)


def test_forces_at_points_vectorized_equals_one_by_one(rng):
    a = RigidBoxes([[0.1, 0.1, 0.1]] * 3, [1.0] * 3)
    b = RigidBoxes([[0.1, 0.1, 0.1]] * 3, [1.0] * 3)
    for boxes in (a, b):
        for i in range(3):
            boxes.set_pose(i, c=[i, 0.5, 0.0])
    body = np.array([2, 0, 2, 1])
    forces = rng.normal(size=(4, 3))
    points = rng.normal(size=(4, 3))
    a.apply_forces_at_points(body, forces, points)
    for k in range(4):
        b.apply_force_at_point(body[k], forces[k], points[k])
    np.testing.assert_allclose(a.force, b.force, atol=LOAD_TOL)
    np.testing.assert_allclose(a.torque, b.torque, atol=LOAD_TOL)
    with pytest.raises(IndexError):
        a.apply_forces_at_points([3], forces[:1], points[:1])


# ---------------------------------------------------------------- kinematic bodies

def test_kinematic_body_is_not_moved_by_the_integrator():
    boxes = RigidBoxes([[0.1, 0.05, 0.08]] * 2, [1.0, 1.0])
    q = scipy_to_wxyz(Rotation.from_rotvec([0.1, 0.2, 0.3]))
    # Body 0 kinematic, half sunk into the ground, moving, loaded: none of it matters.
    boxes.set_pose(0, c=[0.0, 0.01, 0.0], q=q, v=[1.0, -2.0, 0.5], w=[3.0, 0.0, -1.0])
    boxes.set_kinematic(0, True)
    boxes.set_pose(1, c=[1.0, 1.0, 0.0])
    before = [getattr(boxes, k)[0].copy() for k in ("c", "q", "v", "w")]
    for _ in range(20):
        boxes.apply_force_at_point(0, [5.0, 5.0, 5.0], [0.1, 0.05, 0.0])
        n_done, status = boxes.advance(50, DT)
        assert status == STATUS_OK
    for k, old in zip(("c", "q", "v", "w"), before):
        np.testing.assert_array_equal(getattr(boxes, k)[0], old)
    # The dynamic body was integrated meanwhile (fell under gravity).
    assert boxes.v[1, 1] == pytest.approx(-G * 1000 * DT, rel=1e-9)
    # Switched back to dynamic, it responds to gravity and contact again.
    boxes.set_kinematic(0, False)
    boxes.advance(3000, DT)
    assert boxes.c[0, 1] > 0.04  # pushed out of the ground (half-extents >= 0.05)


# ---------------------------------------------------------------- instability is data

def test_advance_reports_non_finite_state():
    boxes = RigidBoxes([[0.1, 0.1, 0.1]] * 2, [1.0, 1.0])
    boxes.set_pose(0, c=[0.0, 1.0, 0.0])
    boxes.set_pose(1, c=[1.0, 1.0, 0.0])
    boxes.torque[1] = [np.nan, 0.0, 0.0]
    n_done, status = boxes.advance(100, DT)
    assert (n_done, status) == (1, STATUS_NONFINITE)


def test_advance_reports_runaway_speed_with_the_failing_step():
    boxes = RigidBoxes([[0.1, 0.1, 0.1]], [2.0])
    boxes.set_pose(0, c=[0.0, 1.0, 0.0])
    force = 6000.0  # [N] -> 3000 m/s^2 -> +1 m/s per step
    max_speed = 50.5  # [m/s]
    boxes.force[0] = [force, 0.0, 0.0]
    n_done, status = boxes.advance(1000, DT, gravity=NO_GRAVITY, terrain_params=FAR_PLANE,
                                   max_speed=max_speed)
    assert status == STATUS_RUNAWAY
    assert n_done == 51  # speed after k steps is k m/s; 51 > 50.5 is the first over
    assert boxes.v[0, 0] == pytest.approx(51.0, rel=1e-12)


def test_contact_settings_reject_out_of_range_values():
    with pytest.raises(ValueError, match="restitution"):
        ContactSettings(restitution=1.5)
    with pytest.raises(ValueError, match="position_beta"):
        ContactSettings(position_beta=0.0)
    with pytest.raises(ValueError):
        RigidBoxes([[0.1, -0.1, 0.1]], [1.0])
