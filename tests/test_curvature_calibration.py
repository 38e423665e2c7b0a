"""Each body's strain-per-curvature gain (bodies/curvature_calibration.py), the mirror-symmetric FEM
mesh, and the FEM snake at its defaults (issue 11)."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from bench_myriapoda.bodies.curvature_calibration import (CAL_STRAIN, calibration_key, circle_curvature,
                                                          lateral_gain, measure_lateral_gain)
from bench_myriapoda.bodies.fem import mesh as M
from bench_myriapoda.core import registry
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.calibration import calibrated_body_info
from bench_myriapoda.harness.runner import Creature, run_case
from bench_myriapoda.world.world import build_world

LATTICE_GAIN_REL_TOL = 0.02   # the lattice's fibres sit at the corners: kappa = 2 strain / width exactly
FEM_MIN_SPEED_BL_PER_CYCLE = 0.1
FEM_MAX_HEADING_DRIFT_DEG_PER_CYCLE = 2.0


def test_circle_curvature_of_an_arc():
    th = np.linspace(0.2, 1.4, 9)
    pts = np.column_stack([3.0 + 0.5 * np.cos(th), -1.0 + 0.5 * np.sin(th)])
    assert circle_curvature(pts) == pytest.approx(2.0, rel=1e-12)
    assert circle_curvature(np.column_stack([th, 2 * th])) == 0.0


def test_lattice_gain_is_half_the_width_over_the_length(tmp_path, monkeypatch):
    monkeypatch.setenv("BENCH_MYRIAPODA_CACHE", str(tmp_path))
    registry.load_all()
    case = resolve_case("snake", "massspring", "flat", "lateral-undulation")
    res = measure_lateral_gain(registry.BODIES["massspring"].factory, case, build_world(case))
    cre = case.creature
    # a fibre strain a at z = +-w/2 bends the lattice to kappa = 2 a / w: gain = a / (kappa L) = w / (2 L)
    assert res["strain_per_curvature"] == pytest.approx(cre.width_m / (2 * cre.body_length_m),
                                                        rel=LATTICE_GAIN_REL_TOL)
    assert res["curvature_m"] == pytest.approx(2 * CAL_STRAIN / cre.width_m, rel=LATTICE_GAIN_REL_TOL)
    # cached: a second call reads the file, and the key follows what shapes the gain
    g = lateral_gain(registry.BODIES["massspring"].factory, case, build_world(case))
    assert list(tmp_path.rglob("*.json")) and g == pytest.approx(res["strain_per_curvature"], rel=1e-12)
    stiffer = dataclasses.replace(case, body=dataclasses.replace(case.body, stiffness=1.0))
    assert calibration_key(stiffer) != calibration_key(case)
    friction = dataclasses.replace(case, friction=dataclasses.replace(case.friction, mu_transverse=2.0))
    assert calibration_key(friction) == calibration_key(case)  # measured weightless, off the ground


def test_the_controller_gets_the_gain_and_scales_the_command(tmp_path, monkeypatch):
    monkeypatch.setenv("BENCH_MYRIAPODA_CACHE", str(tmp_path))
    case = resolve_case("snake", "massspring", "flat", "lateral-undulation", overrides=["gait.curvature_amplitude=7"])
    c = Creature(case)
    info = calibrated_body_info(c.body, case, c.world)
    from bench_myriapoda.core.protocols import LATERAL
    assert c.controller.waves[LATERAL, 0] == pytest.approx(7 * info["strain_per_curvature"], rel=1e-12)
    raw = resolve_case("snake", "massspring", "flat", "lateral-undulation", overrides=["gait.curvature_amplitude=0"])
    assert Creature(raw).controller.waves[LATERAL, 0] == raw.gait.amplitude


@pytest.mark.parametrize("cells", [(2, 2, 2), (3, 2, 4)])
def test_mirrored_split_is_mirror_symmetric_and_conforming(cells):
    nodes, tets = M.box_grid((0.3, 0.2, 0.4), cells, origin=(0.0, 0.0, -0.2), mirror_z=0.0)
    key = lambda p: tuple(sorted(map(tuple, np.round(p, 12))))  # noqa: E731
    mirrored = nodes * np.array([1.0, 1.0, -1.0])
    assert {key(nodes[t]) for t in tets} == {key(mirrored[t]) for t in tets}
    plain_nodes, plain = M.box_grid((0.3, 0.2, 0.4), cells, origin=(0.0, 0.0, -0.2))
    assert {key(plain_nodes[t]) for t in plain} != {key(mirrored[t]) for t in plain}  # Kuhn alone is not
    assert M.signed_volumes(nodes, tets).min() > 0.0
    f = np.concatenate([tets[:, [1, 2, 3]], tets[:, [0, 2, 3]], tets[:, [0, 1, 3]], tets[:, [0, 1, 2]]])
    _, counts = np.unique(np.sort(f, axis=1), axis=0, return_counts=True)
    nx, ny, nz = cells
    assert counts.max() == 2 and (counts == 1).sum() == 4 * (nx * ny + ny * nz + nx * nz)


@pytest.mark.slow
def test_fem_snake_slithers_straight_at_its_defaults():
    case = resolve_case("snake", "fem", "flat", duration=10.0)
    r = run_case(case)
    assert r.status == "ok", r.message
    assert r.metrics["speed_bl_per_cycle"] >= FEM_MIN_SPEED_BL_PER_CYCLE, r.metrics
    assert abs(r.metrics["heading_drift_deg_per_cycle"]) <= FEM_MAX_HEADING_DRIFT_DEG_PER_CYCLE, r.metrics
