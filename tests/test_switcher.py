"""The leg Switcher (Sec. 4.2): the rules one by one, the left/right
synchronization, the stance IK, a plain-Python reference, and a kinematic
treadmill experiment in which the leg wave emerges."""
from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit

from bench_myriapoda.kinematics import legs as L
from bench_myriapoda.controllers.myriapod import switcher as S
from bench_myriapoda.controllers.myriapod.switcher import (ADJUST, SB1, SB2, SF1, SF2, STANCE,
                                                           DIRECT, RETROGRADE)
from bench_myriapoda.world.terrain_kernels import PLANE

DT = 1.0 / 300.0  # [s]
ANGLE_TOL = 1e-12  # [rad] kernel vs plain-Python reference, and exact target landings
LINE_TOL = 1e-12  # [rad] deviation of the swing path from the straight line to the target
IK_TOL = 1e-9  # [rad] stance IK reproduces the angles at touch-down


def make(n_segments, wave=RETROGRADE, states=SF1, **kw):
    n = 2 * n_segments
    st = np.full(n, states, dtype=np.int64) if np.isscalar(states) else np.asarray(states, np.int64)
    params = S.switcher_params(wave_direction=wave, **kw)
    pep = (params[S.THETA_PEP], params[S.ALPHA_S], params[S.BETA_S])
    return dict(states=st, angles=np.tile(pep, (n, 1)).astype(float), airborne=np.ones(n, bool),
                touching=np.zeros(n, bool), ik_failed=np.zeros(n, bool), params=params,
                entered=np.zeros(n, bool))


def step(w, dt=DT):
    S.switcher_step(w["states"], w["angles"], w["airborne"], w["touching"], w["ik_failed"], w["params"],
                    dt, w["entered"])


def collapse(seq):
    out = [seq[0]]
    for s in seq[1:]:
        if s != out[-1]:
            out.append(s)
    return out


def pose(params, state):
    return np.array(S.target_pose(state, params))


# --------------------------------------------------------------------------
# rule 1 and the forward-kinematics motion
# --------------------------------------------------------------------------

def test_suspended_legs_cycle_sf1_sf2_sb1_sb2_without_stance_or_adjust():
    """Fig. 10 A: never touching, every leg loops SF1 -> SF2 -> SB1 -> SB2 -> SF1."""
    w = make(4)
    hist = []
    for _ in range(3000):  # 10 s, several cycles
        step(w)
        hist.append(w["states"].copy())
    hist = np.array(hist)
    assert not np.isin(hist, [STANCE, ADJUST]).any()
    for k in range(8):
        seq = collapse(list(hist[:, k]))
        assert seq[:13] == [SF1, SF2, SB1, SB2] * 3 + [SF1]


def test_state_durations_and_exact_arrival_at_target_poses():
    """All three angles arrive together: a state lasts ceil(max |change| / (speed dt))
    steps, moves on the straight line to its target at the swing speed, and ends
    exactly on the target pose."""
    w = make(1)
    p = w["params"]
    speed_step = p[S.SWING_SPEED] * DT
    states, angles = [], [w["angles"][0].copy()]
    for _ in range(400):
        step(w)
        states.append(int(w["states"][0]))
        angles.append(w["angles"][0].copy())
    states, angles = np.array(states), np.array(angles)  # angles[j + 1] is after step j
    start_of_run = np.flatnonzero(np.diff(states, prepend=-1) != 0)
    start = pose(p, SB2)  # the leg starts at the PEP
    for state, first, end in zip([SF1, SF2, SB1, SB2], start_of_run[:4], start_of_run[1:5]):
        assert (states[first:end] == state).all()
        target = pose(p, state)
        n_expected = np.max(np.abs(target - start)) / speed_step
        assert abs(n_expected - round(n_expected)) > 1e-6  # not a tie: ceil is unambiguous
        assert end - first == math.ceil(n_expected)
        direction = (target - start) / np.max(np.abs(target - start))
        moves = np.diff(angles[first:end + 1], axis=0)
        np.testing.assert_allclose(moves[:-1], np.tile(speed_step * direction, (len(moves) - 1, 1)),
                                   rtol=0, atol=LINE_TOL)
        np.testing.assert_array_equal(angles[end], target)  # landed exactly on the target
        start = target


