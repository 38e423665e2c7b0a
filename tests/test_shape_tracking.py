"""The commanded shape, achieved under load (issue 27): closed-loop shape tracking and its metrics.

Set-up of the issue: the default snake (50 segments, 2.5 m, 1 kg) on flat ground, commanded
curvature x body length 7, one wave per body, f = 0.140071 Hz and mu_f = 0.05 (Froude number
L f^2 / (g mu_f) = 0.1), mu_b = 1.5 mu_f, Coulomb friction, 3 warm-up cycles and 3 measured
(43 s).  The reference is ``reference.slithering.steady_slithering`` at the COMMANDED shape and the
belly's width (0.05 m = 0.02 BL; tests/test_slithering_bodies.py says why the width).

Open loop (``gait.shape_control = "open_loop"``), the lattice bent to 1.42 of 7 at ratio 5 and did not
move (issue 27's table).  The closed loop is the default, at each body's own proportional gain
(``BodySpec.shape_gain_p``: 2 on the lattice, 0.5 on the fem body, 0.25 on the hybrid) and with the wave's
third temporal harmonic corrected at each body's own gain (``BodySpec.shape_harmonic_gain_per_cycle``: 1, 1
and 0.5; why in docs/explanation/shape-tracking.md).  The default run holds ratio 1 and 5 on the lattice
(5 cycles), ratios 1.5 and 5 on the fem body and ratio 3 on the hybrid (4 cycles, 2 of them warm-up), the
harmonic correction on a model plant and on the lattice at ratio 1.5; the whole grid (three bodies x six
ratios at issue 27's 78.5 s, 11 cycles, as scenarios/matrix/slithering.toml) runs with BENCH_LONG_TESTS=1.
"""
from __future__ import annotations

import dataclasses
import functools
import json
import math
import os

import numpy as np
import pandas as pd
import pytest

from bench_myriapoda.controllers.muscle_waves import fill_activation, wave_table
from bench_myriapoda.controllers.shape_tracking import TrackGains, TrackState, measured_curvature, track_tick
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.core.protocols import MUSCLES
from bench_myriapoda.core.series import Series
from bench_myriapoda.harness.runner import Creature, run_case
from bench_myriapoda.metrics.shape_tracking import (SHAPE_ERROR_THRESHOLD, commanded_curvature, shape_tracking_error,
                                                    shape_tracking_metrics)
from bench_myriapoda.reference.slithering import steady_slithering
from bench_myriapoda.report.tables import comparison_tables

COMMAND = 7.0
MU_F = 0.05
MU_B_OVER_MU_F = 1.5
# the closed loop is the default, at each body's own proportional gain (BodySpec.shape_gain_p)
CLOSED = {"massspring": (), "fem": (), "hybrid": ()}
SETTINGS = (f"gait.curvature_amplitude={COMMAND}", "gait.wavelength_bl=1", "gait.frequency_hz=0.140071",
            f"friction.mu_forward={MU_F}", "friction.model=coulomb", f"friction.mu_backward={MU_B_OVER_MU_F * MU_F}",
            "metrics.warmup_cycles=3")
DURATION_S = 43.0  # 6 periods of 7.14 s: 3 warm-up (the ramp and the integral's settling), 3 measured
SUBSET_S = 35.7  # the default run's lattice cases: 5 periods, 3 warm-up and 2 measured
SHORT_S = 28.6  # the default run's fem and hybrid cases: 4 periods, 2 warm-up (SHORT_WARMUP) and 2 measured (the
# fewest steady cycles, metrics.min_steady_cycles); they cost ~1 (fem) and ~2.5 (hybrid) CPU s per simulated second,
# the lattice ~0.15
SHORT_WARMUP = "metrics.warmup_cycles=2"  # the shape error settles within 2 cycles (0.05 over the third at ratio 1.5)
GRID_S = 78.5  # the whole grid at the conditions: 11 periods, 3 warm-up and 8 measured (as the matrix file)
SPEED_REL_TOL = 0.15
ISOTROPIC_MAX_BL_PER_CYCLE = 0.03
RATIOS = (1.0, 1.5, 2.0, 3.0, 5.0, 10.0)
BODIES = ("massspring", "fem", "hybrid")
LONG = pytest.mark.skipif(not os.environ.get("BENCH_LONG_TESTS"),
                          reason="the whole friction grid at 78.5 s, minutes per fem or hybrid run; set BENCH_LONG_TESTS=1")


