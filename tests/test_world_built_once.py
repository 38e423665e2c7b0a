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

import ast
from pathlib import Path

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


# --------------------------------------------------------------------------- statically: who builds a world (issue 42)

PACKAGE = Path(__file__).resolve().parents[1] / "bench_myriapoda"

# What builds (part of) a world from a scenario: the world's constructors, the terrain and food builders and the
# placement check that returns the world it built.  ``World.without_ground`` derives a world and
# ``World.placement_terrain`` reads one; neither is listed.
WORLD_BUILDERS = {"build_world", "world_from_sections", "world_of", "terrain_from_scenario", "placement_terrain",
                  "food_sources", "random_cylinders", "_base_terrain", "check_placements"}

# The owners outside ``world/``, each the one place of its kind (a new one fails the test, and a listed one that
# is gone fails it too):
WORLD_OWNERS = {
    # a run's world, when its caller gives none (``run_world``: ``run_case``, ``Creature``, ``build_body``,
    # ``find_stable_dt``): one per run
    ("bench_myriapoda.harness.runner", "build_world"),
    # the CLI's pre-run placement check builds the case's world and hands it to the run and its animation
    ("bench_myriapoda.cli.case_flags", "check_placements"),
    # the report: one world per stored case (``MatrixResults.world``), handed to every plot of the case
    ("bench_myriapoda.report.matrix_data", "world_from_sections"),
    # the leg controller set up alone (a script, a test); the runner hands it the run's world before its reset.
    # Issue 42: a controller spec that always receives the world removes it.
    ("bench_myriapoda.controllers.myriapod.controller", "world_of"),
}


def world_builds_in(tree: ast.AST) -> set[str]:
    """The ``WORLD_BUILDERS`` names that ``tree`` imports, names or calls as an attribute (``terrain.X``), and
    ``placement_terrain`` only where it is not a world's method (``world.placement_terrain()``)."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            found |= {a.name for a in node.names if a.name in WORLD_BUILDERS}
        elif isinstance(node, ast.Name) and node.id in WORLD_BUILDERS:
            found.add(node.id)
        elif isinstance(node, ast.Attribute) and node.attr in WORLD_BUILDERS:
            if node.attr == "placement_terrain" and not (isinstance(node.value, ast.Name)
                                                         and node.value.id in ("terrain", "_terrain")):
                continue
            found.add(node.attr)
        elif isinstance(node, ast.Attribute) and node.attr == "from_case" and isinstance(node.value, ast.Name) \
                and node.value.id == "World":
            found.add("World.from_case")
    return found


def world_builds_outside_world() -> set[tuple[str, str]]:
    out = set()
    for p in sorted(PACKAGE.rglob("*.py")):
        rel = p.relative_to(PACKAGE.parent).with_suffix("")
        if rel.parts[1] == "world":
            continue
        module = ".".join(rel.parts[:-1] if rel.parts[-1] == "__init__" else rel.parts)
        out |= {(module, name) for name in world_builds_in(ast.parse(p.read_text(encoding="utf-8")))}
    return out


def test_the_world_build_check_finds_one():
    tree = ast.parse("from ..world.terrain import terrain_from_scenario\nfrom ..world import food\n"
                     "def f(sc, world):\n    world.placement_terrain()\n    return food.food_sources(sc), World.from_case(sc)\n")
    assert world_builds_in(tree) == {"terrain_from_scenario", "food_sources", "World.from_case"}


def test_a_world_is_built_from_a_scenario_only_inside_world():
    found = world_builds_outside_world()
    assert found - WORLD_OWNERS == set(), "a world built from a scenario outside world/: " + repr(sorted(found - WORLD_OWNERS))
    assert WORLD_OWNERS - found == set(), "gone: remove from WORLD_OWNERS: " + repr(sorted(WORLD_OWNERS - found))


def test_every_body_factory_receives_the_world_no_signature_is_read():
    """No module reads a callable's signature to decide what to pass it (``inspect.signature``: the old
    ``takes_world``); a body factory is always called ``factory(case, world)``.  The one reader left records
    numba kernels' argument names for the compile plans (``jit.compile_plan``)."""
    bad = {str(p.relative_to(PACKAGE)) for p in PACKAGE.rglob("*.py") if "inspect.signature(" in p.read_text(encoding="utf-8")}
    assert bad == {"jit/compile_plan.py"}, f"signature sniffing in {sorted(bad)}"


