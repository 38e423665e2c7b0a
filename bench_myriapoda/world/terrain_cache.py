"""Mesh terrains built once per machine: the MESH terrain vector kept on disk beside numba's cache.

Building a closed mesh's terrain vector (``meshes.mesh_terrain_params``: the hash grid and the signed distance at
every grid corner) is the most expensive set-up of a run: 6.6 CPU s for the paper's Fig. 1 skull (16
subdivisions, 2-core development machine, warm JIT), paid by every process that runs a mesh scenario once (each
matrix worker, each command, each test worker).  The vector depends only on the mesh's vertices and faces, the grid
settings and the code that builds it, so it is stored under a key made of all of them and read back by any later
process on the same machine.

The key holds: the mesh's vertices and faces (bytes, after scale and translation), the cell size and bands, the
hash of every source file of the package (``core.source_hash.SOURCE_HASH``: any code change builds afresh, as the
JIT cache does), and the code generation target (the host CPU's name and features and the ``NUMBA_CPU_NAME`` /
``NUMBA_CPU_FEATURES`` a user set: a vector computed for one target is never served to another, so a run that asks
for another target, as ``.ci/run``'s second golden pass does, computes its own).

A stored vector carries the SHA-256 of its bytes and is used only when it matches; anything unreadable, truncated
or altered is built again and replaced.  Writes go to a temporary file renamed into place (readers never see half a
file); a cache directory that cannot be written is no error, the vector is then built in each process as before.
"""
from __future__ import annotations

import hashlib
import os
import tempfile
from collections.abc import Callable, Iterable

import numpy as np

from ..core.paths import cache_root
from ..core.source_hash import SOURCE_HASH

FORMAT = 1  # bump when the stored layout changes


def cache_dir() -> str:
    """``terrain/`` under ``core.paths.cache_root()``."""
    return str(cache_root() / "terrain")


def _target() -> bytes:
    """The code generation target numba compiles for in this process."""
    try:
        from llvmlite import binding as llvm

        host = llvm.get_host_cpu_name() + ":" + llvm.get_host_cpu_features().flatten()
    except Exception:  # noqa: BLE001 - no llvmlite query: the environment alone keys it
        host = "unknown"
    return "|".join([host, os.environ.get("NUMBA_CPU_NAME", ""), os.environ.get("NUMBA_CPU_FEATURES", "")]).encode()


def key(arrays: Iterable[np.ndarray], settings: Iterable[float | str]) -> str:
    """The cache key (hex) of a mesh's arrays (their dtype, shape and bytes) and its grid settings."""
    h = hashlib.sha256()
    h.update(f"format {FORMAT} source {SOURCE_HASH}".encode())
    h.update(_target())
    for a in arrays:
        a = np.ascontiguousarray(a)
        h.update(f"{a.dtype.str}{a.shape}".encode())
        h.update(a.tobytes())
    h.update(repr([float(s) if not isinstance(s, str) else s for s in settings]).encode())
    return h.hexdigest()[:32]


def _read(path: str) -> np.ndarray | None:
    """The vector stored at path, or None when it is missing, unreadable or does not match its digest."""
    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError:
        return None
    digest, body = data[:32], data[32:]
    if len(body) == 0 or len(body) % 8 or hashlib.sha256(body).digest() != digest:
        return None
    return np.frombuffer(body, dtype="<f8").astype(np.float64)


def _write(path: str, f: np.ndarray) -> None:
    """Store f at path atomically; any failure leaves the cache as it was."""
    body = np.ascontiguousarray(f, dtype="<f8").tobytes()
    tmp = None
    try:
        os.makedirs(os.path.dirname(path), exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".part-", dir=os.path.dirname(path))
        with os.fdopen(fd, "wb") as fh:
            fh.write(hashlib.sha256(body).digest())
            fh.write(body)
        os.replace(tmp, path)
        tmp = None
    except OSError:
        pass
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def cached(k: str, build: Callable[[], np.ndarray]) -> np.ndarray:
    """The vector stored under key k, else ``build()``'s, stored for later processes. (n,) float64."""
    path = os.path.join(cache_dir(), k + ".f8")
    f = _read(path)
    if f is not None:
        return f
    f = np.asarray(build(), dtype=np.float64)
    _write(path, f)
    return f
