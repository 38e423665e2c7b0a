"""Gait-wave metrics and gait diagrams on synthetic leg-state timelines with known answers.

Every timeline here is generated from explicit stance-onset times, so the
expected duty factor, stride frequency, phase lags, stance fractions, slip and
stride length are known exactly; tolerances below are set by the sampling
interval (an onset is seen at the first sample after it: an error of at most
one sample, dt / period of a cycle).  Conventions: ../shared/design/PAPER-NOTES.md
(positive lag = retrograde, head to tail); ../shared/reference/VALIDATION.md
(centipedes retrograde, millipedes direct; Fig. 10 state cycles).
"""
import math

import matplotlib.image as mpimg
import numpy as np
import pytest

from bench_myriapoda.metrics import gait
from bench_myriapoda.metrics.gait import (
    ADJUST, FLOAT_METRICS, N_STATES, SB1, SB2, SF1, SF2, STANCE, STATE_COLORS, SUSPENDED_CYCLE,
    WALKING_CYCLE, gait_metrics,
)
from bench_myriapoda.report.gait_diagram import leg_rows, plot_gait_diagram, plot_phase_lags

DT = 1e-3                 # [s] regular sampling interval
T0_OFFSET = 3.7e-4        # [s] keeps samples off the exact state boundaries of the generator
PERIOD = 0.8              # [s] stride period
DUTY = 0.6
DURATION = 8.0            # [s]

DUTY_TOL = 0.005          # one sample per stride: dt / PERIOD = 0.00125
FREQ_REL_TOL = 0.005
LAG_TOL = 0.005           # one sample per event: dt / PERIOD
LAG_CV_MAX_CLEAN = 0.05   # a noiseless wave has (almost) no lag spread
STANCE_FRACTION_TOL = 1e-9  # exact when every side holds the same number of legs in stance at all times
IRREGULAR_TOL = 0.01      # samples up to 3 ms apart: 3e-3 / 0.8 per event at worst
SLIP_REL_TOL = 0.01
STRIDE_LENGTH_REL_TOL = 0.01
JITTER_LAG_TOL = 0.01     # circular mean of 1 %-of-a-cycle jitter over ~100 events
PIXEL_COLOR_TOL = 3 / 255  # PNG colours are 8-bit
MIN_BAR_PIXELS = 2000      # far more than a legend swatch (about 15 x 10 px)
DIAGRAM_STANCE_SHARE_TOL = 0.05
TEST_RUNTIME_NOTE = "whole file runs in a few seconds"


# --- Synthetic timelines ----------------------------------------------------------------------
def sample_times(duration=DURATION, dt=DT):
    return T0_OFFSET + dt * np.arange(int(round(duration / dt)))


def wave_onsets(t, n_seg, lag, lr=0.0, period=PERIOD, jitter=0.0, rng=None, periods=None):
    """Per leg, stance-onset times covering t: leg (s, side) starts stance at (s*lag + side*lr + k) * P.

    ``jitter``: std of an independent random shift of every onset [cycles].
    ``periods``: optional (n_legs,) stride period per leg, overriding ``period``.
    """
    onsets = []
    for leg in range(2 * n_seg):
        seg, side = divmod(leg, 2)
        p = period if periods is None else periods[leg]
        offset = seg * lag + side * lr  # [cycles]
        k = np.arange(math.floor(t[0] / p - offset) - 3, math.ceil(t[-1] / p - offset) + 3)
        on = (offset + k) * p
        if jitter:
            on = on + rng.normal(0.0, jitter * p, size=on.shape)
        onsets.append(np.sort(on))
    return onsets


