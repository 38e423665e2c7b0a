"""numba's compiled kernels, paid for once per machine rather than once per worker process.

``compile_lock``   each kernel signature compiled once across processes (a file lock per signature);
``compile_plan``   which kernels each compile group needs, recorded once (``compile_plans.json``), so idle
                   workers compile them ahead of the cases and the fork server loads the cached ones;
``worker_start``   the local workers forked from a server that imported the package and loaded those kernels;
``cache_locator``  numba's cache files found by a kernel's place in the package, not by its install path.

This package imports nothing of the rest of ``bench_myriapoda`` (the kernels are named, and imported by name,
in the recorded plans): the harness uses it, it does not use the harness.  The command that records the plans
runs the harness's executor and lives there (``harness/cold_compile.py``).
"""
