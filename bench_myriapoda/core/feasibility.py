"""Before a case runs: can its body model build it, and what will it cost?

Two checks on a resolved :class:`~.config.Case`, both cheap (no body is built,
no numba function is compiled):

* :func:`check_buildable` -- the limits the body's builder enforces, as its
  backend declares them (``BodySpec.check_buildable``: e.g. a legged chain needs
  >= 2 segments, a link's cross-section must fit on the rigid face); the world's
  (random obstacles and food sources that can be placed) are checked by
  ``world.buildable``, the layer above.  A violation is an
  :class:`~.errors.InputError` naming the source and the key, as for any other
  bad value, instead of an ``error`` row after the run started.
* :func:`estimate` / :func:`check_budget` -- the memory a case will take (from
  its body's declared :class:`~.specs.Footprint`, water grid, terrain mesh and recorded series) and its number of
  steps (duration / dt).  A case over the budget (default: half the machine's
  memory, 1e9 steps) is refused with the estimate in the message; ``--force``
  skips the refusal.

The memory model is deliberately simple and errs high: per tetrahedron
``BYTES_PER_TET`` and per node ``BYTES_PER_NODE`` (``tet_mesh_footprint``, which the
FEM and hybrid backends use; ``lattice_footprint`` for point-mass lattices).  Measured peak RSS of
building a ``worm`` on the ``fem`` body at resolution 4 (3,240 tets) and 12
(159,720 tets) differs by 0.55 kB per tet, the ``centipede`` hybrid body 0.37 kB
per tet (resolution 3 and 9); 1 kB per tet leaves room for the sparse
factorization's fill-in, which grows faster than the mesh.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field

import numpy as np

from . import registry
from .errors import InputError
from .specs import Footprint

MAX_STEPS = 1.0e9
# Shallow-water cell updates (cells x sub-steps) of one case: a 1 m square of 0.4 mm cells under 100 m of water
# is 4.9e10 updates for 0.05 s and ran over 60 s (issue 41); 1e10 is a few to ten seconds of one core.
MAX_GRID_WORK = 1.0e10
BYTES_PER_TET = 1024.0
BYTES_PER_NODE = 512.0
BYTES_PER_LATTICE_NODE = 400.0  # mass-spring: the node, ~10 springs, scratch
BYTES_PER_WATER_CELL = 200.0  # shallow water: ~20 float64 fields per cell and the coupling's scratch
BYTES_PER_MESH_TRIANGLE = 1000.0  # terrain mesh: triangles, the spatial hash and the signed-distance samples
# the interpreter with numpy, numba, scipy and the compiled kernels: a matrix worker compiling the
# hybrid chain peaked at 473 MB (397 MB before the workers collected garbage less often, issue 13)
BASE_BYTES = 500.0e6


def machine_memory_bytes() -> float:
    """Physical memory of this machine [bytes] (0 when the OS does not say)."""
    try:
        return float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (ValueError, OSError, AttributeError):
        return 0.0


def _cgroup_limit_bytes() -> float:
    """The memory limit of this process's cgroup (a container's) [bytes]; 0 when there is none."""
    for path in ("/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"):
        try:
            with open(path) as fh:
                text = fh.read().strip()
        except OSError:
            continue
        if text.isdigit() and int(text) < 2 ** 60:  # "max" or a huge number: no limit
            return float(text)
    return 0.0


def available_memory_bytes() -> float:
    """Memory a new allocation can get now [bytes]: MemAvailable of /proc/meminfo (0 when unknown)."""
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return float(line.split()[1]) * 1024.0
    except (OSError, ValueError, IndexError):
        pass
    return 0.0


def default_memory_budget() -> float:
    """Half of the memory this process may have [bytes] -- the machine's, or its container's limit when
    smaller -- and at most what is available now (on a shared machine the memory other processes hold
    is not the case's: a case beyond it is killed by the operating system instead of refused here).
    8 GB when none of it can be read."""
    total = machine_memory_bytes()
    limit = _cgroup_limit_bytes()
    if limit > 0:
        total = min(total, limit) if total > 0 else limit
    budget = 0.5 * total if total > 0 else 8.0e9
    avail = available_memory_bytes()
    return min(budget, avail) if avail > 0 else budget


@dataclass
class Estimate:
    """What a case will take: ``steps`` (float: may exceed any int), ``memory_bytes`` and its parts."""

    steps: float
    memory_bytes: float
    parts: dict[str, float] = field(default_factory=dict)
    mesh: str = ""  # e.g. "1,234,567 tets, 234,567 nodes"
    work: float = 0.0  # grid work: shallow-water cells x their sub-steps over the run

    def describe(self) -> str:
        parts = ", ".join(f"{k} {_gb(v)}" for k, v in self.parts.items() if v >= 1e6)
        return (f"estimated {_gb(self.memory_bytes)} of memory" + (f" ({parts})" if parts else "")
                + (f" for {self.mesh}" if self.mesh else "") + f", {self.steps:.3g} steps")


def _gb(b: float) -> str:
    return f"{b / 1e9:.3g} GB" if b >= 1e8 else f"{b / 1e6:.3g} MB"


def tet_mesh_footprint(tets: float, nodes: float) -> Footprint:
    """A body of ``tets`` tetrahedra on ``nodes`` nodes (the FEM and hybrid backends)."""
    return Footprint(tets * BYTES_PER_TET + nodes * BYTES_PER_NODE, nodes,
                     f"{tets:,.0f} tets, {nodes:,.0f} nodes" if tets else "")


def lattice_footprint(nodes: float) -> Footprint:
    """A mass-spring lattice of ``nodes`` point masses."""
    return Footprint(nodes * BYTES_PER_LATTICE_NODE, nodes)


def footprint(case) -> Footprint:
    """The memory of the case's body, as its backend declares it (``BodySpec.footprint``; nothing built)."""
    return registry.BODIES[case.body.name].footprint(case)


def estimate(case, keep_nodes: bool = False) -> Estimate:
    """Memory [bytes] and steps of ``case``; ``keep_nodes``: every node position is kept per sample
    (``run --record``, ``--animate``, ``--export-frames``)."""
    sc = case.scenario
    steps = float(case.duration) / float(case.dt) if case.dt > 0 else math.inf
    body = footprint(case)
    parts = {"base": BASE_BYTES, "body": body.body_bytes}
    work = 0.0
    if sc.water_depth_m > 0:
        cells, water_steps = water_size(case)
        parts["water grid"] = cells * BYTES_PER_WATER_CELL
        work = cells * water_steps
    if sc.terrain == "mesh":
        if sc.mesh == "skull":
            tris = 12.0 * sc.mesh_subdivisions ** 2
        else:  # a mesh file: about 50 bytes per triangle on disk for the common formats
            try:
                tris = os.path.getsize(sc.mesh) / 50.0
            except OSError:
                tris = 0.0
        parts["terrain mesh"] = tris * BYTES_PER_MESH_TRIANGLE
    samples = steps * case.dt * case.record.sample_hz + 1.0
    per_sample = 8.0 * (18.0 * case.creature.segments + 64.0) + (24.0 * body.nodes if keep_nodes else 0.0)
    parts["recorded series"] = samples * per_sample
    return Estimate(steps, sum(parts.values()), parts, body.mesh, work)


def water_size(case) -> tuple[float, float]:
    """(cells, sub-steps over the whole run) of the case's shallow-water grid (``world.water``): cells per
    axis counted separately (a region and a cell of 5e-324 m are one cell, not 0 / 0), sub-steps of at most
    water_courant dx / sqrt(g d) [s] each (``world.water_coupling``).  Either is inf when it does not fit a
    float, which no budget accepts."""
    sc = case.scenario
    x0, x1, z0, z1 = sc.water_region_m
    cell = sc.water_cell_m
    with np.errstate(all="ignore"):
        nx = max(round(float(np.float64(x1 - x0) / cell)) if math.isfinite((x1 - x0) / cell) else math.inf, 2)
        nz = max(round(float(np.float64(z1 - z0) / cell)) if math.isfinite((z1 - z0) / cell) else math.inf, 2)
        dx = float(np.float64(x1 - x0) / nx) if math.isfinite(nx) else 0.0
        speed = math.sqrt(max(sc.gravity_m_s2, 0.0) * sc.water_depth_m)
        max_dt = float(np.float64(sc.water_courant) * dx / speed) if speed > 0 else math.inf
        water_steps = float(case.duration) / max_dt if max_dt > 0 else math.inf
    return float(nx) * float(nz), max(water_steps, 1.0)

# Triangles of a terrain mesh: its spatial hash, exact signed-distance samples and per-query scans grow with
# them; 1,080,000 (skull, mesh_subdivisions = 300) and a 327,680-face file each took over 60 s for a 0.05 s
# run (issue 41); the default skull (92: 101,568 triangles) builds in seconds.
MAX_TERRAIN_TRIANGLES = 250_000


def terrain_triangles(sc) -> int:
    """Triangles of a scenario's terrain mesh: 12 n^2 for the skull, the file's face count otherwise (read once
    per process, as the configuration check read it)."""
    if sc.mesh == "skull":
        return 12 * int(sc.mesh_subdivisions) ** 2
    from .mesh_files import load_closed_mesh

    return len(load_closed_mesh(sc.mesh).faces)


PART_KEYS = {"water grid": "scenario.water_cell_m", "terrain mesh": "scenario.mesh_subdivisions",
             "recorded series": "duration"}


def check_budget(case, source: str, memory_budget: float | None = None, max_steps: float | None = None,
                 keep_nodes: bool = False) -> Estimate:
    """Refuse (``InputError`` naming ``source`` and the key that drives the estimate) a case whose
    :func:`estimate` exceeds the budget: ``memory_budget`` [bytes] (default half the machine's memory),
    ``max_steps`` (default ``MAX_STEPS``)."""
    budget = default_memory_budget() if memory_budget is None else memory_budget
    cap = MAX_STEPS if max_steps is None else max_steps
    est = estimate(case, keep_nodes)
    if not est.steps <= cap:
        raise InputError(source, "duration", f"case too large: {est.steps:.3g} steps (duration {case.duration:g} s / "
                                             f"dt {case.dt:g} s) exceed the limit of {cap:.3g} steps (--max-steps); "
                                             "shorten the duration or pass --force")
    if not est.work <= MAX_GRID_WORK * cap / MAX_STEPS:  # --max-steps scales it as it scales the steps
        raise InputError(source, "scenario.water_cell_m",
                         f"case too large: its shallow-water grid needs {est.work:.3g} cell updates (cells x "
                         f"sub-steps of water_courant dx / sqrt(g d)); at most {MAX_GRID_WORK * cap / MAX_STEPS:.3g} "
                         "(--max-steps scales it): raise scenario.water_cell_m or water_courant, shrink "
                         "water_region_m, shorten the duration, or pass --force")
    sc = case.scenario
    if sc.terrain == "mesh":
        tris = terrain_triangles(sc)
        if tris > MAX_TERRAIN_TRIANGLES:
            key = "scenario.mesh_subdivisions" if sc.mesh == "skull" else "scenario.mesh"
            raise InputError(source, key, f"case too large: the terrain mesh has {tris:,} triangles; at most "
                                          f"{MAX_TERRAIN_TRIANGLES:,} (its spatial hash cells and exact distance "
                                          "samples are built before the run: a million triangles took minutes); "
                                          + ("lower scenario.mesh_subdivisions" if sc.mesh == "skull" else
                                             "decimate the mesh") + " or pass --force")
    if not est.memory_bytes <= budget:
        top = max((k for k in est.parts if k != "base"), key=lambda k: est.parts[k])
        key = PART_KEYS.get(top) or ("body.resolution" if hasattr(case.body, "resolution") else "creature.segments")
        raise InputError(source, key, f"case too large: {est.describe()} exceeds the memory budget of "
                                      f"{_gb(budget)} (--memory-budget); lower {key} or pass --force")
    return est


# --------------------------------------------------------------------------- geometry

def check_buildable(case, source: str) -> None:
    """The body builder's limits (``BodySpec.check_buildable``), checked on the configuration (see the module
    docstring); the world builders' are ``world.buildable.check_placements``."""
    registry.BODIES[case.body.name].check_buildable(case, source)