def states_from_onsets(t, onsets, duty, brief=True):
    """(T, n_legs) states: STANCE for the first ``duty`` of each stride, then the swing.

    Swing (fraction r of the swing time): SF1 r < 0.45, ADJUST r < 0.5, SF2
    r < 0.92, SB1 after, i.e. the converged walking cycle of paper Fig. 10 D
    with brief ADJUST and SB1; ``brief=False`` gives plain SF1 then SF2.
    """
    duty = np.broadcast_to(np.asarray(duty, dtype=float), (len(onsets),))
    states = np.empty((len(t), len(onsets)), dtype=np.int8)
    for leg, on in enumerate(onsets):
        k = np.searchsorted(on, t, side="right") - 1
        q = (t - on[k]) / (on[k + 1] - on[k])
        r = (q - duty[leg]) / (1.0 - duty[leg])
        if brief:
            swing = np.select([r < 0.45, r < 0.5, r < 0.92], [SF1, ADJUST, SF2], SB1)
        else:
            swing = np.where(r < 0.5, SF1, SF2)
        states[:, leg] = np.where(q < duty[leg], STANCE, swing)
    return states


def wave_timeline(n_seg=10, lag=0.1, lr=0.0, duty=DUTY, t=None, **kw):
    t = sample_times() if t is None else t
    return t, states_from_onsets(t, wave_onsets(t, n_seg, lag, lr, **kw), duty)


def states_from_runs(runs, dt=DT):
    """(t, leg_states) of one leg from a list of (state, duration [s]) runs."""
    seq = np.concatenate([np.full(max(int(round(d / dt)), 1), s, dtype=np.int8) for s, d in runs])
    return T0_OFFSET + dt * np.arange(len(seq)), seq


# --- Wave metrics -----------------------------------------------------------------------------
def test_retrograde_wave_in_antiphase_is_recovered():
    # centipede-like: each leg touches down 0.1 cycle after the same-side leg ahead; sides in antiphase
    t, states = wave_timeline(n_seg=10, lag=0.1, lr=0.5)
    m, labels = gait_metrics(t, states, warmup_s=0.0)
    assert set(m) == set(FLOAT_METRICS)
    assert m["duty_factor_mean"] == pytest.approx(DUTY, abs=DUTY_TOL)
    assert m["duty_factor_std"] < DUTY_TOL
    assert m["stride_frequency_hz"] == pytest.approx(1 / PERIOD, rel=FREQ_REL_TOL)
    assert m["phase_lag_mean"] == pytest.approx(0.1, abs=LAG_TOL)
    assert m["phase_lag_cv"] < LAG_CV_MAX_CLEAN
    assert labels["wave_direction"] == "retrograde"
    assert m["legs_per_wave"] == pytest.approx(10.0, rel=LAG_TOL / 0.1)
    assert m["lr_phase_diff"] == pytest.approx(0.5, abs=LAG_TOL)
    # lag 0.1 over 10 segments spaces the onsets of a side evenly: exactly 6 of 10 legs always stand
    assert m["stance_fraction_min"] == pytest.approx(DUTY, abs=STANCE_FRACTION_TOL)
    assert m["stance_fraction_mean"] == pytest.approx(DUTY, abs=STANCE_FRACTION_TOL)
    assert m["stepping_leg_fraction"] == 1.0
    assert m["walking_cycle_leg_fraction"] == 1.0


def test_direct_wave_has_negative_lag():
    # millipede-like: each leg touches down 0.12 cycle BEFORE the leg ahead (tail-to-head wave)
    t, states = wave_timeline(n_seg=12, lag=-0.12, lr=0.0)
    m, labels = gait_metrics(t, states)
    assert m["phase_lag_mean"] == pytest.approx(-0.12, abs=LAG_TOL)
    assert labels["wave_direction"] == "direct"
    assert m["legs_per_wave"] == pytest.approx(1 / 0.12, rel=LAG_TOL / 0.12)
    assert m["lr_phase_diff"] == pytest.approx(0.0, abs=LAG_TOL)
    assert m["stance_fraction_min"] < m["stance_fraction_mean"] <= 1.0
    assert m["stance_fraction_mean"] == pytest.approx(DUTY, abs=DUTY_TOL)


@pytest.mark.parametrize("lr, expected", [(0.0, 0.0), (0.5, 0.5), (0.25, 0.25), (0.75, 0.25), (0.6, 0.4)])
def test_left_right_phase_difference_wraps_to_half_a_cycle(lr, expected):
    t, states = wave_timeline(n_seg=6, lag=0.15, lr=lr)
    m, _ = gait_metrics(t, states)
    assert m["lr_phase_diff"] == pytest.approx(expected, abs=LAG_TOL)


