"""numba's cache files found by a kernel's place in the package (``jit/cache_locator.py``): the same code at two
paths shares its compiled kernels; code outside the package keeps numba's own locators."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numba
from numba.core.caching import CompileResultCacheImpl

import bench_myriapoda
from bench_myriapoda.core import source_hash
from bench_myriapoda.jit.cache_locator import SUBDIR, PackageRelativeCacheLocator, package_relative_dir

ROOT = Path(bench_myriapoda.__file__).resolve().parent


def test_the_suite_installs_its_locator_first_and_keeps_numbas_own():
    names = numba.config.CACHE_LOCATOR_CLASSES.split(",")
    assert names[0] == "bench_myriapoda.jit.cache_locator.PackageRelativeCacheLocator"
    assert names[1:] == list(source_hash.NUMBA_LOCATORS)


def test_a_package_kernel_is_filed_by_its_directory_inside_the_package():
    from bench_myriapoda.bodies.massspring import kernels

    impl = CompileResultCacheImpl(kernels.advance.py_func)  # what numba makes for a cache=True kernel
    loc = impl.locator
    assert isinstance(loc, PackageRelativeCacheLocator)
    assert Path(loc.get_cache_path()) == Path(numba.config.CACHE_DIR) / SUBDIR / "bodies" / "massspring"
    assert package_relative_dir(str(ROOT / "__init__.py")) == ()


def test_code_outside_the_package_is_left_to_numba():
    assert package_relative_dir(__file__) is None
    assert PackageRelativeCacheLocator.from_function(test_code_outside_the_package_is_left_to_numba, __file__) is None


def test_a_copy_of_the_package_elsewhere_loads_the_kernels_compiled_here(tmp_path):
    """A kernel compiled (or loaded) by the checkout, then called from a copy of the package at another path
    (another worktree or install of the same code): loaded from the cache, not compiled again."""
    import numpy as np

    from bench_myriapoda.kinematics.rotations import matvec

    matvec(np.eye(3), 1.0, 2.0, 3.0)  # in numba's cache now, from the checkout's path
    copy = tmp_path / "elsewhere"
    shutil.copytree(ROOT, copy / "bench_myriapoda", ignore=shutil.ignore_patterns("__pycache__"))
    probe = ("import json, numpy as np, bench_myriapoda as bm; from bench_myriapoda.kinematics.rotations import "
             "matvec as k; k(np.eye(3), 1.0, 2.0, 3.0); import numba; print(json.dumps([bm.__file__, "
             "numba.config.CACHE_DIR, sum(k.stats.cache_hits.values()), sum(k.stats.cache_misses.values())]))")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "BENCH_MYRIAPODA_ROOT")}
    env["PYTHONPATH"] = str(copy)
    out = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, env=env, capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    file, cache_dir, hits, misses = json.loads(out.stdout.splitlines()[-1])
    assert Path(file).is_relative_to(copy)
    assert cache_dir == numba.config.CACHE_DIR  # the same sources, so the same cache directory
    assert (hits, misses) == (1, 0)


def test_a_changed_package_under_the_same_cache_dir_compiles_its_own(tmp_path):
    """A NUMBA_CACHE_DIR of the user's own is shared by every version of the package run with it: a copy whose
    kernel file is unchanged but whose other sources differ (a callee could be among them) must not load the
    first copy's machine code."""
    same, changed = tmp_path / "same", tmp_path / "changed"
    for where in (same, changed):
        shutil.copytree(ROOT, where / "bench_myriapoda", ignore=shutil.ignore_patterns("__pycache__"))
    with open(changed / "bench_myriapoda" / "core" / "errors.py", "a") as f:
        f.write("\n# another version of the package\n")
    probe = ("import json, numpy as np, bench_myriapoda as bm; from bench_myriapoda.kinematics.rotations import "
             "matvec as k; k(np.eye(3), 1.0, 2.0, 3.0); "
             "print(json.dumps([sum(k.stats.cache_hits.values()), sum(k.stats.cache_misses.values())]))")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "BENCH_MYRIAPODA_ROOT")}
    env["NUMBA_CACHE_DIR"] = str(tmp_path / "users-own-cache")

    def hits_misses(copy: Path) -> list:
        out = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, env=dict(env, PYTHONPATH=str(copy)),
                             capture_output=True, text=True, timeout=120)
        assert out.returncode == 0, out.stderr[-2000:]
        return json.loads(out.stdout.splitlines()[-1])

    assert hits_misses(same) == [0, 1]  # compiled into the empty cache
    assert hits_misses(changed) == [0, 1]  # another version: compiled again, not loaded
    assert hits_misses(same) == [1, 0]
