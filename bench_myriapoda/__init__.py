"""bench-myriapoda: a benchmark suite for simulated myriapods, worms and snakes."""
from __future__ import annotations

import os

# First, for its effect: numba's cache directory, keyed by the hash of the sources, set before anything imports numba.
from .core import source_hash  # noqa: F401

__version__ = "0.1.0"

# Cold start (issue 13): numba's type inference tries many typing templates per operation and builds an error
# for each one that does not match (about 65,000 in one compile of the hybrid chain's kernels); with colorama
# installed, each error's message is coloured, which runs colorama's init and wraps stdout and stderr every
# time (5 % of the profiled compile).  Plain messages cost nothing; they only matter when a kernel fails to
# compile, and then they read the same without the terminal colours.  Read when numba.core.errors is imported
# (after this line, as the package does not import numba itself); a user's own setting wins.
os.environ.setdefault("NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING", "1")


# The Python API (api.py), imported on first use: `import bench_myriapoda` stays light (no numba,
# no pandas) and numba's cache directory is set (core.source_hash) before anything imports numba.
_API = ("run", "run_matrix", "load_results", "resolve", "Result", "Series")


def __getattr__(name: str):
    if name in _API:
        from . import api

        return getattr(api, name)
    raise AttributeError(f"module 'bench_myriapoda' has no attribute {name!r}")


def __dir__():
    return sorted(list(globals()) + list(_API))


__all__ = ["__version__", *_API]
