"""The leg Switcher of the myriapod paper (Fang, Jiang & Terzopoulos 2013, Sec. 4.2).

Every leg runs the same six-state machine; the kernels below update all legs of
a creature at once, one call per time step, and are callable from another
@njit loop.  Legs are indexed ``k = 2 * segment + side`` (side 0 left, 1 right;
segment 0 is the head), angles are ``angles[k] = (theta, alpha, beta)`` [rad]
as in ``bench_myriapoda.kinematics.legs``.

States and their target poses (Sec. 4.2, "Leg States")
------------------------------------------------------
======  ====================================  ============================
state   motion                                target pose (theta, alpha, beta)
======  ====================================  ============================
SF1     sway forward, up (leave the ground)   MUP = (0, alpha_M, 0)
SF2     sway forward, down                    AEP = (theta_M, alpha_S, beta_S)
SB1     sway backward, down (find ground)     MDP = (0, alpha_m, 0)
SB2     sway backward, up                     PEP = (theta_m, alpha_S, beta_S)
STANCE  tip fixed on the ground, angles by IK  none (App. B)
ADJUST  move to the phase-setting pose         (theta_M + d_theta_T, alpha_S + d_alpha_T,
                                               beta_S + d_beta_T)
======  ====================================  ============================

(The paper says STANCE "ideally starts at the PEP and ends at the AEP"; with the
body moving forward over a fixed tip it is the other way round -- SF2 ends at
the AEP and "sends the leg to the STANCE state", and SF1 starts from the PEP.)

Outside STANCE the angles move by forward kinematics toward the state's target
at the swing speed: the pose travels on the straight line to the target in
(theta, alpha, beta) space and **all three angles arrive together**, the one
with the largest remaining difference turning at ``SWING_SPEED`` [rad/s] (a
Chebyshev-norm speed: no joint ever turns faster than the swing speed, and a
state's duration is max|target - start| / speed).  The last step lands exactly
on the target.

Rules, in the order one ``switcher_step`` applies them
------------------------------------------------------
All decisions of a step are taken before any leg moves (Sec. 6, step 4:
"the Switcher checks the leg states and updates them; ... otherwise forward
kinematics will update the leg rotations"), so the result does not depend on
the order of the legs.

1. Rule 3: a STANCE leg whose IK failed (``ik_failed``, reported by
   ``stance_inverse_kinematics`` in the previous step) enters SF1.
2. Rule 2, as a touch-down: a non-STANCE leg enters STANCE when its tip touches
   the ground (``touching``) *and it has been off the ground since it last left
   STANCE* (``airborne``, a per-leg latch kept here).  The paper says
   "whenever"; so the rule applies in every swing state -- including SF1, which
   "can end prematurely and enter the STANCE state" on irregular ground
   (Sec. 4.2) -- but not to a tip that simply never left the ground: a leg
   released by rule 3 still has its tip on the ground at the PEP, and
   re-entering STANCE there would chatter between rules 2 and 3 and, worse,
   emit spurious STANCE events that rule 4 would propagate down the wave.
   The step's touch-downs are reported in ``entered_stance`` (the caller fixes
   the tips there: ``fix_stance_tips``).
3. Rule 4: a leg enters ADJUST when its previous leg entered STANCE in this
   step.  The previous leg is the same-side leg of segment
   ``i - wave_direction``: the anterior neighbour for ``wave_direction = +1``
   (retrograde wave, head to tail, centipedes) and the posterior one for -1
   (direct wave, millipedes); PAPER-NOTES.md.  The first segment in the wave's
   order (the head for +1, the tail for -1) has no previous leg.  "Whenever"
   is taken literally: the rule also interrupts a STANCE leg.  Sparing STANCE
   legs looks gentler but breaks the coupling: a leg that happens to be in
   STANCE whenever its predecessor lands is then never re-phased, and with
   equal stance durations it keeps its arbitrary phase forever (seen in the
   treadmill experiment of tests/test_switcher.py with STANCE legs spared).  In the converged wave a leg
   is swinging when its predecessor lands, so the interruption acts only in
   transients.  A leg that touches down in the same step stays in STANCE
   (rule 2 first: its own touch-down is the event that rule 4 would impose).
4. Rules 1 and 5: a non-STANCE leg whose pose is within ``ARRIVAL_TOL`` of its
   state's target (max-norm over the three angles) takes the next state:
   SF1 -> SF2 -> SB1 -> SB2 -> SF1, ADJUST -> SF2.  One such transition per
   leg and step.
5. Synchronization (Sec. 4.2): when the left leg of the first segment in the
   wave's order enters SF1 in this step (by any rule), its right leg enters
   SF1 too, from whatever state.  As printed the rule is one-way: it pulls a
   right leg that lags (still in STANCE) along, but a right leg that already
   left STANCE is not held back, so the pair can settle with the right leg
   leading by a constant offset (the treadmill experiment in
   tests/test_switcher.py shows offsets of 0 to 0.24 s at a 2 s period).  The
   other segments' sides follow their own previous legs.
6. Forward kinematics: every non-STANCE leg moves toward its target.

Parameter vector ``params`` (float64, N_SWITCHER_PARAMS), built by
``switcher_params``:

===============  =======  ============================================
THETA_AEP        [rad]    theta_M, forward extreme (AEP), > THETA_PEP
THETA_PEP        [rad]    theta_m, backward extreme (PEP)
ALPHA_S          [rad]    alpha of the AEP and PEP (stance pose)
BETA_S           [rad]    beta of the AEP and PEP
ALPHA_MUP        [rad]    alpha_M, femur elevation of the middle up pose
ALPHA_MDP        [rad]    alpha_m, femur elevation of the middle down pose
ADJ_D_THETA      [rad]    theta_T - theta_M  (ADJUST target offsets:
ADJ_D_ALPHA      [rad]    alpha_T - alpha_S   they set the phase lag
ADJ_D_BETA       [rad]    beta_T - beta_S     between neighbouring legs)
SWING_SPEED      [rad/s]  angular speed outside STANCE (> 0)
ARRIVAL_TOL      [rad]    a target pose counts as reached within this
WAVE_DIRECTION   [-]      +1 retrograde (previous leg = anterior), -1 direct
===============  =======  ============================================

Per-step order for a caller (Sec. 6, step 4), all arrays preallocated:

    tips_touching(...)                       # touching, from the legs' FK tips
    switcher_step(states, angles, airborne, touching, ik_failed, params, dt, entered_stance)
    fix_stance_tips(entered_stance, seg_c, seg_R, geom, angles, tips)
    stance_inverse_kinematics(states, seg_c, seg_R, geom, tips, angles, ik_failed)
"""
from __future__ import annotations

