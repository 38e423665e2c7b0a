"""The flags that choose and configure one case (``run``, ``stable-dt``) and the resource budget a case must fit
before it runs (those two and ``matrix``): the flags, the case they resolve to, and the checks of both."""
from __future__ import annotations

import argparse
import math

from ..core import registry
from ..core.config import resolve_case
from ..core.errors import InputError
from ..core.feasibility import check_budget, check_buildable
from ..world.buildable import check_placements


def bodies() -> list[str]:
    registry.load_all()
    return list(registry.BODIES)


def case_arguments(p: argparse.ArgumentParser) -> None:
    """The flags that select and configure one case (shared by run and stable-dt)."""
    p.add_argument("--creature", required=True, help="creature name (models/NAME.toml) or a .toml path")
    p.add_argument("--body", required=True, help="body model: " + ", ".join(sorted(bodies())))
    p.add_argument("--scenario", required=True, help="scenario name (scenarios/NAME.toml) or a .toml path")
    p.add_argument("--gait", help="gait (default: the creature's default gait)")
    p.add_argument("--duration", type=float, metavar="SECONDS",
                   help="simulated time [s] (default: the scenario's scenario.duration_s)")
    p.add_argument("--dt", type=float, metavar="SECONDS", help="time step [s] (default: the body model's)")
    p.add_argument("--seed", type=int, metavar="N", help="random seed (default 0)")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="override a configuration key by dotted path, e.g. friction.mu_transverse=0.2 "
                        "(repeatable; `bench-myriapoda keys` lists them all)")


def budget_arguments(p: argparse.ArgumentParser) -> None:
    """The resource budget a case must fit before it runs (core/feasibility.py)."""
    p.add_argument("--force", action="store_true", help="run a case even when its resource estimate exceeds "
                                                        "the budget below")
    p.add_argument("--memory-budget", type=float, metavar="GB", default=None,
                   help="refuse a case estimated to need more memory (default: half of this machine's)")
    p.add_argument("--max-steps", type=float, metavar="N", default=None,
                   help="refuse a case of more time steps (duration / dt; default 1e9)")


def resolve(args):
    """The case the flags of :func:`case_arguments` choose (``core.config.resolve_case``)."""
    return resolve_case(args.creature, args.body, args.scenario, args.gait, duration=args.duration, dt=args.dt,
                        seed=args.seed, overrides=args.set)


def case_source(args) -> str:
    """How a message names the case of run and stable-dt: CREATURE/BODY/SCENARIO as given."""
    return f"{args.creature}/{args.body}/{args.scenario}"


def check_case_fits(case, args, source: str, keep_nodes: bool = False, buildable: bool = True):
    """(Unless --force) the case fits the resource budget and (``buildable``) its body can be built
    (core/feasibility.py) and its world too: returns that world (``world.world.World``, built once by
    ``world.buildable.check_placements``; the caller runs the case in it), None when not ``buildable``."""
    budget = None
    if args.memory_budget is not None:
        if not (math.isfinite(args.memory_budget) and args.memory_budget > 0):
            raise InputError("--memory-budget", None, f"{args.memory_budget} is out of range; must be a number of GB > 0")
        budget = args.memory_budget * 1e9
    if args.max_steps is not None and not (math.isfinite(args.max_steps) and args.max_steps >= 1):
        raise InputError("--max-steps", None, f"{args.max_steps} is out of range; must be a number >= 1")
    if not args.force:
        check_budget(case, source, budget, args.max_steps, keep_nodes)
    elif not math.isfinite(case.duration / case.dt) or case.duration / case.dt > 2 ** 62:
        raise InputError(source, None, f"duration {case.duration:g} s / dt {case.dt:g} s: too many steps to count, "
                                       "even with --force")
    if not buildable:
        return None
    check_buildable(case, source)
    return check_placements(case, source)
