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
from numba.core.caching import CacheImpl

import bench_myriapoda
from bench_myriapoda.jit.cache_locator import SUBDIR, PackageRelativeCacheLocator, package_relative_dir

ROOT = Path(bench_myriapoda.__file__).resolve().parent


def test_the_suite_installs_its_locator_first_and_keeps_numbas_own():
    names = numba.config.CACHE_LOCATOR_CLASSES.split(",")
    assert names[0] == "bench_myriapoda.jit.cache_locator.PackageRelativeCacheLocator"
    assert names[1:] == list(bench_myriapoda.NUMBA_LOCATORS)


def test_a_package_kernel_is_filed_by_its_directory_inside_the_package():
    from bench_myriapoda.bodies.massspring import kernels

    impl = CacheImpl.__subclasses__()[0](kernels.advance.py_func)  # numba's CompileResultCacheImpl
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
