"""Before a case runs: can the world builders place what its scenario asks for?

Random cylinders and food sources are drawn when the world is built; a scenario that leaves no room
for them is refused before the run starts (an ``InputError`` naming the source and the key, as for
any other bad value), instead of an ``error`` row after it started.  The check builds the world, and the CLI
runs the case in that world (issue 30 item 1: one build per case).  The body's own limits are
``core.feasibility.check_buildable``.
"""
from __future__ import annotations

import math

from ..core.errors import InputError
from .meshes import MAX_HASH_CELLS, mesh_file_problem, skull_hash_cells
from .world import World, build_world


def check_placements(case, source: str) -> World:
    """Random cylinders and food sources the world builders can place (they raise InputError otherwise), and
    the surfaces they can build (:func:`check_surfaces`).

    Returns the case's world, built here once (``world.build_world``: the placements are checked by building
    them): the caller hands it to the run and to whatever draws the run, so the check is not a second build."""
    check_surfaces(case, source)
    sc = case.scenario
    if sc.obstacle_cylinders:
        x0, x1, z0, z1 = sc.obstacle_region_m
        far = max(math.hypot(x, z) for x in (x0, x1) for z in (z0, z1))
        if far - sc.obstacle_radius_m[0] < sc.obstacle_clear_radius_m:
            raise InputError(source, "scenario.obstacle_clear_radius_m",
                             f"{sc.obstacle_clear_radius_m} m: no room for random cylinders, the clear disc covers "
                             f"obstacle_region_m {list(sc.obstacle_region_m)}; must be smaller")
    return _reattribute(lambda: build_world(case), source)


def _reattribute(fn, source: str):
    try:
        return fn()
    except InputError as exc:
        raise InputError(source, exc.key, exc.message) from None


def check_surfaces(case, source: str) -> None:
    """The terrain mesh's spatial hash fits its cell limit and a body surface file is a mesh type trimesh
    reads -- found by the world and body builders only after seconds of building otherwise."""
    sc, body = case.scenario, case.body
    if sc.terrain == "mesh" and sc.mesh == "skull":
        cells = skull_hash_cells(sc.mesh_subdivisions, sc.mesh_scale, sc.mesh_cell_edges, sc.mesh_band_m)
        if cells > MAX_HASH_CELLS:
            raise InputError(source, "scenario.mesh_subdivisions",
                             f"{sc.mesh_subdivisions}: the terrain's hash grid would have about {cells:,.0f} cells; "
                             f"at most {MAX_HASH_CELLS:,}: lower scenario.mesh_subdivisions or raise "
                             "scenario.mesh_cell_edges")
    if getattr(body, "mesh", None) not in (None, "grid", "capsule"):
        problem = mesh_file_problem(body.mesh)
        if problem:
            raise InputError(source, "body.mesh", f"{problem}; or use 'grid' or 'capsule'")
