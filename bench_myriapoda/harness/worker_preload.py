"""What the local workers' fork server imports once, so that every worker forked from it starts with it loaded.

Importing this module imports the worker's code (``executors``, ``runner``: numpy, numba, scipy, every
body's kernels module) and registers the body models (``registry.load_all``), the part of a spawned
worker's start that does not depend on the case (see ``worker_start``).  Nothing here compiles a kernel.
"""
from ..core import registry
from . import executors, runner  # noqa: F401 -- imported for the fork server's children

registry.load_all()
