"""bench-myriapoda: a benchmark suite for simulated myriapods, worms and snakes."""
from __future__ import annotations

import hashlib
import os
from pathlib import Path

__version__ = "0.1.0"


def _source_hash() -> str:
    """The hash (16 hex digits) of every source file of this package, names and contents."""
    h = hashlib.sha256()
    root = Path(__file__).resolve().parent
    for p in sorted(root.rglob("*.py")):
        h.update(str(p.relative_to(root)).encode())
        h.update(p.read_bytes())
    return h.hexdigest()[:16]


SOURCE_HASH = _source_hash()  # keys what is built from the code and kept on disk: numba's cache, mesh terrains


def _numba_cache_dir() -> str:
    """A numba cache directory keyed by the hash of every source file of this package.

    numba's on-disk cache (``cache=True``) is invalidated only by changes to the
    file that defines a function, not to the files of the functions it calls, so
    editing a shared kernel (e.g. ``contact_kernels.py``) would leave callers in
    other modules running stale machine code.  Keying the whole cache on all
    sources makes any edit start from a clean cache.
    """
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "bench-myriapoda", "numba", SOURCE_HASH)


NUMBA_CACHE_DIR_GIVEN = "NUMBA_CACHE_DIR" in os.environ  # the user's own (checked by core.numba_env), not ours
if not NUMBA_CACHE_DIR_GIVEN:  # a user's own choice wins
    os.environ["NUMBA_CACHE_DIR"] = _numba_cache_dir()
# The kernels' cache files found by their place in the package, not by its install path (jit/cache_locator.py):
# a wheel, a second worktree or a rebuilt venv of the same code loads what the first compiled.  numba's own
# locators follow ours in numba's own order (the setting replaces numba's list); a user's own list wins.
NUMBA_LOCATORS = ("UserProvidedCacheLocator", "InTreeCacheLocator", "UserWideCacheLocator", "IPythonCacheLocator",
                  "ZipCacheLocator")
CACHE_LOCATOR_CLASSES = ",".join(["bench_myriapoda.jit.cache_locator.PackageRelativeCacheLocator", *NUMBA_LOCATORS])
NUMBA_CACHE_LOCATOR_CLASSES_GIVEN = "NUMBA_CACHE_LOCATOR_CLASSES" in os.environ
os.environ.setdefault("NUMBA_CACHE_LOCATOR_CLASSES", CACHE_LOCATOR_CLASSES)
try:  # numba may already be imported: its config read the environment then
    import sys

    if "numba" in sys.modules:
        if not NUMBA_CACHE_DIR_GIVEN:
            sys.modules["numba"].config.CACHE_DIR = os.environ["NUMBA_CACHE_DIR"]
        sys.modules["numba"].config.CACHE_LOCATOR_CLASSES = os.environ["NUMBA_CACHE_LOCATOR_CLASSES"]
except AttributeError:
    pass

# Cold start (issue 13): numba's type inference tries many typing templates per operation and builds an error
# for each one that does not match (about 65,000 in one compile of the hybrid chain's kernels); with colorama
# installed, each error's message is coloured, which runs colorama's init and wraps stdout and stderr every
# time (5 % of the profiled compile).  Plain messages cost nothing; they only matter when a kernel fails to
# compile, and then they read the same without the terminal colours.  Read when numba.core.errors is imported
# (after this line, as the package does not import numba itself); a user's own setting wins.
os.environ.setdefault("NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING", "1")


# The Python API (api.py), imported on first use: `import bench_myriapoda` stays light (no numba,
# no pandas) and the numba cache directory above is set before anything imports numba.
_API = ("run", "run_matrix", "load_results", "resolve", "Result", "Series")


def __getattr__(name: str):
    if name in _API:
        from . import api

        return getattr(api, name)
    raise AttributeError(f"module 'bench_myriapoda' has no attribute {name!r}")


def __dir__():
    return sorted(list(globals()) + list(_API))


__all__ = ["__version__", *_API]
