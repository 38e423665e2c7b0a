"""Before a case runs: can its body model build it, and what will it cost?

Two checks on a resolved :class:`~.config.Case`, both cheap (no body is built,
no numba function is compiled):

* :func:`check_buildable` -- the geometric limits the body builders enforce
  (a legged chain or a hybrid body needs >= 2 segments; a link's cross-section
  must fit on the rigid face; the creature must be heavier than its links),
  random obstacles and food sources that can be placed.  A violation is an
  :class:`~.errors.InputError` naming the source and the key, as for any other
  bad value, instead of an ``error`` row after the run started.
* :func:`estimate` / :func:`check_budget` -- the memory a case will take (from
  its mesh, water grid, terrain mesh and recorded series) and its number of
  steps (duration / dt).  A case over the budget (default: half the machine's
  memory, 1e9 steps) is refused with the estimate in the message; ``--force``
  skips the refusal.

The memory model is deliberately simple and errs high: per tetrahedron
``BYTES_PER_TET`` and per node ``BYTES_PER_NODE``.  Measured peak RSS of
building a ``worm`` on the ``fem`` body at resolution 4 (3,240 tets) and 12
(159,720 tets) differs by 0.55 kB per tet, the ``centipede`` hybrid body 0.37 kB
per tet (resolution 3 and 9); 1 kB per tet leaves room for the sparse
factorization's fill-in, which grows faster than the mesh.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field

from .errors import InputError

MAX_STEPS = 1.0e9
BYTES_PER_TET = 1024.0
BYTES_PER_NODE = 512.0
BYTES_PER_LATTICE_NODE = 400.0  # mass-spring: the node, ~10 springs, scratch
BYTES_PER_WATER_CELL = 200.0  # shallow water: ~20 float64 fields per cell and the coupling's scratch
BYTES_PER_MESH_TRIANGLE = 1000.0  # terrain mesh: triangles, the spatial hash and the signed-distance samples
# the interpreter with numpy, numba, scipy and the compiled kernels: a matrix worker compiling the
# hybrid chain peaked at 473 MB (397 MB before the workers collected garbage less often, issue 13)
BASE_BYTES = 500.0e6
DERIVED = -1.0  # the body configs' "derive from the creature" value


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

    def describe(self) -> str:
        parts = ", ".join(f"{k} {_gb(v)}" for k, v in self.parts.items() if v >= 1e6)
        return (f"estimated {_gb(self.memory_bytes)} of memory" + (f" ({parts})" if parts else "")
                + (f" for {self.mesh}" if self.mesh else "") + f", {self.steps:.3g} steps")


def _gb(b: float) -> str:
    return f"{b / 1e9:.3g} GB" if b >= 1e8 else f"{b / 1e6:.3g} MB"


def _cells(resolution: int, unit: str) -> tuple[int, int, int]:
    c = max(1, int(resolution) - 1) if unit == "nodes" else max(1, int(resolution))
    return c, c, c


def mesh_size(case) -> tuple[float, float, float]:
    """(tets, nodes, lattice nodes) of the case's body, counted from its configuration (nothing built)."""
    body, cre = case.body, case.creature
    n = int(cre.segments)
    legged = bool(cre.legs_per_segment)
    if body.name == "fem":
        tpc = int(body.tets_per_cell)
        if legged:
            cx, cy, cz = _cells(body.resolution, body.resolution_unit)
            parts = max(1, 2 * n - 1)
            return parts * cx * cy * cz * tpc, (parts * cx + 1) * (cy + 1) * (cz + 1), 0.0
        if body.mesh == "grid":
            cx, cy, cz = _cells(body.resolution, body.resolution_unit)
            return n * cx * cy * cz * tpc, (n * cx + 1) * (cy + 1) * (cz + 1), 0.0
        # fTetWild at a target edge of fac * bounding-box diagonal: about (1 / fac)^3 tets, within a factor of 10
        tets = 10.0 / float(body.mesh_edge_length_fac) ** 3
        return tets, tets / 4.0, 0.0
    if body.name == "hybrid":
        cx, cy, cz = _cells(body.resolution, body.resolution_unit)
        links = max(1, n - 1)
        return links * cx * cy * cz * int(body.tets_per_cell), links * (cx + 1) * (cy + 1) * (cz + 1), 0.0
    if body.name == "massspring" and legged:
        return 0.0, 0.0, max(1, n - 1) * 4.0 * (int(body.link_cells) + 1)
    return 0.0, 0.0, 4.0 * (n + 1)  # Miller's lattice: four nodes per cross-section


