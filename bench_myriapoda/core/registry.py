"""Name -> implementation lookups for body models and gaits.

The harness never branches on a backend's type: it looks a body model or a gait up here by the
name used on the command line and in files.  The entries come from one explicit table,
``bench_myriapoda.catalog`` (nothing registers itself on import); :func:`load_all` copies it in.
``register_body`` / ``register_gait`` add entries at run time (a test, or a researcher's own
backend in a script).
"""
from __future__ import annotations

from .specs import BodySpec, GaitSpec


BODIES: dict[str, BodySpec] = {}
GAITS: dict[str, GaitSpec] = {}


def register_body(spec: BodySpec) -> None:
    BODIES[spec.name] = spec


def register_gait(spec: GaitSpec) -> None:
    GAITS[spec.name] = spec


def load_all() -> None:
    """Fill the lookups from the catalog (once; entries added at run time are kept)."""
    from .. import catalog
    for name, spec in catalog.BODIES.items():
        BODIES.setdefault(name, spec)
    for name, spec in catalog.GAITS.items():
        GAITS.setdefault(name, spec)
