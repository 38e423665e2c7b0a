"""The world of one run, built once from the scenario: terrain with its obstacles, food sources, the water's bed.

``build_world(case)`` (or ``World.from_case``) builds it; the runner does so once per run and hands the same
``World`` to the body (its factory's ``world`` argument), the controller (its constructor's) and the metrics
(their ``world`` argument), so no part of a run rebuilds the terrain from the scenario (issue 30 item 1: the
terrain used to be rebuilt in about 13 places, a 10^5-triangle mesh terrain each time from its cache, random
cylinders and food sources redrawn each time).  Each of those keeps a fallback that builds its own world when
it is given none (a body or controller built alone, by a test or a script).  The curvature calibration
(``harness.calibration``, on a cache miss) measures a short copy of the body in a world of its own (no ground,
no gravity: ``bodies.curvature_calibration._calibration_case``): a different world, which
``harness.calibration`` builds through ``build_world`` from that case's own scenario.  Outside a run the same
rule holds: the CLI builds a case's world once in its pre-run placement check (``world.buildable``) and hands
it to the run and to the animation; the report builds one world per stored case
(``report.matrix_data.MatrixResults.world``) and hands it to every plot of that case.

What the world holds does not change during a run (Newton's "model", as against the body's state): the
terrain vector ``terr`` (``terrain_kernels`` layout, obstacles and their grid included) is shared by
everything that queries it and must not be written to (``tests/test_world_built_once.py`` checks it is the
same bytes after a run).  It stays a writable array for numba: a read-only one would compile every kernel
that takes it a second time.  The water's surface is the run's state, in ``water_coupling.WaterCoupling``;
the world holds its bed (the terrain) and whether there is water at all.
"""
from __future__ import annotations

import inspect
from dataclasses import dataclass
from typing import Any

import numpy as np

from . import food as _food
from . import terrain as _terrain


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

    @property
    def terrain_none(self) -> bool:
        """The scenario has no ground (``terrain = "none"``: a plane far below, ``terrain.NO_GROUND_HEIGHT_M``)."""
        return self.scenario.terrain == "none"

    @property
    def has_water(self) -> bool:
        return self.scenario.water_depth_m > 0.0

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


def takes_world(make) -> bool:
    """True when ``make`` (a body factory, a controller class) accepts a ``world`` keyword: it is then given
    the run's ``World``; one that does not (a user's, written before the world existed) gets the case alone."""
    try:
        params = inspect.signature(make).parameters.values()
    except (TypeError, ValueError):  # a callable without a signature Python can read
        return False
    return any(p.name == "world" or p.kind is inspect.Parameter.VAR_KEYWORD for p in params)


def made_in(make, case, world: World):
    """``make(case)`` in ``world``: passed as its ``world`` keyword when it takes one (``takes_world``)."""
    return make(case, world=world) if takes_world(make) else make(case)


def world_of(case, world: World | None) -> World:
    """``world`` when given, else ``case``'s built here: for a body, a controller or a metric used without a
    runner (the runner always passes its one world)."""
    return build_world(case) if world is None else world