import numpy as np
from numba import njit

from bench_myriapoda.core.leg_timeline import (ADJUST, N_STATES, SB1, SB2, SF1, SF2,  # noqa: F401 (re-exported)
                                               STANCE, STATE_NAMES)
from bench_myriapoda.kinematics.legs import (ALPHA, BETA, THETA, leg_ik_from_segment, leg_tip,
                                         side_sign)

# The state codes are the legged timeline record's (core.leg_timeline), which the gait metrics read.

RETROGRADE = 1
DIRECT = -1

# layout of the parameter vector
THETA_AEP, THETA_PEP, ALPHA_S, BETA_S, ALPHA_MUP, ALPHA_MDP = 0, 1, 2, 3, 4, 5
ADJ_D_THETA, ADJ_D_ALPHA, ADJ_D_BETA = 6, 7, 8
SWING_SPEED, ARRIVAL_TOL, WAVE_DIRECTION = 9, 10, 11
ADJUST_FROM_STANCE = 12  # 1: rule 4 also pulls a STANCE leg into ADJUST ("whenever"); 0: only swinging legs
N_SWITCHER_PARAMS = 13


def switcher_params(theta_aep: float = 0.5, theta_pep: float = -0.5, alpha_s: float = 0.3,
                    beta_s: float = 1.3, alpha_mup: float = 0.6, alpha_mdp: float = -0.4,
                    adj_d_theta: float = -0.3, adj_d_alpha: float = 0.3, adj_d_beta: float = -0.8,
                    swing_speed: float = 4.0, arrival_tol: float = 1e-9,
                    wave_direction: int = RETROGRADE, adjust_from_stance: bool = True) -> np.ndarray:
    """The Switcher parameter vector (see the module docstring for units).

    The paper gives no values; the defaults suit ``legs.leg_geometry``'s
    default leg (femur 1, tibia 1.2, gamma 0.5): the tip is about 0.90 below
    the root at the AEP and PEP, 1.33 below at the MDP and 0.69 above at the
    MUP; the ADJUST target lifts the leg above the AEP (d_alpha_T > 0) so that
    a leg pulled out of STANCE by rule 4 leaves the ground.
    """
    values = np.empty(N_SWITCHER_PARAMS)
    values[THETA_AEP], values[THETA_PEP] = theta_aep, theta_pep
    values[ALPHA_S], values[BETA_S] = alpha_s, beta_s
    values[ALPHA_MUP], values[ALPHA_MDP] = alpha_mup, alpha_mdp
    values[ADJ_D_THETA], values[ADJ_D_ALPHA], values[ADJ_D_BETA] = adj_d_theta, adj_d_alpha, adj_d_beta
    values[SWING_SPEED], values[ARRIVAL_TOL] = swing_speed, arrival_tol
    values[WAVE_DIRECTION] = wave_direction
    values[ADJUST_FROM_STANCE] = 1.0 if adjust_from_stance else 0.0
    if not np.all(np.isfinite(values)):
        raise ValueError(f"switcher parameters must be finite, got {values}")
    if wave_direction not in (RETROGRADE, DIRECT):
        raise ValueError(f"wave_direction must be +1 (retrograde) or -1 (direct), got {wave_direction}")
    if not swing_speed > 0.0:
        raise ValueError(f"swing_speed must be > 0 rad/s, got {swing_speed}")
    if not arrival_tol >= 0.0:
        raise ValueError(f"arrival_tol must be >= 0 rad, got {arrival_tol}")
    if not theta_pep < theta_aep:
        raise ValueError(f"need theta_pep < theta_aep, got {theta_pep} >= {theta_aep}")
    if not alpha_mdp < alpha_mup:
        raise ValueError(f"need alpha_mdp < alpha_mup, got {alpha_mdp} >= {alpha_mup}")
    return values


