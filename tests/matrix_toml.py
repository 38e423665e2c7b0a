"""Matrix files the tests write, in one place: the small matrices several test files run.

``tiny_worm_matrix``: the 4-segment lattice worm on flat ground over a grid of keys (the cheapest matrix
that still runs cases in parallel).  ``WORM_ON_A_CLIFF``: a ``[[block]]`` table of the report's test matrices
(tests/test_report.py, tests/test_validate.py).
"""
from __future__ import annotations

import json

# (matrix blocks are TOML data: ``duplicates`` pairs them by shape with other test matrices; alike by design)
WORM_ON_A_CLIFF = """
[[block]]
creatures = ["worm"]
bodies = ["massspring"]
scenarios = ["cliff"]
gaits = ["rectilinear"]
duration = 0.6
"""


def tiny_worm_matrix(duration: float, grid: dict[str, list], name: str | None = None) -> str:
    """TOML of a matrix of the 4-segment lattice worm on flat ground for ``duration`` [s], one case per point of
    ``grid`` (key -> values, as a ``[matrix.grid]`` table); ``name``: the matrix's name (none: unnamed)."""
    lines = ["[matrix]"] + ([f"name = {json.dumps(name)}"] if name is not None else [])
    lines += ['creatures = ["worm"]', 'bodies = ["massspring"]', 'scenarios = ["flat"]', f"duration = {duration!r}",
              'set = { "creature.segments" = 4 }', "[matrix.grid]"]
    lines += [f"{json.dumps(key)} = {json.dumps(values)}" for key, values in grid.items()]
    return "\n".join(lines) + "\n"
