"""The paper's worlds (issue 6) run on every body model, and Miller's gaits run on the new terrains."""
from __future__ import annotations

import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.world.terrain import terrain_from_scenario
from bench_myriapoda.world.terrain_kernels import signed_distance

WORLDS = ("fig1-mesh", "terrain", "fig13-cylinders", "foraging", "fig12-water-foraging")


@pytest.mark.parametrize("body", ["hybrid", "massspring", "fem"])
@pytest.mark.parametrize("scenario", WORLDS)
def test_every_world_runs_on_every_legged_body(scenario, body):
    case = resolve_case("centipede", body, scenario, duration=0.6)
    r = run_case(case)
    assert r.status == "ok", r.message
    m = r.metrics
    # the body starts above the surface and the legs hold it there: no segment centre inside the terrain
    assert m["terrain_clearance_min_m"] > 0.0
    assert m["obstacle_penetration_max_m"] <= 0.0 or m["obstacle_penetration_max_m"] < 0.05
    if scenario == "fig12-water-foraging":
        assert m["wake_energy"] > 0 and m["water_points_submerged_mean"] > 0


def test_centipede_walks_over_the_skull():
    """Fig. 1: on the closed mesh the legs find footholds on the dome and the body follows its curve."""
    case = resolve_case("centipede", "hybrid", "fig1-mesh", duration=3.0)
    r = run_case(case)
    assert r.status == "ok", r.message
    kind, f = terrain_from_scenario(case.scenario)
    s = r.series
    # placed straight over the curved dome, the body settles onto it (ADJUSTMENT); from then on every
    # segment centre stays at standing height over the mesh surface: it neither sinks in nor falls off
    settled = s.segment_centers[s.t >= 1.5][::10]
    phi = np.array([[signed_distance(kind, f, *p) for p in frame] for frame in settled])
    assert phi.min() > 0.5 and phi.max() < 1.5
    # on top of the skull (its dome is about 47 m above the ground plane), and walking forward
    assert s.com[-1, 1] > 40.0
    assert r.metrics["speed_m_per_s"] > 0.3
    # the body bends over the dome: the side view of the segment centres is not a straight line
    c = s.segment_centers[-1]
    line = np.polyfit(c[:, 0], c[:, 1], 1)
    assert np.abs(np.polyval(line, c[:, 0]) - c[:, 1]).max() > 0.2


HEIGHTFIELD_SMALL = ["scenario.heightfield_amplitude_m=[0.0,0.02]", "scenario.heightfield_width_m=[0.1,0.3]",
                     "scenario.heightfield_extent_m=2.0", "scenario.start_height_m=0.0"]
CYLINDERS_SMALL = ["scenario.obstacle_region_m=[0.3,3.0,-1.0,1.0]", "scenario.obstacle_radius_m=[0.02,0.05]",
                   "scenario.obstacle_height_m=[0.05,0.1]", "scenario.obstacle_clear_radius_m=0.3",
                   "scenario.start_height_m=0.0"]


@pytest.mark.parametrize("creature,gait", [("worm", "rectilinear"), ("snake", "lateral-undulation")])
@pytest.mark.parametrize("scenario,overrides", [("terrain", HEIGHTFIELD_SMALL), ("fig13-cylinders", CYLINDERS_SMALL)])
def test_miller_gaits_on_the_new_terrains(creature, gait, scenario, overrides):
    """Worm and snake crawl forward over a Miller-scale height field and among small cylinders."""
    # 4 s: under the 2 steady cycles after which speeds count (metrics.min_steady_cycles, issue 26); pinned to 0
    # here, where the speed only has to show forward motion over the terrain
    case = resolve_case(creature, "massspring", scenario, gait, duration=4.0,
                        overrides=[*overrides, "metrics.min_steady_cycles=0"])
    r = run_case(case)
    assert r.status == "ok", r.message
    assert r.metrics["speed_m_per_s"] > 0.02
    assert r.metrics["max_penetration_m"] < case.stability.max_penetration_m
