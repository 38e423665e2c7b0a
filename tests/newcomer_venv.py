"""A newcomer's environment, shared by the journeys (tests/test_journeys.py) and the main-job fixture
(conftest.quick_run): one fresh virtual environment per test session with the checkout installed as
``pip install -e .`` installs it, and the environment a newcomer's shell gives its commands.

Why one venv per session and not one per test: a venv with the package's own dependencies installed from an
index takes minutes and the network; instead, as tests/test_wheel_install.py does, a ``.pth`` line appends
the test environment's site-packages (numpy, numba, pandas, ...) after the venv's own, so the venv's install
of our package comes first and the rest is borrowed (what ``--system-site-packages`` does, but for whichever
environment runs pytest, a venv included).  The install is editable, so the kernels' numba cache is the
checkout's.  Under pytest-xdist the workers share the one venv: the first builds it under a lock in the
session's shared temporary directory.
"""
from __future__ import annotations

import os
import subprocess
import sys
import sysconfig
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def shared_tmp(tmp_path_factory, config) -> Path:
    """The temporary directory all pytest-xdist workers of this session share (the session's own without xdist)."""
    worker = getattr(config, "workerinput", {}).get("workerid", "master")
    return tmp_path_factory.getbasetemp() if worker == "master" else tmp_path_factory.getbasetemp().parent


def lock_dir(path: Path, timeout_s: float = 900.0):
    """A lock shared by xdist workers: the directory ``path`` exists while one holds it."""
    deadline = time.monotonic() + timeout_s
    while True:
        try:
            path.mkdir()
            return
        except FileExistsError:
            if time.monotonic() > deadline:
                raise TimeoutError(f"{path} held for over {timeout_s:.0f} s") from None
            time.sleep(0.5)


def build_venv(where: Path) -> Path:
    """A venv at ``where`` with the checkout installed editable; returns its bin directory."""
    import venv

    venv.create(where, with_pip=False)  # this interpreter's pip installs into it (--python): no ensurepip
    bindir = where / ("Scripts" if os.name == "nt" else "bin")
    py = bindir / "python"
    cmd = [sys.executable, "-m", "pip", "--python", str(py), "install", "--no-deps", "-q", "-e", str(ROOT)]
    try:  # offline when the build backend is here; otherwise pip fetches setuptools and wheel to build with
        import setuptools  # noqa: F401
        import wheel  # noqa: F401
        cmd.append("--no-build-isolation")
    except ImportError:
        pass
    proc = subprocess.run(cmd, capture_output=True, text=True)
    assert proc.returncode == 0, f"pip install -e failed:\n{proc.stdout[-2000:]}\n{proc.stderr[-4000:]}"
    venv_site = Path(subprocess.run([str(py), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                                    capture_output=True, text=True, check=True).stdout.strip())
    import site
    borrowed = dict.fromkeys([*site.getsitepackages(), sysconfig.get_paths()["purelib"]])
    (venv_site / "zz_borrowed_site_packages.pth").write_text("".join(f"{p}\n" for p in borrowed))
    assert (bindir / "bench-myriapoda").is_file(), "pip did not install the console script"
    return bindir


def session_venv(tmp_path_factory, config) -> Path:
    """The bin directory of the session's fresh venv, built once for all xdist workers."""
    shared = shared_tmp(tmp_path_factory, config)
    where, lock, done = shared / "journey-venv", shared / "journey-venv.lock", shared / "journey-venv.done"
    lock_dir(lock)
    try:
        if not done.exists():
            build_venv(where)
            done.write_text("ok")
    finally:
        lock.rmdir()
    return where / ("Scripts" if os.name == "nt" else "bin")


def newcomer_env(bindir: Path) -> dict[str, str]:
    """A newcomer's shell: the venv's bin first on PATH, nothing of the test process's import paths."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "BENCH_MYRIAPODA_ROOT", "PYTHONHOME")}
    env["PATH"] = str(bindir) + os.pathsep + env.get("PATH", "")
    env["VIRTUAL_ENV"] = str(bindir.parent)
    env["MPLBACKEND"] = "Agg"
    return env