# --------------------------------------------------------------------------- the commands: one build per run (issue 42)

@pytest.fixture
def build_log(monkeypatch, tmp_path):
    """Counts world builds in this process and in every worker process (``tests/world_build_counter.py``, read as
    a plugin module by each process's ``registry.load_all``); yields the log's path."""
    from bench_myriapoda.core import registry

    log = tmp_path / "builds.log"
    monkeypatch.setenv("WORLD_BUILD_LOG", str(log))
    monkeypatch.setenv(registry.PLUGINS_ENV, "world_build_counter")
    import world_build_counter

    world_build_counter.install()
    try:
        yield log
    finally:
        world_build_counter.uninstall()


MATRIX_TOML = """[matrix]
name = "worlds"
seeds = [0]

[[block]]
creatures = ["worm"]
bodies = ["massspring"]
gaits = ["rectilinear"]
scenarios = ["fig13-cylinders"]
duration = 0.1
set = { "scenario.obstacle_region_m" = [0.3, 3.0, -1.0, 1.0], "scenario.obstacle_radius_m" = [0.02, 0.05], "scenario.obstacle_height_m" = [0.05, 0.1], "scenario.obstacle_clear_radius_m" = 0.3, "scenario.start_height_m" = 0.0 }

[[block]]
creatures = ["centipede"]
bodies = ["hybrid"]
scenarios = ["foraging"]
duration = 0.1
"""


def test_the_matrix_and_its_report_build_each_cases_world_once(build_log, tmp_path, capsys):
    """``matrix`` (its cases run in worker processes): one world per case; ``report`` on its directory: one world
    per case it draws (from above and from the side, in several sections), none more."""
    from world_build_counter import counts

    from bench_myriapoda.cli import main

    matrix, out = tmp_path / "worlds.toml", tmp_path / "out"
    matrix.write_text(MATRIX_TOML)
    assert main(["matrix", str(matrix), "--workers", "1", "--out", str(out)]) == 0, capsys.readouterr().err
    assert counts(build_log) == {"terrain": 2, "food": 2}, "matrix: two cases, each world built once"
    build_log.unlink()
    assert main(["report", str(out)]) == 0, capsys.readouterr().err
    drawn = counts(build_log)
    assert 1 <= drawn["terrain"] <= 2, f"report: {drawn['terrain']} terrains built for 2 cases"
    assert drawn["food"] == drawn["terrain"]


def test_validate_builds_one_world_per_run(build_log, monkeypatch, tmp_path, capsys):
    """``validate``: the stable-dt check runs its lattice at many time steps in one world, built once (and the
    body it measures omega_max of lives in it)."""
    from world_build_counter import counts

    from bench_myriapoda.cli import main
    from bench_myriapoda.harness import stable_dt

    runs = []
    original = stable_dt.run_case

    def counted_run(case, *args, **kwargs):
        runs.append(kwargs.get("world"))
        return original(case, *args, **kwargs)

    monkeypatch.setattr(stable_dt, "run_case", counted_run)
    code = main(["validate", "--quick", "--check", "analytic.stable-dt", "--body", "massspring", "--json", "--no-store",
                 "--out", str(tmp_path)])
    assert code in (0, 1), capsys.readouterr().err
    assert len(runs) >= 3 and all(w is runs[0] for w in runs), "the stable-dt trials share one world"
    assert counts(build_log) == {"terrain": 1, "food": 1}
