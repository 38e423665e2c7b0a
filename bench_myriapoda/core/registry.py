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


def _plugin_error(module: str, what: str) -> InputError:
    return InputError(PLUGINS_ENV, module, what)


def _import_plugin(module: str):
    """Import a plugin module by its dotted name; anything that goes wrong while it is imported (a bad
    name, a SyntaxError, an exception or endless recursion at import, ``SystemExit``) is an InputError
    naming the environment variable and the module, never a traceback or a silent exit."""
    parts = module.split(".")
    if not all(p.isidentifier() for p in parts):
        raise _plugin_error(module, "not a module name: give dotted Python names (my_package.bodies), "
                                    "comma-separated; relative names (.x) cannot be imported by name")
    try:
        return importlib.import_module(module)
    except RecursionError:
        raise _plugin_error(module, "cannot import the plugin module (endless recursion at import)") from None
    except (Exception, SystemExit) as exc:  # SystemExit: a plugin must not end the command with exit 0
        what = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
        raise _plugin_error(module, f"cannot import the plugin module ({what[:200]})") from None


def _table(mod, module: str, table: str) -> dict:
    """``mod.BODIES`` or ``mod.GAITS`` ({} when absent), which must be a dict."""
    try:
        rows = getattr(mod, table, {})
    except (Exception, SystemExit) as exc:  # a module __getattr__ that raises
        raise _plugin_error(f"{module}.{table}", f"reading it raised {type(exc).__name__}: {str(exc)[:200]}") from None
    if not isinstance(rows, dict):
        raise _plugin_error(f"{module}.{table}", f"must be a dict of specs by name, got {type(rows).__name__} "
                                                 f"{rows!r:.60}")
    return rows


def load_all() -> None:
    """Fill the lookups from the table modules (entries already there, e.g. added at run time, are kept).

    A plugin module that cannot be imported (see ``_import_plugin``), a table that is not a dict, a row that
    is not a spec of its own name, or a plugin row whose name another spec holds, is an ``InputError``
    naming the environment variable."""
    for module in table_modules():
        mod = importlib.import_module(module) if module == CATALOG_MODULE else _import_plugin(module)
        for table, lookup, kind in (("BODIES", BODIES, BodySpec), ("GAITS", GAITS, GaitSpec)):
            for name, spec in _table(mod, module, table).items():
                if not isinstance(spec, kind) or spec.name != name:
                    raise InputError(PLUGINS_ENV, f"{module}.{table}[{name!r}]",
                                     f"must be a {kind.__name__} named {name!r}")
                if module != CATALOG_MODULE and lookup.get(name, spec) is not spec:
                    raise InputError(PLUGINS_ENV, f"{module}.{table}[{name!r}]", "name already taken; choose "
                                                                               "another")
                lookup.setdefault(name, spec)