@njit(cache=True)
def target_pose(state, params):
    """Target (theta, alpha, beta) [rad] of a non-STANCE state (Sec. 4.2); nan for STANCE."""
    if state == SF1:  # MUP
        return 0.0, params[ALPHA_MUP], 0.0
    if state == SF2:  # AEP
        return params[THETA_AEP], params[ALPHA_S], params[BETA_S]
    if state == SB1:  # MDP
        return 0.0, params[ALPHA_MDP], 0.0
    if state == SB2:  # PEP
        return params[THETA_PEP], params[ALPHA_S], params[BETA_S]
    if state == ADJUST:
        return (params[THETA_AEP] + params[ADJ_D_THETA], params[ALPHA_S] + params[ADJ_D_ALPHA],
                params[BETA_S] + params[ADJ_D_BETA])
    return np.nan, np.nan, np.nan


@njit(cache=True)
def state_after_target(state):
    """The state that follows when ``state``'s target pose is reached (rules 1 and 5)."""
    if state == SF1:
        return SF2
    if state == SF2:
        return SB1
    if state == SB1:
        return SB2
    if state == SB2:
        return SF1
    if state == ADJUST:
        return SF2
    return state


@njit(cache=True)
def previous_leg(k, n_segments, wave_direction):
    """Index of leg k's previous leg for rule 4, or -1 when it has none.

    The same-side leg of segment ``k // 2 - wave_direction`` (anterior for a
    retrograde wave, +1; posterior for a direct wave, -1).
    """
    i = k // 2 - wave_direction
    if i < 0 or i >= n_segments:
        return -1
    return 2 * i + k % 2


@njit(cache=True)
def first_wave_segment(n_segments, wave_direction):
    """The segment whose legs lead the wave: the head (retrograde) or the tail (direct)."""
    return 0 if wave_direction > 0 else n_segments - 1


@njit(cache=True)
def _pose_error(angles, k, t_theta, t_alpha, t_beta):
    """max-norm distance [rad] of leg k's pose from a target."""
    return max(abs(t_theta - angles[k, THETA]), abs(t_alpha - angles[k, ALPHA]),
               abs(t_beta - angles[k, BETA]))


@njit(cache=True)
def _move_toward(angles, k, t_theta, t_alpha, t_beta, max_step):
    """Move leg k's pose along the straight line to the target by at most max_step [rad]
    in every angle, all three arriving together; lands exactly on the target."""
    d_theta = t_theta - angles[k, THETA]
    d_alpha = t_alpha - angles[k, ALPHA]
    d_beta = t_beta - angles[k, BETA]
    m = max(abs(d_theta), abs(d_alpha), abs(d_beta))
    if m <= max_step:
        angles[k, THETA], angles[k, ALPHA], angles[k, BETA] = t_theta, t_alpha, t_beta
    else:
        s = max_step / m
        angles[k, THETA] += s * d_theta
        angles[k, ALPHA] += s * d_alpha
        angles[k, BETA] += s * d_beta