def snake_case(body: str, ratio: float, *extra: str, duration: float = DURATION_S):
    return resolve_case("snake", body, "flat", "lateral-undulation", duration=duration,
                        overrides=list(SETTINGS) + [f"friction.mu_transverse={ratio * MU_F}", *extra])


@functools.lru_cache(maxsize=None)
def slither(body: str, ratio: float, *extra: str):
    r = run_case(snake_case(body, ratio, *extra))
    assert r.status == "ok", r.message
    return r


def reference_speed(ratio: float) -> float:
    """Hu et al.'s model at the commanded shape and the belly's width [BL/cycle]."""
    return steady_slithering(COMMAND, 1.0, 1.0, MU_B_OVER_MU_F, ratio, width_bl=0.05 / 2.5).speed_bl_per_cycle


@functools.lru_cache(maxsize=None)
def slither_for(body: str, ratio: float, duration: float, *extra: str):
    r = run_case(snake_case(body, ratio, *extra, duration=duration))
    assert r.status == "ok", r.message
    return r


def check_tracks_and_moves(body: str, ratio: float, *extra: str, duration: float = DURATION_S) -> None:
    m = slither_for(body, ratio, duration, *CLOSED[body], *extra).metrics
    print("GRID", body, ratio, duration, "reference", round(reference_speed(ratio), 4),
          {k: round(m[k], 4) for k in ("speed_bl_per_cycle", "shape_tracking_error", "curvature_amplitude",
                                       "muscle_strain_peak", "muscle_saturation_fraction",
                                       "shape_harmonic_content")})
    assert m["shape_tracking_error"] <= SHAPE_ERROR_THRESHOLD, (body, ratio, m)
    assert m["shape_not_achieved"] == 0.0
    assert m["muscle_saturation_fraction"] == 0.0, (body, ratio, m)
    if ratio == 1.0:
        assert abs(m["speed_bl_per_cycle"]) < ISOTROPIC_MAX_BL_PER_CYCLE, (body, m)
    else:
        ref = reference_speed(ratio)
        assert m["speed_bl_per_cycle"] == pytest.approx(ref, rel=SPEED_REL_TOL), (body, ratio, ref, m)


# ----------------------------------------------------------------------------- the measurement, unit by unit

def arc_frames(kappa: float, n: int, pitch: float) -> tuple[np.ndarray, np.ndarray]:
    """(n, 3, 3) segment frames along a planar arc of curvature kappa [1/m] walked from the head, and the
    rest centres (n,) [m]; x axis toward the head, y up."""
    s = 0.5 * pitch + pitch * np.arange(n)
    R = np.zeros((n, 3, 3))
    for j, sj in enumerate(s):
        psi = kappa * sj  # heading of the x axis, left turn positive about +y
        R[j] = [[math.cos(psi), 0.0, math.sin(psi)], [0.0, 1.0, 0.0], [-math.sin(psi), 0.0, math.cos(psi)]]
    return R, s


@pytest.mark.parametrize("kappa", [2.8, -1.3])
def test_the_measured_curvature_of_an_arc_is_its_curvature_with_its_sign(kappa):
    R, s = arc_frames(kappa, 12, 0.05)
    out = np.zeros(12)
    measured_curvature(R, s, s, np.zeros(12), out)
    np.testing.assert_allclose(out, kappa, rtol=1e-12)
    # the hybrid's layout: muscles (links) at the midpoints of the boxes
    mid = 0.5 * (s[1:] + s[:-1])
    out = np.zeros(11)
    measured_curvature(R, s, mid, np.zeros(12), out)
    np.testing.assert_allclose(out, kappa, rtol=1e-12)


