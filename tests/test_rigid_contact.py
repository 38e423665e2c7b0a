"""Box-terrain contact: impulses against numpy references, Coulomb friction, resting.

World: y up, g = 9.81 m/s^2 along -y, dt = 1/3000 s.  The terrain is the plane
y = 0 unless stated otherwise; SLOPE rises toward +x (terrain_kernels).
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bench_myriapoda.bodies.rigid import STATUS_OK, ContactSettings, RigidBoxes
from bench_myriapoda.world.terrain_kernels import SLAB, SLOPE

DT = 1.0 / 3000.0  # [s]
G = 9.81  # [m/s^2]
NO_GRAVITY = (0.0, 0.0, 0.0)
HALF = np.array([0.1, 0.05, 0.08])  # [m] a segment-sized box
SIGNS = np.array([[sx, sy, sz] for sz in (-1, 1) for sy in (-1, 1) for sx in (-1, 1)])
CORNERS = SIGNS * HALF  # body-frame corners in the kernels' order (bit 0: x, 1: y, 2: z)

IMPULSE_TOL = 1e-12  # [m/s, kg m^2/s] single-contact impulse vs Baraff's closed form
STICK_TOL = 1e-9  # [m/s, N s] single sticking contact vs the 3x3 solve (PGS converged)
LCP_VEL_TOL = 1e-7  # [m/s] residual velocities allowed by the Signorini-Coulomb check
LCP_IMPULSE_REL_TOL = 1e-6  # relative slack on the friction-disk conditions
STOP_DISTANCE_REL_TOL = 0.05  # sliding distance vs v0^2 / (2 mu g)
SLOPE_ACCEL_REL_TOL = 0.05  # acceleration vs g (sin a - mu cos a)
STATIC_DRIFT_TOL = 1e-6  # [m] displacement of a box sticking to a slope over 2 s
REST_PENETRATION_TOL = 1e-4  # [m] deepest corner of a box at rest
REST_SPEED_TOL = 1e-6  # [m/s] speed of any point of a box at rest
REST_HEIGHT_TOL = 2e-5  # [m] centre height vs the half-extent it stands on (slop 1e-5)
REST_JITTER_TOL = 1e-7  # [m] motion of a resting box over its last 0.5 s
BOUNCE_REL_TOL = 0.02  # bounce apex vs e^2 h
PROJECTION_ENERGY_TOL = 2e-3  # [m] of lift (as m g h) the position correction may add


def box(c, q=(1.0, 0.0, 0.0, 0.0), v=(0.0, 0.0, 0.0), w=(0.0, 0.0, 0.0), mass=1.0):
    boxes = RigidBoxes([HALF], [mass])
    boxes.set_pose(0, c=c, q=q, v=v, w=w)
    return boxes


def corners_world(boxes: RigidBoxes) -> np.ndarray:
    return boxes.world_points(0, CORNERS)


def inverse_world_inertia(boxes: RigidBoxes) -> np.ndarray:
    R = boxes.rotation_matrices()[0]
    return R @ np.diag(1.0 / boxes.inertia_body[0]) @ R.T


# ---------------------------------------------------------------- impulses vs references

def tilted_box_with_one_corner_down(v, w):
    """A box tilted so that exactly corner 0 (-x, -y, -z) is 0.1 mm below the plane."""
    rot = Rotation.from_rotvec([0.3, 0.1, -0.25])
    low = rot.apply(CORNERS)
    k = int(np.argmin(low[:, 1]))
    c = np.array([0.0, -low[k, 1] - 1e-4, 0.0])
    boxes = box(c, np.roll(rot.as_quat(), 1), v, w)
    depth = corners_world(boxes)[:, 1]
    assert np.sum(depth < 0.0) == 1
    return boxes, k


def test_single_corner_impact_matches_baraff_impulse():
    """Frictionless collision: j = -(1 + e) v_rel / (1/m + n . (I^-1 (r x n)) x r).

    Baraff 1997, Rigid Body Simulation II, Sec. 8 (one body against a fixed
    surface).  Compared on v and L, which the orientation drift does not change.
    """
    e = 0.5
    boxes, k = tilted_box_with_one_corner_down(v=[0.4, -1.5, 0.2], w=[1.0, -2.0, 0.5])
    m = boxes.mass[0]
    r = corners_world(boxes)[k] - boxes.c[0]
    n = np.array([0.0, 1.0, 0.0])
    Iinv = inverse_world_inertia(boxes)
    v0, L0 = boxes.v[0].copy(), boxes.angular_momentum()[0].copy()
    v_rel = n @ (v0 + np.cross(boxes.w[0], r))
    assert v_rel < -0.05
    j = -(1.0 + e) * v_rel / (1.0 / m + n @ np.cross(Iinv @ np.cross(r, n), r))
    settings = ContactSettings(friction=0.0, restitution=e, position_iterations=0)
    boxes.advance(1, DT, gravity=NO_GRAVITY, contact=settings)
    np.testing.assert_allclose(boxes.v[0], v0 + j * n / m, atol=IMPULSE_TOL)
    np.testing.assert_allclose(boxes.angular_momentum()[0], L0 + np.cross(r, j * n),
                               atol=IMPULSE_TOL)
    np.testing.assert_allclose(boxes.impulse_cache[0, k], [j, 0.0, 0.0], atol=IMPULSE_TOL)


def test_single_sticking_contact_matches_3x3_solve():
    """With ample friction the corner's full velocity is set: v_t = 0, v_n = -e v_n^-.

    The impulse P solves K P = u_target - u with K = 1/m I - [r]x I_w^-1 [r]x
    (Baraff II, Sec. 8 generalised to three directions) and lies inside the cone.
    """
    e, mu = 0.3, 5.0
    boxes, k = tilted_box_with_one_corner_down(v=[0.3, -1.0, -0.2], w=[0.5, 1.0, -1.5])
    m = boxes.mass[0]
    r = corners_world(boxes)[k] - boxes.c[0]
    Iinv = inverse_world_inertia(boxes)
    v0, L0 = boxes.v[0].copy(), boxes.angular_momentum()[0].copy()
    u = v0 + np.cross(boxes.w[0], r)
    rx = np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])
    K = np.eye(3) / m - rx @ Iinv @ rx
    P = np.linalg.solve(K, np.array([0.0, -e * u[1], 0.0]) - u)
    assert np.hypot(P[0], P[2]) < mu * P[1]
    settings = ContactSettings(friction=mu, restitution=e, position_iterations=0,
                               velocity_iterations=200, velocity_tolerance=0.0)
    boxes.advance(1, DT, gravity=NO_GRAVITY, contact=settings)
    np.testing.assert_allclose(boxes.v[0], v0 + P / m, atol=STICK_TOL)
    np.testing.assert_allclose(boxes.angular_momentum()[0], L0 + np.cross(r, P), atol=STICK_TOL)


def check_signorini_coulomb(boxes, before, mu, terrain_normal, tangents):
    """Numpy check of the contact conditions after one step from state `before`.

    For every corner in contact: v_n >= 0, lam_n >= 0, lam_n v_n = 0; |lam_t| <=
    mu lam_n; sticking (inside the disk) means no slip; slipping means lam_t
    opposes the slip.  Also the impulses account for the whole momentum change.
    """
    c0, R0, v0, w0 = before
    m = boxes.mass[0]
    Iinv = R0 @ np.diag(1.0 / boxes.inertia_body[0]) @ R0.T
    # Post-solve velocities: v is not changed by the drift; L is not either.
    v1 = boxes.v[0]
    w1 = Iinv @ boxes.angular_momentum()[0]
    lam = boxes.impulse_cache[0]
    in_contact = np.flatnonzero(np.any(lam != 0.0, axis=1))
    assert in_contact.size >= 2
    total_p = np.zeros(3)
    total_ang = np.zeros(3)
    n = terrain_normal
    t1, t2 = tangents
    for k in in_contact:
        r = R0 @ CORNERS[k]
        u = v1 + np.cross(w1, r)
        ln, lt = lam[k, 0], lam[k, 1:]
        vn, vt = u @ n, np.array([u @ t1, u @ t2])
        assert ln >= 0.0
        assert vn > -LCP_VEL_TOL
        assert abs(ln * vn) < LCP_VEL_TOL * ln + 1e-15
        assert np.linalg.norm(lt) <= mu * ln * (1.0 + LCP_IMPULSE_REL_TOL)
        if np.linalg.norm(lt) < mu * ln * (1.0 - LCP_IMPULSE_REL_TOL):
            assert np.linalg.norm(vt) < LCP_VEL_TOL
        elif np.linalg.norm(vt) > LCP_VEL_TOL:
            cos = lt @ vt / (np.linalg.norm(lt) * np.linalg.norm(vt))
            assert cos < -1.0 + 1e-6
        P = ln * n + lt[0] * t1 + lt[1] * t2
        total_p += P
        total_ang += np.cross(r, P)
    np.testing.assert_allclose(v1 - v0, total_p / m, atol=1e-12)
    np.testing.assert_allclose(w1 - w0, Iinv @ total_ang, atol=1e-10)


@pytest.mark.parametrize("v, w", [
    ([0.6, -0.05, 0.2], [0.0, 3.0, 0.0]),   # sliding and spinning about y: all corners slip
    ([0.0, -0.2, 0.0], [0.0, 0.05, 0.0]),   # slow landing with a little yaw: mixed
    ([0.02, -0.01, 0.0], [0.0, 0.0, 0.0]),  # creeping: sticks
])
def test_four_contact_solution_satisfies_signorini_coulomb(v, w):
    mu = 0.4
    boxes = box([0.0, HALF[1] - 2e-6, 0.0], v=v, w=w)
    before = (boxes.c[0].copy(), boxes.rotation_matrices()[0], boxes.v[0].copy(),
              boxes.w[0].copy())
    settings = ContactSettings(friction=mu, position_iterations=0, velocity_iterations=500,
                               velocity_tolerance=0.0)
    # Gravity's kick happens before the contact solve: fold it into the reference state.
    before = (before[0], before[1], before[2] + np.array([0.0, -G * DT, 0.0]), before[3])
    boxes.advance(1, DT, contact=settings)
    # The plane's tangent basis in the kernels: x projected on the plane, t2 = n x t1.
    n = np.array([0.0, 1.0, 0.0])
    t1 = np.array([1.0, 0.0, 0.0])
    check_signorini_coulomb(boxes, before, mu, n, (t1, np.cross(n, t1)))


# ---------------------------------------------------------------- Coulomb friction, analytic

@pytest.mark.parametrize("mu, v0, heading", [(0.5, 2.0, 0.0), (0.3, 1.0, 0.7), (0.8, 3.0, -2.0)])
def test_sliding_box_stops_after_v0_squared_over_2_mu_g(mu, v0, heading):
    direction = np.array([np.cos(heading), 0.0, np.sin(heading)])
    boxes = box([0.0, HALF[1] - 1e-6, 0.0], v=v0 * direction)
    settings = ContactSettings(friction=mu)
    t_stop = v0 / (mu * G)
    assert boxes.advance(int(1.5 * t_stop / DT), DT, contact=settings)[1] == STATUS_OK
    travelled = boxes.c[0] - np.array([0.0, HALF[1], 0.0])
    expected = v0**2 / (2.0 * mu * G)
    assert abs(travelled @ direction / expected - 1.0) < STOP_DISTANCE_REL_TOL
    # Friction opposes the motion: the box keeps its heading and does not yaw.
    assert np.linalg.norm(travelled - (travelled @ direction) * direction) < 1e-3 * expected
    assert np.linalg.norm(boxes.v[0]) < REST_SPEED_TOL


def box_on_slope(angle):
    """A box lying flat on the SLOPE terrain through the origin, rising toward +x."""
    n = np.array([-np.sin(angle), np.cos(angle), 0.0])
    q = (np.cos(angle / 2), 0.0, 0.0, np.sin(angle / 2))  # box x axis along the slope
    return box(n * (HALF[1] - 1e-7), q=q), n


@pytest.mark.parametrize("deg, mu", [(30.0, 0.3), (25.0, 0.2), (40.0, 0.6)])
def test_box_slides_down_steep_slope_at_g_sin_minus_mu_cos(deg, mu):
    a = np.radians(deg)
    assert np.tan(a) > mu
    boxes, n = box_on_slope(a)
    c0 = boxes.c[0].copy()
    t = 1.0
    status = boxes.advance(int(round(t / DT)), DT, terrain_kind=SLOPE, terrain_params=[0.0, a],
                           contact=ContactSettings(friction=mu))[1]
    assert status == STATUS_OK
    downhill = -np.array([np.cos(a), np.sin(a), 0.0])
    s = (boxes.c[0] - c0) @ downhill
    expected = G * (np.sin(a) - mu * np.cos(a))
    assert abs(2.0 * s / t**2 / expected - 1.0) < SLOPE_ACCEL_REL_TOL
    assert abs((boxes.c[0] - c0) @ n) < REST_HEIGHT_TOL  # still on the surface


@pytest.mark.parametrize("deg, mu", [(10.0, 0.5), (15.0, 0.3), (20.0, 0.4)])
def test_box_sticks_to_shallow_slope(deg, mu):
    a = np.radians(deg)
    assert np.tan(a) < mu
    boxes, _ = box_on_slope(a)
    c0 = boxes.c[0].copy()
    status = boxes.advance(6000, DT, terrain_kind=SLOPE, terrain_params=[0.0, a],
                           contact=ContactSettings(friction=mu))[1]
    assert status == STATUS_OK
    assert np.linalg.norm(boxes.c[0] - c0) < STATIC_DRIFT_TOL
    assert np.linalg.norm(boxes.v[0]) < REST_SPEED_TOL


# ---------------------------------------------------------------- impacts and rest

def test_dropped_box_comes_to_rest_without_sinking_or_jitter():
    q = np.roll(Rotation.from_rotvec([0.5, 0.2, 0.35]).as_quat(), 1)
    boxes = box([0.0, 0.35, 0.0], q=q, v=[0.3, 0.0, -0.1], w=[2.0, -1.0, 3.0])
    settings = ContactSettings(friction=0.5, restitution=0.3)
    e_start = boxes.energy().total()
    worst_energy = -np.inf
    for _ in range(25):  # 2.5 s
        assert boxes.advance(300, DT, contact=settings)[1] == STATUS_OK
        worst_energy = max(worst_energy, boxes.energy().total())
    positions = []
    for _ in range(50):  # the last 0.5 s, sampled every 10 ms
        boxes.advance(30, DT, contact=settings)
        positions.append(corners_world(boxes))
    positions = np.array(positions)
    assert np.ptp(positions, axis=0).max() < REST_JITTER_TOL
    corners_y = positions[-1][:, 1]
    assert -corners_y.min() < REST_PENETRATION_TOL
    radius = np.linalg.norm(HALF)
    assert np.linalg.norm(boxes.v[0]) + radius * np.linalg.norm(boxes.w[0]) < REST_SPEED_TOL
    # It lies on a face: that face's axis is vertical and the centre sits one half-extent up.
    R = boxes.rotation_matrices()[0]
    axis = int(np.argmax(np.abs(R[1, :])))
    assert abs(R[1, axis]) > 1.0 - 1e-9
    assert abs(boxes.c[0, 1] - HALF[axis]) < REST_HEIGHT_TOL
    # Contact only dissipates; projection may lift by a fraction of a millimetre.
    assert worst_energy < e_start + boxes.mass[0] * G * PROJECTION_ENERGY_TOL


@pytest.mark.parametrize("e", [0.5, 0.8])
def test_flat_drop_bounces_to_e_squared_height(e):
    h = 0.2
    boxes = box([0.0, HALF[1] + h, 0.0])
    settings = ContactSettings(restitution=e)
    heights = []
    for _ in range(int(1.0 / DT)):
        boxes.advance(1, DT, contact=settings)
        heights.append(boxes.c[0, 1] - HALF[1])
    heights = np.array(heights)
    first_rise = int(np.argmax(np.diff(heights) > 0.0))
    apex = heights[first_rise:].max()
    assert abs(apex / (e * e * h) - 1.0) < BOUNCE_REL_TOL


def test_position_projection_removes_penetration_without_adding_velocity():
    depth = 5e-3
    slop = ContactSettings().slop
    boxes = box([0.0, HALF[1] - depth, 0.0])
    boxes.advance(200, DT, gravity=NO_GRAVITY)
    assert -corners_world(boxes)[:, 1].min() <= slop * (1.0 + 1e-6)
    np.testing.assert_allclose(boxes.v[0], 0.0, atol=1e-15)
    np.testing.assert_allclose(boxes.w[0], 0.0, atol=1e-15)


def test_box_rests_on_slab_top():
    """The SLAB terrain (Miller's book): a box dropped on the slab stays on top of it."""
    ground, top, edge, radius = 0.0, 0.3, 1.0, 0.02
    boxes = box([0.5, top + HALF[1] + 0.05, 0.0])
    boxes.advance(3000, DT, terrain_kind=SLAB, terrain_params=[ground, top, edge, radius])
    assert abs(boxes.c[0, 1] - (top + HALF[1])) < REST_HEIGHT_TOL
    assert abs(boxes.c[0, 0] - 0.5) < REST_JITTER_TOL
    assert np.linalg.norm(boxes.v[0]) < REST_SPEED_TOL


# ---------------------------------------------------------------- friction kernel vs reference

def friction_reference(K, u, limit):
    """Maximum dissipation by brute force: the impulse in the disk that minimises the
    kinetic energy of the remaining slip, (u + K l)^T K^-1 (u + K l) / 2."""
    from scipy.optimize import minimize_scalar

    Kinv = np.linalg.inv(K)
    stick = -Kinv @ u
    if np.linalg.norm(stick) <= limit:
        return stick

    def energy(theta):
        s = u + K @ (limit * np.array([np.cos(theta), np.sin(theta)]))
        return s @ Kinv @ s

    # Bracket the minimum near the direction of -u, then refine.
    thetas = np.linspace(-np.pi, np.pi, 721)
    best = thetas[np.argmin([energy(t) for t in thetas])]
    res = minimize_scalar(energy, bounds=(best - 0.01, best + 0.01), method="bounded",
                          options={"xatol": 1e-12})
    return limit * np.array([np.cos(res.x), np.sin(res.x)])


FRICTION_KERNEL_TOL = 1e-6  # relative to the disk radius (the reference's optimiser limit)


def test_coulomb_friction_impulse_matches_brute_force_maximum_dissipation():
    from bench_myriapoda.bodies.rigid_kernels import _coulomb_friction_impulse

    rng = np.random.default_rng(7)
    n_kinetic = 0
    for _ in range(60):
        A = rng.normal(size=(2, 2))
        K = A @ A.T + 0.05 * np.eye(2)  # SPD, often strongly anisotropic
        Kinv = np.linalg.inv(K)
        u = rng.normal(size=2)
        limit = np.linalg.norm(Kinv @ u) * rng.uniform(0.05, 1.5)
        got = np.array(_coulomb_friction_impulse(K[0, 0], K[0, 1], K[1, 1], Kinv[0, 0],
                                                 Kinv[0, 1], Kinv[1, 1], u[0], u[1], limit))
        ref = friction_reference(K, u, limit)
        np.testing.assert_allclose(got, ref, atol=FRICTION_KERNEL_TOL * limit)
        n_kinetic += np.linalg.norm(Kinv @ u) > limit
    assert 20 < n_kinetic < 60  # both branches exercised


def test_anisotropic_box_friction_follows_hu_et_al_law():
    """A sliding box contact takes Hu et al.'s friction -lam_n (mu_1 s_1, mu_2 s_2), s the unit
    resulting slip (the law of the point nodes and of reference.slithering), not the
    maximum-dissipation point of the same ellipse; sticking when -K^-1 u lies in the ellipse."""
    from bench_myriapoda.bodies.rigid_kernels import _hu_friction_impulse

    rng = np.random.default_rng(11)
    n_kinetic = 0
    for _ in range(200):
        A = rng.normal(size=(2, 2))
        K = A @ A.T + 0.05 * np.eye(2)
        u = rng.normal(size=2)
        m1, m2 = rng.uniform(0.05, 1.0, 2)
        lam = rng.uniform(0.01, 2.0)
        got = np.array(_hu_friction_impulse(K[0, 0], K[0, 1], K[1, 1], u[0], u[1], m1, m2, lam))
        stick = -np.linalg.solve(K, u)
        if (stick[0] / m1) ** 2 + (stick[1] / m2) ** 2 <= lam ** 2:
            np.testing.assert_allclose(got, stick, rtol=1e-9, atol=1e-12)
            continue
        n_kinetic += 1
        slip = u + K @ got
        s = slip / np.linalg.norm(slip)
        np.testing.assert_allclose(got, -lam * np.array([m1 * s[0], m2 * s[1]]), atol=1e-8 * lam)
    assert 50 < n_kinetic < 200
