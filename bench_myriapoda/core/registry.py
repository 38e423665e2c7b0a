"""Name -> implementation registries for body models and gaits.

The harness never branches on a backend's type: it looks a body model or a
gait up here by the name used on the command line and in files.  Backends
register themselves when ``bench_myriapoda.bodies`` is imported; gaits when
``bench_myriapoda.controllers`` is imported.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable


@dataclass(frozen=True)
class BodySpec:
    """A body model backend.

    ``config_cls``   frozen dataclass of the backend's ``[body]`` keys (has a ``name`` field).
    ``factory``      ``factory(case) -> Body`` building the simulated body for a resolved case.
    ``capabilities`` what the backend can honour, e.g. ``{"muscles", "friction:coulomb"}``.
    ``default_dt``   ``default_dt(body_config) -> float`` time step [s] when none is given.
    """

    name: str
    description: str
    config_cls: type
    factory: Callable[[Any], Any]
    capabilities: frozenset
    default_dt: Callable[[Any], float]


@dataclass(frozen=True)
class GaitSpec:
    """A gait (controller): what it needs from a body, and how it drives muscles."""

    name: str
    description: str
    requires: frozenset


BODIES: dict[str, BodySpec] = {}
GAITS: dict[str, GaitSpec] = {}


def register_body(spec: BodySpec) -> None:
    BODIES[spec.name] = spec


def register_gait(spec: GaitSpec) -> None:
    GAITS[spec.name] = spec


def load_all() -> None:
    """Import the packages whose modules register backends and gaits."""
    import bench_myriapoda.bodies  # noqa: F401
    import bench_myriapoda.controllers  # noqa: F401