def test_a_command_beyond_the_muscle_strength_is_clipped_counted_and_does_not_wind_up():
    n = 4
    s = np.linspace(0.1, 0.4, n)
    waves = np.zeros((3, 5))
    waves[1, :4] = (0.1, 2 * math.pi, 1.0, 0.0)  # LATERAL amplitude 0.1
    a, b, lateral, counts = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(3)
    straight = np.zeros(n)  # the body does not bend at all
    gains = tuple(TrackGains(ramp_s=0.0, dt_tick=0.01, strain_per_kappa=-0.1, kp=2.0, ki=5.0, umax=0.02, passes=0))
    state = tuple(TrackState(a, b, lateral, counts, err=np.zeros(n), tmp=np.zeros(n)))
    for tick in range(200):
        track_tick(straight, s, waves, 0.01 * tick, True, gains, state)
        assert np.all(np.abs(lateral) <= 0.02)
    assert counts[0] == 200 * n and counts[1] > 0.9 * counts[0] and counts[2] == 0.02
    # the integral stopped growing once clipped: far below what 2 s of this error would integrate to
    assert np.all(np.hypot(a, b) < 0.1)


def commanded_centre_line(case, t: np.ndarray, phase_shift: float = 0.0, scale: float = 1.0) -> Series:
    """A centre line bent exactly to ``scale`` x the commanded ground curvature (``commanded_curvature``), its
    phase shifted by ``phase_shift`` [rad]: 50 centres one pitch apart, integrated from the head."""
    cre = case.creature
    pitch = cre.segment_length_m
    ds = pitch / 20.0
    s_fine = np.arange(0.0, cre.body_length_m + ds / 2, ds)
    shifted = case.gait.phase_deg + math.degrees(phase_shift)
    g = dataclasses.replace(case.gait, phase_deg=shifted)
    kappa = scale * commanded_curvature(dataclasses.replace(case, gait=g), s_fine, t)
    phi = np.concatenate([np.zeros((len(t), 1)), np.cumsum(0.5 * (kappa[:, 1:] + kappa[:, :-1]) * ds, axis=1)], axis=1)
    # walked from the head toward -x; a left turn (positive curvature) rotates the walking direction about +y
    dx, dz = -np.cos(phi), np.sin(phi)
    x = np.concatenate([np.zeros((len(t), 1)), np.cumsum(0.5 * (dx[:, 1:] + dx[:, :-1]) * ds, axis=1)], axis=1)
    z = np.concatenate([np.zeros((len(t), 1)), np.cumsum(0.5 * (dz[:, 1:] + dz[:, :-1]) * ds, axis=1)], axis=1)
    idx = np.round((0.5 + np.arange(cre.segments)) * pitch / ds).astype(int)
    c = np.stack([x[:, idx], np.zeros((len(t), len(idx))), z[:, idx]], axis=2)
    head = np.stack([x[:, 0], np.zeros(len(t)), z[:, 0]], axis=1)
    return Series(t=t, com=c.mean(axis=1), head=head, tail=c[:, -1], segment_centers=c, energy=np.zeros((len(t), 3)),
                  nodes=None)


def test_the_shape_error_is_zero_for_the_commanded_shape_and_grows_with_what_is_missing():
    case = snake_case("massspring", 1.0, "gait.frequency_hz=0.5", "gait.ramp_s=0")
    t = np.linspace(0.0, 4.0, 81)
    exact = commanded_centre_line(case, t)
    assert shape_tracking_error(exact, case, 0, len(t) - 1) < 0.02
    assert shape_tracking_metrics(exact, case, 0, len(t) - 1)["shape_not_achieved"] == 0.0
    straight = commanded_centre_line(case, t, scale=0.0)
    assert shape_tracking_error(straight, case, 0, len(t) - 1) == pytest.approx(1.0 / math.sqrt(2), abs=0.03)
    lagging = commanded_centre_line(case, t, phase_shift=math.pi / 2)  # sqrt(2) sin(pi / 4) = 1
    assert shape_tracking_error(lagging, case, 0, len(t) - 1) == pytest.approx(1.0, abs=0.03)
    small = commanded_centre_line(case, t, scale=0.8)  # 20 % of the amplitude missing: flagged
    assert shape_tracking_error(small, case, 0, len(t) - 1) == pytest.approx(0.2 / math.sqrt(2), abs=0.01)
    assert shape_tracking_metrics(small, case, 0, len(t) - 1)["shape_not_achieved"] == 1.0
    mirrored = commanded_centre_line(case, t, scale=-1.0)  # the opposite bend: the sign is measured
    assert shape_tracking_error(mirrored, case, 0, len(t) - 1) == pytest.approx(2.0 / math.sqrt(2), abs=0.05)
    worm = resolve_case("worm", "massspring", "flat")
    assert shape_tracking_metrics(exact, worm, 0, len(t) - 1) == {}


