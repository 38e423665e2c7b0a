"""The runner builds a run's world once (issue 30 item 1).

The terrain (obstacles included), the food sources and the water's bed are built from the scenario in one
place, ``world.world.build_world``, and handed to the body, the controller and the metrics.  Every way of
building a terrain from a scenario goes through ``world.terrain._base_terrain``, and every way of placing food
through ``world.food.food_sources``: counted across ``run_case`` for a legless creature among obstacles, a
legged one with food, and a legged one in water with food, each must run exactly once.  The world's terrain
array is shared by everything in the run, so nothing may write to it: its bytes after the run are those it
was built with.
"""
from __future__ import annotations

import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import Creature, run_case
from bench_myriapoda.world import food, terrain
from bench_myriapoda.world.world import World, build_world

CYLINDERS_SMALL = ["scenario.obstacle_region_m=[0.3,3.0,-1.0,1.0]", "scenario.obstacle_radius_m=[0.02,0.05]",
                   "scenario.obstacle_height_m=[0.05,0.1]", "scenario.obstacle_clear_radius_m=0.3",
                   "scenario.start_height_m=0.0"]

CASES = {
    # legless, among obstacles: the body, the muscle-wave controller, the behaviour and posture metrics
    "worm-cylinders": ("worm", "massspring", "fig13-cylinders", "rectilinear", CYLINDERS_SMALL),
    # legged with food: the leg controller (its terrain and food), the legged monitor
    "centipede-foraging": ("centipede", "hybrid", "foraging", None, []),
    # legged in water with food: the water's bed as well
    "centipede-water": ("centipede", "massspring", "fig12-water-foraging", None, []),
}


class Builds:
    """Counts the terrain and food builds and keeps every terrain built (kind, f, a copy of f's bytes)."""

    def __init__(self, monkeypatch):
        self.terrains, self.food, self.built = 0, 0, []
        base, sources, full = terrain._base_terrain, food.food_sources, terrain.terrain_from_scenario

        def counted_base(sc):
            self.terrains += 1
            return base(sc)

        def counted_food(*args, **kwargs):
            self.food += 1
            return sources(*args, **kwargs)

        def kept(sc):
            kind, f = full(sc)
            self.built.append((f, f.tobytes()))
            return kind, f

        monkeypatch.setattr(terrain, "_base_terrain", counted_base)
        monkeypatch.setattr(food, "food_sources", counted_food)
        monkeypatch.setattr(terrain, "terrain_from_scenario", kept)


@pytest.mark.parametrize("name", list(CASES))
def test_a_run_builds_its_world_once(name, monkeypatch):
    creature, body, scenario, gait, overrides = CASES[name]
    case = resolve_case(creature, body, scenario, gait, duration=0.1, overrides=overrides)
    builds = Builds(monkeypatch)
    r = run_case(case)
    assert r.status == "ok", r.message
    assert builds.terrains == 1, f"the terrain was built {builds.terrains} times in one run"
    assert builds.food == 1, f"the food sources were placed {builds.food} times in one run"
    assert len(builds.built) == 1
    f, before = builds.built[0]
    assert f.tobytes() == before, "the world's terrain array was written to during the run"
    if case.scenario.water_depth_m > 0:
        assert r.metrics["wake_energy"] >= 0.0


def test_the_creature_hands_its_world_to_the_body_and_the_controller():
    """One world object: the body's and the controller's terrain arrays are the world's, not equal copies."""
    case = resolve_case("centipede", "fem", "foraging", duration=0.1)
    world = build_world(case)
    cr = Creature(case, world=world)
    assert cr.world is world and cr.body.world is world and cr.controller.world is world
    assert cr.body.terr is world.terr and cr.controller.terr is world.terr
    assert len(cr.controller.food) == len(world.food) > 0


def test_a_world_is_frozen():
    case = resolve_case("worm", "massspring", "fig13-cylinders", "rectilinear", overrides=CYLINDERS_SMALL)
    world = World.from_case(case)
    with pytest.raises(AttributeError):
        world.terr = np.zeros(3)
    kind, f = world.terrain
    assert kind == world.terr_kind and f is world.terr and world.has_water is False