@pytest.mark.parametrize("lag, expected, direction", [
    (0.45, 0.45, "retrograde"),
    (0.55, -0.45, "direct"),      # 0.55 of a cycle behind is 0.45 ahead: the shorter way round
    (-0.45, -0.45, "direct"),
    (0.95, -0.05, "direct"),
])
def test_lags_wrap_to_the_nearest_half_cycle(lag, expected, direction):
    t, states = wave_timeline(n_seg=8, lag=lag)
    m, labels = gait_metrics(t, states)
    assert m["phase_lag_mean"] == pytest.approx(expected, abs=LAG_TOL)
    assert labels["wave_direction"] == direction


def test_jittered_lag_near_half_cycle_averages_circularly():
    # events scatter across +-0.5: a linear mean would drag the lag toward 0 and blow up the CV
    rng = np.random.default_rng(3)
    t, states = wave_timeline(n_seg=10, lag=0.49, jitter=0.01, rng=rng)
    m, labels = gait_metrics(t, states)
    wrapped_events = np.concatenate(list(gait.phase_lag_events(gait.stride_stats(t, states).onset_times).values()))
    assert (wrapped_events < 0).any(), "the jitter must push some events across the wrap for this test to bite"
    assert m["phase_lag_mean"] == pytest.approx(0.49, abs=JITTER_LAG_TOL)
    assert labels["wave_direction"] == "retrograde"
    assert m["phase_lag_cv"] < 0.1
    assert abs(np.mean(wrapped_events) - 0.49) > 0.05  # what the naive mean would have reported


def test_duty_std_and_frequency_average_over_legs():
    # left legs: duty 0.5, period 0.8 s; right legs: duty 0.7, period 0.5 s
    t = sample_times()
    n_seg = 5
    periods = np.array([0.8, 0.5] * n_seg)
    duty = np.array([0.5, 0.7] * n_seg)
    states = states_from_onsets(t, wave_onsets(t, n_seg, 0.1, periods=periods), duty)
    m, _ = gait_metrics(t, states)
    assert m["duty_factor_mean"] == pytest.approx(0.6, abs=DUTY_TOL)
    assert m["duty_factor_std"] == pytest.approx(0.1, abs=DUTY_TOL)  # population std over legs
    assert m["stride_frequency_hz"] == pytest.approx(0.5 * (1 / 0.8 + 1 / 0.5), rel=FREQ_REL_TOL)
    st = gait.stride_stats(t, states)
    assert st.stride_frequency_hz[0::2] == pytest.approx(np.full(n_seg, 1 / 0.8), rel=FREQ_REL_TOL)
    assert st.stride_frequency_hz[1::2] == pytest.approx(np.full(n_seg, 1 / 0.5), rel=FREQ_REL_TOL)


def test_irregular_sampling():
    rng = np.random.default_rng(7)
    t = T0_OFFSET + np.cumsum(rng.uniform(0.2e-3, 3e-3, size=4000))
    t, states = wave_timeline(n_seg=8, lag=0.125, lr=0.5, t=t)
    m, labels = gait_metrics(t, states)
    assert m["duty_factor_mean"] == pytest.approx(DUTY, abs=IRREGULAR_TOL)
    assert m["stride_frequency_hz"] == pytest.approx(1 / PERIOD, rel=IRREGULAR_TOL)
    assert m["phase_lag_mean"] == pytest.approx(0.125, abs=IRREGULAR_TOL)
    assert m["lr_phase_diff"] == pytest.approx(0.5, abs=IRREGULAR_TOL)
    # time-weighted: 8 evenly spaced onsets per side with duty 0.6 hold 4.8 legs on average
    assert m["stance_fraction_mean"] == pytest.approx(DUTY, abs=IRREGULAR_TOL)
    assert labels["wave_direction"] == "retrograde"