def test_the_comparison_table_says_a_run_did_not_reach_its_shape():
    row = {"creature": "snake", "body": "massspring", "gait": "lateral-undulation", "scenario": "flat", "seed": 0,
           "status": "ok", "metric.speed_bl_per_cycle": 0.001, "metric.shape_tracking_error": 0.6,
           "metric.shape_not_achieved": 1.0}
    ok = dict(row, body="fem", **{"metric.speed_bl_per_cycle": 0.39, "metric.shape_tracking_error": 0.05,
                                  "metric.shape_not_achieved": 0.0})
    # the creature's tables (title, table): the one with the speeds is its locomotion table
    table = next(t for _, t in comparison_tables(pd.DataFrame([row, ok]))["snake"]
                 if t is not None and "speed [BL/cycle]" in t.table.columns)
    speed = table.table.columns.get_loc("speed [BL/cycle]")
    notes = dict(zip(table.table["body"], table.notes.iloc[:, speed]))
    assert notes == {"massspring": "shape", "fem": ""} and "shape_not_achieved" in table.footnotes["shape"]
    assert dict(zip(table.table["body"], table.table["shape error"])) == {"massspring": 0.6, "fem": 0.05}


# ----------------------------------------------------------------------------- the controller on every body

def test_the_closed_loop_key_makes_a_closed_loop_controller_and_the_open_loop_is_the_default():
    closed = Creature(snake_case("massspring", 5.0, "gait.shape_control=closed_loop", duration=0.1))
    assert not closed.controller.open_loop and closed.controller.rate_hz == 250.0
    # pinned since the closed loop became the default (test_the_closed_loop_is_the_default_at_each_bodys_own_gain)
    old = Creature(snake_case("massspring", 5.0, "gait.shape_control=open_loop", duration=0.1))
    assert old.controller.open_loop and old.controller.tracker is None and old.controller.rate_hz == 0.0
    worm = Creature(resolve_case("worm", "massspring", "flat", duration=0.1))  # no commanded shape: open loop
    assert worm.controller.open_loop and worm.controller.tracker is None


@pytest.mark.parametrize("body, gain", [("massspring", 2.0), ("fem", 0.5), ("hybrid", 0.25)])
def test_the_closed_loop_is_the_default_at_each_bodys_own_gain(body, gain):
    from bench_myriapoda.core import registry

    registry.load_all()
    assert registry.BODIES[body].shape_gain_p == gain
    c = Creature(snake_case(body, 5.0, duration=0.1))
    assert not c.controller.open_loop and c.controller.tracker.kp == gain
    # the key still overrides the body's gain; the sidewinder stays open loop (models/snake.toml says why)
    assert Creature(snake_case(body, 5.0, "gait.shape_gain_p=0.5", duration=0.1)).controller.tracker.kp == 0.5
    side = Creature(resolve_case("snake", body, "flat", "sidewinding", duration=0.1))
    assert side.controller.open_loop and side.controller.tracker is None


def test_smoothing_along_the_body_keeps_the_commanded_wave_and_removes_element_scale_waves():
    from bench_myriapoda.controllers.shape_tracking import SMOOTHING_PASSES, smooth_along_body

    n = 50
    i = np.arange(n)
    for period, low, high in ((50, 0.95, 1.0), (25, 0.85, 0.9), (6, 0.05, 0.15), (4, 0.0, 0.01), (2, 0.0, 1e-9)):
        x = np.cos(2 * math.pi * i / period)
        y = x.copy()
        smooth_along_body(y, SMOOTHING_PASSES, np.zeros(n))
        inner = slice(12, n - 12)  # away from the mirrored ends
        gain = np.max(np.abs(y[inner])) / np.max(np.abs(x[inner]))
        assert low <= gain <= high, (period, gain)


