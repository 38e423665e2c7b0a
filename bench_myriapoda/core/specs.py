"""What the catalog says of a body model backend and of a gait (``bench_myriapoda.catalog``)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable


@dataclass(frozen=True)
class BodySpec:
    """A body model backend.

    ``config_cls``   frozen dataclass of the backend's ``[body]`` keys (has a ``name`` field).
    ``factory``      ``factory(case) -> Body`` (``core.protocols.Body``) for a resolved case.
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
    """A gait: what it needs from a body (``requires``), and the controller that drives it
    (``controller(case) -> Controller``, ``core.protocols.Controller``)."""

    name: str
    description: str
    requires: frozenset
    controller: Callable[[Any], Any] | None = None