def test_time_weighting_under_state_dependent_sampling():
    # a recorder that samples stance 10x more densely than swing (e.g. adaptive steps at contact):
    # counting samples would report ~94 % stance; holding each sample until the next gives the truth
    fine = sample_times(dt=0.5e-3)
    _, fine_states = wave_timeline(n_seg=2, lag=0.0, t=fine)
    keep = (fine_states[:, 0] == STANCE) | (np.arange(len(fine)) % 10 == 0)
    t, states = fine[keep], fine_states[keep]
    m, _ = gait_metrics(t, states)
    assert m["stance_fraction_mean"] == pytest.approx(DUTY, abs=IRREGULAR_TOL)
    assert m["duty_factor_mean"] == pytest.approx(DUTY, abs=IRREGULAR_TOL)
    assert gait.state_time_fractions(t, states)[:, STANCE] == pytest.approx(np.full(4, DUTY), abs=IRREGULAR_TOL)


def test_warmup_skips_an_irregular_start():
    rng = np.random.default_rng(11)
    warmup = 2.0
    t, states = wave_timeline(n_seg=6, lag=0.2)
    garbage = t < warmup
    # random states held for 20 ms blocks: many short, random "strides" before the gait settles
    blocks = rng.integers(0, N_STATES, size=(int(warmup / 0.02) + 1, states.shape[1]))
    states[garbage] = blocks[((t[garbage] - t[0]) / 0.02).astype(int)]
    settled, _ = gait_metrics(t, states, warmup_s=warmup)
    unsettled, _ = gait_metrics(t, states, warmup_s=0.0)
    assert settled["duty_factor_mean"] == pytest.approx(DUTY, abs=DUTY_TOL)
    assert settled["stride_frequency_hz"] == pytest.approx(1 / PERIOD, rel=FREQ_REL_TOL)
    assert settled["phase_lag_mean"] == pytest.approx(0.2, abs=LAG_TOL)
    assert abs(unsettled["stride_frequency_hz"] - 1 / PERIOD) > 0.5  # the warm-up matters


# --- Edge cases -------------------------------------------------------------------------------
def test_no_stance_at_all_gives_nan_not_a_crash():
    # a suspended creature (Fig. 10 A): every leg loops SF1 -> SF2 -> SB1 -> SB2
    t = sample_times(4.0)
    n_legs = 8
    phase = (t[:, None] / 0.4 + np.arange(n_legs) * 0.1) % 1.0
    states = np.array(SUSPENDED_CYCLE, dtype=np.int8)[(phase * 4).astype(int)]
    tips = np.zeros(states.shape + (3,))
    com = np.zeros((len(t), 3))
    m, labels = gait_metrics(t, states, tips, com, body_length=0.1, warmup_s=1.0)
    for name in ("duty_factor_mean", "duty_factor_std", "stride_frequency_hz", "phase_lag_mean", "phase_lag_cv",
                 "legs_per_wave", "lr_phase_diff", "stride_length_bl", "foot_slip_mean_m"):
        assert math.isnan(m[name]), name
    assert m["stance_fraction_min"] == 0.0 and m["stance_fraction_mean"] == 0.0
    assert m["stepping_leg_fraction"] == 0.0
    assert m["walking_cycle_leg_fraction"] == 0.0
    assert labels["wave_direction"] == "undefined"


def test_single_leg():
    t = sample_times()
    onsets = wave_onsets(t, 1, 0.0)[:1]
    states = states_from_onsets(t, onsets, DUTY)
    assert states.shape[1] == 1
    m, labels = gait_metrics(t, states)
    assert m["duty_factor_mean"] == pytest.approx(DUTY, abs=DUTY_TOL)
    assert m["duty_factor_std"] == 0.0
    assert m["stride_frequency_hz"] == pytest.approx(1 / PERIOD, rel=FREQ_REL_TOL)
    assert math.isnan(m["phase_lag_mean"]) and math.isnan(m["lr_phase_diff"]) and math.isnan(m["legs_per_wave"])
    assert labels["wave_direction"] == "undefined"


