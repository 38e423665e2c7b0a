"""Where the data folders (models/, scenarios/) are.

They are data, not Python packages (ARCHITECTURE.md).  Three places, first match wins:

1. ``BENCH_MYRIAPODA_ROOT``: a directory holding ``models/`` and ``scenarios/``;
2. a source checkout (or an editable install): the folders beside ``bench_myriapoda/``;
3. an installed wheel: ``bench_myriapoda/_data/``, where the build copies them (``setup.py``).

A user's own creature, scenario or matrix file never needs to be in any of
them: wherever a name is accepted, a path to a ``.toml`` file works too.
"""
from __future__ import annotations

import os
from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parents[1]
CHECKOUT_ROOT = PACKAGE_DIR.parent
WHEEL_DATA_ROOT = PACKAGE_DIR / "_data"


def _has_data(root: Path) -> bool:
    return (root / "models").is_dir() and (root / "scenarios").is_dir()


def _is_checkout(root: Path) -> bool:
    # pyproject.toml too: site-packages (the parent of an installed package) may hold unrelated folders
    # named models/ or scenarios/, never our pyproject.toml
    return _has_data(root) and (root / "pyproject.toml").is_file()


def project_root() -> Path:
    """The directory whose ``models/`` and ``scenarios/`` are the suite's built-in data."""
    env = os.environ.get("BENCH_MYRIAPODA_ROOT")
    if env:
        return Path(env)
    if _is_checkout(CHECKOUT_ROOT):
        return CHECKOUT_ROOT
    return WHEEL_DATA_ROOT


def models_dir() -> Path:
    return project_root() / "models"


def scenarios_dir() -> Path:
    return project_root() / "scenarios"


def cache_root() -> Path:
    """Where what the suite builds once per machine is kept (tetrahedral meshes, curvature calibrations, mesh
    terrains): ``$BENCH_MYRIAPODA_CACHE``, else ``$XDG_CACHE_HOME/bench-myriapoda``, else
    ``~/.cache/bench-myriapoda``.  numba's compiled kernels go to ``numba/`` under the XDG one
    (``bench_myriapoda.__init__``)."""
    env = os.environ.get("BENCH_MYRIAPODA_CACHE")
    if env:
        return Path(env)
    base = os.environ.get("XDG_CACHE_HOME")
    return (Path(base) if base else Path.home() / ".cache") / "bench-myriapoda"