# --------------------------------------------------------------------------
# rules 2 and 3
# --------------------------------------------------------------------------

def test_touch_down_enters_stance_and_reports_the_event():
    for state in (SF1, SF2, SB1, SB2, ADJUST):
        w = make(3, states=state)
        w["angles"][:] = pose(w["params"], SF2) + 0.3  # away from every target
        before = w["angles"].copy()
        w["touching"][3] = True
        step(w)
        assert w["states"][3] == STANCE and w["entered"][3]
        assert w["entered"].sum() == 1
        np.testing.assert_array_equal(w["angles"][3], before[3])  # STANCE angles are left to the IK
        assert not w["airborne"][3]


def test_rule3_ik_failure_in_stance_enters_sf1_and_no_immediate_re_stance():
    w = make(2, states=STANCE)
    w["airborne"][:] = False
    w["touching"][:] = True  # the released tip is still on the ground
    w["ik_failed"][2] = True
    step(w)
    assert w["states"][2] == SF1 and not w["entered"].any()
    w["ik_failed"][:] = False
    for _ in range(5):  # still on the ground: no touch-down, no chatter
        step(w)
        assert w["states"][2] == SF1 and not w["entered"].any()
    w["touching"][2] = False  # lifted off
    step(w)
    w["touching"][2] = True  # SF1 ends prematurely on a bump (Sec. 4.2)
    step(w)
    assert w["states"][2] == STANCE and w["entered"][2]


def test_stance_legs_ignore_touching_and_stay_without_ik_failure():
    w = make(2, states=STANCE)
    before = w["angles"].copy()
    for touching in (True, False):
        w["touching"][:] = touching
        step(w)
        assert (w["states"] == STANCE).all() and not w["entered"].any()
    np.testing.assert_array_equal(w["angles"], before)


# --------------------------------------------------------------------------
# rules 4 and 5
# --------------------------------------------------------------------------

@pytest.mark.parametrize("wave", [RETROGRADE, DIRECT])
def test_previous_leg_landing_sends_the_leg_to_adjust_then_sf2(wave):
    n_seg = 4
    w = make(n_seg, wave=wave, states=SF2)
    w["angles"][:] = pose(w["params"], SF1)  # at the MUP, on the way to the AEP
    lander = 2 * 1 + 1  # right leg of segment 1
    w["touching"][lander] = True
    step(w)
    follower_seg = 1 + wave  # segment 2 (retrograde) or 0 (direct)
    other_seg = 1 - wave
    assert w["states"][2 * follower_seg + 1] == ADJUST
    assert w["states"][2 * follower_seg] == SF2  # the other side is not coupled
    assert w["states"][2 * other_seg + 1] == SF2  # the relation is one-way
    assert S.previous_leg(2 * follower_seg + 1, n_seg, wave) == lander
    # rule 5: at the ADJUST target the leg enters SF2
    w["touching"][:] = False
    target = pose(w["params"], ADJUST)
    k = 2 * follower_seg + 1
    for _ in range(1000):
        step(w)
        if w["states"][k] != ADJUST:
            break
    assert w["states"][k] == SF2
    dist_from_target = np.max(np.abs(w["angles"][k] - target))
    assert 0.0 < dist_from_target <= w["params"][S.SWING_SPEED] * DT + ANGLE_TOL  # left the target this step


def test_previous_leg_relation_and_wave_ends():
    n_seg = 5
    for k in range(2 * n_seg):
        i, side = divmod(k, 2)
        retro = S.previous_leg(k, n_seg, RETROGRADE)
        direct = S.previous_leg(k, n_seg, DIRECT)
        assert retro == (-1 if i == 0 else 2 * (i - 1) + side)
        assert direct == (-1 if i == n_seg - 1 else 2 * (i + 1) + side)
    assert S.first_wave_segment(n_seg, RETROGRADE) == 0
    assert S.first_wave_segment(n_seg, DIRECT) == n_seg - 1


