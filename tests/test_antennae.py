"""The myriapod's antennae (paper Sec. 5.2, Fig. 11) and the brain's AVOIDANCE (Sec. 4.3).

Conventions: world y up, the creature faces +x, z is its right; the left antenna sits at -z.
The head's turn direction is + = left (a positive rotation about +y), as the scenario's
``control_turn_rate_deg_s``; the heading atan2(-x_z, x_x) of the head's x axis grows in a left turn.
"""
import math
from dataclasses import replace

import numpy as np

from bench_myriapoda.harness.runner import Creature
import pytest

from bench_myriapoda.controllers.myriapod import antennae as A
from bench_myriapoda.controllers.myriapod.controller import (
    AVOIDANCE,
    RANDOM_WALK,
    TROPHOTROPISM,
    TURN_LEFT,
    TURN_RIGHT,
    MyriapodController,
    avoidance_turn,
)
from bench_myriapoda.core import registry
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.core.schema import AntennaeConfig
from bench_myriapoda.world import terrain_kernels as TK

DT = 1.0 / 3000.0


def rotation_y(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def random_rotation(rng):
    q = rng.normal(size=4)
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def fk(c, R, angles, cfg=None):
    cfg = cfg or AntennaeConfig()
    n = angles.shape[1]
    pts, frames = np.zeros((2, n + 1, 3)), np.zeros((2, n + 1, 3, 3))
    A.antennae_forward_kinematics(c, R, A.antenna_params(cfg), angles, pts, frames)
    return pts, frames


def heading(R):
    return math.atan2(-R[2, 0], R[0, 0])


# --------------------------------------------------------------------------- kinematics

def test_forward_kinematics_keeps_link_lengths_and_roots_on_the_head():
    rng = np.random.default_rng(1)
    cfg = AntennaeConfig()
    for _ in range(20):
        c, R = rng.normal(size=3), random_rotation(rng)
        angles = rng.uniform(-1.0, 1.0, (2, cfg.n_links, 2))
        pts, frames = fk(c, R, angles)
        seg = np.linalg.norm(np.diff(pts, axis=1), axis=2)
        np.testing.assert_allclose(seg, cfg.link_length_m, rtol=0, atol=1e-12)
        # roots at (root_x, root_y, -+root_z) in the head frame: left at -z, right at +z
        np.testing.assert_allclose(pts[0, 0], c + R @ [cfg.root_x_m, cfg.root_y_m, -cfg.root_z_m], atol=1e-12)
        np.testing.assert_allclose(pts[1, 0], c + R @ [cfg.root_x_m, cfg.root_y_m, cfg.root_z_m], atol=1e-12)
        for a in range(2):
            for i in range(cfg.n_links + 1):  # every frame a rotation
                np.testing.assert_allclose(frames[a, i].T @ frames[a, i], np.eye(3), atol=1e-12)


def test_the_antenna_moves_rigidly_with_the_head():
    rng = np.random.default_rng(2)
    angles = rng.uniform(-0.8, 0.8, (2, 12, 2))
    c1, R1 = rng.normal(size=3), random_rotation(rng)
    c2, R2 = rng.normal(size=3), random_rotation(rng)
    p1, _ = fk(c1, R1, angles)
    p2, _ = fk(c2, R2, angles)
    np.testing.assert_allclose(p2, c2 + (p1 - c1) @ (R2 @ R1.T).T, atol=1e-12)


def test_angle_conventions_theta_outward_phi_up_mirror_image():
    cfg = AntennaeConfig()
    n = cfg.n_links
    c, R = np.zeros(3), np.eye(3)
    straight, _ = fk(c, R, np.zeros((2, n, 2)))
    np.testing.assert_allclose(straight[:, -1, 0] - straight[:, 0, 0], n * cfg.link_length_m)  # along +x
    ang = np.zeros((2, n, 2))
    ang[:, 0, A.THETA] = 0.3   # outward
    ang[:, 0, A.PHI] = 0.2     # up
    p, _ = fk(c, R, ang)
    assert p[0, -1, 2] < p[0, 0, 2] and p[1, -1, 2] > p[1, 0, 2]    # left goes to -z, right to +z
    assert p[0, -1, 1] > p[0, 0, 1] and p[1, -1, 1] > p[1, 0, 1]    # both up
    np.testing.assert_allclose(p[0] * [1, 1, -1], p[1], atol=1e-12)  # mirror images in the x-y plane


# --------------------------------------------------------------------------- motion

def test_root_turns_at_omega0_toward_random_targets_and_redraws_them():
    cfg = AntennaeConfig()
    ant = A.Antennae(cfg, DT, np.random.default_rng(0), TK.header(0.0))
    w0 = math.radians(cfg.omega0_deg_s)
    lo = np.radians([cfg.root_theta_range_deg[0], cfg.root_phi_range_deg[0]])
    hi = np.radians([cfg.root_theta_range_deg[1], cfg.root_phi_range_deg[1]])
    c, R = np.array([0.0, 1.0, 0.0]), np.eye(3)
    arrivals = 0
    drawn0 = ant.targets_drawn
    for k in range(6000):  # 2 s
        before = ant.nominal[:, 0].copy()
        target = ant.root_target.copy()
        ant.step(c, R, k * DT)
        step = np.linalg.norm(ant.nominal[:, 0] - before, axis=1)
        for a in range(2):
            if ant.arrived[a]:
                arrivals += 1
                np.testing.assert_allclose(ant.nominal[a, 0], target[a], atol=1e-15)  # landed on it
                assert step[a] <= w0 * DT + 1e-15
                assert np.all(ant.root_target[a] >= lo) and np.all(ant.root_target[a] <= hi)  # a new one
            else:
                assert step[a] == pytest.approx(w0 * DT, rel=1e-9)  # constant angular speed
                # on the straight line toward the target
                d_before, d_now = target[a] - before[a], target[a] - ant.nominal[a, 0]
                assert abs(d_before[0] * d_now[1] - d_before[1] * d_now[0]) < 1e-12
    assert arrivals >= 4
    assert ant.targets_drawn - drawn0 == arrivals


def test_links_follow_the_travelling_wave():
    cfg = replace(AntennaeConfig(), wave_amplitude_theta_deg=10.0, wave_amplitude_phi_deg=5.0,
                  wave_base_theta_deg=3.0, wave_base_phi_deg=-2.0, wave_frequency_hz=1.5, wave_lambda_deg=40.0)
    ant = A.Antennae(cfg, DT, np.random.default_rng(0), TK.header(0.0))
    for k in range(0, 900, 7):
        t = k * DT
        ant.step(np.zeros(3), np.eye(3), t)
        i = np.arange(1, cfg.n_links)
        ph = 2 * math.pi * 1.5 * t - math.radians(40.0) * i
        ang = ant.joint_angles()
        for a in range(2):
            np.testing.assert_allclose(ang[a, 1:, A.THETA], math.radians(10.0) * np.sin(ph) + math.radians(3.0),
                                       atol=1e-12)
            np.testing.assert_allclose(ang[a, 1:, A.PHI], math.radians(5.0) * np.sin(ph) + math.radians(-2.0),
                                       atol=1e-12)


def test_deferred_links_equal_the_full_step_bit_for_bit():
    """``antennae_step(..., links=False)`` then ``antennae_links`` for the last step (the fused chunk's way on a
    terrain without obstacles) leaves the doubles of ``links=True`` every step; with obstacles ``links`` is
    ignored.  Random head poses, root targets redrawn, offsets relaxing from a retraction."""
    rng = np.random.default_rng(5)
    cfg = replace(AntennaeConfig(), wave_amplitude_theta_deg=10.0, wave_amplitude_phi_deg=5.0)
    for f in (TK.header(0.0), cylinder_terrain(0.3, 0.0, 0.05)):
        full = A.Antennae(cfg, DT, np.random.default_rng(1), f)
        lazy = A.Antennae(cfg, DT, np.random.default_rng(1), f)
        for a in (full, lazy):
            a.offsets[:] = 0.01 * np.arange(a.offsets.size).reshape(a.offsets.shape)
        names = ("nominal", "offsets", "root_target", "root_omega", "retracting", "contact", "rising",
                 "contact_point", "contact_normal", "contact_depth", "arrived", "points", "frames")
        for chunk in (1, 5, 40):
            for k in range(chunk):
                t = k * DT
                c, R = 0.01 * rng.normal(size=3), random_rotation(rng)
                full.step(c, R, t)
                n_r, arrived = A.antennae_step(c, R, t, DT, lazy.params, lazy.f, *lazy.step_packs(), False)
                if arrived:
                    for a in (A.LEFT, A.RIGHT):
                        if lazy.arrived[a]:
                            lazy.root_target[a] = lazy._draw()
            A.antennae_links(lazy.params, t, lazy.nominal, lazy.offsets, lazy.points, lazy.frames)
            for name in names:
                np.testing.assert_array_equal(getattr(lazy, name), getattr(full, name), err_msg=name)
        assert full.targets_drawn > 2


# --------------------------------------------------------------------------- contact and retraction

def cylinder_terrain(x, z, radius, height=3.0):
    return TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(x, z, radius, -1.0, height)])