@njit(cache=True)
def switcher_step(states, angles, airborne, touching, ik_failed, params, dt, entered_stance):
    """One Switcher update of all legs (Sec. 4.2 rules 1-5 and synchronization).

    states: (n_legs,) int64, updated in place; angles: (n_legs, 3) [rad], moved
    in place for non-STANCE legs (STANCE legs are left to the IK);
    airborne: (n_legs,) bool latch "tip off the ground since leaving STANCE",
    updated in place (initialize it to ``~touching``);
    touching: (n_legs,) bool, tip on the ground now (``legs.tips_touching``);
    ik_failed: (n_legs,) bool, the last ``stance_inverse_kinematics`` result;
    params: (N_SWITCHER_PARAMS,); dt [s]; entered_stance: (n_legs,) bool,
    overwritten with this step's touch-downs.  n_legs must be even.
    """
    n_legs = states.shape[0]
    n_segments = n_legs // 2
    wave = 1 if params[WAVE_DIRECTION] > 0.0 else -1
    tol = params[ARRIVAL_TOL]
    lead_left = 2 * first_wave_segment(n_segments, wave)
    lead_right = lead_left + 1
    lead_left_was_sf1 = states[lead_left] == SF1

    # rules 3 and 2
    for k in range(n_legs):
        entered_stance[k] = False
        if states[k] == STANCE and ik_failed[k]:
            states[k] = SF1
        if states[k] != STANCE:
            if not touching[k]:
                airborne[k] = True
            elif airborne[k]:
                states[k] = STANCE
                entered_stance[k] = True
                airborne[k] = False

    # rule 4 (needs every leg's touch-down of this step), then rules 1 and 5
    for k in range(n_legs):
        if entered_stance[k]:
            continue
        p = previous_leg(k, n_segments, wave)
        if p >= 0 and entered_stance[p] and (states[k] != STANCE or params[ADJUST_FROM_STANCE] != 0.0):
            states[k] = ADJUST
        if states[k] == STANCE:
            continue
        t_theta, t_alpha, t_beta = target_pose(states[k], params)
        if _pose_error(angles, k, t_theta, t_alpha, t_beta) <= tol:
            states[k] = state_after_target(states[k])

    # left/right synchronization of the leading segment
    if not lead_left_was_sf1 and states[lead_left] == SF1:
        states[lead_right] = SF1

    # forward kinematics toward the targets
    max_step = params[SWING_SPEED] * dt
    for k in range(n_legs):
        if states[k] != STANCE:
            t_theta, t_alpha, t_beta = target_pose(states[k], params)
            _move_toward(angles, k, t_theta, t_alpha, t_beta, max_step)


@njit(cache=True)
def fix_stance_tips(entered_stance, seg_c, seg_R, geom, angles, tips):
    """Fix the tips of the legs that touched down: tips[k] = FK tip for entered_stance[k].

    Call right after ``switcher_step`` (which leaves STANCE legs' angles alone, so
    the FK tip is the one that touched).  seg_c: (n_segments, 3) [m]; seg_R:
    (n_segments, 3, 3); geom: (n_legs, N_LEG_GEOM); angles: (n_legs, 3) [rad];
    tips: (n_legs, 3) [m], rows of the other legs left unchanged.
    """
    for k in range(entered_stance.shape[0]):
        if entered_stance[k]:
            i = k // 2
            tips[k, 0], tips[k, 1], tips[k, 2] = leg_tip(seg_c[i], seg_R[i], geom[k], side_sign(k),
                                                         angles[k, THETA], angles[k, ALPHA],
                                                         angles[k, BETA])


@njit(cache=True)
def stance_inverse_kinematics(states, seg_c, seg_R, geom, tips, angles, ik_failed):
    """Angles of the STANCE legs by IK (App. B) from their fixed tips and the
    roots given by their segments' (Targeter) poses.

    states: (n_legs,) int64; seg_c: (n_segments, 3) [m]; seg_R: (n_segments, 3, 3);
    geom: (n_legs, N_LEG_GEOM); tips: (n_legs, 3) [m].  angles: (n_legs, 3) [rad],
    rows of STANCE legs overwritten where the IK succeeds.  ik_failed: (n_legs,)
    bool, overwritten: True for STANCE legs without a convex solution (rule 3
    acts on it in the next ``switcher_step``), False for all other legs.
    """
    for k in range(states.shape[0]):
        if states[k] == STANCE:
            ik_failed[k] = not leg_ik_from_segment(seg_c, seg_R, geom, tips, angles, k)
        else:
            ik_failed[k] = False


def state_names(states) -> list[str]:
    """Readable names of an array of states."""
    return [STATE_NAMES[int(s)] for s in states]