class OldOpenLoop:
    """The open-loop controller before issue 27, written out: the calibrated wave table, filled by chunks."""

    requires = frozenset({MUSCLES})
    open_loop = True
    rate_hz = 0.0

    def __init__(self, case):
        self.case = case

    def reset(self, case, info, rng=None):
        self.waves = wave_table(case.gait, case.creature.body_length_m, strain_per_curvature=info["strain_per_curvature"])
        # the table as the open loop has always built it, written out: a change to wave_table fails here
        g, L = case.gait, case.creature.body_length_m
        k = 2 * math.pi / (g.wavelength_bl * L)
        assert self.waves[1, :4].tolist() == [g.curvature_amplitude * info["strain_per_curvature"], k,
                                              2 * math.pi * g.frequency_hz, math.radians(g.phase_deg)]
        self.s = np.ascontiguousarray(info["muscle_s"], dtype=np.float64)

    def fill(self, t0, dt, n, act):
        act.ensure_rows(n)
        fill_activation(self.waves, self.case.gait.ramp_s, self.s, t0, dt, n, act.muscle)
        act.muscles_on = True

    def step(self, obs, t, act):
        self.fill(t, 0.0, 1, act)


@pytest.mark.parametrize("gait", ["lateral-undulation", "sidewinding"])
def test_the_open_loop_key_reproduces_the_old_controller_bit_for_bit(gait):
    case = resolve_case("snake", "massspring", "flat", gait, duration=1.0,
                        overrides=["gait.shape_control=open_loop", "friction.mu_transverse=0.5"])
    new = run_case(case)
    old = run_case(case, controller=OldOpenLoop(case))
    assert new.status == old.status == "ok"
    for key in ("segment_centers", "com", "energy", "head", "tail"):
        np.testing.assert_array_equal(getattr(new.series, key), getattr(old.series, key), err_msg=key)
    # and the closed loop does change the motion (the two keys are not the same controller)
    closed = run_case(resolve_case("snake", "massspring", "flat", gait, duration=1.0,
                                   overrides=["friction.mu_transverse=0.5", "gait.shape_control=closed_loop"]))
    assert not np.array_equal(closed.series.segment_centers, new.series.segment_centers)
    if gait == "lateral-undulation":  # the default is the closed loop: without the key the motion is not the old one
        default = run_case(resolve_case("snake", "massspring", "flat", gait, duration=1.0,
                                        overrides=["friction.mu_transverse=0.5"]))
        np.testing.assert_array_equal(default.series.segment_centers, closed.series.segment_centers)


def test_open_loop_under_lateral_friction_is_flagged_shape_not_achieved():
    """Issue 27's finding, now measured and said: the open-loop lattice at ratio 5 bends to a fifth."""
    r = slither_for("massspring", 5.0, SUBSET_S, "gait.shape_control=open_loop")
    assert r.metrics["shape_tracking_error"] > 0.5 and r.metrics["shape_not_achieved"] == 1.0
    assert r.message.startswith("shape_not_achieved") and "open-loop" in r.message
    assert r.to_json_dict()["metrics"]["shape_not_achieved"] == 1.0


def test_a_weak_muscle_is_flagged_and_reports_saturation():
    r = slither_for("massspring", 5.0, SUBSET_S, *CLOSED["massspring"], "gait.max_muscle_strain=0.03")
    m = r.metrics
    assert m["shape_not_achieved"] == 1.0 and m["shape_tracking_error"] > SHAPE_ERROR_THRESHOLD
    assert m["muscle_saturation_fraction"] > 0.5 and m["muscle_strain_peak"] == pytest.approx(0.03)
    assert "muscle_saturation_fraction" in r.message
    # the same case at the default strength (0.3) reaches its shape unsaturated: the strength made the difference
    strong = slither_for("massspring", 5.0, SUBSET_S, *CLOSED["massspring"]).metrics
    assert strong["shape_not_achieved"] == 0.0 and strong["muscle_saturation_fraction"] == 0.0


@pytest.mark.parametrize("ratio", [1.0, 5.0])
def test_the_lattice_snake_reaches_the_commanded_shape_and_the_reference_speed(ratio):
    check_tracks_and_moves("massspring", ratio, duration=SUBSET_S)


@pytest.mark.parametrize("ratio", [1.5, 5.0])
def test_the_fem_snake_reaches_the_commanded_shape_and_the_reference_speed(ratio):
    """Ratio 1.5 is the cell the fundamental-only loop missed by 30 % (0.069 against 0.099 BL/cycle); with the third
    harmonic corrected by default it read 0.0926 and shape error 0.054 on this 28.6 s run (~15 CPU s)."""
    check_tracks_and_moves("fem", ratio, SHORT_WARMUP, duration=SHORT_S)


def test_the_hybrid_snake_reaches_the_commanded_shape_and_the_reference_speed():
    check_tracks_and_moves("hybrid", 3.0, SHORT_WARMUP, duration=SHORT_S)


