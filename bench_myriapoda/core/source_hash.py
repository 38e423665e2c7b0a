"""The hash of the package's sources, which keys what is built from the code and kept on disk, and numba's cache
directory keyed by it.

Imported first by the package's ``__init__`` (so before anything imports numba): it sets ``NUMBA_CACHE_DIR`` to
``~/.cache/bench-myriapoda/numba/<SOURCE_HASH>`` unless the user set it.  Also keyed by the hash: the mesh terrains
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
    if "numba" in sys.modules:  # numba may already be imported: its config read the environment then
        try:
            sys.modules["numba"].config.CACHE_DIR = os.environ["NUMBA_CACHE_DIR"]
        except AttributeError:
            pass
