"""Leg kinematics (bench_myriapoda.kinematics.legs): FK geometry and conventions, the
IK of App. B (round trip, failures, a scipy reference), the all-legs kernels."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import least_squares
from scipy.spatial.transform import Rotation

from bench_myriapoda.kinematics import legs as L
from bench_myriapoda.world.terrain_kernels import PLANE, SLOPE, terrain_phi_numpy

ROUND_TRIP_TOL = 1e-9  # [rad] FK -> IK recovers the angles
FK_REF_TOL = 1e-12  # [m] FK vs the numpy transform-chain reference
IK_REF_TOL = 1e-7  # [rad] IK vs scipy least squares on the FK residual (xtol 1e-14)
LENGTH_TOL = 1e-12  # [m] link lengths preserved by FK

FEMUR, TIBIA, GAMMA = 1.0, 1.2, 0.5
ROOT = (0.15, -0.05, 0.4)
MIN_PLANE_DIST = 0.05  # [m] keep the tip off the root's vertical, where theta is ill-conditioned


def geometry(n_segments=1, gamma=GAMMA):
    return L.leg_geometry(n_segments, ROOT, FEMUR, TIBIA, gamma)


def random_pose(rng):
    return rng.normal(size=3), Rotation.random(random_state=rng).as_matrix()


def random_convex_angles(rng, gamma=GAMMA):
    """Random (theta, alpha, beta) with beta > 0 whose tip is not near the root's vertical."""
    while True:
        theta = rng.uniform(-1.4, 1.4)
        alpha = rng.uniform(-1.2, 1.3)
        beta = rng.uniform(0.05, math.pi - gamma - 0.05)
        _, _, pu, _ = L.leg_plane_points(alpha, beta, FEMUR, TIBIA, gamma)
        if abs(pu) > MIN_PLANE_DIST:
            return theta, alpha, beta


