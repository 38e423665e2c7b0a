"""Legs against obstacles and terrain (issue 16, controllers/myriapod/leg_collision.py).

Kernel level first: one leg pair on a segment held still, stepped in the
controller's leg order (touch test, Switcher, cut at the surface, fix the
touched-down tips, forward kinematics).  A leg swung into a tall cylinder stops
on its side; a leg coming down onto a low cylinder lands on its top and enters
STANCE at the top's height -- and without the collision the same swings end
inside.  Then the whole centipede on the three obstacle scenarios, all three
bodies: no knee or tip ever inside an obstacle or the ground.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from bench_myriapoda.kinematics import legs as L
from bench_myriapoda.controllers.myriapod import leg_collision as LC
from bench_myriapoda.controllers.myriapod import switcher as SW
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.world import terrain_kernels as TK

SURFACE_TOL_M = 1e-9          # a stopped tip lies this close to the surface (bisection to 2^-40 of a step)
LEG_PENETRATION_TOL_M = 1e-9  # leg_penetration_max_m on the obstacle scenarios (seen: <= 1.7e-15 m, round-off)
# a coarse step: the tip moves ~8 cm per step, more than the 1 cm contact distance, so that the touch test
# alone cannot catch it before it is inside (at fine steps a fast leg, or a knee, still gets there)
DT = 0.01
RIGHT = 1


def _pair():
    """(geom (2, 6), switcher params, segment centre (1, 3), rotation (1, 3, 3)) of one default leg pair,
    the segment at the standing height above y = 0."""
    geom = L.leg_geometry(1, (0.0, 0.0, 0.5), 1.0, 1.2, 0.5)
    params = SW.switcher_params(theta_aep=0.5, theta_pep=-0.5, alpha_s=0.3, beta_s=1.3, alpha_mup=0.6,
                                alpha_mdp=-0.4, swing_speed=4.0)
    c = np.zeros((1, 3))
    R = np.eye(3)[None].copy()
    tip = L.leg_tip(c[0], R[0], geom[RIGHT], 1.0, params[SW.THETA_AEP], params[SW.ALPHA_S], params[SW.BETA_S])
    c[0, 1] = -tip[1]  # the AEP tip on the ground
    return geom, params, c, R


def _aep_tip(geom, params, c, R):
    return np.array(L.leg_tip(c[0], R[0], geom[RIGHT], 1.0, params[SW.THETA_AEP], params[SW.ALPHA_S],
                              params[SW.BETA_S]))


def _swing(f, geom, params, c, R, collide=True, steps=400):
    """Both legs start at the MUP in SF2 (swinging down to the AEP); step the controller's leg order.

    Returns (states (steps, 2), tips (steps, 2, 3), knees (steps, 2, 3), stopped: any cut).
    """
    states = np.full(2, SW.SF2, dtype=np.int64)
    angles = np.array([[0.0, params[SW.ALPHA_MUP], 0.0]] * 2)
    O, M, P = np.zeros((2, 3)), np.zeros((2, 3)), np.zeros((2, 3))
    L.legs_forward_kinematics(c, R, geom, angles, O, M, P)
    touching, airborne = np.zeros(2, bool), np.ones(2, bool)
    ik_failed, entered, stopped = np.zeros(2, bool), np.zeros(2, bool), np.zeros(2, bool)
    out_s, out_p, out_m, any_stop = [], [], [], False
    for _ in range(steps):
        L.tips_touching(TK.PLANE, f, P, 0.01, touching)
        prev = angles.copy()
        SW.switcher_step(states, angles, airborne, touching, ik_failed, params, DT, entered)
        if collide:
            LC.stop_swinging_legs(states, prev, angles, c, R, geom, TK.PLANE, f, stopped)
            any_stop |= bool(stopped.any())
        stance_tips = P.copy()
        SW.fix_stance_tips(entered, c, R, geom, angles, stance_tips)
        if collide:
            LC.surface_touchdown_tips(entered, stance_tips, TK.PLANE, f)
        L.legs_forward_kinematics(c, R, geom, angles, O, M, P)
        st = states == SW.STANCE
        P[st] = stance_tips[st]
        out_s.append(states.copy())
        out_p.append(P.copy())
        out_m.append(M.copy())
        if st.all():
            break
    return np.array(out_s), np.array(out_p), np.array(out_m), any_stop


def _phi(f, p):
    return np.array([TK.signed_distance(TK.PLANE, f, *q) for q in p.reshape(-1, 3)]).reshape(p.shape[:-1])


def test_a_leg_swung_into_a_cylinder_stops_at_its_surface():
    geom, params, c, R = _pair()
    aep = _aep_tip(geom, params, c, R)
    # a tall post whose side the right tip meets on its way from the MUP (x 0, z 2.5, 1.6 m up) forward,
    # down and inward to the AEP (x 0.5, z 1.4, on the ground); the AEP itself is outside the post
    cx, cz, r = aep[0] + 0.2, aep[2] + 0.6, 0.35
    f = TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(cx, cz, r, -1.0, 3.0)])
    states, tips, knees, stopped = _swing(f, geom, params, c, R)
    assert stopped
    assert _phi(f, tips).min() >= 0.0 and _phi(f, knees).min() >= 0.0  # never inside
    assert states[-1, RIGHT] == SW.STANCE
    final = tips[-1, RIGHT]
    assert abs(math.hypot(final[0] - cx, final[2] - cz) - r) < SURFACE_TOL_M  # on the side wall
    assert final[1] > 0.05  # above the ground: the post stopped it
    # the same swing without the collision ends inside the post
    _, free_tips, _, _ = _swing(f, geom, params, c, R, collide=False)
    assert _phi(f, free_tips[:, RIGHT]).min() < -0.02  # (seen: 2.9 cm inside)


def test_a_leg_that_lands_on_a_cylinder_top_enters_stance_at_the_tops_height():
    geom, params, c, R = _pair()
    aep = _aep_tip(geom, params, c, R)
    top = 0.3
    # wide enough (radius 1.2 m around the AEP) that the whole swing path lies above the top
    f = TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(aep[0], aep[2], 1.2, -1.0, top)])
    states, tips, knees, stopped = _swing(f, geom, params, c, R)
    assert stopped
    k = int(np.argmax(states[:, RIGHT] == SW.STANCE))
    assert states[k, RIGHT] == SW.STANCE and (states[k:, RIGHT] == SW.STANCE).all()
    assert 0.0 <= tips[-1, RIGHT, 1] - top < SURFACE_TOL_M           # planted on the top
    assert math.hypot(tips[-1, RIGHT, 0] - aep[0], tips[-1, RIGHT, 2] - aep[2]) < 1.2
    assert _phi(f, tips).min() >= 0.0 and _phi(f, knees).min() >= 0.0
    # the left leg, with no cylinder below it, lands on the ground
    assert states[-1, 0] == SW.STANCE and abs(tips[-1, 0, 1]) < 0.011
    # without the collision the right tip sinks into the cylinder before it touches
    _, free_tips, _, _ = _swing(f, geom, params, c, R, collide=False)
    assert free_tips[:, RIGHT, 1].min() < top - 0.005  # (seen: 1.1 cm inside)


def test_a_leg_pushed_inside_by_its_segment_escapes_to_the_surface():
    geom, params, c, R = _pair()
    aep = _aep_tip(geom, params, c, R)
    f = TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(aep[0], aep[2], 0.5, -1.0, 0.3)])
    states = np.array([SW.SB1, SW.SB1], dtype=np.int64)
    angles = np.array([[params[SW.THETA_AEP], params[SW.ALPHA_S], params[SW.BETA_S]]] * 2)
    prev = angles.copy()  # the segment did not move the angles: its pose put the tip 0.3 m inside
    stopped = np.zeros(2, bool)
    stuck = LC.stop_swinging_legs(states, prev, angles, c, R, geom, TK.PLANE, f, stopped)
    assert stuck == 0 and stopped[RIGHT]
    kn, tp = LC.knee_tip_phi(TK.PLANE, f, c[0], R[0], geom[RIGHT], 1.0, *angles[RIGHT])
    assert kn >= 0.0 and 0.0 <= min(kn, tp) < SURFACE_TOL_M


@pytest.mark.parametrize("check_knees", [True, False])
def test_knees_inside_and_penetration_equals_the_two_kernels(check_knees):
    """The one-pass kernel of the compiled controller gives ``stance_knees_inside``'s ik_failed and
    ``legs_penetration``'s depth, and the tips' signed distances ``legs.tips_touching`` tests."""
    rng = np.random.default_rng(3)
    f = TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(0.2, 0.1, 0.3, -1.0, 0.4)])
    n = 40
    knees, tips = rng.uniform(-0.6, 0.6, (n, 3)), rng.uniform(-0.6, 0.6, (n, 3))
    states = np.where(rng.random(n) < 0.6, SW.STANCE, SW.SF2).astype(np.int64)
    failed0 = rng.random(n) < 0.2
    ref, got = failed0.copy(), failed0.copy()
    if check_knees:
        LC.stance_knees_inside(states, knees, TK.PLANE, f, ref)
    depth = LC.legs_penetration(TK.PLANE, f, knees, tips)
    tip_phi = np.zeros(n)
    assert LC.knees_inside_and_penetration(states, knees, tips, TK.PLANE, f, check_knees, got, tip_phi) == depth
    np.testing.assert_array_equal(got, ref)
    assert depth > 0.0 and (ref != failed0).any() == check_knees
    for cd in (0.0, 0.01):
        touching = np.zeros(n, bool)
        L.tips_touching(TK.PLANE, f, tips, cd, touching)
        np.testing.assert_array_equal(tip_phi <= cd, touching)


@pytest.mark.slow
@pytest.mark.parametrize("body", ["hybrid", "massspring", "fem"])
@pytest.mark.parametrize("scenario,duration", [("fig13-cylinders", 12.0), ("foraging", 10.0),
                                               ("fig12-water-foraging", 6.0)])
def test_no_leg_tip_or_knee_inside_an_obstacle_or_the_ground(body, scenario, duration):
    r = run_case(resolve_case("centipede", body, scenario, duration=duration))
    assert r.status == "ok", r.message
    assert r.metrics["leg_penetration_max_m"] < LEG_PENETRATION_TOL_M
    assert r.metrics["leg_stuck"] == 0
    if scenario == "fig13-cylinders":
        assert r.metrics["leg_stops"] > 0  # the legs did meet the cylinders
