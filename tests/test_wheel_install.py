"""A normal (non-editable) install: build the wheel, install it into a fresh virtual
environment, and use it from a directory outside the checkout.

The wheel must carry ``models/`` and ``scenarios/`` (copied into
``bench_myriapoda/_data/`` by ``setup.py``), and the installed package must find
them without a checkout.  To keep the test offline-friendly and fast, the fresh venv
borrows the third-party packages (numpy, numba, ...) of the environment running the
tests: a ``.pth`` file appends that environment's site-packages to the venv's path
(the ``--system-site-packages`` idea, but for whichever environment runs pytest, a
venv included).  Our own package comes from the wheel: the venv's site-packages come
first, and the test checks that ``bench_myriapoda.__file__`` lies inside the venv.
"""
from __future__ import annotations

import json
import os
import shutil
import site
import subprocess
import sys
import sysconfig
import venv
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SOURCES = ("pyproject.toml", "setup.py", "MANIFEST.in", "README.md", "bench_myriapoda", "models", "scenarios")

pytestmark = pytest.mark.slow  # wheel build, venv, and one run that compiles its kernels: about a minute


def _data_files() -> set[str]:
    """Every data file the wheel must ship, as its path inside the wheel."""
    return {f"bench_myriapoda/_data/{p.relative_to(ROOT).as_posix()}"
            for d in ("models", "scenarios") for p in (ROOT / d).rglob("*.toml")}


