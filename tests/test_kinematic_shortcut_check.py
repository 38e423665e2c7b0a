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