def test_warmup_longer_than_the_run_gives_nan():
    t, states = wave_timeline(n_seg=3)
    m, labels = gait_metrics(t, states, warmup_s=2 * DURATION)
    assert all(math.isnan(v) for v in m.values())
    assert labels["wave_direction"] == "undefined"


def test_leg_that_never_steps_is_left_out_of_the_averages_but_counted():
    t, states = wave_timeline(n_seg=4, lag=0.25)
    states[:, 5] = SF1  # leg R2 hangs in the air the whole run
    m, _ = gait_metrics(t, states)
    assert m["stepping_leg_fraction"] == pytest.approx(7 / 8)
    assert m["duty_factor_mean"] == pytest.approx(DUTY, abs=DUTY_TOL)
    assert m["phase_lag_mean"] == pytest.approx(0.25, abs=LAG_TOL)  # R1->R2 and R2->R3 have no events


def test_bad_inputs_are_rejected():
    t, states = wave_timeline(n_seg=2)
    with pytest.raises(ValueError, match="unknown leg state"):
        gait_metrics(t, np.where(states == STANCE, 9, states))
    with pytest.raises(ValueError, match="increasing"):
        gait_metrics(t[::-1], states)
    with pytest.raises(ValueError, match="tips"):
        gait.foot_slip_mean(t, states, np.zeros((len(t), 3)))


def test_phase_wrapping_helpers():
    assert gait.wrap_phase(0.5) == 0.5
    assert gait.wrap_phase(-0.5) == 0.5
    assert gait.wrap_phase(0.75) == pytest.approx(-0.25)
    assert gait.wrap_phase(1.0) == 0.0
    assert gait.circular_mean([0.49, -0.49]) == pytest.approx(0.5)
    assert gait.circular_mean([0.1, 0.2]) == pytest.approx(0.15, abs=1e-3)
    assert math.isnan(gait.circular_mean([0.0, 0.5]))  # opposite phases have no mean direction
    assert math.isnan(gait.circular_mean([]))


# --- Foot slip and stride length --------------------------------------------------------------
def tips_for(t, states, drift_m_s, swing_speed=0.3):
    """Tip positions: swing tips fly forward fast; stance tips drift along x at ``drift_m_s`` from touchdown."""
    n_legs = states.shape[1]
    tips = np.zeros(states.shape + (3,))
    base = np.arange(n_legs)[None, :] * 0.01
    tips[..., 2] = base
    stance = states == STANCE
    for leg in range(n_legs):
        start = np.flatnonzero(stance[:, leg] & ~np.r_[False, stance[:-1, leg]])
        run_start = start[np.maximum(np.searchsorted(start, np.arange(len(t)), side="right") - 1, 0)]
        since = t - t[run_start] if len(start) else np.zeros_like(t)
        tips[:, leg, 0] = np.where(stance[:, leg], 0.05 + drift_m_s * since, swing_speed * t)
        tips[:, leg, 1] = np.where(stance[:, leg], 0.0, 0.01)
    return tips


def test_foot_slip_with_known_drift():
    # synchronous legs, recording from mid-swing to mid-swing: every stance run is complete
    t = sample_times(10 * PERIOD) + 0.5 * (DUTY + 1) * PERIOD
    t, states = wave_timeline(n_seg=5, lag=0.0, t=t)
    assert (states[0] != STANCE).all() and (states[-1] != STANCE).all()
    drift = 0.01  # [m/s]
    m, _ = gait_metrics(t, states, tips_for(t, states, drift))
    # slip grows linearly over a stance of DUTY * PERIOD: its mean over the stance is half the final value
    stance_samples = round(DUTY * PERIOD / DT)
    expected = drift * DT * (stance_samples - 1) / 2
    assert m["foot_slip_mean_m"] == pytest.approx(expected, rel=SLIP_REL_TOL)
    m0, _ = gait_metrics(t, states, tips_for(t, states, 0.0))
    assert m0["foot_slip_mean_m"] == pytest.approx(0.0, abs=1e-15)  # swing motion is not slip


