"""Bodies in the scenario's shallow water: feet and nodes make ripples, a wake forms behind, volume is kept."""
from __future__ import annotations

import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.report.animate import FrameRecorder

WATER = ["scenario.water_depth_m=0.05", "scenario.water_region_m=[-12.0, 8.0, -5.0, 5.0]",
         "scenario.water_cell_m=0.1"]


@pytest.fixture(scope="module")
def centipede_in_water():
    case = resolve_case("centipede", "hybrid", "walk", duration=3.0, overrides=["creature.segments=6", *WATER])
    rec = FrameRecorder(1)
    volumes, couplings = [], []

    def hook(t, body, water):
        rec(t, body, water)
        volumes.append(water.water.volume())
        couplings[:] = [water]

    result = run_case(case, on_sample=hook)
    return result, rec, volumes, couplings[0]


def coupling_estimate(run) -> float:
    return run[3].energy[-1]


def test_feet_make_a_wake_behind_the_walking_centipede(centipede_in_water):
    result, rec, volumes, _ = centipede_in_water
    assert result.status == "ok", result.message
    m = result.metrics
    assert m["wake_energy"] > 0 and m["wake_energy_max"] > 0
    # the sampled estimate (2 x potential energy) agrees with the exact energy at the end within a factor 2
    assert 0.5 < coupling_estimate(centipede_in_water) / m["wake_energy"] < 2.0
    assert m["water_points_submerged_mean"] > 6  # most of the 12 feet are in the water at any time
    # volume: the feet move water, they never create or destroy it
    assert max(volumes) - min(volumes) < 1e-9 * volumes[0]
    # the wake lies behind: the creature (about 1 m/s) outruns the ripples (sqrt(g d) = 0.7 m/s), so the
    # water well ahead of the head is still, the water behind it is not
    surface = rec.water_frames[-1].astype(float)
    x0, x1, z0, z1 = rec.water_region
    xs = np.linspace(x0, x1, surface.shape[0], endpoint=False) + 0.5 * (x1 - x0) / surface.shape[0]
    head_x = float(result.series.head[-1, 0])
    tail_x = float(result.series.tail[-1, 0])
    ahead = np.mean(surface[xs > head_x + 2.0] ** 2)
    behind = np.mean(surface[(xs > tail_x) & (xs < head_x)] ** 2)
    assert behind > 0 and ahead < 0.02 * behind


def test_a_worm_pushes_water_with_its_body():
    case = resolve_case("worm", "massspring", "flat", duration=2.0,
                        overrides=["scenario.water_depth_m=0.01", "scenario.water_region_m=[-1.0, 1.0, -0.5, 0.5]",
                                   "scenario.water_cell_m=0.01", "scenario.water_point_radius_m=0.005"])
    result = run_case(case)
    assert result.status == "ok"
    assert result.metrics["wake_energy_max"] > 0 and result.metrics["water_points_submerged_mean"] > 0
    assert "water_s" in result.timings


def test_no_water_no_wake_metrics():
    result = run_case(resolve_case("worm", "massspring", "flat", duration=0.2))
    assert "wake_energy" not in result.metrics and "water_s" not in result.timings