def estimate(case, keep_nodes: bool = False) -> Estimate:
    """Memory [bytes] and steps of ``case``; ``keep_nodes``: every node position is kept per sample
    (``run --record``, ``--animate``, ``--export-frames``)."""
    sc = case.scenario
    steps = float(case.duration) / float(case.dt)
    tets, nodes, lattice = mesh_size(case)
    parts = {"base": BASE_BYTES,
             "body": tets * BYTES_PER_TET + nodes * BYTES_PER_NODE + lattice * BYTES_PER_LATTICE_NODE}
    if sc.water_depth_m > 0:
        x0, x1, z0, z1 = sc.water_region_m
        parts["water grid"] = (x1 - x0) * (z1 - z0) / sc.water_cell_m ** 2 * BYTES_PER_WATER_CELL
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
    per_sample = 8.0 * (18.0 * case.creature.segments + 64.0) + (24.0 * (nodes + lattice) if keep_nodes else 0.0)
    parts["recorded series"] = samples * per_sample
    mesh = f"{tets:,.0f} tets, {nodes:,.0f} nodes" if tets else ""
    return Estimate(steps, sum(parts.values()), parts, mesh)


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
    if not est.memory_bytes <= budget:
        top = max((k for k in est.parts if k != "base"), key=lambda k: est.parts[k])
        key = PART_KEYS.get(top) or ("body.resolution" if hasattr(case.body, "resolution") else "creature.segments")
        raise InputError(source, key, f"case too large: {est.describe()} exceeds the memory budget of "
                                      f"{_gb(budget)} (--memory-budget); lower {key} or pass --force")
    return est


# --------------------------------------------------------------------------- geometry

def _pick(value: float, default: float) -> float:
    return default if value == DERIVED else value


def check_buildable(case, source: str) -> None:
    """The body builders' and world builders' limits, checked on the configuration (see the module docstring)."""
    body, cre = case.body, case.creature
    _check_surfaces(case, source)
    legged = bool(cre.legs_per_segment)
    chain = body.name == "hybrid" or (legged and body.name in ("massspring", "fem"))
    if chain and cre.segments < 2:
        what = "a hybrid body" if body.name == "hybrid" else f"a legged {body.name} chain"
        raise InputError(source, "creature.segments", f"{cre.segments}: {what} needs >= 2 segments (one link)")
    if body.name == "hybrid" or (legged and body.name == "massspring"):
        _check_link_fit(case, source)
    if legged and body.name == "massspring":
        lay = _layout(body, cre)
        cells = int(body.link_cells)
        free = ((cre.segments - 1) * body.link_density_kg_m3 * lay["ll"] * lay["wl"] * lay["hl"]
                * (cells - 1) / (cells + 1))
        if not cre.mass_kg > free:
            raise InputError(source, "creature.mass_kg", f"{cre.mass_kg} kg is not more than the free link nodes' "
                                                         f"{free:.4g} kg; must be larger (or lower "
                                                         "body.link_density_kg_m3)")
    if legged and body.name == "fem" and not body.block_density_kg_m3 > 0:
        ll = body.link_length_m if body.link_length_m > 0 else 0.5 * cre.segment_length_m
        rho = body.density_kg_m3 if body.density_kg_m3 > 0 else 1.0
        m_links = rho * (cre.segments - 1) * ll * cre.width_m * cre.height_m
        if not cre.mass_kg > m_links:
            raise InputError(source, "creature.mass_kg", f"{cre.mass_kg} kg is not more than the links' mass "
                                                         f"{m_links:.4g} kg; must be larger (or set "
                                                         "body.block_density_kg_m3)")
    if body.name == "hybrid" and body.rigid_density_kg_m3 == DERIVED:
        free = _hybrid_free_mass(case)
        if not cre.mass_kg > free:
            raise InputError(source, "creature.mass_kg", f"{cre.mass_kg} kg is not more than the free FEM nodes' "
                                                         f"mass {free:.4g} kg; must be larger (or set "
                                                         "body.rigid_density_kg_m3)")
    _check_placements(case, source)