def test_stride_length_with_known_com_speed():
    t, states = wave_timeline(n_seg=5, lag=0.2)
    speed, body_length = 0.05, 0.2  # [m/s], [m]
    com = np.column_stack([
        speed * t,
        0.02 + 0.004 * np.sin(2 * np.pi * t / PERIOD),        # bob once per stride
        0.003 * np.sin(2 * np.pi * t / PERIOD + 1.0),         # sway once per stride
    ])
    m, _ = gait_metrics(t, states, com=com, body_length=body_length, warmup_s=1.0)
    assert m["stride_length_bl"] == pytest.approx(speed * PERIOD / body_length, rel=STRIDE_LENGTH_REL_TOL)


# --- State sequences and the Fig. 10 convergence ----------------------------------------------
def test_run_lengths_and_time_fractions():
    t = np.array([0.0, 0.1, 0.2, 0.5, 0.6, 1.0])
    leg = np.array([SF1, SF1, SF2, STANCE, STANCE, SF1], dtype=np.int8)
    runs = gait.run_lengths(t, leg)
    assert runs.codes.tolist() == [SF1, SF2, STANCE, SF1]
    assert runs.start.tolist() == [0, 2, 3, 5]
    assert runs.duration == pytest.approx([0.2, 0.3, 0.5, 0.0])
    frac = gait.state_time_fractions(t, leg)[0]  # sample-and-hold over irregular spacing
    assert frac[[SF1, SF2, STANCE]] == pytest.approx([0.2, 0.3, 0.5])
    assert frac.sum() == pytest.approx(1.0)
    seqs = gait.state_sequences(t, np.column_stack([leg, leg[::-1]]))
    assert seqs[1].tolist() == [SF1, STANCE, SF2, SF1]


def converging_leg(rng):
    """3 s of irregular landing (Fig. 10 B, C), then 6 s of walking (Fig. 10 D).

    The walking cycle is SF1 -> SF2 -> STANCE; ADJUST interrupts SF1 in every
    other cycle and SB1 precedes the touchdown in most.
    """
    runs = [(int(s), float(d)) for s, d in zip(rng.integers(0, N_STATES, 60), rng.uniform(0.01, 0.1, 60))]
    for k in range(int(6.0 / 0.8)):
        cycle = [(SF1, 0.1)]
        if k % 2:
            cycle += [(ADJUST, 0.03), (SF1, 0.04)]
        cycle += [(SF2, 0.14)]
        if k % 4 != 3:
            cycle += [(SB1, 0.03)]
        cycle += [(STANCE, 0.46)]
        runs += cycle
    return states_from_runs(runs)


def test_fig10_leg_converges_to_walking_cycle():
    t, leg = converging_leg(np.random.default_rng(5))
    check = gait.walking_cycle_check(t, leg, last_fraction=0.5)
    assert check.converged, check.reasons
    assert check.summary.cycle == WALKING_CYCLE
    assert check.summary.share >= gait.MIN_CYCLE_SHARE
    assert 0 < check.summary.fractions[ADJUST] <= gait.BRIEF_STATE_MAX_FRACTION
    assert 0 < check.summary.fractions[SB1] <= gait.BRIEF_STATE_MAX_FRACTION
    assert check.summary.fractions[STANCE] > 0.5
    assert check.summary.fractions[SB2] == 0.0
    # the irregular landing alone has not converged
    landing = t < 3.0
    assert not gait.walking_cycle_check(t[landing], leg[landing], last_fraction=1.0)


def test_fig10_suspended_loop_is_not_converged():
    t, leg = states_from_runs([(s, 0.1) for _ in range(20) for s in SUSPENDED_CYCLE])
    check = gait.walking_cycle_check(t, leg)
    assert not check.converged
    assert check.summary.cycle == (SF1, SF2, SB2)  # the check ignores SB1 runs, but SB2 remains
    assert gait.dominant_cycle(t, leg).cycle == SUSPENDED_CYCLE
    assert gait.dominant_cycle(t, leg).share == 1.0
    assert check.summary.fractions[[SF1, SF2, SB1, SB2]] == pytest.approx([0.25] * 4, abs=0.01)
    assert any("SB1" in r for r in check.reasons)