def test_rule4_interrupts_stance_but_not_a_simultaneous_touch_down():
    w = make(3, states=STANCE)
    w["states"][0] = SF2  # head left leg lands ...
    w["touching"][0] = True
    w["states"][4] = SF2  # ... while segment 2's left leg lands too
    w["touching"][4] = True
    step(w)
    assert w["states"][0] == STANCE and w["states"][4] == STANCE
    assert w["states"][2] == ADJUST  # segment 1 left was in STANCE: re-phased
    assert w["states"][3] == STANCE  # right side untouched
    assert list(np.flatnonzero(w["entered"])) == [0, 4]


# --------------------------------------------------------------------------
# synchronization of the first segment's legs
# --------------------------------------------------------------------------

@pytest.mark.parametrize("wave", [RETROGRADE, DIRECT])
def test_lead_left_entering_sf1_pulls_the_right_leg_into_sf1(wave):
    n_seg = 3
    lead = S.first_wave_segment(n_seg, wave)
    w = make(n_seg, wave=wave, states=STANCE)
    w["ik_failed"][2 * lead] = True  # lead left leaves STANCE (rule 3)
    other = 2 * (n_seg - 1 - lead)
    w["ik_failed"][other] = True  # a non-lead left leg too
    step(w)
    assert w["states"][2 * lead] == SF1 and w["states"][2 * lead + 1] == SF1
    assert w["states"][other] == SF1 and w["states"][other + 1] == STANCE  # no sync off the lead
    # entering SF1 by rule 1 (end of SB2) also synchronizes
    w = make(n_seg, wave=wave, states=SB2)
    w["angles"][:] = pose(w["params"], SB1)
    w["states"][2 * lead + 1] = SF2
    w["angles"][2 * lead + 1] = pose(w["params"], SF1)
    while w["states"][2 * lead] == SB2:
        step(w)
    assert w["states"][2 * lead] == SF1 and w["states"][2 * lead + 1] == SF1


def test_right_leg_entering_sf1_does_not_pull_the_left():
    w = make(2, states=STANCE)
    w["ik_failed"][1] = True
    step(w)
    assert w["states"][1] == SF1 and w["states"][0] == STANCE


# --------------------------------------------------------------------------
# stance IK and tip fixing
# --------------------------------------------------------------------------

def test_fix_tips_and_stance_ik_round_trip_and_failure():
    n_seg = 3
    geom = L.leg_geometry(n_seg)
    seg_c = np.array([[0.0, 1.0, 0.0], [-1.0, 1.0, 0.0], [-2.0, 1.0, 0.0]])
    seg_R = np.tile(np.eye(3), (n_seg, 1, 1))
    w = make(n_seg, states=SF2)
    w["angles"][:] = pose(w["params"], SF2) - (0.1, 0.0, 0.0)
    w["touching"][[1, 4]] = True
    step(w)
    tips = np.full((2 * n_seg, 3), 7.0)
    S.fix_stance_tips(w["entered"], seg_c, seg_R, geom, w["angles"], tips)
    O, M, P = (np.empty((2 * n_seg, 3)) for _ in range(3))
    L.legs_forward_kinematics(seg_c, seg_R, geom, w["angles"], O, M, P)
    np.testing.assert_allclose(tips[[1, 4]], P[[1, 4]], atol=1e-15)
    assert (tips[[0, 2, 3, 5]] == 7.0).all()  # other rows untouched
    at_touch = w["angles"].copy()
    S.stance_inverse_kinematics(w["states"], seg_c, seg_R, geom, tips, w["angles"], w["ik_failed"])
    assert not w["ik_failed"].any()
    np.testing.assert_allclose(w["angles"], at_touch, rtol=0, atol=IK_TOL)
    at_touch = w["angles"].copy()
    # the body moves: leg 1 (head) follows by IK, leg 4 (segment 2) is left out of reach
    seg_c[0, 0] += 0.2
    seg_c[2, 0] += 5.0
    S.stance_inverse_kinematics(w["states"], seg_c, seg_R, geom, tips, w["angles"], w["ik_failed"])
    assert list(np.flatnonzero(w["ik_failed"])) == [4]
    assert w["angles"][1, L.THETA] < at_touch[1, L.THETA]  # root moved forward: the leg swings back
    np.testing.assert_array_equal(w["angles"][4], at_touch[4])
    L.legs_forward_kinematics(seg_c, seg_R, geom, w["angles"], O, M, P)
    np.testing.assert_allclose(P[1], tips[1], atol=1e-12)  # the stance tip stays put
    step(w)  # rule 3 acts on the report
    assert w["states"][4] == SF1 and w["states"][1] == STANCE