@LONG
@pytest.mark.parametrize("body", BODIES)
@pytest.mark.parametrize("ratio", RATIOS)
def test_every_body_reaches_the_commanded_shape_over_the_friction_grid(body, ratio):
    """The whole grid (scenarios/matrix/slithering.toml) at the defaults: the closed loop with the third harmonic
    corrected at each body's own gain; the waveform's harmonics small too."""
    check_tracks_and_moves(body, ratio, duration=GRID_S)
    assert slither_for(body, ratio, GRID_S, *CLOSED[body]).metrics["shape_harmonic_content"] < 0.05


def test_the_friction_sweep_figure_draws_every_body_against_the_reference(tmp_path):
    from bench_myriapoda.report import friction_sweep

    rows = []
    for body, speeds in (("massspring", (0.0, 0.17, 0.39)), ("fem", (0.0, 0.16, 0.001))):
        for ratio, v in zip((1.0, 2.0, 5.0), speeds):
            case = snake_case(body, ratio)
            rows.append({"creature": "snake", "body": body, "status": "ok", "case_json": json.dumps(case.to_dict()),
                         "grid.friction.mu_transverse": ratio * MU_F, "metric.speed_bl_per_cycle": v,
                         "metric.shape_not_achieved": float(v == 0.001)})
    df = pd.DataFrame(rows)
    assert friction_sweep.has_friction_sweep(df, ["friction.mu_transverse"])
    assert not friction_sweep.has_friction_sweep(df, ["dt"])
    cases = friction_sweep.sweep_cases(df)
    assert sorted(set(cases["ratio"].round(9))) == [1.0, 2.0, 5.0]
    path = friction_sweep.plot_speed_vs_friction_ratio(df, tmp_path / "sweep.png")
    assert path.exists() and path.stat().st_size > 10_000


