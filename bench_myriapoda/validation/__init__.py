"""``bench-myriapoda validate``: verdicts against the papers and analytic references.

One module per family of checks (``analytic``, ``miller``, ``paper``, ``cross_body``,
``throughput``), the explicit table of checks in ``registry``, the shared types and verdict
rules in ``core``, the runner and the store table in ``run``, and the work-precision
diagrams in ``work_precision``.  Importing this package imports nothing else.
"""
