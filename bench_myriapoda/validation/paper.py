"""The myriapod paper (Fang, Jiang & Terzopoulos, SCA 2013): Fig. 4, Fig. 10 A and D, the leg wave's
direction, CONTROL turns, obstacle avoidance and foraging.

Criteria follow tests/test_myriapod.py, tests/test_hybrid.py and tests/test_foraging.py; the
constants are here so that ``validate`` states them next to the measured value.
"""
from __future__ import annotations

import math

import numpy as np

from .core import Context, Outcome, failed_run, holds, not_applicable

FANG = "Fang et al. 2013"
IMPACT_STRAIN_MIN = 0.01        # Fig. 4: the links deform by at least 1 % on impact ...
STATIC_STRAIN_MAX = 0.005       # ... and are back under 0.5 % (their sag on the ground) at the end
HANG_STATE_MIN_SHARE = 0.15     # Fig. 10 A: each of SF1, SF2, SB1, SB2 takes at least this share of the time
HANG_ELONGATION_MIN_M = 0.01    # ... and the body elongates by more than this
MIN_CONVERGED_LEGS = 0.5        # Fig. 10 D: "most legs": at least half pass metrics.gait.walking_cycle_check
WAVE_LAG_MIN = 0.05             # |phase lag| [cycles] that counts as a travelling wave
TURN_DEG, TURN_TOL_DEG = 40.0, 8.0   # CONTROL: the commanded 40 degree left turn
HEADING_ERROR_MAX_DEG = 2.0
FOOD_TIME_LIMIT_S = 6.0         # food 3 m ahead, 2 m to the side: reached within this time
BODY_PENETRATION_LIMIT_M = 0.05  # avoidance: the body no deeper into a cylinder than this

# Fig. 10 D at a duration where the walking cycle can be counted: the gait metrics start one second
# after ADJUSTMENT ends (harness/legged.py) and walking_cycle_check needs MIN_CYCLES (2) complete
# SF1 -> ... -> SF1 cycles, i.e. three SF1 onsets, in that window.  At the default stride frequency
# (about 0.9 Hz on the hybrid body) that is about 4.5 s of walking: a 3 s walk (the quick matrix)
# cannot pass by construction, whatever the legs do.  See walking_window_note().
WALK_DURATION_S = 10.0


def _timeline(r):
    t, states, _tips = r.extra["leg_timeline"]
    return np.asarray(t), np.asarray(states)


# --------------------------------------------------------------------------- Fig. 4

def fig4_drop(ctx: Context, body: str) -> Outcome:
    """The Fig. 4 chain dropped onto a slippery plane: the links deform on impact and recover."""
    from ..core.config import resolve_case
    from ..harness.runner import Creature

    ref = f"impact strain >= {IMPACT_STRAIN_MIN:g}, final <= {STATIC_STRAIN_MAX:g} (Fig. 4)"
    case = resolve_case("chain", body, "fig4-drop", duration=2.0 if ctx.quick else 3.0)
    cr = Creature(case)
    cr.compile()
    b = cr.body
    impact, done, chunk = 0.0, 0, max(1, int(round(0.005 / case.dt)))  # tet quality every 5 ms
    while done < case.steps:
        k, code = cr.advance(done * case.dt, min(chunk, case.steps - done))
        if code != 0:
            return Outcome("FAIL", None, ref, "-", b.status_text(code))
        done += k
        b.observe(done * case.dt)
        impact = max(impact, b.tet_quality()[2])
    _min_j, inverted, final = b.tet_quality()
    ok = impact >= IMPACT_STRAIN_MIN and final <= STATIC_STRAIN_MAX and inverted == 0
    return holds(ok, f"impact {impact:.3f}, final {final:.4f}", ref, "both bounds, no inverted tet",
                 f"largest link strain on impact {impact:.3g}, at {done * case.dt:.1f} s {final:.3g}; "
                 f"{inverted} inverted tets", impact_strain=impact, final_strain=final)


# --------------------------------------------------------------------------- Fig. 10 A

def judge_hang(t, states, elongation_m: float) -> Outcome:
    """Fig. 10 A criteria on a leg timeline (t (T,) [s], states (T, n_legs)) and the hanging elongation [m]."""
    from ..controllers.myriapod import switcher as SW
    from ..metrics.gait import dominant_cycle, format_cycle

    ref = "SF1 -> SF2 -> SB1 -> SB2, no STANCE/ADJUST, elongates (Fig. 10 A)"
    states = np.asarray(states)
    shares = {name: float(np.mean(states == code)) for name, code in
              (("SF1", SW.SF1), ("SF2", SW.SF2), ("SB1", SW.SB1), ("SB2", SW.SB2), ("STANCE", SW.STANCE),
               ("ADJUST", SW.ADJUST))}
    cycle = format_cycle(dominant_cycle(t, states[:, 0], last_fraction=0.5).cycle) or "(none)"
    ok = (shares["STANCE"] == 0 and shares["ADJUST"] == 0
          and all(shares[s] > HANG_STATE_MIN_SHARE for s in ("SF1", "SF2", "SB1", "SB2"))
          and elongation_m > HANG_ELONGATION_MIN_M)
    return holds(bool(ok), f"{cycle}; elongation {elongation_m * 100:.1f} cm", ref,
                 f"each loop state > {HANG_STATE_MIN_SHARE:g} of the time, elongation > {HANG_ELONGATION_MIN_M:g} m",
                 "time shares " + ", ".join(f"{k} {v:.2f}" for k, v in shares.items()),
                 elongation_m=elongation_m, **{f"share_{k}": v for k, v in shares.items()})