def test_fig10_long_sb1_is_not_brief():
    # right cycle shape, but the leg gropes for the ground in SB1 for a third of the time
    t, leg = states_from_runs([(s, d) for _ in range(12) for s, d in ((SF1, 0.1), (SF2, 0.1), (SB1, 0.3), (STANCE, 0.4))])
    check = gait.walking_cycle_check(t, leg)
    assert check.summary.cycle == WALKING_CYCLE
    assert not check.converged
    assert check.reasons == (f"SB1 takes {check.summary.fractions[SB1]:.2f} of the time, "
                             f"brief means <= {gait.BRIEF_STATE_MAX_FRACTION}",)


def test_fig10_walking_leg_fraction_over_legs():
    t, states = wave_timeline(n_seg=4, lag=0.25)
    _, hanging = states_from_runs([(s, 0.1) for _ in range(20) for s in SUSPENDED_CYCLE])
    states[:, 0] = np.resize(hanging, len(t))  # one of 8 legs still hangs
    assert gait.walking_cycle_leg_fraction(t, states) == pytest.approx(7 / 8)


# --- Plots --------------------------------------------------------------------------------------
def _color_pixel_counts(png):
    img = mpimg.imread(png)[..., :3]
    counts = {}
    for code, hexcol in enumerate(STATE_COLORS):
        rgb = np.array([int(hexcol[i:i + 2], 16) / 255 for i in (1, 3, 5)])
        counts[code] = int(np.all(np.abs(img - rgb) <= PIXEL_COLOR_TOL, axis=-1).sum())
    return counts


def test_gait_diagram_png_shows_the_state_colours(tmp_path):
    t, states = wave_timeline(n_seg=6, lag=0.15, lr=0.5)
    png = plot_gait_diagram(t, states, tmp_path / "gait.png", last_seconds=1.0, title="synthetic wave")
    assert png.exists() and png.stat().st_size > 0
    counts = _color_pixel_counts(png)
    for code in (STANCE, SF1, SF2):
        assert counts[code] > MIN_BAR_PIXELS, (code, counts)
    # SB2 never occurs: only its legend swatch may carry its colour
    assert 0 < counts[SB2] < MIN_BAR_PIXELS, counts
    drawn = sum(counts.values())
    assert counts[STANCE] / drawn == pytest.approx(DUTY, abs=DIAGRAM_STANCE_SHARE_TOL)


def test_gait_diagram_irregular_sampling_and_layouts(tmp_path):
    rng = np.random.default_rng(2)
    t = T0_OFFSET + np.cumsum(rng.uniform(0.5e-3, 4e-3, size=1500))
    t, states = wave_timeline(n_seg=3, lag=-0.2, t=t)
    png = plot_gait_diagram(t, states, tmp_path / "sub" / "gait.png", last_seconds=2.0, layout="interleaved")
    assert _color_pixel_counts(png)[STANCE] > MIN_BAR_PIXELS
    rows = leg_rows(6, "grouped")
    assert [leg for leg, _ in rows] == [0, 2, 4, 1, 3, 5]      # left block head to tail, then right block
    assert rows[3][1] - rows[2][1] > 1.0                          # a gap between the blocks
    with pytest.raises(ValueError):
        leg_rows(6, "diagonal")


def test_phase_lag_plot_writes_png(tmp_path):
    t, states = wave_timeline(n_seg=8, lag=0.1, lr=0.5)
    mean, spread = gait.phase_lags_per_leg(t, states)
    assert np.isnan(mean[:2]).all()                               # the head has no leg ahead
    assert mean[2:] == pytest.approx(np.full(14, 0.1), abs=LAG_TOL)
    assert (spread[2:] < LAG_TOL).all()
    png = plot_phase_lags(t, states, tmp_path / "lags.png", title="synthetic")
    img = mpimg.imread(png)
    assert img.ndim == 3 and img.shape[0] > 100 and img.shape[1] > 100
