"""The numba environment variables the suite depends on, checked before numba is imported.

numba reads its ``NUMBA_*`` variables once, at import.  A value it cannot parse (``NUMBA_OPT=abc``,
``NUMBA_DISABLE_JIT=yes``) gets a multi-line warning with a traceback and is then ignored -- the run
goes on with exit 0 under a configuration nobody chose; ``NUMBA_NUM_THREADS=0`` is a traceback at
the first compile; an unknown ``NUMBA_CPU_NAME`` makes LLVM print "not a recognized processor" and
compile for a baseline target (or abort); ``NUMBA_CACHE_DIR`` that is a file makes every
``cache=True`` kernel fail to save.  :func:`check_numba_env` turns each into one ``InputError``
naming the variable and what is allowed, before anything runs.
"""
from __future__ import annotations

import os
import sys
import tempfile
from collections.abc import Mapping

from . import source_hash
from .errors import InputError

THREADING_LAYERS = ("default", "safe", "forksafe", "threadsafe", "tbb", "omp", "workqueue")
OPT_LEVELS = ("0", "1", "2", "3", "max")


def _int_in(env: Mapping[str, str], name: str, lo: int, hi: int | None, meaning: str) -> None:
    if name not in env:
        return
    text = env[name]
    try:
        v = int(text)
    except ValueError:
        v = None
    if v is None or v < lo or (hi is not None and v > hi):
        allowed = f"an integer {lo} to {hi}" if hi is not None else f"an integer >= {lo}"
        raise InputError(name, None, f"{text!r:.40} is not allowed; must be {allowed} ({meaning}), or unset")


def check_numba_env(env: Mapping[str, str] | None = None) -> None:
    """Each numba variable the suite depends on, when set, has a value numba uses as given (module
    docstring); an ``InputError`` naming the variable otherwise."""
    env = os.environ if env is None else env
    _int_in(env, "NUMBA_NUM_THREADS", 1, None, "threads of numba's parallel pool")
    _int_in(env, "NUMBA_DISABLE_JIT", 0, 1, "1 runs the kernels as plain Python")
    if "NUMBA_OPT" in env and env["NUMBA_OPT"] not in OPT_LEVELS:
        raise InputError("NUMBA_OPT", None, f"{env['NUMBA_OPT']!r:.40} is not allowed; must be one of "
                                            f"{', '.join(OPT_LEVELS)} (LLVM's optimisation level), or unset")
    layer = env.get("NUMBA_THREADING_LAYER")
    if layer is not None and layer not in THREADING_LAYERS:
        raise InputError("NUMBA_THREADING_LAYER", None, f"{layer!r:.40} is not allowed; must be one of "
                                                        f"{', '.join(THREADING_LAYERS)}, or unset")
    if "NUMBA_CACHE_DIR" in env and (source_hash.NUMBA_CACHE_DIR_GIVEN or env is not os.environ):  # not our default
        _check_cache_dir(env["NUMBA_CACHE_DIR"])
    cpu = env.get("NUMBA_CPU_NAME")
    if cpu:  # empty: numba's default, the host's CPU
        _check_cpu_name(cpu)
    if "NUMBA_CACHE_LOCATOR_CLASSES" in env and (source_hash.NUMBA_CACHE_LOCATOR_CLASSES_GIVEN
                                                 or env is not os.environ):  # not our default
        _check_locator_classes(env["NUMBA_CACHE_LOCATOR_CLASSES"])


def _check_cache_dir(text: str) -> None:
    """NUMBA_CACHE_DIR: a directory that exists and is writable, or can be made (its nearest existing
    parent is a writable directory).  Empty means numba's default (beside each source file)."""
    name = "NUMBA_CACHE_DIR"
    if text == "":
        return
    if "\0" in text:
        raise InputError(name, None, "contains a NUL character; give a directory path")
    path = os.path.abspath(text)
    probe = path
    while not os.path.lexists(probe):
        parent = os.path.dirname(probe)
        if parent == probe:
            break
        probe = parent
    if not os.path.isdir(probe):
        what = "is not a directory" if probe == path else f"cannot be made: {probe} is not a directory"
        raise InputError(name, None, f"{text!r:.200} {what}; give a directory numba can write its compiled "
                                     "kernels to, or unset it")
    if not os.access(probe, os.W_OK | os.X_OK):
        raise InputError(name, None, f"{text!r:.200}: {probe} is not writable; give a directory numba can write "
                                     "its compiled kernels to, or unset it")


def _check_locator_classes(text: str) -> None:
    """NUMBA_CACHE_LOCATOR_CLASSES: comma-separated numba locator names (``UserProvidedCacheLocator``, ...) or
    ``module.Class`` paths that import.  numba reads it at the first cached kernel and raises there (a traceback
    in the middle of a run) when an entry does not resolve."""
    import importlib

    from numba.core import caching  # here, not at the top: only a user's own setting pays numba's import

    name = "NUMBA_CACHE_LOCATOR_CLASSES"
    for entry in (e.strip() for e in text.split(",")):
        if not entry:
            continue
        if "." not in entry:
            if not isinstance(getattr(caching, entry, None), type):
                raise InputError(name, None, f"{entry!r:.60} is not one of numba's cache locators; give names such "
                                             "as UserProvidedCacheLocator or module.Class paths, or unset it")
            continue
        module, _, cls = entry.rpartition(".")
        try:
            ok = isinstance(getattr(importlib.import_module(module), cls, None), type)
        except Exception:  # noqa: BLE001 - any failure to import is the same answer
            ok = False
        if not ok:
            raise InputError(name, None, f"{entry!r:.100} does not import as a class; give module.Class paths or "
                                         "numba's locator names, or unset it")


def _check_cpu_name(cpu: str) -> None:
    """NUMBA_CPU_NAME: a processor LLVM knows (``generic``, ``haswell``, ``znver3``, ...).  LLVM says so
    only on stderr, when a target machine is made: that message is caught here (file descriptor 2 pointed
    at a temporary file for the call) and made the error.  Without real descriptors nothing is checked."""
    try:
        import llvmlite.binding as ll
    except ImportError:  # no llvmlite: numba cannot be imported either, and says so itself
        return
    try:
        ll.initialize_native_target()
        target = ll.Target.from_default_triple()
    except Exception:  # noqa: BLE001 -- an LLVM without a native target: numba reports that itself
        return
    try:
        sys.stderr.flush()
        saved = os.dup(2)
    except (OSError, ValueError, AttributeError):
        return
    with tempfile.TemporaryFile() as caught:
        try:
            os.dup2(caught.fileno(), 2)
            target.create_target_machine(cpu=cpu)
        finally:
            os.dup2(saved, 2)
            os.close(saved)
        caught.seek(0)
        said = caught.read().decode("utf-8", "replace")
    if "not a recognized processor" in said:
        raise InputError("NUMBA_CPU_NAME", None, f"{cpu!r:.60} is not a processor LLVM knows; give one such as "
                                                 "generic, haswell, skylake-avx512 or znver3, or unset it "
                                                 "(the host's)")