def fig10a_hang(ctx: Context, body: str) -> Outcome:
    """Hanging by the head: legs cycle SF1 -> SF2 -> SB1 -> SB2 without STANCE or ADJUST; the body elongates."""
    r = ctx.run("centipede", body, "hang", duration=3.0)
    if r.status != "ok":
        return failed_run(r, "Fig. 10 A")
    t, states = _timeline(r)
    return judge_hang(t, states, r.metrics.get("hanging_elongation_m", math.nan))


# --------------------------------------------------------------------------- Fig. 10 D

def walking_window_note(metrics: dict, duration: float) -> str | None:
    """Why ``walking_cycle_leg_fraction`` cannot pass in a run this short, or None when it can.

    The window starts one second after ADJUSTMENT ends; it must hold at least three SF1 onsets
    (MIN_CYCLES = 2 complete cycles) per leg, i.e. at least (MIN_CYCLES + 1) / stride frequency.
    """
    from ..metrics.gait import MIN_CYCLES

    t_walk = metrics.get("time_to_walk_s", math.nan)
    f = metrics.get("stride_frequency_hz", math.nan)
    start = (t_walk if isinstance(t_walk, float) and math.isfinite(t_walk) else 0.0) + 1.0
    window = duration - start
    if not (isinstance(f, float) and math.isfinite(f) and f > 0):
        return f"no complete stride in the {max(window, 0):.1f} s window after ADJUSTMENT + 1 s"
    need = (MIN_CYCLES + 1) / f
    if window < need:
        return (f"{duration:g} s run: the gait window (from {start:.1f} s) is {window:.1f} s, shorter than the "
                f"{need:.1f} s that {MIN_CYCLES} complete cycles at {f:.2f} Hz need; run >= {start + need:.0f} s")
    return None


def judge_walk_cycle(metrics: dict, duration: float) -> Outcome:
    """Fig. 10 D criterion on a walk's metrics: NOT APPLICABLE when the run is too short to count cycles."""
    frac = metrics.get("walking_cycle_leg_fraction", math.nan)
    note = walking_window_note(metrics, duration)
    if note is not None:
        return not_applicable(note, MIN_CONVERGED_LEGS, f">= {MIN_CONVERGED_LEGS:g}")
    return holds(bool(frac >= MIN_CONVERGED_LEGS), frac, MIN_CONVERGED_LEGS, f">= {MIN_CONVERGED_LEGS:g}",
                 f"{duration:g} s walk; stride {metrics.get('stride_frequency_hz', math.nan):.2f} Hz, "
                 f"walking from {metrics.get('time_to_walk_s', math.nan):.2f} s",
                 stride_frequency_hz=metrics.get("stride_frequency_hz"))


def fig10d_walk(ctx: Context, body: str) -> Outcome:
    """On flat ground most legs converge to SF1 -> SF2 -> STANCE with short ADJUST and SB1 (Fig. 10 D)."""
    r = ctx.run("centipede", body, "walk", duration=WALK_DURATION_S)
    if r.status != "ok":
        return failed_run(r, "Fig. 10 D")
    return judge_walk_cycle(r.metrics, WALK_DURATION_S)


# --------------------------------------------------------------------------- the wave's direction

def judge_wave(metrics: dict, labels: dict, expected: str) -> Outcome:
    """The leg wave's direction from the mean phase lag and its label."""
    lag = metrics.get("phase_lag_mean", math.nan)
    label = (labels or {}).get("wave_direction", "undefined")
    sign = 1.0 if expected == "retrograde" else -1.0
    ok = label == expected and sign * lag > WAVE_LAG_MIN
    return holds(bool(ok), f"{label} (lag {lag:+.3f})", expected,
                 f"sign of the phase lag, |lag| > {WAVE_LAG_MIN:g} cycles",
                 f"mean phase lag {lag:+.3f} cycles behind the same-side leg ahead", phase_lag_mean=lag)


def _wave(ctx: Context, creature: str, body: str, expected: str, duration: float) -> Outcome:
    r = ctx.run(creature, body, "walk", duration=duration)
    if r.status != "ok":
        return failed_run(r, expected)
    return judge_wave(r.metrics, r.extra.get("labels", {}), expected)


def centipede_wave(ctx: Context, body: str) -> Outcome:
    """The centipede's leg wave is retrograde (head to tail) while it walks forward."""
    return _wave(ctx, "centipede", body, "retrograde", WALK_DURATION_S)


def millipede_wave(ctx: Context, body: str) -> Outcome:
    """The millipede's leg wave is direct (tail to head)."""
    return _wave(ctx, "millipede", body, "direct", 4.0 if ctx.quick else 8.0)


