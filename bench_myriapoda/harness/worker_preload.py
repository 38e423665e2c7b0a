"""What the local workers' fork server imports once, so that every worker forked from it starts with it loaded.

Importing this module imports the worker's code (``executors``, ``runner``: numpy, numba, scipy, every
body's kernels module) and registers the body models (``registry.load_all``), the part of a spawned
worker's start that does not depend on the case (see ``worker_start``).  Nothing here compiles a kernel.
"""
from ..core import registry
from ..core.errors import InputError
from . import executors, runner  # noqa: F401 -- imported for the fork server's children

try:
    registry.load_all()
except InputError:
    # A plugin module (BENCH_MYRIAPODA_PLUGINS) found only on the parent's sys.path: before Python 3.12 the fork
    # server does not take the parent's sys.path, its forked workers do.  The catalog's rows are loaded by now;
    # each worker loads the tables again once forked (executors' worker loop) and reports a plugin that fails.
    pass