# --------------------------------------------------------------------------
# plain-Python reference of the whole step
# --------------------------------------------------------------------------

def reference_step(states, angles, airborne, touching, ik_failed, p, dt):
    """The rules of the module docstring, written out plainly (lists, dicts).

    Deliberately written again, apart from the kernel it checks (``duplicates`` pairs a few of its lines with
    ``switcher.switcher_step``): an independent reference, not shared code."""
    n = len(states)
    n_seg = n // 2
    wave = int(p[S.WAVE_DIRECTION])
    targets = {SF1: (0.0, p[S.ALPHA_MUP], 0.0), SF2: (p[S.THETA_AEP], p[S.ALPHA_S], p[S.BETA_S]),
               SB1: (0.0, p[S.ALPHA_MDP], 0.0), SB2: (p[S.THETA_PEP], p[S.ALPHA_S], p[S.BETA_S]),
               ADJUST: (p[S.THETA_AEP] + p[S.ADJ_D_THETA], p[S.ALPHA_S] + p[S.ADJ_D_ALPHA],
                        p[S.BETA_S] + p[S.ADJ_D_BETA])}
    following = {SF1: SF2, SF2: SB1, SB1: SB2, SB2: SF1, ADJUST: SF2}
    states, airborne = [int(s) for s in states], [bool(a) for a in airborne]
    angles = [list(map(float, a)) for a in angles]
    lead = 0 if wave > 0 else n_seg - 1
    lead_was_sf1 = states[2 * lead] == SF1
    entered = [False] * n
    for k in range(n):
        if states[k] == STANCE and ik_failed[k]:
            states[k] = SF1  # rule 3: a stance leg whose IK failed lifts off
        swinging = states[k] != STANCE
        # rule 2: a swinging leg touches down once it has been airborne; off the ground it is airborne
        entered[k] = bool(swinging and touching[k] and airborne[k])
        airborne[k] = bool((airborne[k] or not touching[k]) and not entered[k]) if swinging else airborne[k]
        states[k] = STANCE if entered[k] else states[k]
    for k in range(n):
        if entered[k]:
            continue
        prev_seg = k // 2 - wave
        if 0 <= prev_seg < n_seg and entered[2 * prev_seg + k % 2]:
            states[k] = ADJUST
        if states[k] != STANCE:
            if max(abs(t - a) for t, a in zip(targets[states[k]], angles[k])) <= p[S.ARRIVAL_TOL]:
                states[k] = following[states[k]]
    if not lead_was_sf1 and states[2 * lead] == SF1:
        states[2 * lead + 1] = SF1
    for k in range(n):
        if states[k] != STANCE:
            delta = [t - a for t, a in zip(targets[states[k]], angles[k])]
            m = max(abs(d) for d in delta)
            if m <= p[S.SWING_SPEED] * dt:
                angles[k] = list(targets[states[k]])
            else:
                angles[k] = [a + d * (p[S.SWING_SPEED] * dt / m) for a, d in zip(angles[k], delta)]
    return states, angles, airborne, entered


@pytest.mark.parametrize("wave", [RETROGRADE, DIRECT])
def test_switcher_step_matches_plain_python_reference(wave):
    rng = np.random.default_rng(10 + wave)
    n_seg = 6
    w = make(n_seg, wave=wave, states=rng.integers(0, 6, 2 * n_seg))
    w["angles"][:] = rng.uniform(-1.0, 1.0, (2 * n_seg, 3))
    w["airborne"][:] = rng.random(2 * n_seg) < 0.5
    w["params"][S.ARRIVAL_TOL] = 1e-3
    seen = set()
    for _ in range(2000):
        w["touching"][:] = rng.random(2 * n_seg) < 0.15
        w["ik_failed"][:] = rng.random(2 * n_seg) < 0.05
        want = reference_step(w["states"], w["angles"], w["airborne"], w["touching"], w["ik_failed"],
                              w["params"], DT)
        step(w)
        np.testing.assert_array_equal(w["states"], want[0])
        np.testing.assert_allclose(w["angles"], want[1], rtol=0, atol=ANGLE_TOL)
        np.testing.assert_array_equal(w["airborne"], want[2])
        np.testing.assert_array_equal(w["entered"], want[3])
        seen.update(int(s) for s in w["states"])
    assert seen == set(range(S.N_STATES))  # every state was exercised