def _layout(body, cre) -> dict[str, float]:
    lr = _pick(body.rigid_length_m, cre.segment_length_m)
    wr = _pick(body.rigid_width_m, cre.width_m)
    hr = _pick(body.rigid_height_m, cre.height_m)
    return dict(lr=lr, wr=wr, hr=hr, ll=_pick(body.link_length_m, 0.5 * lr), wl=_pick(body.link_width_m, wr),
                hl=_pick(body.link_height_m, hr))


def _check_link_fit(case, source: str) -> None:
    lay = _layout(case.body, case.creature)
    for key, v in lay.items():
        if not v > 0:
            name = {"lr": "rigid_length_m", "wr": "rigid_width_m", "hr": "rigid_height_m", "ll": "link_length_m",
                    "wl": "link_width_m", "hl": "link_height_m"}[key]
            raise InputError(source, f"body.{name}", f"{v}: must be > 0 (or -1: derived from the creature)")
    if lay["wl"] > lay["wr"]:
        raise InputError(source, "body.link_width_m", f"{lay['wl']} m is wider than the rigid face "
                                                      f"({lay['wr']} m); must be <= it")
    if lay["hl"] > lay["hr"]:
        raise InputError(source, "body.link_height_m", f"{lay['hl']} m is taller than the rigid face "
                                                       f"({lay['hr']} m); must be <= it")


def _hybrid_free_mass(case) -> float:
    """Lumped mass of the hybrid links' free nodes [kg]: the link mesh is built (numpy only; its size is
    bounded by the resource check, which runs first) and each tet's mass shared by its four nodes."""
    import numpy as np

    from ..bodies.fem.mesh import signed_volumes
    from ..bodies.hybrid.body import build_mesh, hybrid_layout

    lay = hybrid_layout(case.body, case.creature)
    m = build_mesh(lay, case.body.tets_per_cell)
    share = np.repeat(case.body.density_kg_m3 * signed_volumes(m.nodes, m.tets) / 4.0, 4)
    mass = np.bincount(m.tets.ravel(), weights=share, minlength=len(m.nodes))
    return float(mass[~m.attached].sum())


def _check_placements(case, source: str) -> None:
    """Random cylinders and food sources the world builders can place (they raise InputError otherwise)."""
    sc = case.scenario
    if sc.obstacle_cylinders:
        from ..world.terrain import random_cylinders

        x0, x1, z0, z1 = sc.obstacle_region_m
        far = max(math.hypot(x, z) for x in (x0, x1) for z in (z0, z1))
        if far - sc.obstacle_radius_m[0] < sc.obstacle_clear_radius_m:
            raise InputError(source, "scenario.obstacle_clear_radius_m",
                             f"{sc.obstacle_clear_radius_m} m: no room for random cylinders, the clear disc covers "
                             f"obstacle_region_m {list(sc.obstacle_region_m)}; must be smaller")
        _reattribute(lambda: random_cylinders(sc), source)
    if case.food.count and sc.terrain != "mesh":  # on a mesh the terrain takes seconds to build: checked at run time
        from ..world.food import food_sources

        _reattribute(lambda: food_sources(sc, case.food), source)


def _reattribute(fn, source: str) -> None:
    try:
        fn()
    except InputError as exc:
        raise InputError(source, exc.key, exc.message) from None


def _check_surfaces(case, source: str) -> None:
    """The terrain mesh's spatial hash fits its cell limit and a body surface file is a mesh type trimesh
    reads -- found by the world and body builders only after seconds of building otherwise."""
    sc, body = case.scenario, case.body
    if sc.terrain == "mesh" and sc.mesh == "skull":
        from ..world.meshes import MAX_HASH_CELLS, skull_hash_cells

        cells = skull_hash_cells(sc.mesh_subdivisions, sc.mesh_scale, sc.mesh_cell_edges, sc.mesh_band_m)
        if cells > MAX_HASH_CELLS:
            raise InputError(source, "scenario.mesh_subdivisions",
                             f"{sc.mesh_subdivisions}: the terrain's hash grid would have about {cells:,.0f} cells; "
                             f"at most {MAX_HASH_CELLS:,}: lower scenario.mesh_subdivisions or raise "
                             "scenario.mesh_cell_edges")
    if getattr(body, "mesh", None) not in (None, "grid", "capsule"):
        from ..world.meshes import mesh_file_problem

        problem = mesh_file_problem(body.mesh)
        if problem:
            raise InputError(source, "body.mesh", f"{problem}; or use 'grid' or 'capsule'")
