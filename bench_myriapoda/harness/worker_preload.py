"""What the local workers' fork server imports once, so that every worker forked from it starts with it loaded.

Importing this module imports the worker's code (``executors``, ``runner``: numpy, numba, scipy, every
body's kernels module), registers the body models (``registry.load_all``) and loads the recorded compile
groups' top-level kernels that are in numba's disk cache (``compile_plan.preload_cached``): the part of a
worker's start that does not depend on the case (see ``worker_start``).  A forked worker then finds those
kernels loaded instead of loading them from the cache for its first case of each group.  Nothing here
compiles a kernel: on a cold cache nothing is loaded.
"""
from ..core import registry
from ..core.errors import InputError
from . import executors, runner  # noqa: F401 -- imported for the fork server's children
from ..jit.compile_plan import preload_cached

try:
    registry.load_all()
except InputError:
    # A plugin module (BENCH_MYRIAPODA_PLUGINS) found only on the parent's sys.path: before Python 3.12 the fork
    # server does not take the parent's sys.path, its forked workers do.  The catalog's rows are loaded by now;
    # each worker loads the tables again once forked (executors' worker loop) and reports a plugin that fails.
    pass

try:
    preload_cached()
except Exception:  # noqa: BLE001 -- an exception here would stop the fork server; the workers load their own
    pass
