"""A named gait added in one file and one table row (issue 30, item 6): its own configuration class and its
controller here, its ``GaitSpec`` row in ``GAITS`` below, read through ``BENCH_MYRIAPODA_PLUGINS``; it runs
on all three body models with no change to any file of the package.

``standing-wave``: the body bends sideways in place, a standing wave of LATERAL strain
``amplitude * sin(pi s / L) * sin(2 pi f t)`` (s the rest arc length from the head, L the body length);
``nodes`` (a key of its own) adds nodes to the standing wave: ``sin((nodes + 1) pi s / L)``.
"""
from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from bench_myriapoda.core import registry
from bench_myriapoda.core.protocols import LATERAL, MUSCLES, Actuation, Observation
from bench_myriapoda.core.schema import GaitConfig, rng
from bench_myriapoda.core.specs import GaitSpec

NAME = "standing-wave"
MODULE = "test_named_gait"
ROOT = Path(__file__).resolve().parents[1]


@dataclass(frozen=True)
class StandingWaveConfig(GaitConfig):
    """``[gaits.standing-wave]``: GaitConfig's keys (amplitude, frequency_hz, ramp_s, ...) and its own."""

    nodes: int = rng(0, ge=0, le=8, doc="nodes of the standing wave between the ends")


class StandingWaveController:
    """Open loop: fills the LATERAL channel of every muscle segment with the standing wave (module docstring)."""

    requires = frozenset({MUSCLES})
    open_loop = True
    rate_hz = 0.0

    def __init__(self, case):
        g = case.gait
        self.amplitude, self.omega = float(g.amplitude), 2.0 * np.pi * float(g.frequency_hz)
        self.k = (int(g.nodes) + 1) * np.pi / case.creature.body_length_m
        self.ramp_s = float(g.ramp_s)
        self.shape = np.zeros(0)

    def reset(self, case, body_info, rng=None) -> None:
        self.shape = self.amplitude * np.sin(self.k * np.asarray(body_info["muscle_s"], float))

    def fill(self, t0: float, dt: float, n_steps: int, act: Actuation) -> None:
        act.ensure_rows(n_steps)
        t = t0 + np.arange(n_steps) * dt
        ramp = np.clip(t / self.ramp_s, 0.0, 1.0) if self.ramp_s > 0 else np.ones_like(t)
        act.muscle[:n_steps] = 0.0
        act.muscle[:n_steps, :, LATERAL] = (ramp * np.sin(self.omega * t))[:, None] * self.shape[None, :]
        act.muscles_on = True

    def step(self, obs: Observation, t: float, act: Actuation) -> None:
        self.fill(t, 0.0, 1, act)


# The one table row.
GAITS = {NAME: GaitSpec(name=NAME, description="a standing wave of lateral bending (tests/test_named_gait.py)",
                        requires=frozenset({MUSCLES}), controller=StandingWaveController,
                        config_cls=StandingWaveConfig)}


@pytest.fixture
def plugin(monkeypatch):
    monkeypatch.setenv(registry.PLUGINS_ENV, MODULE)
    registry.load_all()
    assert registry.GAITS[NAME] is sys.modules[MODULE].GAITS[NAME]
    yield
    registry.GAITS.pop(NAME, None)


@pytest.fixture
def creature(tmp_path):
    """The worm with the new gait among its gaits and a table of its keys (a creature file of the test's own)."""
    text = (ROOT / "models" / "worm.toml").read_text()
    text = text.replace('gaits = ["rectilinear"]', f'gaits = ["rectilinear", "{NAME}"]')
    text += f'\n[gaits.{NAME}]\namplitude = 0.1\nfrequency_hz = 1.0\nramp_s = 0.2\nnodes = 1\n'
    path = tmp_path / "worm-standing.toml"
    path.write_text(text)
    return str(path)


@pytest.mark.parametrize("body", ["massspring", "fem", "hybrid"])
def test_a_named_gait_in_one_file_runs_on_every_body(plugin, creature, body):
    from bench_myriapoda import api
    res = api.run(creature, body, "flat", NAME, duration=1.0, set={f"gait.nodes": 1})
    assert res.status == "ok", res.message
    assert type(res.case.gait) is StandingWaveConfig and res.case.gait.nodes == 1
    assert res.case.gait.amplitude == 0.1  # the creature file's [gaits.standing-wave] table
    # the body bends sideways: the segment centres leave the straight line they started on
    z = res.series.segment_centers[:, :, 2]
    assert np.ptp(z[0]) < 1e-6 and np.max(np.ptp(z, axis=1)) > 1e-3


def test_a_named_gaits_own_keys_are_checked(plugin, creature):
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.core.errors import InputError
    with pytest.raises(InputError, match="gait.nodes"):
        resolve_case(creature, "massspring", "flat", NAME, overrides=["gait.nodes=99"])


class DeclaredOnly:
    """The paper's leg controller seen only through what a controller declares to the runner
    (``core.protocols.Controller``) and a legged one to the harness (``core.leg_timeline.LeggedController``):
    any other attribute read raises, so a harness or metric that reads the controller's internals fails."""

    def __init__(self, inner):
        from bench_myriapoda.core.leg_timeline import LeggedController
        from bench_myriapoda.core.protocols import Controller
        allowed = set()
        for proto in (Controller, LeggedController):
            allowed |= set(proto.__annotations__) | {n for n in vars(proto) if not n.startswith("_")}
        object.__setattr__(self, "inner", inner)
        object.__setattr__(self, "allowed", frozenset(allowed))

    def __getattr__(self, name):
        if name.startswith("__") or name not in self.allowed:
            raise AttributeError(f"read of the controller's undeclared attribute {name!r}")
        return getattr(self.inner, name)


def test_a_legged_run_reads_the_controller_only_through_the_declared_records():
    from bench_myriapoda.controllers.myriapod.controller import MyriapodController
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.harness.runner import run_case
    case = resolve_case("centipede", "hybrid", "walk", duration=2.0, overrides=["creature.segments=4"])
    seen = run_case(case, controller=DeclaredOnly(MyriapodController(case)))
    bare = run_case(case, controller=MyriapodController(case))
    assert seen.status == bare.status == "ok", (seen.message, bare.message)
    assert len(seen.extra["leg_timeline"][0]) > 2 and "time_to_walk_s" in seen.metrics
    # the same run: the timeline and every metric bit for bit (the bare one runs the fused path, which
    # tests/test_fused_walk.py holds bitwise equal to the Python path the wrapped one runs)
    for a, b in zip(seen.extra["leg_timeline"], bare.extra["leg_timeline"]):
        assert np.array_equal(a, b)
    assert np.array_equal(seen.extra["brain_timeline"], bare.extra["brain_timeline"])
    assert seen.extra["labels"] == bare.extra["labels"]
    assert seen.metrics.keys() == bare.metrics.keys()
    for k, v in seen.metrics.items():
        assert v == bare.metrics[k] or (np.isnan(v) and np.isnan(bare.metrics[k])), k
