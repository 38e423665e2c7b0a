"""The myriapod: leg controller on the hybrid body against the paper's Fig. 10 and the literature."""
import json

import numpy as np
import pytest

from bench_myriapoda.controllers.myriapod import switcher as SW
from bench_myriapoda.controllers.myriapod.controller import ADJUSTMENT
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.metrics.gait import walking_cycle_check

MIN_CONVERGED_LEGS = 0.5     # share of legs whose last cycles are SF1 -> SF2 -> STANCE (brief ADJUST, SB1)


def run(creature, scenario, duration, *sets, body="hybrid"):
    case = resolve_case(creature, body, scenario, duration=duration, overrides=list(sets))
    r = run_case(case)
    assert r.status == "ok", r.message
    return case, r


@pytest.fixture(scope="module")
def centipede_walk():
    return run("centipede", "walk", 10.0)


def test_centipede_walks_forward_for_10_seconds_without_instability(centipede_walk):
    case, r = centipede_walk
    assert r.metrics["speed_m_per_s"] > 0.5 * case.controller.head_speed_m_s
    assert r.metrics["min_J"] > 0.5 and r.metrics["inverted_elements_max"] == 0
    assert r.metrics["coupling_residual_max_m"] < 0.05 * case.creature.segment_length_m


def test_on_flat_ground_legs_converge_to_sf1_sf2_stance(centipede_walk):
    # paper Fig. 10 D: SF1 -> SF2 -> STANCE with short appearances of ADJUST and SB1
    _, r = centipede_walk
    t, states, _ = r.extra["leg_timeline"]
    converged = [walking_cycle_check(t, states[:, k], last_fraction=0.4).converged for k in range(states.shape[1])]
    assert np.mean(converged) >= MIN_CONVERGED_LEGS, np.mean(converged)
    late = states[t > t[-1] - 3.0]
    assert np.mean(late == SW.STANCE) > 0.5            # most of the time on the ground
    assert np.mean(late == SW.SB2) < 0.02              # the suspended loop's SB2 has gone
    assert np.mean(late == SW.ADJUST) < 0.15           # ADJUST is brief


def test_centipede_wave_is_retrograde(centipede_walk):
    _, r = centipede_walk
    assert r.metrics["phase_lag_mean"] > 0.05
    assert r.extra["labels"]["wave_direction"] == "retrograde"


def test_millipede_wave_is_direct():
    _, r = run("millipede", "walk", 8.0)
    assert r.metrics["phase_lag_mean"] < -0.05
    assert r.extra["labels"]["wave_direction"] == "direct"


def test_dropped_it_stays_in_adjustment_until_most_legs_touch_then_walks():
    case, r = run("centipede", "drop-adjust", 5.0)
    t_walk = r.metrics["time_to_walk_s"]
    fall = np.sqrt(2 * (case.scenario.start_height_m - 0.5) / case.scenario.gravity_m_s2)
    assert t_walk > fall  # not before the legs can reach the ground
    s = r.series
    before = s.t < t_walk
    # while adjusting, the head does not walk: it falls, and is only nudged by the supported
    # segments behind it (a fraction of a segment, against 1 m/s once walking)
    head_dx = np.abs(s.head[before, 0] - s.head[0, 0]).max()
    assert head_dx < 0.25 * case.creature.segment_length_m, head_dx
    assert r.series.head[-1, 0] - r.series.head[before][-1, 0] > 0.5 * case.controller.head_speed_m_s * (
        s.t[-1] - t_walk)
    t, _, _ = r.extra["leg_timeline"]
    brain = r.extra["brain_timeline"]
    assert np.all(brain[t < t_walk] == ADJUSTMENT) and not np.any(brain[t > t_walk] == ADJUSTMENT)
    assert r.metrics["touch_fraction_at_walk"] > case.controller.adjustment_majority


def test_hanging_legs_cycle_without_stance_and_the_body_elongates():
    # paper Fig. 10 A: SF1 -> SF2 -> SB1 -> SB2, never STANCE or ADJUST
    _, r = run("centipede", "hang", 3.0)
    t, states, _ = r.extra["leg_timeline"]
    assert not np.any(states == SW.STANCE) and not np.any(states == SW.ADJUST)
    for code in (SW.SF1, SW.SF2, SW.SB1, SW.SB2):
        assert np.mean(states == code) > 0.15
    assert r.metrics["hanging_elongation_m"] > 0.01
    assert r.metrics["brain_mode_final"] == ADJUSTMENT


def test_control_mode_follows_the_turn_schedule():
    case, r = run("centipede", "control", 12.0)
    assert r.metrics["heading_error_deg"] < 2.0
    # the commanded 40 degree left turn (10 deg/s from 4 s to 8 s) shows in the head's path
    h = r.series.head
    early = h[(r.series.t > 2.0) & (r.series.t < 4.0)]
    late = h[r.series.t > 9.0]
    d0 = early[-1] - early[0]
    d1 = late[-1] - late[0]
    turn = np.degrees(np.arctan2(-d1[2], d1[0]) - np.arctan2(-d0[2], d0[0]))
    assert turn == pytest.approx(40.0, abs=8.0)


def test_plot_gait_and_labels_from_the_cli(capsys, tmp_path):
    from bench_myriapoda.cli import main
    png = tmp_path / "gait.png"
    code = main(["run", "--creature", "centipede", "--body", "hybrid", "--scenario", "walk", "--duration", "2",
                 "--json", "--store", str(tmp_path / "r.sqlite"), "--plot-gait", str(png)])
    d = json.loads(capsys.readouterr().out)
    assert code == 0 and png.stat().st_size > 10_000
    assert d["labels"]["wave_direction"] in ("retrograde", "direct", "undefined", "synchronous")
    assert main(["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat",
                 "--plot-gait", str(tmp_path / "x.png")]) == 2


@pytest.mark.parametrize("segments", [3, 100])
def test_segment_counts_from_3_to_100_run(segments):
    _, r = run("centipede", "walk", 0.3, f"creature.segments={segments}")
    assert r.metrics["body_length_m"] > segments * 1.0
