"""numba's on-disk cache found by a kernel's place inside the package, not by where the package is installed.

numba files a cached kernel under ``NUMBA_CACHE_DIR/<dir>_<sha1 of the source file's absolute directory>``, so
the same code at another path compiles every kernel again (about 40 to 100 CPU s per body group): a wheel
installed next to a checkout, a second git worktree of the same commit, a venv rebuilt elsewhere.  A path tells
two builds apart no better than the hash of every source file of the package (``core.source_hash.SOURCE_HASH``)
does, and numba (0.68, the version this was written against) stamps each cache index with the hash of its source
file's content.  So here a package kernel is filed under ``NUMBA_CACHE_DIR/package-<sources' hash>/<its
directory relative to the package>``, the same for every copy of the same code.  A function outside the package
(a user's plugin, a test file) is left to numba's own locators.

Installed by ``core/source_hash.py`` (imported first by the package) through numba's ``NUMBA_CACHE_LOCATOR_CLASSES`` (a user's own
setting wins).  A numba without that setting ignores it and keeps its path-keyed cache: slower, never wrong.
"""
from __future__ import annotations

import os
from pathlib import Path

from numba.core import config

from ..core.source_hash import SOURCE_HASH

try:  # numba's public name (the one NUMBA_CACHE_LOCATOR_CLASSES resolves)
    from numba.core.caching import UserProvidedCacheLocator
except ImportError:  # pragma: no cover - an older numba's name; it may not read NUMBA_CACHE_LOCATOR_CLASSES
    from numba.core.caching import _UserProvidedCacheLocator as UserProvidedCacheLocator

PACKAGE_ROOT = Path(__file__).resolve().parents[1]  # .../bench_myriapoda
# NUMBA_CACHE_DIR/package-<SOURCE_HASH>/<directory inside the package>/<module>.<kernel>-<line>.{nbi,nbc}.  The
# sources' hash again, although the suite's default NUMBA_CACHE_DIR already holds it: a NUMBA_CACHE_DIR of the
# user's own is shared by whatever code runs with it, and numba stamps a kernel's index with its own file only,
# so two versions of the package whose kernel files are equal but whose callees differ would load each other's
# machine code.
SUBDIR = f"package-{SOURCE_HASH}"

def package_relative_dir(py_file: str) -> tuple[str, ...] | None:
    """The directory of ``py_file`` relative to the package (``()`` for the package's top level), or None for a
    file outside it."""
    try:
        return Path(py_file).resolve().parent.relative_to(PACKAGE_ROOT).parts
    except (ValueError, OSError):
        return None


class PackageRelativeCacheLocator(UserProvidedCacheLocator):
    """numba's ``NUMBA_CACHE_DIR`` locator with the path-hashed subdirectory replaced by the kernel's directory
    inside the package; the source stamp (a hash of the file's content) and the file names stay numba's."""

    def __init__(self, py_func, py_file):
        super().__init__(py_func, py_file)
        self._cache_path = os.path.join(config.CACHE_DIR, SUBDIR, *package_relative_dir(py_file))

    @classmethod
    def from_function(cls, py_func, py_file):
        if not config.CACHE_DIR or package_relative_dir(py_file) is None:
            return None  # numba's next locator
        return super().from_function(py_func, py_file)
