"""Named records at the boundary between Python and a numba kernel.

A kernel's inputs are named records (``collections.namedtuple``: numba compiles one as a struct of its fields,
and a kernel reads them by name, ``links.x``; issue 42).  Python builds a record by field name.  Where a kernel
is called from Python often (a body's ``advance`` every step on the Python path, a fused chunk at every sample),
the record crosses the call as a plain tuple of its fields (:func:`plain`) and the kernel's entry names it again
with the same class (``FEMLinks(*links)``): numba's dispatcher types a namedtuple argument several times slower
than a plain tuple of the same fields (its C fingerprint of a namedtuple spells out the class and field names),
while building a namedtuple inside compiled code costs nothing.  Measured on the 18-segment hybrid chain's five
records (a trivial ``@njit`` kernel taking them, numba 0.68.1, timeit best of 5): 18.1 us a call as namedtuples,
7.1 us as plain tuples.  Both ends use one class, so the fields' order is the class's by construction, never
counted by hand.
"""
from __future__ import annotations


def plain(record: tuple) -> tuple:
    """``record`` (a namedtuple) as a plain tuple of its fields, in the class's order, for a kernel call from
    Python (module docstring); a nested record stays as it is (make it plain first where it crosses too)."""
    return tuple(record)