# --------------------------------------------------------------------------- CONTROL, behaviour

def judge_control(t, head, heading_error_deg: float) -> Outcome:
    """CONTROL criteria on the head's path: t (T,) [s], head (T, 3) [m]."""
    t, head = np.asarray(t), np.asarray(head)
    early = head[(t > 2.0) & (t < 4.0)]
    late = head[t > 9.0]
    if len(early) < 2 or len(late) < 2:
        return not_applicable(f"the run ends at {t[-1]:.1f} s; the turn schedule needs 10 s or more", TURN_DEG)
    d0, d1 = early[-1] - early[0], late[-1] - late[0]
    turn = math.degrees(math.atan2(-d1[2], d1[0]) - math.atan2(-d0[2], d0[0]))
    ok = abs(turn - TURN_DEG) <= TURN_TOL_DEG and heading_error_deg < HEADING_ERROR_MAX_DEG
    return holds(bool(ok), round(turn, 2), TURN_DEG,
                 f"+/- {TURN_TOL_DEG:g} deg; heading error < {HEADING_ERROR_MAX_DEG:g} deg",
                 f"head path turned {turn:.1f} deg; mean heading error {heading_error_deg:.2f} deg", "deg",
                 heading_error_deg=heading_error_deg)


def control_turn(ctx: Context, body: str) -> Outcome:
    """CONTROL mode: straight, a commanded 40 degree left turn (10 deg/s from 4 to 8 s), straight."""
    r = ctx.run("centipede", body, "control", duration=12.0)
    if r.status != "ok":
        return failed_run(r, TURN_DEG)
    return judge_control(r.series.t, r.series.head, r.metrics.get("heading_error_deg", math.nan))


def _heading_change(r) -> float:
    s = r.series
    d0 = s.head[0] - s.segment_centers[0, 0]
    d1 = s.head[-1] - s.segment_centers[-1, 0]
    a0, a1 = math.atan2(-d0[2], d0[0]), math.atan2(-d1[2], d1[0])
    return (a1 - a0 + math.pi) % (2 * math.pi) - math.pi


def foraging(ctx: Context, body: str) -> Outcome:
    """TROPHOTROPISM: food 3 m ahead and 2 m to the right is reached, turning right, within 6 s."""
    ref = f"food reached within {FOOD_TIME_LIMIT_S:g} s, turning toward it (Sec. 4.3, 6.2)"
    r = ctx.run("centipede", body, "walk", duration=8.0,
                overrides=("food.sources=[3.0, 0.0, 2.0, 1.0]", "controller.random_turn_max_deg=0"))
    if r.status != "ok":
        return failed_run(r, ref)
    m = r.metrics
    t_food = m.get("time_to_first_food_s", math.nan)
    turn = math.degrees(_heading_change(r))
    ok = m.get("food_reached", 0) >= 1 and t_food <= FOOD_TIME_LIMIT_S and turn < 0
    return holds(ok, t_food, FOOD_TIME_LIMIT_S, f"<= {FOOD_TIME_LIMIT_S:g} s and a right turn",
                 f"food reached {m.get('food_reached', 0):g}; heading change {turn:+.1f} deg; trophotropism "
                 f"{m.get('brain_trophotropism_fraction', math.nan):.2f} of the time", "s")


def avoidance(ctx: Context, body: str) -> Outcome:
    """AVOIDANCE: among 25 random tall cylinders the body keeps out of them (antennae turn the head away)."""
    ref = f"body penetration <= {BODY_PENETRATION_LIMIT_M:g} m, >= 3 antenna contacts (Sec. 4.3, 6.2)"
    r = ctx.run("centipede", body, "foraging", duration=12.0 if ctx.quick else 25.0, overrides=(
        "creature.segments=6", "scenario.obstacle_cylinders=25", "scenario.obstacle_region_m=[5.0, 35.0, -12.0, 12.0]",
        "scenario.obstacle_radius_m=[0.3, 0.6]", "scenario.terrain_seed=0", "food.seed=0"))
    if r.status != "ok":
        return failed_run(r, ref)
    return judge_avoidance(r.metrics)


def judge_avoidance(m: dict, min_contacts: int = 3) -> Outcome:
    """AVOIDANCE criteria on a run's behaviour metrics."""
    pen = m.get("obstacle_penetration_body_max_m", math.nan)
    ok = pen <= BODY_PENETRATION_LIMIT_M and m.get("obstacle_contacts", 0) >= min_contacts \
        and m.get("brain_avoidance_fraction", 0) > 0.02
    return holds(bool(ok), pen, BODY_PENETRATION_LIMIT_M, f"<= {BODY_PENETRATION_LIMIT_M:g} m, >= {min_contacts} "
                 "antenna contacts",
                 f"{m.get('obstacle_contacts', 0):g} antenna contacts, avoidance "
                 f"{m.get('brain_avoidance_fraction', math.nan):.2f} of the time, path "
                 f"{m.get('path_length_m', math.nan):.1f} m", "m")
