"""The hash of the package's sources, which keys what is built from the code and kept on disk, and numba's cache
directory keyed by it.

Imported first by the package's ``__init__`` (so before anything imports numba): it sets ``NUMBA_CACHE_DIR`` to
``~/.cache/bench-myriapoda/numba/<SOURCE_HASH>`` unless the user set it, and numba's cache locators to the
package's own first (``jit.cache_locator``) unless the user set them.  Also keyed by the hash: the mesh terrains
(``world.terrain_cache``), the stable-dt brackets and the report's main job (``harness.stable_dt.source_hash``).
Standard library only: ``import bench_myriapoda`` stays light.
"""
from __future__ import annotations

import hashlib
import os
import sys
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1]  # bench_myriapoda/


def _source_hash() -> str:
    """The hash (16 hex digits) of every source file of this package, names and contents."""
    h = hashlib.sha256()
    for p in sorted(PACKAGE.rglob("*.py")):
        h.update(str(p.relative_to(PACKAGE)).encode())
        h.update(p.read_bytes())
    return h.hexdigest()[:16]


SOURCE_HASH = _source_hash()


def numba_cache_dir() -> str:
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
    os.environ["NUMBA_CACHE_DIR"] = numba_cache_dir()

# The kernels' cache files found by their place in the package, not by its install path (jit/cache_locator.py):
# a wheel, a second worktree or a rebuilt venv of the same code loads what the first compiled.  numba's own
# locators follow ours in numba's own order (the setting replaces numba's list); a user's own list wins.
NUMBA_LOCATORS = ("UserProvidedCacheLocator", "InTreeCacheLocator", "UserWideCacheLocator", "IPythonCacheLocator",
                  "ZipCacheLocator")
CACHE_LOCATOR_CLASSES = ",".join(["bench_myriapoda.jit.cache_locator.PackageRelativeCacheLocator", *NUMBA_LOCATORS])
NUMBA_CACHE_LOCATOR_CLASSES_GIVEN = "NUMBA_CACHE_LOCATOR_CLASSES" in os.environ
os.environ.setdefault("NUMBA_CACHE_LOCATOR_CLASSES", CACHE_LOCATOR_CLASSES)

if "numba" in sys.modules:  # numba may already be imported: its config read the environment then
    try:
        if not NUMBA_CACHE_DIR_GIVEN:
            sys.modules["numba"].config.CACHE_DIR = os.environ["NUMBA_CACHE_DIR"]
        sys.modules["numba"].config.CACHE_LOCATOR_CLASSES = os.environ["NUMBA_CACHE_LOCATOR_CLASSES"]
    except AttributeError:
        pass
