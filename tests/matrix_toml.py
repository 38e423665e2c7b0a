"""Matrix files the tests write, in one place: the small matrices several test files run.

``tiny_worm_matrix``: the 4-segment lattice worm on flat ground over a grid of keys (the cheapest matrix
that still runs cases in parallel).  ``block`` / ``toml_table``: a matrix's tables written from keywords, so
that the test matrices (tests/test_report.py, tests/test_validate.py) say only what differs between them;
``WORM_ON_A_CLIFF``: a ``[[block]]`` table both of them run.
"""
from __future__ import annotations

import json



def toml_value(v) -> str:
    """``v`` (a str, number, bool, list or dict of them) as a TOML value; a dict as an inline table with quoted
    keys (dotted configuration keys stay one key)."""
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{json.dumps(k)} = {toml_value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, bool):
        return "true" if v else "false"
    return json.dumps(v) if isinstance(v, str) else repr(v)


def toml_table(header: str, **keys) -> str:
    """A TOML table ``[header]`` (or ``[[block]]`` for header ``"[block]"``), one ``key = value`` line per keyword
    in order; a keyword ending in ``_`` (``set_``) names the key without it."""
    lines = [f"[{header}]"] + [f"{k.rstrip('_')} = {toml_value(v)}" for k, v in keys.items()]
    return "\n" + "\n".join(lines) + "\n"


def block(**keys) -> str:
    """A matrix's ``[[block]]`` table of ``keys`` (``toml_table``)."""
    return toml_table("[block]", **keys)


WORM_ON_A_CLIFF = block(creatures=["worm"], bodies=["massspring"], scenarios=["cliff"], gaits=["rectilinear"],
                        duration=0.6)


def tiny_worm_matrix(duration: float, grid: dict[str, list], name: str | None = None) -> str:
    """TOML of a matrix of the 4-segment lattice worm on flat ground for ``duration`` [s], one case per point of
    ``grid`` (key -> values, as a ``[matrix.grid]`` table); ``name``: the matrix's name (none: unnamed)."""
    lines = ["[matrix]"] + ([f"name = {json.dumps(name)}"] if name is not None else [])
    lines += ['creatures = ["worm"]', 'bodies = ["massspring"]', 'scenarios = ["flat"]', f"duration = {duration!r}",
              'set = { "creature.segments" = 4 }', "[matrix.grid]"]
    lines += [f"{json.dumps(key)} = {json.dumps(values)}" for key, values in grid.items()]
    return "\n".join(lines) + "\n"
