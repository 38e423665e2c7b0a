"""Controllers as a layer of their own: every creature on every body model, one interface.

The conformance rows are built from the registry and the creature files, so a new body backend,
creature or gait adds rows by itself."""
from __future__ import annotations

import math
import runpy
import tomllib
from pathlib import Path

import numpy as np
import pytest

from bench_myriapoda.core import registry
from bench_myriapoda.core.config import creature_names, load_creature_file, resolve_case
from bench_myriapoda.core.protocols import MUSCLES, SEGMENTS, Actuation, Body, Controller, Observation
from bench_myriapoda.harness.runner import Creature, run_case

ROOT = Path(__file__).resolve().parents[1]
STANDARD_METRICS = ("speed_m_per_s", "travel_angle_deg", "contact_fraction", "max_penetration_m", "body_length_m",
                    "t_fail_s", "energy_drift_rel")
SCENARIO = {True: "walk", False: "flat"}  # legged creatures walk, the others crawl
CONFORMANCE_S = 0.5


def rows():
    registry.load_all()
    out = []
    for creature in creature_names():
        _, data = load_creature_file(creature)
        legged = data["creature"].get("legs_per_segment", 0) > 0
        scenario = "fig4-drop" if creature == "chain" else SCENARIO[legged]
        for body in sorted(registry.BODIES):
            for gait in data["creature"].get("gaits", []):
                out.append((creature, body, gait, scenario))
    return out


ROWS = rows()


def test_every_creature_runs_on_every_body_with_every_gait():
    registry.load_all()
    pairs = {(c, b) for c, b, _, _ in ROWS}
    assert len(pairs) == len(creature_names()) * len(registry.BODIES) >= 18
    for creature, body, gait, scenario in ROWS:
        resolve_case(creature, body, scenario, gait)  # raises InputError for an unsupported combination


def test_list_json_shows_every_creature_body_pair_with_all_its_gaits(capsys):
    import json
    from bench_myriapoda.cli import main
    assert main(["list", "--json"]) == 0
    listed = {(r["creature"], r["body"], r["gait"]) for r in json.loads(capsys.readouterr().out)["supported"]}
    assert listed == {(c, b, g) for c, b, g, _ in ROWS}
    assert len({(c, b) for c, b, _ in listed}) >= 18


@pytest.mark.parametrize("creature, body, gait, scenario", ROWS, ids=["-".join(r[:3]) for r in ROWS])
def test_conformance(creature, body, gait, scenario):
    case = resolve_case(creature, body, scenario, gait, duration=CONFORMANCE_S)
    c = Creature(case)
    assert isinstance(c.body, Body) and isinstance(c.controller, Controller)
    assert c.controller.requires <= c.body.capabilities
    c.compile()
    # observation shapes as declared (core.protocols.Observation)
    obs = c.body.observe(0.0)
    n = c.body.n_segments
    assert obs.seg_pos.shape == (n, 3) and obs.seg_rot.shape == (n, 3, 3) and obs.seg_vel.shape == (n, 3)
    assert obs.seg_half.shape == (n, 3) and obs.seg_contact.shape == (n,) and obs.seg_contact.dtype == bool
    np.testing.assert_allclose(np.einsum("nji,njk->nik", obs.seg_rot, obs.seg_rot), np.tile(np.eye(3), (n, 1, 1)),
                               atol=1e-9)
    np.testing.assert_allclose(np.linalg.det(obs.seg_rot), 1.0, atol=1e-9)
    assert obs.segment_centers.ndim == 2 and obs.segment_centers.shape[1] == 3
    assert obs.com.shape == (3,) and obs.head.shape == (3,) and obs.energy.shape == (3,)
    assert len(c.body.muscle_s) == c.body.n_muscle_segments
    act = Actuation.for_body(c.body)
    assert act.muscle.shape[1:] == (c.body.n_muscle_segments, 3)
    if SEGMENTS in c.body.capabilities:
        assert act.support_c.shape == (n, 3) and act.support_R.shape == (n, 3, 3)
    # a short run: ok, finite energy, the standard metrics
    res = run_case(case)
    assert res.status == "ok", res.message
    assert np.all(np.isfinite(res.series.energy))
    for key in STANDARD_METRICS:
        assert key in res.metrics, key
    assert res.series.segment_rotations.shape[1:] == (n, 3, 3)


def test_the_muscle_wave_buffer_equals_the_kernel_wave():
    """An open-loop controller's chunk is bitwise the activation a kernel evaluates at t0 + k dt."""
    from bench_myriapoda.controllers.muscle_waves import MuscleWaveController, segment_activation
    from bench_myriapoda.core.protocols import body_info
    case = resolve_case("snake", "massspring", "flat", "sidewinding")
    c = Creature(case)
    ctrl = MuscleWaveController(case)
    ctrl.reset(case, body_info(c.body, case.dt))
    act = Actuation.for_body(c.body)
    ctrl.fill(1.25, case.dt, 7, act)
    out = np.zeros_like(act.muscle[0])
    for k in range(7):
        segment_activation(ctrl.waves, case.gait.ramp_s, c.body.muscle_s, 1.25 + k * case.dt, out)
        np.testing.assert_array_equal(act.muscle[k], out)


def test_a_controller_the_body_cannot_honour_is_an_error_before_the_run():
    class NeedsLegs:
        requires = frozenset({SEGMENTS, "legs"})

        def reset(self, case, info, rng):
            pass

        def step(self, obs, t, act):
            pass

    res = run_case(resolve_case("worm", "massspring", "flat", duration=0.1), controller=NeedsLegs())
    assert res.status == "error" and "cannot honour" in res.message


def _readme_example() -> str:
    # the worked example moved from the README to the controller tutorial (issue 29)
    text = (ROOT / "docs" / "tutorials" / "own-controller.md").read_text(encoding="utf-8")
    start = text.index("<!-- extending-example -->")
    block = text[start:].split("```python\n", 1)[1].split("```", 1)[0]
    return block


def test_the_readme_example_is_the_examples_file():
    assert _readme_example().strip() == (ROOT / "examples" / "speed_controller.py").read_text().strip()


def test_the_readme_worked_example_moves_the_worm_on_all_three_bodies():
    import bench_myriapoda as bm
    ns = runpy.run_path(str(ROOT / "examples" / "speed_controller.py"), run_name="example")
    for body in ("massspring", "fem", "hybrid"):
        ctrl = ns["SpeedController"]()
        # a 6 s run has 1 steady cycle: metrics.min_steady_cycles pinned to 0 so the travel angle is a number
        res = bm.run(creature="worm", body=body, scenario="flat", duration=6.0, controller=ctrl,
                     metrics__min_steady_cycles=0)
        assert res.status == "ok", res.message
        forward = (res.series.com[-1, 0] - res.series.com[0, 0]) / res.metrics["body_length_m"]
        assert forward > 0.1, (body, forward)              # it crawled forward (+x, its heading), in BL
        assert abs(res.metrics["travel_angle_deg"]) < 20   # along its axis
        assert 0.02 <= ctrl.amplitude <= 0.3               # the controller acted within its limits


@pytest.mark.slow
@pytest.mark.parametrize("creature, gait", [("worm", "rectilinear"), ("snake", "lateral-undulation"),
                                            ("caterpillar", "arching")])
def test_legless_creatures_move_forward_on_the_hybrid_body(creature, gait):
    res = run_case(resolve_case(creature, "hybrid", "flat", gait, duration=8.0))
    assert res.status == "ok", res.message
    assert res.metrics["speed_bl_per_cycle"] > 0.01
    assert abs(res.metrics["travel_angle_deg"]) < 30
