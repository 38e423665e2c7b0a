"""Counts world builds in every process of a command, the matrix's worker processes included (issue 42).

A plugin module (``BENCH_MYRIAPODA_PLUGINS=world_build_counter``, no tables of its own): every process that reads
the lookups (``registry.load_all``: the CLI's, and each matrix worker's before its first case) imports it, and
when ``$WORLD_BUILD_LOG`` names a file, it wraps the world's two builders (``terrain._base_terrain``: a terrain,
obstacles included; ``food.food_sources``: the food placed on it) so that each call appends one line
(``terrain`` or ``food``) to that file.  Lines are appended with one ``write`` each (``O_APPEND``), so the
processes' lines do not mix.  ``uninstall()`` puts the builders back (the test's own process).
"""
from __future__ import annotations

import os

from bench_myriapoda.world import food, terrain

LOG_ENV = "WORLD_BUILD_LOG"
_ORIGINAL = {}


def _log(what: str) -> None:
    fd = os.open(os.environ[LOG_ENV], os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
    try:
        os.write(fd, f"{what} {os.getpid()}\n".encode())
    finally:
        os.close(fd)


def install() -> None:
    if _ORIGINAL or not os.environ.get(LOG_ENV):
        return
    _ORIGINAL["terrain"], _ORIGINAL["food"] = terrain._base_terrain, food.food_sources
    base, sources = terrain._base_terrain, food.food_sources

    def counted_base(sc):
        _log("terrain")
        return base(sc)

    def counted_food(*args, **kwargs):
        _log("food")
        return sources(*args, **kwargs)

    terrain._base_terrain, food.food_sources = counted_base, counted_food


def uninstall() -> None:
    if _ORIGINAL:
        terrain._base_terrain, food.food_sources = _ORIGINAL.pop("terrain"), _ORIGINAL.pop("food")


def counts(path) -> dict[str, int]:
    """{"terrain": n, "food": n} of a log (no file: nothing built)."""
    out = {"terrain": 0, "food": 0}
    if os.path.exists(path):
        for line in open(path, encoding="utf-8"):
            out[line.split()[0]] += 1
    return out


install()