def sample_points(points):
    """The contact samples of each link: its middle and its end (2, 2N, 3)."""
    mid = 0.5 * (points[:, :-1] + points[:, 1:])
    return np.concatenate([mid, points[:, 1:]], axis=1)


def obstacle_phi(f, pts):
    return np.array([[TK.obstacles_phi(f, *p)[0] for p in side] for side in pts])


def test_a_touching_antenna_retracts_out_of_the_obstacle_and_signals_its_side():
    cfg = AntennaeConfig()
    margin = cfg.contact_margin_m
    c, R = np.array([0.0, 1.0, 0.0]), np.eye(3)
    ant = A.Antennae(cfg, DT, np.random.default_rng(3), TK.header(0.0))
    ant.nominal[:, 0] = ant.root_target[:] = [0.7, 0.0]   # both splayed 40 degrees outward
    ant.step(c, R, 0.0)
    # a cylinder through the middle of the left antenna as it is now
    mid = ant.points[0, cfg.n_links // 2]
    f = cylinder_terrain(mid[0], mid[2], 0.4)
    ant.f = f
    before = obstacle_phi(f, sample_points(ant.points))
    assert before[0].min() < -0.1 and before[1].min() > 0.5     # the left antenna is deep inside, not the right
    depth_seen, events = 0.0, []
    for k in range(1, 3001):  # 1 s with the head held still
        ant.step(c, R, k * DT)
        phi = obstacle_phi(f, sample_points(ant.points))
        # pulled out within the same step: no sample stays inside (held at the margin while touching)
        assert phi.min() >= margin - 1e-6, (k, phi.min())
        np.testing.assert_allclose(np.linalg.norm(np.diff(ant.points, axis=1), axis=2), cfg.link_length_m,
                                   atol=1e-12)
        depth_seen = max(depth_seen, ant.contact_depth[0])
        if ant.rising.any():
            events.append((k, ant.rising.copy()))
        assert not ant.contact[1]                                  # the right antenna never touched
    first_k, first = events[0]
    assert first_k == 1 and first[0] and not first[1]              # signalled at once, on the left
    assert depth_seen > 0.1                                        # the contact was seen before the pull-out
    assert ant.contact_events == len(events) < 30                  # counted on rising edges, not per step
    assert np.linalg.norm(ant.contact_normal[0]) == pytest.approx(1.0)
    # the retracted antenna ends outside the obstacle
    assert obstacle_phi(f, sample_points(ant.points)).min() > 0.0


def test_retraction_turns_the_root_along_the_obstacle_normal():
    # the left antenna turned outward (-z) into a wall on its side: the root's target swings it back inward,
    # theta (outward) decreases; pitched up into a ceiling: phi decreases
    cfg = replace(AntennaeConfig(), wave_amplitude_theta_deg=0.0, wave_amplitude_phi_deg=0.0)
    c, R = np.array([0.0, 1.0, 0.0]), np.eye(3)
    for box, start, axis in (((2.0, 1.0, -1.4, 2.0, 2.0, 0.95), (0.3, 0.0), A.THETA),   # wall at z < -0.45
                             ((2.0, 2.3, 0.0, 2.0, 1.0, 2.0), (0.0, 0.3), A.PHI)):      # ceiling at y > 1.3
        ant = A.Antennae(cfg, DT, np.random.default_rng(4), TK.header(0.0))
        ant.nominal[:, 0] = start
        ant.root_target[:] = start
        ant.step(c, R, 0.0)
        ant.f = TK.with_obstacles(TK.header(0.0), [TK.box_record(*box)])
        assert obstacle_phi(ant.f, sample_points(ant.points))[0].min() < -0.1   # the left antenna is inside
        before = ant.nominal[0, 0].copy()
        ant.step(c, R, DT)
        assert ant.contact[0] and ant.retracting[0]
        assert before[axis] - ant.root_target[0, axis] > 0.9 * math.radians(cfg.retract_angle_deg)
        assert ant.root_omega[0] == pytest.approx(math.radians(cfg.retract_speed_deg_s))
        for k in range(2, 600):                       # it swings out at the retraction speed
            ant.step(c, R, k * DT)
        assert obstacle_phi(ant.f, sample_points(ant.points))[0].min() > 0.0


# --------------------------------------------------------------------------- the brain's rule

def test_avoidance_rule_left_turns_right_right_turns_left_both_follow_priority():
    assert avoidance_turn(True, False, "left") == TURN_RIGHT
    assert avoidance_turn(False, True, "left") == TURN_LEFT
    assert avoidance_turn(True, False, "right") == TURN_RIGHT
    assert avoidance_turn(False, True, "right") == TURN_LEFT
    assert avoidance_turn(True, True, "left") == TURN_RIGHT      # the left antenna wins: away from it
    assert avoidance_turn(True, True, "right") == TURN_LEFT
    assert avoidance_turn(False, False, "left") == 0.0


@pytest.fixture(scope="module")
def controller():
    case = resolve_case("centipede", "hybrid", "walk", overrides=["food.sources=[10.0, 0.0, 3.0, 1.0]"])
    return MyriapodController(case, 6, 1.5)


def test_brain_priorities_avoidance_over_trophotropism_over_random_walk(controller):
    ctrl = controller
    ctrl.brain = RANDOM_WALK
    ctrl.antennae.contact[:] = [False, False]
    ctrl.food_signal[:] = [0.0, 0.0]
    ctrl._switch_brain(1.0)
    assert ctrl.brain == RANDOM_WALK
    ctrl.food_signal[:] = [0.02, 0.05]                     # food sensed, stronger on the right
    ctrl._switch_brain(1.1)
    _, rate, turn = ctrl._head_command(1.1)
    assert ctrl.brain == TROPHOTROPISM and turn == TURN_RIGHT and rate > 0
    ctrl.antennae.contact[:] = [False, True]               # a right contact beats the food
    ctrl._switch_brain(1.2)
    _, rate, turn = ctrl._head_command(1.2)
    assert ctrl.brain == AVOIDANCE and turn == TURN_LEFT
    ctrl.antennae.contact[:] = [False, False]              # held for avoid_hold_s after the last contact
    ctrl._switch_brain(1.2 + 0.5 * ctrl.avoid_hold)
    assert ctrl.brain == AVOIDANCE
    ctrl._switch_brain(1.2 + 1.5 * ctrl.avoid_hold)
    assert ctrl.brain == TROPHOTROPISM
    ctrl.antennae.contact[:] = [True, False]               # a new episode, begun by the left antenna: turn right
    ctrl._switch_brain(2.0)
    assert ctrl._head_command(2.0)[2] == TURN_RIGHT
    ctrl.antennae.contact[:] = [False, True]               # the direction holds to the episode's end
    ctrl._switch_brain(2.1)
    assert ctrl._head_command(2.1)[2] == TURN_RIGHT
    ctrl.avoid_priority = "right"
    ctrl.antennae.contact[:] = [True, True]                # both at once: the priority antenna (now right) wins
    ctrl._switch_brain(2.2)
    assert ctrl._head_command(2.2)[2] == TURN_LEFT
    ctrl.antennae.contact[:] = [True, False]               # ... for the rest of the episode
    ctrl._switch_brain(2.3)
    assert ctrl._head_command(2.3)[2] == TURN_LEFT
    ctrl.avoid_priority = "left"
    ctrl.antennae.contact[:] = [False, False]
    ctrl._switch_brain(10.0)                               # episode over
    ctrl.antennae.contact[:] = [True, True]                # a new episode with both at once, priority left
    ctrl._switch_brain(10.1)
    assert ctrl._head_command(10.1)[2] == TURN_RIGHT


# --------------------------------------------------------------------------- on the walking centipede

def walk_into(sets, seconds):
    """A 6-segment centipede walking straight (no random turns) on the hybrid body; per-sample log."""
    case = resolve_case("centipede", "hybrid", "walk", duration=seconds,
                        overrides=["creature.segments=6", "controller.random_turn_max_deg=0"] + sets)
    registry.load_all()
    body = Creature(case)
    body.compile()
    ctrl = body.controller
    log = []
    done = 0
    while done < case.steps:  # one step at a time: contacts can be brief
        k, status = body.advance(done * case.dt, 1)
        assert status == 0, body.status_text(status)
        done += k
        R = body.body.segment_poses()[1][0]
        log.append((done * case.dt, heading(R), ctrl.brain, *ctrl.antennae.contact))
    return body, np.array(log)


def first_contact(log):
    i = np.flatnonzero(log[:, 3] + log[:, 4])[0]
    return i, bool(log[i, 3]), bool(log[i, 4])


@pytest.mark.parametrize("side", ["left", "right"])
def test_a_contact_on_one_antenna_turns_the_head_the_other_way(side):
    # a tall cylinder ahead and to one side (left = -z): only that antenna reaches it
    z = -2.6 if side == "left" else 2.6
    _, log = walk_into([f"scenario.obstacle_cylinder_list=[4.0, {z}, 0.5, 3.0]"], 6.0)
    i, left, right = first_contact(log)
    assert (left, right) == ((True, False) if side == "left" else (False, True))
    assert np.all(log[:, 4 if side == "left" else 3] == 0)         # the other antenna never touched it
    assert abs(log[i, 1]) < math.radians(5.0)                       # it was walking about straight until then
    assert AVOIDANCE in log[i:, 2]
    turned = log[-1, 1] - log[i, 1]
    # left contact -> right turn -> the heading decreases; right contact -> it increases
    assert (turned < -math.radians(10.0)) if side == "left" else (turned > math.radians(10.0)), math.degrees(turned)


@pytest.mark.parametrize("priority", ["left", "right"])
def test_both_antennae_touching_a_wall_follow_the_priority_rule(priority):
    # a wall across the path, its face 2 m ahead of the head's front, and antennae that keep pressing on what
    # they touch (a tiny retraction of the root): both touch the wall at once soon after it starts walking
    _, log = walk_into(["scenario.obstacle_box_list=[2.25, 1.5, 0.0, 0.25, 1.5, 8.0, 0.0]",
                           "antennae.retract_angle_deg=0.5", "antennae.omega0_deg_s=5",
                           f"controller.avoid_priority={priority}"], 1.5)
    walking = log[:, 2] != 0                                        # after ADJUSTMENT
    both = np.flatnonzero(walking & (log[:, 3] > 0) & (log[:, 4] > 0))
    assert len(both)                                                # both touch at once
    i = both[0]
    assert np.all(log[i:, 2] == AVOIDANCE)
    turned = log[-1, 1] - log[i, 1]
    # priority left: the left antenna wins, the head turns right (heading decreases), and vice versa
    assert (turned < -math.radians(10.0)) if priority == "left" else (turned > math.radians(10.0)), \
        math.degrees(turned)
