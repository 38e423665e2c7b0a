"""Compiled compositions of a body and a controller: one numba call runs both for a chunk of steps.

Bodies and controllers never import each other (tests/test_import_graph.py); this package imports
both and composes their kernels.  ``legged_walk``: the leg controller on any body that offers a legged
pack (``bodies.legged_chunk``: today the hybrid, mass-spring and FEM myriapods; the runner's
``Stepper`` picks it where it applies).
"""