def harmonic_loop(lead_deg: float, plant_lag_deg: float, gain_per_cycle: float, cycles: int = 25,
                  disturbance: float = 0.3, h: int = 3) -> np.ndarray:
    """The tracker on a model plant: each segment's measured strain-equivalent curvature is its command, delayed by
    plant_lag_deg at h times the wave frequency, plus a disturbance of amplitude ``disturbance`` at harmonic h (the
    shape's third harmonic that Coulomb friction adds).  Returns the largest RMS shape error [strain] of each cycle."""
    f, rate, n = 0.14, 50.0, 12
    omega, dt = 2 * math.pi * f, 1 / rate
    s = np.linspace(0.1, 2.4, n)
    k = 2 * math.pi / 2.5
    waves = np.zeros((3, 5))
    waves[1, :4] = (1.0, k, omega, 0.0)
    delay = int(round(math.radians(plant_lag_deg) / (h * omega) / dt))
    lead = math.radians(lead_deg)
    gains = tuple(TrackGains(ramp_s=0.0, dt_tick=dt, strain_per_kappa=1.0, kp=0.0, ki=2.0 * f, umax=10.0, passes=0,
                             harmonics=np.array([h], dtype=np.int64), ki_h=np.array([gain_per_cycle * f]),
                             lead_cos=np.array([math.cos(lead)]), lead_sin=np.array([math.sin(lead)])))
    state = TrackState(np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(3), np.zeros(n), np.zeros(n),
                       np.zeros((1, n)), np.zeros((1, n)))
    past = [np.zeros(n)] * (delay + 1)
    per_cycle = int(round(rate / f))
    worst = np.zeros(cycles)
    for tick in range(cycles * per_cycle):
        t = tick * dt
        theta = k * s - omega * t
        measured = past[0] + disturbance * np.sin(h * theta)
        track_tick(measured, s, waves, t, False, gains, tuple(state))
        past = past[1:] + [state.lateral.copy()]
        worst[tick // per_cycle] = max(worst[tick // per_cycle], float(np.sqrt(np.mean((np.sin(theta) - measured) ** 2))))
    return worst


def test_the_harmonic_correction_removes_a_third_harmonic_and_its_lead_keeps_a_lagging_plant_stable():
    """Step 3b of controllers/shape_tracking.py on a model plant: the correction at 3 omega removes a third
    harmonic the plant adds (without it the error stays at the disturbance, 0.3 / sqrt(2)); a plant lagging
    120 degrees at 3 omega makes the uncompensated correction diverge (to the muscle's limit), and a lead equal
    to the lag makes it converge again."""
    off = harmonic_loop(0.0, 0.0, 0.0)
    assert off[-1] == pytest.approx(0.3 / math.sqrt(2), rel=0.05)
    assert harmonic_loop(0.0, 0.0, 1.0)[-1] < 0.01
    assert harmonic_loop(0.0, 30.0, 1.0)[-1] < 0.01
    assert harmonic_loop(0.0, 120.0, 1.0)[-1] > 1.0
    assert harmonic_loop(120.0, 120.0, 1.0)[-1] < 0.01


NO_HARMONIC_CORRECTION = "gait.shape_harmonic_gain_per_cycle=0"  # the loop before the correction became the default
HARMONIC_CORRECTION = ("gait.shape_harmonics=[3]", "gait.shape_harmonic_gain_per_cycle=1",
                       "gait.shape_harmonic_lead_deg=90")
# Each body's own setting, the default since issue 27's last step (BodySpec.shape_harmonic_gain_per_cycle): the hybrid
# at gain 1 missed its shape at mu_t / mu_f = 1 (shape_tracking_error 0.153, the harmonic content still falling after
# 11 cycles); at 0.5 it holds it (0.058) and still reaches the reference at 1.5 (0.0960 against 0.0989 BL/cycle)
GRID_HARMONIC_CORRECTION = {"massspring": HARMONIC_CORRECTION, "fem": HARMONIC_CORRECTION,
                            "hybrid": ("gait.shape_harmonics=[3]", "gait.shape_harmonic_gain_per_cycle=0.5",
                                       "gait.shape_harmonic_lead_deg=90")}


def test_the_third_harmonic_correction_makes_the_lattice_snake_follow_the_commanded_waveform():
    """At mu_t / mu_f = 1.5 Coulomb friction bends the lattice snake with the wave's third and fifth harmonics in
    time (``shape_harmonic_content`` 0.087 over the 3 steady cycles of a 43 s run); the correction of the third
    harmonic at a 90 degree lead halves it (0.053) and the shape error with it (0.067 -> 0.051), unsaturated.
    ~8 CPU s a run."""
    plain = slither_for("massspring", 1.5, DURATION_S, NO_HARMONIC_CORRECTION).metrics
    fixed = slither_for("massspring", 1.5, DURATION_S, *HARMONIC_CORRECTION).metrics
    assert plain["shape_harmonic_content"] > 0.075
    assert fixed["shape_harmonic_content"] < 0.065
    assert fixed["shape_harmonic_content"] < 0.75 * plain["shape_harmonic_content"]
    assert fixed["shape_tracking_error"] < plain["shape_tracking_error"]
    assert fixed["muscle_saturation_fraction"] == 0.0


@pytest.mark.parametrize("body, gain", [("massspring", 1.0), ("fem", 1.0), ("hybrid", 0.5)])
def test_the_harmonic_correction_is_the_default_at_each_bodys_own_gain(body, gain):
    """The default closed loop corrects the third harmonic at the body's own gain (``BodySpec``) and a 90 degree
    lead: the tracker of a default case is the tracker of the case with the grid's explicit keys, and
    ``gait.shape_harmonic_gain_per_cycle=0`` switches the correction off."""
    from bench_myriapoda.core import registry
    from bench_myriapoda.harness.calibration import calibrated_body_info

    registry.load_all()
    assert registry.BODIES[body].shape_harmonic_gain_per_cycle == gain

    def tracker(*extra):
        c = Creature(snake_case(body, 1.5, *extra, duration=0.1))
        c.controller.reset(c.case, calibrated_body_info(c.body, c.case, c.world))
        return c.controller.tracker

    default, explicit, off = tracker(), tracker(*GRID_HARMONIC_CORRECTION[body]), tracker(NO_HARMONIC_CORRECTION)
    f = 0.140071
    assert default.harmonics.tolist() == [3] and default.ki_h.tolist() == [gain * f]
    assert default.lead_cos == pytest.approx([0.0], abs=1e-15) and default.lead_sin.tolist() == [1.0]
    for a, b in zip(default.gains, explicit.gains):
        np.testing.assert_array_equal(a, b)
    assert off.harmonics.shape == (0,) and off.ki_h.shape == (0,)