def test_switcher_params_validation():
    with pytest.raises(ValueError, match="wave_direction"):
        S.switcher_params(wave_direction=0)
    with pytest.raises(ValueError, match="swing_speed"):
        S.switcher_params(swing_speed=0.0)
    with pytest.raises(ValueError, match="theta_pep"):
        S.switcher_params(theta_pep=0.6)
    assert S.state_names([SF1, STANCE, ADJUST]) == ["SF1", "STANCE", "ADJUST"]


# --------------------------------------------------------------------------
# kinematic experiment: the leg wave emerges on a treadmill
# --------------------------------------------------------------------------

TREAD_SEGMENTS = 8
TREAD_SPEED = 1.5  # [m/s] ground speed under the fixed segments
TREAD_HEIGHT = 0.92  # [m] root height above the ground; the AEP tip is 0.90 below the root
TREAD_CONTACT = 0.005  # [m] contact distance
TREAD_TIME = 60.0  # [s]
TREAD_SETTLE = 48.0  # [s] transient discarded
ALLOWED_TRANSITIONS = {(STANCE, SF1), (SF1, SF2), (SF1, ADJUST), (SF2, ADJUST), (ADJUST, SF2), (SF2, SB1),
                       (SF2, STANCE), (SB1, STANCE)}
BRIEF_ADJUST = 0.10  # max fraction of time in ADJUST ("short appearances", Sec. 4.2)
BRIEF_SB1 = 0.02  # max fraction of time in SB1
MIN_STANCE = 0.5  # min fraction of time in STANCE
LAG_TOL = 2.5 * DT  # [s] spread of the onset lags between neighbours


@njit
def _treadmill_loop(n_steps, dt, speed, contact, seg_c, seg_R, geom, ground, states, angles, airborne,
                    touching, ik_failed, params, entered, tips, O, M, P, hist):
    """The per-step controller calls of the treadmill inside one compiled loop:
    the kernels compose inside another @njit loop, with no allocation per step."""
    for s in range(n_steps):
        for k in range(states.shape[0]):
            if states[k] == STANCE:
                tips[k, 0] -= speed * dt
        L.legs_forward_kinematics(seg_c, seg_R, geom, angles, O, M, P)
        L.tips_touching(PLANE, ground, P, contact, touching)
        S.switcher_step(states, angles, airborne, touching, ik_failed, params, dt, entered)
        S.fix_stance_tips(entered, seg_c, seg_R, geom, angles, tips)
        S.stance_inverse_kinematics(states, seg_c, seg_R, geom, tips, angles, ik_failed)
        hist[s] = states


def treadmill(wave, seed, duration=TREAD_TIME, compiled=True):
    """Segments held still over a ground sliding backward at TREAD_SPEED: the
    kinematic equivalent of a body walking forward at constant speed, with
    every segment supported.  Not a body simulation -- the body's speed does not
    depend on the legs -- but the rules, the FK and the stance IK are the real
    ones, and a stance ends when the IK fails (the tip out of convex reach).
    ``compiled``: run the steps in ``_treadmill_loop``, else in a Python loop."""
    rng = np.random.default_rng(seed)
    n_seg, n = TREAD_SEGMENTS, 2 * TREAD_SEGMENTS
    geom = L.leg_geometry(n_seg)
    seg_c = np.zeros((n_seg, 3))
    seg_c[:, 0] = -np.arange(n_seg) * 1.0
    seg_c[:, 1] = TREAD_HEIGHT
    seg_R = np.tile(np.eye(3), (n_seg, 1, 1))
    w = make(n_seg, wave=wave, states=rng.integers(0, 4, n))
    w["angles"][:] = np.column_stack([rng.uniform(-0.5, 0.5, n), rng.uniform(0.0, 0.6, n),
                                      rng.uniform(0.0, 1.3, n)])
    ground = np.zeros(8)
    tips = np.zeros((n, 3))
    O, M, P = (np.empty((n, 3)) for _ in range(3))
    n_steps = int(round(duration / DT))
    hist = np.empty((n_steps, n), np.int64)
    if compiled:
        _treadmill_loop(n_steps, DT, TREAD_SPEED, TREAD_CONTACT, seg_c, seg_R, geom, ground, w["states"],
                        w["angles"], w["airborne"], w["touching"], w["ik_failed"], w["params"], w["entered"],
                        tips, O, M, P, hist)
        return hist, w["angles"]
    for s in range(n_steps):
        stance = w["states"] == STANCE
        tips[stance, 0] -= TREAD_SPEED * DT
        L.legs_forward_kinematics(seg_c, seg_R, geom, w["angles"], O, M, P)
        L.tips_touching(PLANE, ground, P, TREAD_CONTACT, w["touching"])
        step(w)
        S.fix_stance_tips(w["entered"], seg_c, seg_R, geom, w["angles"], tips)
        S.stance_inverse_kinematics(w["states"], seg_c, seg_R, geom, tips, w["angles"], w["ik_failed"])
        hist[s] = w["states"]
    return hist, w["angles"]


