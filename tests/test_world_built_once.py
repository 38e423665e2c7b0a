"""The runner builds a run's world once (issue 30 item 1).

The terrain (obstacles included), the food sources and the water's bed are built from the scenario in one
place, ``world.world.build_world``, and handed to the body, the controller and the metrics; outside a run
too, the CLI's placement check, its animation and the report's plots of a case each build the case's world
once (the tests below the line).  Every way of
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


# --------------------------------------------------------------------------- outside a run: one build per case

def test_the_cli_run_with_its_animation_builds_the_world_once(monkeypatch, tmp_path, capsys):
    """``run --animate``: the pre-run placement check builds the world, the run and the animation use it."""
    from bench_myriapoda.cli import main

    builds = Builds(monkeypatch)
    gif = tmp_path / "worm.gif"
    argv = ["run", "--creature", "worm", "--body", "massspring", "--scenario", "fig13-cylinders", "--gait",
            "rectilinear", "--duration", "0.1", "--no-store", "--animate", str(gif)]
    for kv in CYLINDERS_SMALL:
        argv += ["--set", kv]
    assert main(argv) == 0, capsys.readouterr().err
    assert gif.is_file()
    assert builds.terrains == 1, f"the terrain was built {builds.terrains} times by run --animate"
    assert builds.food == 1, f"the food sources were placed {builds.food} times by run --animate"


def test_the_placement_check_returns_the_world_it_built(monkeypatch):
    from bench_myriapoda.world.buildable import check_placements

    case = resolve_case("centipede", "hybrid", "foraging", duration=0.1)
    builds = Builds(monkeypatch)
    world = check_placements(case, "centipede/hybrid/foraging")
    assert isinstance(world, World) and len(world.food) > 0
    assert (builds.terrains, builds.food) == (1, 1)


def test_a_controller_passed_in_lives_in_the_runs_world(monkeypatch):
    """A controller built alone (no world) and handed to the creature: one build, the controller's world is
    the creature's; one built with a world brings it along."""
    from bench_myriapoda.controllers.myriapod.controller import MyriapodController

    case = resolve_case("centipede", "fem", "foraging", duration=0.1)
    builds = Builds(monkeypatch)
    cr = Creature(case, MyriapodController(case))
    assert (builds.terrains, builds.food) == (1, 1)
    assert cr.controller.world is cr.world and cr.body.world is cr.world
    world = build_world(case)
    builds.terrains = builds.food = 0
    cr = Creature(case, MyriapodController(case, world=world))
    assert (builds.terrains, builds.food) == (0, 0)
    assert cr.world is world and cr.body.world is world


def test_the_reports_plots_of_a_case_draw_its_one_world(monkeypatch, tmp_path):
    """A matrix directory's case is drawn from the side and from above (``report.build``'s paper and trajectory
    sections, each top view twice): its world is built once, from its stored sections, and the plots draw it."""
    import json

    import pandas as pd

    from bench_myriapoda.report.matrix_data import MatrixResults
    from bench_myriapoda.report.series_plots import plot_side_strip
    from bench_myriapoda.report.trajectories import plot_top_views

    case = resolve_case("centipede", "hybrid", "foraging", duration=0.1)
    r = run_case(case)
    assert r.status == "ok", r.message
    d = case.to_dict()
    res = MatrixResults(tmp_path, "m", "", [], pd.DataFrame({"case_hash": ["h"], "case_json": [json.dumps(d)]}), [])
    builds = Builds(monkeypatch)
    plot_side_strip("side", r.series, d["scenario"], tmp_path / "side.png", world=res.world("h"))
    for name in ("top.png", "paper_top.png"):
        plot_top_views([("run", r.series)], tmp_path / name, scenarios=[d["scenario"]], foods=[d["food"]],
                       worlds=[res.world("h")])
    assert (builds.terrains, builds.food) == (1, 1)
    assert np.array_equal(res.world("h").food, build_world(case).food)
