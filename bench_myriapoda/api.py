"""The Python API: run a case from a script or a notebook.

    import bench_myriapoda as bm
    result = bm.run(creature="worm", body="fem", scenario="flat", duration=4.0)
    result.status, result.metrics["speed_bl_per_cycle"]
"""
from __future__ import annotations

from typing import Any, Iterable, Mapping

from .core.config import resolve_case
from .harness.runner import RunResult, run_case


def run(creature: str, body: str, scenario: str, gait: str | None = None, *, duration: float | None = None,
        dt: float | None = None, seed: int | None = None, controller: Any = None,
        set: Mapping[str, Any] | Iterable[str] = (), **overrides: Any) -> RunResult:
    """Resolve a case exactly as the command line does and run it; nothing is stored.

    ``set``: dotted configuration keys, as ``--set`` takes them ({"friction.mu_transverse": 0.2} or
    ["friction.mu_transverse=0.2"]); keyword ``overrides`` spell the dots as double underscores
    (``friction__mu_transverse=0.2``).  ``controller``: your own controller object
    (``core.protocols.Controller``: ``reset(case, body_info, rng)`` and ``step(obs, t, act)``)
    instead of the gait's.  Bad input raises ``core.errors.InputError`` with its one-line message.
    """
    items = [f"{k}={v}" for k, v in set.items()] if isinstance(set, Mapping) else list(set)
    items += [f"{k.replace('__', '.')}={v}" for k, v in overrides.items()]
    case = resolve_case(creature, body, scenario, gait, duration=duration, dt=dt, seed=seed, overrides=items)
    return run_case(case, controller=controller)
