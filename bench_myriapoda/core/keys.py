"""Every configuration key ``--set`` accepts, described: type, default, allowed values, unit, meaning.

The list is derived from the same tables :func:`config.apply_override` checks
against (``schema.SECTIONS``, each body model's config class, ``TOP_LEVEL_SCALARS``),
minus the name keys that are chosen with flags (``config.NAME_KEYS``), so it cannot
drift from what is accepted.  ``bench-myriapoda keys`` prints it.
"""
from __future__ import annotations

import dataclasses
import re
from typing import Any

from . import registry
from .config import NAME_KEYS
from .errors import InputError
from .schema import SECTIONS, TOP_LEVEL_SCALARS, describe_section
from .suggest import did_you_mean

TOP = "top"  # the section name under which dt, duration and seed are listed

# Units by key-name suffix, longest first, for keys whose description states none.
_SUFFIX_UNITS = (("_kg_m3", "kg/m^3"), ("_deg_s", "deg/s"), ("_rad_s", "rad/s"), ("_m_s2", "m/s^2"), ("_m_s", "m/s"),
                 ("_n_m", "N/m"), ("_pa", "Pa"), ("_hz", "Hz"), ("_deg", "deg"), ("_kg", "kg"), ("_s", "s"),
                 ("_m", "m"))
_BRACKETS = re.compile(r"\[([^\[\]]+)\]")


def unit_of(key: str, doc: str) -> str:
    """The unit of a key: the ``[unit]`` groups of its description (``[lo, hi]``-style shapes, with a
    comma, are not units), else from its name's suffix (``_m``, ``_deg_s``, ...), else ``""``."""
    units = [u for u in _BRACKETS.findall(doc) if "," not in u and not u.startswith(("lo", "x", "-"))]
    if units:
        return ", ".join(dict.fromkeys(units))
    name = key.rsplit(".", 1)[-1]
    for suffix, unit in _SUFFIX_UNITS:
        if name.endswith(suffix):
            return unit
    return ""


def _allowed_text(allowed: dict[str, Any]) -> str:
    parts = []
    for op, word in (("ge", ">="), ("gt", ">"), ("le", "<="), ("lt", "<")):
        if op in allowed:
            parts.append(f"{word} {allowed[op]:g}")
    if "choices" in allowed:
        parts.append("one of " + ", ".join(map(str, allowed["choices"])))
    if "length" in allowed:
        parts.append(f"{allowed['length']} numbers")
    if "multiple" in allowed:
        parts.append(f"groups of {allowed['multiple']}")
    if allowed.get("ordered"):
        parts.append("lo <= hi")
    return ", ".join(parts)


def _plain(v: Any) -> Any:
    return list(v) if isinstance(v, tuple) else v


def _row(key: str, section: str, r: dict[str, Any]) -> dict[str, Any]:
    return {"key": key, "section": section, "type": r["type"], "default": _plain(r["default"]),
            "allowed": {k: _plain(v) for k, v in r["allowed"].items()}, "allowed_text": _allowed_text(r["allowed"]),
            "unit": unit_of(key, r["doc"]), "description": r["doc"]}


def sections() -> list[str]:
    """Every section name ``keys SECTION`` takes."""
    return [TOP, *SECTIONS, "body"]


def config_keys(section: str | None = None) -> list[dict[str, Any]]:
    """Every key ``--set`` accepts (of ``section``, or all), one dict per key and body model.

    Each dict: ``key`` (dotted, as ``--set`` takes it), ``section``, ``type``, ``default``,
    ``allowed`` (``ge``/``gt``/``le``/``lt``/``choices``/``length``/``multiple``/``ordered``),
    ``allowed_text``, ``unit`` and ``description``; a ``body.*`` key also has ``bodies``, the body
    models that have it with that default (a key with different defaults per model is listed once
    per default), and a gait's own key (not ``GaitConfig``'s) has ``gaits``, the gaits that have it.  Raises :class:`InputError` for an unknown section.
    """
    if section is not None and section not in sections():
        raise InputError("keys", None, f"unknown section {section!r}{did_you_mean(section, sections())}; "
                                       f"choose one of {', '.join(sections())}")
    registry.load_all()
    rows: list[dict[str, Any]] = []
    if section in (None, TOP):
        for key, (tp, meta) in TOP_LEVEL_SCALARS.items():
            r = {"type": {"float": "a number", "int": "an integer"}[tp], "default": {"seed": 0}.get(key),
                 "allowed": {k: v for k, v in meta.items() if k in ("ge", "gt", "le", "lt") and v is not None},
                 "doc": meta.get("doc", "")}
            rows.append(_row(key, TOP, r))
    for name, cls in SECTIONS.items():
        if section in (None, name):
            rows += [_row(f"{name}.{r['key']}", name, r) for r in describe_section(cls)
                     if f"{name}.{r['key']}" not in NAME_KEYS]
        if name == "gait" and section in (None, name):
            rows += _own_gait_keys(cls)
    if section in (None, "body"):
        rows += _shared_rows("body", "bodies", ((b, spec.config_cls) for b, spec in registry.BODIES.items()),
                             skip=lambda key: f"body.{key}" in NAME_KEYS)
    return rows


def _own_gait_keys(base: type) -> list[dict[str, Any]]:
    """The keys a gait's own configuration class adds to ``base`` (``GaitSpec.config_cls``), one row per key
    and default with ``gaits``, the gaits that have it (the muscle waves' shape keys, a plugin gait's own)."""
    common = {f.name for f in dataclasses.fields(base)}
    return _shared_rows("gait", "gaits", ((g, spec.config_cls) for g, spec in registry.GAITS.items()),
                        skip=lambda key: key in common)


def _shared_rows(section: str, owners_field: str, classes, skip) -> list[dict[str, Any]]:
    """One row per key of the (owner, config class) pairs ``classes`` and per default, description and range,
    with ``owners_field`` the sorted owners that have it that way; keys for which ``skip(key)`` is true are
    left out."""
    merged: dict[tuple, dict[str, Any]] = {}
    for owner, cls in sorted(classes, key=lambda oc: oc[0]):
        for r in describe_section(cls):
            if skip(r["key"]):
                continue
            ident = (r["key"], repr(r["default"]), r["doc"], repr(sorted(r["allowed"].items(), key=str)))
            if ident not in merged:
                merged[ident] = _row(f"{section}.{r['key']}", section, r)
                merged[ident][owners_field] = []
            merged[ident][owners_field].append(owner)
    return sorted(merged.values(), key=lambda row: (row["key"], row[owners_field]))


def accepted_keys() -> set[str]:
    """The dotted keys ``--set`` accepts (some body model's key for ``body.*``, some gait's for ``gait.*``), from
    the config tables."""
    registry.load_all()
    keys = set(TOP_LEVEL_SCALARS)
    keys |= {f"{s}.{f.name}" for s, cls in SECTIONS.items() for f in dataclasses.fields(cls)}
    keys |= {f"body.{f.name}" for spec in registry.BODIES.values() for f in dataclasses.fields(spec.config_cls)}
    keys |= {f"gait.{f.name}" for spec in registry.GAITS.values() for f in dataclasses.fields(spec.config_cls)}
    return keys - set(NAME_KEYS)
