"""Name -> implementation lookups for body models and gaits.

The harness never branches on a backend's type: it looks a body model or a gait up here by the
name used on the command line and in files.  The entries come from explicit tables -- modules with
a ``BODIES`` dict of ``BodySpec`` and a ``GAITS`` dict of ``GaitSpec`` by name (nothing registers
itself on import) -- which :func:`load_all` reads by module name, as a package's entry points are
read: first the built-in ``bench_myriapoda.catalog``, then each module named in the environment
variable ``BENCH_MYRIAPODA_PLUGINS`` (comma-separated), so that a researcher's own body model or
gait runs through the command line without a change to the package.  Reading them by name keeps
this lowest layer from importing the catalog, which imports every body and controller.
``register_body`` / ``register_gait`` add entries at run time (a test, or a script).
"""
from __future__ import annotations

import importlib
import os

from .errors import InputError
from .specs import BodySpec, GaitSpec

CATALOG_MODULE = "bench_myriapoda.catalog"
PLUGINS_ENV = "BENCH_MYRIAPODA_PLUGINS"

BODIES: dict[str, BodySpec] = {}
GAITS: dict[str, GaitSpec] = {}


def register_body(spec: BodySpec) -> None:
    BODIES[spec.name] = spec


def register_gait(spec: GaitSpec) -> None:
    GAITS[spec.name] = spec


def table_modules() -> list[str]:
    """The modules whose tables fill the lookups: the catalog, then ``$BENCH_MYRIAPODA_PLUGINS``'s."""
    plugins = [m.strip() for m in os.environ.get(PLUGINS_ENV, "").split(",")]
    return [CATALOG_MODULE] + [m for m in plugins if m]


def load_all() -> None:
    """Fill the lookups from the table modules (entries already there, e.g. added at run time, are kept).

    A plugin module that cannot be imported, a row that is not a spec of its own name, or a plugin row whose
    name another spec holds, is an ``InputError`` naming the environment variable."""
    for module in table_modules():
        try:
            mod = importlib.import_module(module)
        except ImportError as exc:
            if module == CATALOG_MODULE:
                raise
            raise InputError(PLUGINS_ENV, module, f"cannot import the plugin module ({exc})") from None
        for table, lookup, kind in (("BODIES", BODIES, BodySpec), ("GAITS", GAITS, GaitSpec)):
            for name, spec in getattr(mod, table, {}).items():
                if not isinstance(spec, kind) or spec.name != name:
                    raise InputError(PLUGINS_ENV, f"{module}.{table}[{name!r}]",
                                     f"must be a {kind.__name__} named {name!r}")
                if module != CATALOG_MODULE and lookup.get(name, spec) is not spec:
                    raise InputError(PLUGINS_ENV, f"{module}.{table}[{name!r}]", "name already taken; choose "
                                                                               "another")
                lookup.setdefault(name, spec)