def _build_wheel(src: Path, dist: Path) -> Path:
    """``pip wheel SRC --no-deps``: offline without build isolation when setuptools and wheel are here."""
    cmd = [sys.executable, "-m", "pip", "wheel", str(src), "--no-deps", "-w", str(dist), "-q"]
    try:
        import setuptools  # noqa: F401
        import wheel  # noqa: F401
        cmd.append("--no-build-isolation")
    except ImportError:  # pip fetches setuptools and wheel for an isolated build
        pass
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=src.parent)
    assert proc.returncode == 0, f"pip wheel failed:\n{proc.stdout}\n{proc.stderr}"
    wheels = list(dist.glob("bench_myriapoda-*.whl"))
    assert len(wheels) == 1, wheels
    return wheels[0]


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(venv python, venv bin dir, wheel path, a work directory outside the checkout, environment)."""
    tmp = tmp_path_factory.mktemp("wheel")
    src = tmp / "src"
    src.mkdir()
    for name in SOURCES:  # a copy: the build writes build/ and *.egg-info next to its sources
        p = ROOT / name
        if p.is_dir():
            shutil.copytree(p, src / name, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        else:
            shutil.copy2(p, src / name)
    whl = _build_wheel(src, tmp / "dist")
    env_dir = tmp / "venv"
    venv.create(env_dir, with_pip=False)  # this interpreter's pip installs into it (--python): no ensurepip
    bindir = env_dir / ("Scripts" if os.name == "nt" else "bin")
    py = bindir / "python"
    proc = subprocess.run([sys.executable, "-m", "pip", "--python", str(py), "install", "--no-deps",
                           "--ignore-installed", "-q", str(whl)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    # then the third-party packages of this environment, after the venv's own site-packages; a path
    # added by a .pth line is not itself scanned for .pth files, so an editable install of the checkout
    # there (a finder hooked in by a .pth) does not come along
    venv_site = Path(subprocess.run([str(py), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                                    capture_output=True, text=True, check=True).stdout.strip())
    borrowed = dict.fromkeys([*site.getsitepackages(), sysconfig.get_paths()["purelib"]])
    (venv_site / "zz_borrowed_site_packages.pth").write_text("".join(f"{p}\n" for p in borrowed))
    work = tmp / "elsewhere"
    work.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("BENCH_MYRIAPODA_ROOT", "PYTHONPATH")}
    # numba's cache is the checkout's (the default, keyed by the package's source hash; jit/cache_locator.py files
    # each kernel by its place in the package): the installed copy of the same code loads what the checkout compiled
    return py, bindir, whl, work, env


def _run(cmd, work, env, timeout=600):
    proc = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, cwd=work, env=env, timeout=timeout)
    assert proc.returncode == 0, f"{cmd} exited {proc.returncode}:\n{proc.stderr[-3000:]}"
    return proc.stdout


def test_wheel_ships_every_model_scenario_and_matrix_file(installed):
    _, _, whl, _, _ = installed
    with zipfile.ZipFile(whl) as z:
        names = set(z.namelist())
    want = _data_files()
    assert {"bench_myriapoda/_data/models/worm.toml", "bench_myriapoda/_data/scenarios/flat.toml",
            "bench_myriapoda/_data/scenarios/matrix/quick.toml", "bench_myriapoda/_data/scenarios/paper/walk.toml"} <= want
    assert want <= names, sorted(want - names)
    # base install stays lean: the heavy mesh and dask stacks are extras
    with zipfile.ZipFile(whl) as z:
        meta = next(z.read(n).decode() for n in z.namelist() if n.endswith(".dist-info/METADATA"))
    base = [ln for ln in meta.splitlines() if ln.startswith("Requires-Dist:") and "extra ==" not in ln]
    assert not any(pkg in ln for ln in base for pkg in ("pytetwild", "pyvista", "dask", "mujoco"))
    assert any("tqdm" in ln for ln in base)
    for extra in ("dask", "mesh", "peers", "test"):
        assert f"Provides-Extra: {extra}" in meta


def test_installed_package_comes_from_the_wheel_and_finds_its_data(installed):
    py, _, _, work, env = installed
    out = _run([py, "-c", "import json, bench_myriapoda as b; from bench_myriapoda.core import paths; "
                          "from bench_myriapoda.harness.matrix import matrix_paths; "
                          "print(json.dumps([b.__file__, str(paths.project_root()), sorted(matrix_paths())]))"],
               work, env)
    file, root, matrices = json.loads(out)
    venv_dir = py.parent.parent
    assert Path(file).is_relative_to(venv_dir), file
    assert Path(root) == Path(file).parent / "_data"
    assert matrices == sorted(p.stem for p in (ROOT / "scenarios" / "matrix").glob("*.toml"))


def test_installed_list_json_and_one_run_outside_the_checkout(installed):
    _, bindir, _, work, env = installed
    cat = json.loads(_run([bindir / "bench-myriapoda", "list", "--json"], work, env))
    assert sorted(cat["creatures"]) == sorted(p.stem for p in (ROOT / "models").glob("*.toml"))
    assert {"flat", "drop", "walk", "hang"} <= set(cat["scenarios"])  # top level and scenarios/paper
    venv_dir = bindir.parent
    assert all(Path(c["file"]).is_relative_to(venv_dir) for c in cat["creatures"].values())
    res = json.loads(_run([bindir / "bench-myriapoda", "run", "--creature", "worm", "--body", "massspring",
                           "--scenario", "flat", "--duration", "0.2", "--json", "--no-store"], work, env))
    assert res["status"] == "ok"
    assert res["case"]["scenario"]["name"] == "flat"
    assert res["timings"]["steps"] > 0 and res["metrics"]["body_length_m"] > 0
    assert list(work.iterdir()) == []  # --no-store: nothing written in the working directory


def test_installed_package_takes_a_users_own_files(installed):
    """A path to a .toml works wherever a name does, with no checkout around."""
    py, _, _, work, env = installed
    own = work / "own"
    own.mkdir(exist_ok=True)
    scen = (ROOT / "scenarios" / "flat.toml").read_text().replace('name = "flat"', 'name = "my-flat"')
    worm = (ROOT / "models" / "worm.toml").read_text().replace("segments = 20", "segments = 7")
    assert "my-flat" in scen and "segments = 7" in worm
    (own / "my-flat.toml").write_text(scen)
    (own / "my-worm.toml").write_text(worm)
    out = _run([py, "-c", "from bench_myriapoda.core.config import resolve_case; "
                          "c = resolve_case('my-worm.toml', 'massspring', 'my-flat.toml'); "
                          "print(c.creature.name, c.creature.segments, c.scenario.name)"], own, env)
    assert out.split() == ["worm", "7", "my-flat"]


def test_wheel_ships_the_recorded_compile_plans_and_the_installed_package_reads_them(installed):
    """The compile plans are a data file (``jit/compile_plans.json``, package data in pyproject.toml), not a module:
    the wheel carries it and the installed package reads the same plans as the checkout."""
    py, _, whl, work, env = installed
    with zipfile.ZipFile(whl) as z:
        assert "bench_myriapoda/jit/compile_plans.json" in z.namelist()
    out = _run([py, "-c", "import json; from bench_myriapoda.jit import compile_plan as cp; d = cp.shipped_plans(); "
                          "print(json.dumps([cp.PLANS_FILE.as_posix(), d.numba_version, sorted(d.plans)]))"], work, env)
    path, version, groups = json.loads(out)
    assert Path(path).is_relative_to(py.parent.parent), path
    from bench_myriapoda.jit.compile_plan import read_plans

    here = read_plans()
    assert version == here.numba_version and groups == sorted(here.plans) and groups


def test_the_installed_copy_loads_the_kernels_the_checkout_compiled(installed):
    """The same code installed elsewhere compiles nothing (jit/cache_locator.py): numba's cache files are found by
    a kernel's place inside the package, not by the install path, and the cache directory by the sources' hash."""
    import numba

    import bench_myriapoda as here

    py, _, _, work, env = installed
    assert here.run("worm", "massspring", "flat", duration=0.05).status == "ok"  # the checkout's kernels, cached
    probe = ("import json, numba, sys, bench_myriapoda as bm; r = bm.run('worm', 'massspring', 'flat', duration=0.05); "
             "ks = {id(o): o for m in list(sys.modules.values()) if m and m.__name__.startswith('bench_myriapoda') "
             "for o in vars(m).values() if isinstance(o, numba.core.dispatcher.Dispatcher)}.values(); "
             "print(json.dumps([r.status, bm.core.source_hash.SOURCE_HASH, bm.__file__, numba.config.CACHE_DIR, "
             "sum(sum(k.stats.cache_hits.values()) for k in ks), sum(sum(k.stats.cache_misses.values()) for k in ks)]))")
    status, source_hash, file, cache_dir, hits, misses = json.loads(_run([py, "-c", probe], work, env).splitlines()[-1])
    assert status == "ok" and Path(file).is_relative_to(py.parent.parent), file
    assert source_hash == here.core.source_hash.SOURCE_HASH  # the wheel carries the same sources
    assert cache_dir == numba.config.CACHE_DIR
    assert hits > 0 and misses == 0, (hits, misses)  # the run's entry kernels (8 for this worm), all loaded
