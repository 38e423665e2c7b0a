"""``validate``'s kinematic-shortcut checks (``validation.shortcut``) on constructed runs: the measured value
is the head path deviation in body lengths, the figures the speed ratio, undulations and leg-state agreement."""
import math
from types import SimpleNamespace

import numpy as np
import pytest

from bench_myriapoda.core import registry
from bench_myriapoda.validation import shortcut as SC
from bench_myriapoda.validation.core import INFO


def fake_run(head_x, head_z, states, speed, undulation, status="ok"):
    t = np.arange(len(head_x)) * 0.1
    head = np.stack([head_x, np.ones_like(head_x), head_z], axis=1)
    return SimpleNamespace(status=status, series=SimpleNamespace(t=t, head=head),
                           extra={"leg_timeline": (t, np.asarray(states), None)},
                           metrics={"body_length_m": 25.0, "speed_m_per_s": speed,
                                    "undulation_amplitude_bl": undulation})


class FakeContext:
    quick = True

    def __init__(self, kin, dyn):
        self.runs = {(): kin, SC.DYNAMIC: dyn}

    def run(self, creature, body, scenario, duration=None, overrides=()):
        assert scenario == SC.SCENARIO and duration == 4.0
        return self.runs[tuple(overrides)]


def test_the_check_measures_the_head_path_deviation_in_body_lengths():
    x = np.linspace(0.0, 2.0, 41)
    kin = fake_run(x, np.zeros(41), np.zeros((41, 4), np.int8), 0.5, 0.001)
    states = np.zeros((41, 4), np.int8)
    states[:10, 0] = 4   # a quarter of one leg's rows differ
    dyn = fake_run(0.5 * x, np.full(41, 0.3), states, 0.25, 0.003)
    out = SC.centipede_shortcut(FakeContext(kin, dyn), "hybrid")
    assert out.verdict == INFO and out.unit == "BL"
    assert out.measured == pytest.approx(math.hypot(1.0, 0.3) / 25.0, rel=1e-6)   # at the last sample
    f = out.figures
    assert f["speed_ratio_dynamic_over_kinematic"] == pytest.approx(0.5)
    assert f["undulation_difference_bl"] == pytest.approx(0.002)
    assert f["leg_state_agreement"] == pytest.approx(1.0 - 10 / (41 * 4))


def test_a_failed_dynamic_run_is_a_failed_row():
    x = np.linspace(0.0, 2.0, 41)
    kin = fake_run(x, np.zeros(41), np.zeros((41, 2), np.int8), 0.5, 0.0)
    dyn = fake_run(x, np.zeros(41), np.zeros((41, 2), np.int8), 0.5, 0.0, status="unstable")
    dyn.message = "runaway speed"
    dyn.metrics["t_fail_s"] = 1.0
    out = SC.millipede_shortcut(FakeContext(kin, dyn), "massspring")
    assert out.verdict == "FAIL"


def test_every_legged_body_runs_the_checks_fem_too():
    # (this replaced the test that fem did not run them: fem has a dynamic stance now, bodies/fem/pushed_blocks.py)
    registry.load_all()
    for name in ("paper.kinematic-shortcut-centipede", "paper.kinematic-shortcut-millipede"):
        for body in ("hybrid", "massspring", "fem"):
            assert registry.BODIES[body].checks.get(name) is True, (name, body)   # in validate --quick
    name = "paper.kinematic-shortcut-worlds"   # every scenario: the full validate only (minutes a body)
    for body in ("hybrid", "massspring", "fem"):
        assert registry.BODIES[body].checks.get(name) is False, (name, body)


class WorldsContext:
    """Each world's kinematic and dynamic walks, given; records what was asked."""

    quick = True

    def __init__(self, runs):
        self.runs, self.asked = runs, []

    def run(self, creature, body, scenario, duration=None, overrides=()):
        assert creature == "centipede" and duration == SC.WORLDS_QUICK_S
        self.asked.append((scenario, tuple(overrides)))
        return self.runs[(scenario, tuple(overrides))]


def _worlds(deviation_m, failing=None):
    """Straight kinematic walks, and dynamic ones whose heads end deviation_m[world] to the side; ``failing``:
    a world whose dynamic walk blows up."""
    x = np.linspace(0.0, 2.0, 41)
    states = np.zeros((41, 4), np.int8)
    runs = {}
    for w in SC.WORLDS:
        runs[(w, ())] = fake_run(x, np.zeros(41), states, 0.5, 0.001)
        dyn = fake_run(x, np.linspace(0.0, deviation_m[w], 41), states, 0.4, 0.002,
                       status="unstable" if w == failing else "ok")
        dyn.message, dyn.metrics["t_fail_s"] = "runaway speed", 1.0
        runs[(w, SC.DYNAMIC)] = dyn
    return runs


def test_the_worlds_check_takes_the_largest_deviation_over_every_myriapod_scenario():
    dev = {w: 0.1 * (i + 1) for i, w in enumerate(SC.WORLDS)}
    ctx = WorldsContext(_worlds(dev))
    out = SC.worlds_shortcut(ctx, "massspring")
    assert {s for s, _ in ctx.asked} == set(SC.WORLDS) and len(ctx.asked) == 2 * len(SC.WORLDS)
    assert out.verdict == INFO and out.unit == "BL"
    last = SC.WORLDS[-1]
    assert out.measured == pytest.approx(dev[last] / 25.0)
    for w in SC.WORLDS:
        assert out.figures[f"{w}_deviation_bl"] == pytest.approx(dev[w] / 25.0)
        assert out.figures[f"{w}_speed_ratio"] == pytest.approx(0.8)
        assert out.figures[f"{w}_leg_state_agreement"] == 1.0
    assert last in out.detail


def test_a_world_that_fails_is_named_and_left_out_and_all_failing_is_a_failed_row():
    dev = {w: 0.1 for w in SC.WORLDS}
    dev["terrain"] = 5.0
    out = SC.worlds_shortcut(WorldsContext(_worlds(dev, failing="terrain")), "hybrid")
    assert out.verdict == INFO and out.measured == pytest.approx(0.1 / 25.0)
    assert "terrain (dynamic: unstable)" in out.detail
    assert math.isnan(out.figures["terrain_deviation_bl"])
    runs = _worlds(dev)
    for w in SC.WORLDS:
        runs[(w, ())].status = "unstable"
        runs[(w, ())].message, runs[(w, ())].metrics["t_fail_s"] = "blew up", 0.5
    assert SC.worlds_shortcut(WorldsContext(runs), "fem").verdict == "FAIL"