def test_kernels_compose_inside_an_njit_loop():
    hist_py, angles_py = treadmill(RETROGRADE, 5, duration=5.0, compiled=False)
    hist_nb, angles_nb = treadmill(RETROGRADE, 5, duration=5.0, compiled=True)
    np.testing.assert_array_equal(hist_nb, hist_py)
    np.testing.assert_array_equal(angles_nb, angles_py)
    assert (hist_py == STANCE).any() and (hist_py == ADJUST).any()


def onsets(hist, k):
    return np.flatnonzero((hist[1:, k] == STANCE) & (hist[:-1, k] != STANCE)) * DT


@pytest.mark.parametrize("wave,seed", [(RETROGRADE, 0), (RETROGRADE, 1), (DIRECT, 0), (DIRECT, 1)])
def test_treadmill_converges_to_a_leg_wave(wave, seed):
    hist, _ = treadmill(wave, seed)
    late = hist[int(TREAD_SETTLE / DT):]
    n_seg = TREAD_SEGMENTS
    lead = S.first_wave_segment(n_seg, wave)
    for k in range(2 * n_seg):
        seq = collapse(list(late[:, k]))
        assert set(zip(seq[:-1], seq[1:])) <= ALLOWED_TRANSITIONS, (k, S.state_names(seq))
        assert (late[:, k] == ADJUST).mean() <= BRIEF_ADJUST
        assert (late[:, k] == SB1).mean() <= BRIEF_SB1
        assert (late[:, k] == STANCE).mean() >= MIN_STANCE
        # the cycle is SF1 -> SF2 -> STANCE, with ADJUST in every cycle except at the lead
        assert seq.count(STANCE) >= 3
        assert (ADJUST in seq) == (k // 2 != lead)

    # stance onsets: every leg entrained to the lead's period ...
    late_onsets = [t[t > TREAD_SETTLE] for t in (onsets(hist, k) for k in range(2 * n_seg))]
    period = np.diff(late_onsets[2 * lead]).mean()
    for t in late_onsets:
        assert len(t) >= 4
        assert np.max(np.abs(np.diff(t) - period)) < LAG_TOL
    # ... with a constant lag from each leg's previous leg that is shorter than
    # half a period: the wave travels in the wave's direction (and the lag the
    # other way round, period - lag, is longer than half a period)
    order = list(range(n_seg)) if wave == RETROGRADE else list(range(n_seg - 1, -1, -1))
    for a, b in zip(order[:-1], order[1:]):
        for side in (0, 1):
            ta, tb = late_onsets[2 * a + side], onsets(hist, 2 * b + side)
            lags = np.array([tb[tb > t][0] - t for t in ta[:-1]])
            assert np.ptp(lags) < LAG_TOL
            assert 0.0 < lags.mean() < 0.5 * period
    # the synchronization rule is one-way: the lead's right leg is pulled into
    # SF1 when the left leaves STANCE, so it never lags the left leg
    right = onsets(hist, 2 * lead + 1)
    shift = np.array([right[np.argmin(np.abs(right - t))] - t for t in late_onsets[2 * lead]])
    assert np.ptp(shift) < LAG_TOL and -0.5 * period < shift.mean() <= LAG_TOL
