"""The world of one run, built once from the scenario: terrain with its obstacles, food sources, the water's bed.

``build_world(case)`` (or ``World.from_case``) builds it; the runner does so once per run
(``harness.runner.run_world``) and hands the same ``World`` to the body (every body factory is called
``factory(case, world)``), the controller (``controller(case, world=world)`` when its ``GaitSpec`` says
``takes_world``) and the metrics (their ``world`` argument), so no part of a run rebuilds the terrain from
the scenario (issue 30 item 1: the terrain used to be rebuilt in about 13 places, a 10^5-triangle mesh
terrain each time from its cache, random cylinders and food sources redrawn each time; issue 42: bodies,
metrics and plots have no fallback that builds one, and only ``world/`` builds a world from a scenario, a
static test in ``tests/test_world_built_once.py`` names the few owners outside it).  The curvature
calibration (``bodies.curvature_calibration``, on a cache miss) measures a short copy of the body off the
ground: in the run's world less its ground, obstacles and food (``World.without_ground``), derived, not
built.  Outside a run the same rule holds: the CLI builds a case's world once in its pre-run placement check
(``world.buildable``) and hands it to the run and to the animation; the report builds one world per stored
case (``report.matrix_data.MatrixResults.world``) and hands it to every plot of that case.  Only the leg
controller set up alone (a script, a test) still builds its own (``world_of``).

What the world holds does not change during a run (Newton's "model", as against the body's state): the
terrain vector ``terr`` (``terrain_kernels`` layout, obstacles and their grid included) is shared by
everything that queries it and must not be written to (``tests/test_world_built_once.py`` checks it is the
same bytes after a run).  It stays a writable array for numba: a read-only one would compile every kernel
that takes it a second time.  The water's surface is the run's state, in ``water_coupling.WaterCoupling``;
the world holds its bed (the terrain) and whether there is water at all.
"""
from __future__ import annotations

from collections import namedtuple
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from . import food as _food
from . import terrain as _terrain


# The world as a body's step reads it (issue 42 item 2: each body's step takes the world as a plain argument,
# ``step(..., world, dt, n_steps)``, handed to it by whoever runs it, never held in the body's own parameters):
# gravity (3,) [m/s^2] (0, -g, 0); terr_kind, terr the terrain (``terrain_kernels``).  Crosses into a kernel as a
# plain tuple (``World.step_world``; ``core.kernel_records``) and is named again there with this class.
StepWorld = namedtuple("StepWorld", "gravity terr_kind terr")


@dataclass(frozen=True, eq=False)
class World:
    """A scenario's built world.

    scenario: the ``ScenarioConfig`` it was built from (the base-height rules read its keys);
    terr_kind: the terrain's kind code; terr: its parameter vector (float64, ``terrain_kernels``);
    food: (n, 4) food sources x, y, z [m], intensity (``food.food_sources``).
    """

    scenario: Any
    terr_kind: int
    terr: np.ndarray
    food: np.ndarray

    @classmethod
    def from_case(cls, case) -> World:
        return build_world(case)

    @property
    def terrain(self) -> tuple[int, np.ndarray]:
        """(kind, f): what the kernels query."""
        return self.terr_kind, self.terr

    @cached_property
    def step_world(self) -> tuple:
        """This world as a body's step takes it: a ``StepWorld`` as a plain tuple, built once per world (its terrain
        vector is this world's own, not a copy).  Gravity is the scenario's, (0, -g, 0) [m/s^2]."""
        gravity = np.array([0.0, -self.scenario.gravity_m_s2, 0.0])
        return tuple(StepWorld(gravity=gravity, terr_kind=self.terr_kind, terr=self.terr))

    @property
    def terrain_none(self) -> bool:
        """The scenario has no ground (``terrain = "none"``: a plane far below, ``terrain.NO_GROUND_HEIGHT_M``)."""
        return self.scenario.terrain == "none"

    @property
    def has_water(self) -> bool:
        return self.scenario.water_depth_m > 0.0

    def without_ground(self, scenario) -> World:
        """The world of a body measured apart from the run (``harness.calibration``: the curvature calibration):
        no ground, no obstacles, no food; ``scenario`` (``terrain = "none"``) gives its placement rules.

        Derived here, not built from ``scenario``: what that measurement sees cannot depend on the run's
        terrain (its cache key, ``curvature_calibration.calibration_key``, holds none of the scenario)."""
        if scenario.terrain != "none":
            raise ValueError(f"without_ground: the scenario's terrain is {scenario.terrain!r}; must be 'none'")
        kind, f = _terrain.no_ground_terrain()
        return World(scenario, kind, f, self.food[:0])

    def placement_terrain(self) -> tuple[int, np.ndarray]:
        """The surface a body is placed above at t = 0 (``terrain.placement_terrain``'s rule, from this world)."""
        return _terrain.placement_from(self.scenario, self.terr_kind, self.terr)

    def base_height(self, x, z) -> np.ndarray:
        """Height [m] of the base surface (without obstacles) at (x, z) (``terrain.base_height``)."""
        return _terrain.base_height(self.scenario, self.terr_kind, self.terr, x, z)


def build_world(case) -> World:
    """The world of ``case`` (its ``scenario`` and ``food`` sections): the terrain once, the food on it."""
    return world_from_sections(case.scenario, case.food)


def world_from_sections(sc, food) -> World:
    """The world of a ``ScenarioConfig`` and a ``FoodConfig`` (a stored case's sections, as the report has
    them): the terrain once, the food on it."""
    kind, f = _terrain.terrain_from_scenario(sc)
    sources = _food.food_sources(sc, food, (kind, f))
    return World(sc, kind, f, sources)


def world_of(case, world: World | None) -> World:
    """``world`` when given, else ``case``'s built here: for the leg controller built alone, by a script or a
    test (the runner always hands its one world to the controller it composes; bodies, metrics and plots take
    the world they are given and build none: ``tests/test_world_built_once.py``)."""
    return build_world(case) if world is None else world