def fk_numpy(c, R, root, side, geom_row, theta, alpha, beta):
    """Reference FK as a chain of rotations: segment pose, root, leg-plane frame
    (a rotation about y of +theta for the right leg, -theta for the left, applied
    to a frame whose x axis points outward), alpha and -(beta + gamma) about the
    in-plane normal."""
    femur, tibia, gamma = geom_row[L.FEMUR], geom_row[L.TIBIA], geom_row[L.GAMMA]
    # columns: where the leg-plane frame's x' (outward), y' (up), z' = x' cross y' point
    if side > 0:
        outward = np.column_stack([(0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (-1.0, 0.0, 0.0)])
    else:
        outward = np.column_stack([(0.0, 0.0, -1.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0)])
    plane = Rotation.from_rotvec([0.0, side * theta, 0.0]).as_matrix() @ outward
    rz = lambda a: Rotation.from_rotvec([0.0, 0.0, a]).as_matrix()  # noqa: E731
    O = c + R @ root
    M = O + R @ plane @ rz(alpha) @ np.array([femur, 0.0, 0.0])
    P = M + R @ plane @ rz(alpha) @ rz(-(beta + gamma)) @ np.array([tibia, 0.0, 0.0])
    return O, M, P


def fk(c, R, geom_row, side, theta, alpha, beta):
    O, M, P = np.empty(3), np.empty(3), np.empty(3)
    L.leg_forward_kinematics(c, R, geom_row, side, theta, alpha, beta, O, M, P)
    return O, M, P


def ik(O, P, R, side, geom_row, hint=0.0):
    return L.leg_inverse_kinematics(O, P, R, side, geom_row, hint)


def test_fk_matches_numpy_reference():
    rng = np.random.default_rng(1)
    geom = geometry()
    for _ in range(200):
        c, R = random_pose(rng)
        k = int(rng.integers(2))
        angles = rng.uniform(-2.0, 2.0, 3)
        got = fk(c, R, geom[k], L.side_sign(k), *angles)
        want = fk_numpy(c, R, geom[k, :3], L.side_sign(k), geom[k], *angles)
        for g, w in zip(got, want):
            np.testing.assert_allclose(g, w, rtol=0, atol=FK_REF_TOL)


def test_fk_conventions_theta_forward_and_mirror_symmetry():
    geom = geometry()
    c, R = np.zeros(3), np.eye(3)
    for k in (L.LEFT, L.RIGHT):
        _, _, P0 = fk(c, R, geom[k], L.side_sign(k), 0.0, 0.3, 1.0)
        _, _, P1 = fk(c, R, geom[k], L.side_sign(k), 0.4, 0.3, 1.0)
        assert P1[0] > P0[0]  # theta > 0 swings the tip toward +x (forward) on both sides
        assert P0[2] * L.side_sign(k) > abs(ROOT[2])  # theta = 0: the tip points outward
    _, ML, PL = fk(c, R, geom[0], -1.0, 0.4, 0.3, 1.0)
    _, MR, PR = fk(c, R, geom[1], 1.0, 0.4, 0.3, 1.0)
    mirror = np.array([1.0, 1.0, -1.0])
    np.testing.assert_allclose(PL, PR * mirror, atol=FK_REF_TOL)
    np.testing.assert_allclose(ML, MR * mirror, atol=FK_REF_TOL)


def test_fk_link_lengths_knee_angle_and_alpha_sign():
    rng = np.random.default_rng(2)
    geom = geometry()
    for _ in range(50):
        c, R = random_pose(rng)
        theta, alpha, beta = rng.uniform(-1.0, 1.0, 3)
        O, M, P = fk(c, R, geom[1], 1.0, theta, alpha, beta)
        assert abs(np.linalg.norm(M - O) - FEMUR) < LENGTH_TOL
        assert abs(np.linalg.norm(P - M) - TIBIA) < LENGTH_TOL
        # the tibia is the femur direction turned by beta + gamma: cos of the angle between them
        cos_bend = np.dot(M - O, P - M) / (FEMUR * TIBIA)
        assert abs(cos_bend - math.cos(beta + GAMMA)) < 1e-12
        # alpha is the femur's elevation above the segment's x-z plane
        assert abs((M - O) @ R[:, 1] - FEMUR * math.sin(alpha)) < 1e-12


def test_ik_round_trip_recovers_convex_poses():
    rng = np.random.default_rng(3)
    geom = geometry()
    worst = 0.0
    for _ in range(500):
        c, R = random_pose(rng)
        k = int(rng.integers(2))
        angles = random_convex_angles(rng)
        O, _, P = fk(c, R, geom[k], L.side_sign(k), *angles)
        ok, *got = ik(O, P, R, L.side_sign(k), geom[k])
        assert ok
        worst = max(worst, np.max(np.abs(np.array(got) - angles)))
    assert worst < ROUND_TRIP_TOL


@pytest.mark.parametrize("gamma", [0.0, 0.3, 1.2])
def test_ik_round_trip_other_gammas(gamma):
    rng = np.random.default_rng(4)
    geom = geometry(gamma=gamma)
    for _ in range(100):
        c, R = random_pose(rng)
        angles = random_convex_angles(rng, gamma)
        O, _, P = fk(c, R, geom[0], -1.0, *angles)
        ok, *got = ik(O, P, R, -1.0, geom[0])
        assert ok
        np.testing.assert_allclose(got, angles, rtol=0, atol=ROUND_TRIP_TOL)


def _tip_at_distance(d, elevation=-0.7, theta=0.2):
    """A tip at distance d [m] from the root of the right leg (identity segment pose)."""
    O = np.array(ROOT)
    u = np.array([math.sin(theta), 0.0, math.cos(theta)])
    return O, O + d * (math.cos(elevation) * u + math.sin(elevation) * np.array([0.0, 1.0, 0.0]))


def test_ik_fails_when_the_circles_do_not_meet():
    geom = geometry()
    for d in (FEMUR + TIBIA + 1e-6, FEMUR + TIBIA + 0.5, abs(TIBIA - FEMUR) - 1e-6, 0.05):
        O, P = _tip_at_distance(d)
        ok, theta, alpha, beta = ik(O, P, np.eye(3), 1.0, geom[1])
        assert not ok, d
        assert math.isnan(alpha) and math.isnan(beta)


def test_ik_fails_when_only_a_non_convex_solution_exists():
    """Between d_gamma (the tip distance at beta = 0) and femur + tibia the circles
    meet, but the leg would have to straighten past its fixed bend: beta <= 0."""
    geom = geometry()
    d_gamma = math.sqrt(FEMUR ** 2 + TIBIA ** 2 + 2 * FEMUR * TIBIA * math.cos(GAMMA))
    for d in (d_gamma + 1e-6, 0.5 * (d_gamma + FEMUR + TIBIA), FEMUR + TIBIA - 1e-9):
        O, P = _tip_at_distance(d)
        ok, theta, alpha, beta = ik(O, P, np.eye(3), 1.0, geom[1])
        assert not ok and beta <= 0.0
        # the non-convex angles returned do reach the tip
        _, _, P_back = fk(np.zeros(3), np.eye(3), geom[1], 1.0, theta, alpha, beta)
        np.testing.assert_allclose(P_back, P, atol=1e-9)
    O, P = _tip_at_distance(d_gamma - 1e-6)
    ok, *_ = ik(O, P, np.eye(3), 1.0, geom[1])
    assert ok


def test_ik_theta_hint_for_a_tip_straight_below_the_root():
    geom = geometry()
    O = np.array(ROOT)
    P = O + np.array([0.0, -1.5, 0.0])
    ok, theta, alpha, beta = ik(O, P, np.eye(3), 1.0, geom[1], 0.37)
    assert ok and theta == 0.37
    _, _, P_back = fk(np.zeros(3), np.eye(3), geom[1], 1.0, theta, alpha, beta)
    np.testing.assert_allclose(P_back, P, atol=1e-12)


def test_ik_tip_inward_of_root_keeps_theta_within_half_pi():
    geom = geometry()
    c, R = np.zeros(3), np.eye(3)
    angles = (0.3, 1.0, 2.6)  # knee nearly folded: the tip comes back under the body
    O, _, P = fk(c, R, geom[1], 1.0, *angles)
    assert (P - O)[2] < 0.0
    ok, *got = ik(O, P, R, 1.0, geom[1])
    assert ok
    np.testing.assert_allclose(got, angles, atol=ROUND_TRIP_TOL)


def test_ik_matches_scipy_least_squares_on_fk_residual():
    rng = np.random.default_rng(5)
    geom = geometry()
    for _ in range(20):
        c, R = random_pose(rng)
        angles = random_convex_angles(rng)
        O, _, P = fk(c, R, geom[1], 1.0, *angles)
        ok, *got = ik(O, P, R, 1.0, geom[1])
        assert ok

        def residual(x):
            return fk_numpy(c, R, geom[1, :3], 1.0, geom[1], *x)[2] - P

        # start off the solution, on the convex side (beta > 0 bound selects the branch)
        x0 = np.array(angles) + rng.uniform(-0.15, 0.15, 3)
        x0[2] = max(x0[2], 0.02)
        sol = least_squares(residual, x0, bounds=([-np.pi / 2, -np.pi, 0.0], [np.pi / 2, np.pi, np.pi]),
                            xtol=1e-14, ftol=1e-14, gtol=1e-14)
        assert np.linalg.norm(sol.fun) < 1e-10
        np.testing.assert_allclose(got, sol.x, rtol=0, atol=IK_REF_TOL)


def test_all_legs_kernels_match_single_leg_kernels():
    rng = np.random.default_rng(6)
    n_seg = 5
    geom = geometry(n_seg)
    seg_c = rng.normal(size=(n_seg, 3))
    seg_R = np.stack([Rotation.random(random_state=rng).as_matrix() for _ in range(n_seg)])
    angles = np.array([random_convex_angles(rng) for _ in range(2 * n_seg)])
    O, M, P = (np.empty((2 * n_seg, 3)) for _ in range(3))
    L.legs_forward_kinematics(seg_c, seg_R, geom, angles, O, M, P)
    roots = np.empty_like(O)
    L.legs_roots(seg_c, seg_R, geom, roots)
    np.testing.assert_array_equal(roots, O)
    for k in range(2 * n_seg):
        i = k // 2
        want = fk(seg_c[i], seg_R[i], geom[k], L.side_sign(k), *angles[k])
        for g, w in zip((O[k], M[k], P[k]), want):
            np.testing.assert_array_equal(g, w)
        np.testing.assert_allclose(L.leg_tip(seg_c[i], seg_R[i], geom[k], L.side_sign(k), *angles[k]), P[k],
                                   atol=FK_REF_TOL)
    # IK of all legs; two tips moved out of reach fail and keep their angles
    tips = P.copy()
    tips[3] += 10.0 * seg_R[1][:, 2]
    tips[6] = roots[6]
    got = np.zeros_like(angles)
    got[:, L.THETA] = angles[:, L.THETA]  # hints
    got[3] = got[6] = (9.0, 9.0, 9.0)
    ok = np.ones(2 * n_seg, bool)
    L.legs_inverse_kinematics(seg_c, seg_R, geom, tips, got, ok)
    assert list(np.flatnonzero(~ok)) == [3, 6]
    np.testing.assert_array_equal(got[3], (9.0, 9.0, 9.0))
    np.testing.assert_array_equal(got[6], (9.0, 9.0, 9.0))
    mask = ok.copy()
    np.testing.assert_allclose(got[mask], angles[mask], rtol=0, atol=ROUND_TRIP_TOL)


def test_wrap_equals_the_general_formula_bit_for_bit():
    """``_wrap`` returns a itself when a + pi lies in [0, 2 pi): the general a - 2 pi floor((a + pi) / 2 pi)
    gives the same double there, also for the doubles next to -pi and pi and for -0.0."""
    two_pi = 2.0 * math.pi
    vals = list(np.random.default_rng(3).uniform(-12.0, 12.0, 20000)) + [0.0, -0.0]
    for base in (-3.0 * math.pi, -math.pi, math.pi, 3.0 * math.pi):
        for direction in (np.inf, -np.inf):
            x = base
            for _ in range(64):
                vals.append(x)
                x = float(np.nextafter(x, direction))
    for a in vals:
        want = a - two_pi * math.floor((a + math.pi) / two_pi)
        got = L._wrap(a)
        assert np.float64(got).tobytes() == np.float64(want).tobytes(), a


def _moved_segments_with_planted_tips(rng, n_seg):
    """(geom, seg_c, seg_R, angles, tips, roots): n_seg random segment poses and convex leg angles, the
    tips where those angles put them, then the segments moved a little (the Targeter's new poses) with
    the tips left planted; roots (2 n_seg, 3) of the moved segments."""
    n_legs = 2 * n_seg
    geom = geometry(n_seg)
    seg_c = rng.normal(size=(n_seg, 3))
    seg_R = np.stack([Rotation.random(random_state=rng).as_matrix() for _ in range(n_seg)])
    angles = np.array([random_convex_angles(rng) for _ in range(n_legs)])
    O0, M0, tips = (np.empty((n_legs, 3)) for _ in range(3))
    L.legs_forward_kinematics(seg_c, seg_R, geom, angles, O0, M0, tips)
    seg_c += 0.05 * rng.normal(size=seg_c.shape)
    roots = np.empty((n_legs, 3))
    L.legs_roots(seg_c, seg_R, geom, roots)
    return geom, seg_c, seg_R, angles, tips, roots


def test_stance_ik_and_fk_equals_ik_then_fk_bit_for_bit():
    """The one-pass kernel gives the doubles of the controller's separate sequence (STANCE legs' IK,
    the theta_min test, FK of all legs, planted tips restored), failures and non-STANCE legs included."""
    from bench_myriapoda.controllers.myriapod import switcher as SW
    rng = np.random.default_rng(11)
    n_seg = 6
    n_legs = 2 * n_seg
    geom, seg_c, seg_R, angles, tips, roots = _moved_segments_with_planted_tips(rng, n_seg)
    # some tips out of reach, one on the root
    tips[3] += 10.0 * seg_R[1][:, 2]
    tips[6] = roots[6]
    states = np.where(rng.random(n_legs) < 0.7, SW.STANCE, SW.SF1).astype(np.int64)
    states[[3, 6]] = SW.STANCE
    start = angles + 0.01 * rng.normal(size=angles.shape)
    theta_min = float(np.median(angles[:, L.THETA]))  # some STANCE legs below it
    # reference: the controller's sequence
    a_ref, t_ref, f_ref, O_ref, M_ref = _ik_then_fk_as_the_controller(states, seg_c, seg_R, geom, tips, start,
                                                                      theta_min)
    # the one-pass kernel
    a, t, failed, O, M = _stance_ik_and_fk_one_pass(states, seg_c, seg_R, geom, tips, start, theta_min)
    assert failed[3] and failed[6] and not failed.all()
    assert (~failed & (states == SW.STANCE)).any()
    for got, want in ((a, a_ref), (t, t_ref), (failed, f_ref), (O, O_ref), (M, M_ref)):
        np.testing.assert_array_equal(got, want)


@pytest.mark.parametrize("kind,f", [(PLANE, [0.1] + [0.0] * 7), (SLOPE, [0.0, 0.3] + [0.0] * 6)])
def test_tips_touching_matches_terrain_reference(kind, f):
    rng = np.random.default_rng(7)
    f = np.array(f)
    tips = rng.uniform(-1.0, 1.0, (40, 3))
    out = np.zeros(40, bool)
    contact = 0.05
    L.tips_touching(kind, f, tips, contact, out)
    np.testing.assert_array_equal(out, terrain_phi_numpy(kind, f, tips) <= contact)
    assert out.any() and not out.all()


def test_leg_geometry_validates_and_mirrors():
    geom = L.leg_geometry(3, (0.1, 0.2, 0.3), 1.0, 2.0, 0.4)
    assert geom.shape == (6, L.N_LEG_GEOM)
    np.testing.assert_array_equal(geom[0::2, L.ROOT_Z], -0.3)
    np.testing.assert_array_equal(geom[1::2, L.ROOT_Z], 0.3)
    with pytest.raises(ValueError, match="gamma"):
        L.leg_geometry(1, gamma=-0.1)
    with pytest.raises(ValueError, match="femur"):
        L.leg_geometry(1, femur=0.0)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_stance_ik_and_fk_pairs_equal_ik_then_fk_bit_for_bit(seed):
    """The one-pass kernel runs the two STANCE legs of a segment side by side (``legs._stance_pair``): the same
    doubles as the controller's separate sequence when every leg is in STANCE, with failures of each kind in
    either leg of a pair (tip out of reach, tip on the root, only a non-convex knee) and theta below theta_min,
    and with one leg of a segment swinging."""
    from bench_myriapoda.controllers.myriapod import switcher as SW
    rng = np.random.default_rng(seed)
    n_seg = 8
    n_legs = 2 * n_seg
    geom, seg_c, seg_R, angles, tips, roots = _moved_segments_with_planted_tips(rng, n_seg)
    tips[2] += 10.0 * seg_R[1][:, 2]          # out of reach, left leg of a pair
    tips[5] = roots[5]                        # on the root, right leg of a pair
    # only a non-convex knee: the tip nearly straight out from the root (beta <= 0), left leg of segment 4
    u = seg_R[4] @ np.array([0.0, 0.0, -1.0])
    tips[8] = roots[8] + 0.999 * (geom[8, L.FEMUR] + geom[8, L.TIBIA]) * u
    states = np.full(n_legs, SW.STANCE, np.int64)
    states[13] = SW.SF2                       # segment 6: one leg swinging
    start = angles + 0.01 * rng.normal(size=angles.shape)
    theta_min = float(np.quantile(angles[:, L.THETA], 0.3))
    a_ref, t_ref, f_ref, O_ref, M_ref = _ik_then_fk_as_the_controller(states, seg_c, seg_R, geom, tips, start,
                                                                      theta_min)
    a, t, failed, O, M = _stance_ik_and_fk_one_pass(states, seg_c, seg_R, geom, tips, start, theta_min)
    ok8 = L.leg_ik_from_segment(seg_c, seg_R, geom, tips, start.copy(), 8)   # circles meet, knee non-convex
    assert failed[2] and failed[5] and failed[8] and not ok8 and not failed.all()
    for got, want in ((a, a_ref), (t, t_ref), (failed, f_ref), (O, O_ref), (M, M_ref)):
        np.testing.assert_array_equal(got, want)


def _ik_then_fk_as_the_controller(states, seg_c, seg_R, geom, tips, start, theta_min):
    """The controller's separate sequence, the reference of ``legs.stance_ik_and_fk``: the STANCE legs' IK
    (``switcher.stance_inverse_kinematics``), the theta_min test, then every leg's FK, the STANCE tips kept
    where they were planted.  Returns (angles, tips, failed, knees O, knees M) as new arrays."""
    from bench_myriapoda.controllers.myriapod import switcher as SW
    n_legs = len(states)
    a, t = start.copy(), tips.copy()
    failed = np.zeros(n_legs, bool)
    O, M = np.empty((n_legs, 3)), np.empty((n_legs, 3))
    SW.stance_inverse_kinematics(states, seg_c, seg_R, geom, t, a, failed)
    failed |= (states == SW.STANCE) & (a[:, 0] < theta_min)
    planted = t.copy()
    L.legs_forward_kinematics(seg_c, seg_R, geom, a, O, M, t)
    t[states == SW.STANCE] = planted[states == SW.STANCE]
    return a, t, failed, O, M


def _stance_ik_and_fk_one_pass(states, seg_c, seg_R, geom, tips, start, theta_min):
    """``legs.stance_ik_and_fk`` on copies of the same inputs; returns what the reference returns."""
    from bench_myriapoda.controllers.myriapod import switcher as SW
    n_legs = len(states)
    a, t = start.copy(), tips.copy()
    failed = np.zeros(n_legs, bool)
    O, M = np.empty((n_legs, 3)), np.empty((n_legs, 3))
    L.stance_ik_and_fk(states, SW.STANCE, seg_c, seg_R, geom, t, a, failed, theta_min, O, M)
    return a, t, failed, O, M
