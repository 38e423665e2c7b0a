"""Loading creature and scenario files and resolving one case.

Layers, later ones win:

1. the defaults of each section (``schema.py``, the backend's config class);
2. the creature file ``models/<creature>.toml`` (its ``[gaits.<gait>]`` and
   ``[bodies.<body>]`` tables fill the ``gait`` and ``body`` sections; a gait's
   ``[gaits.<gait>.bodies.<body>]`` table replaces body keys while that gait runs);
3. the scenario file ``scenarios/<scenario>.toml``;
4. command-line flags ``--duration``, ``--dt``, ``--seed``;
5. ``--set KEY=VALUE`` overrides by dotted path.

Every layer is validated where it comes from, so an error names the file or
flag that introduced it.  Nothing here touches the results store.
"""
from __future__ import annotations

import dataclasses
import hashlib
import json
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Mapping

from . import registry
from .errors import InputError
from .paths import models_dir, scenarios_dir
from .suggest import did_you_mean
from .userpaths import check_input_file
from .schema import (SECTIONS, TOP_LEVEL_SCALARS, AntennaeConfig, CollisionConfig, ControllerConfig, CreatureConfig,
                     FoodConfig, FrictionConfig, GaitConfig, LegsConfig, MetricsConfig, RecordConfig, ScenarioConfig,
                     StabilityConfig, check_range, check_section, coerce_value)

CREATURE_FILE_TABLES = {"creature", "legs", "controller", "antennae", "friction", "collision", "gaits", "bodies",
                        "record", "stability", "metrics"}
SCENARIO_FILE_TABLES = {"scenario", "controller", "antennae", "food", "friction", "collision", "record", "stability",
                        "metrics"}
NAME_KEYS = {"creature.name": "--creature", "body.name": "--body", "gait.name": "--gait", "scenario.name": "--scenario"}


@dataclass(frozen=True)
class Case:
    """A fully resolved case: everything a run needs, nothing implicit."""

    creature: CreatureConfig
    legs: LegsConfig
    controller: ControllerConfig
    body: Any
    gait: GaitConfig
    friction: FrictionConfig
    collision: CollisionConfig
    scenario: ScenarioConfig
    record: RecordConfig
    stability: StabilityConfig
    metrics: MetricsConfig
    dt: float
    duration: float
    seed: int
    antennae: AntennaeConfig = dataclasses.field(default_factory=AntennaeConfig)
    food: FoodConfig = dataclasses.field(default_factory=FoodConfig)

    def to_dict(self) -> dict[str, Any]:
        d = dataclasses.asdict(self)
        d["creature"]["gaits"] = list(d["creature"]["gaits"])
        for k in ("control_times_s", "control_speed_m_s", "control_turn_rate_deg_s"):
            d["scenario"][k] = list(d["scenario"][k])
        return d

    def case_hash(self) -> str:
        """sha256 of the canonical JSON of the resolved configuration (first 16 hex digits).

        Computed once per object: a matrix asks for the hash of each of its cases thousands of times
        (labels, resume, the results table), and each computation walks the whole case
        (``dataclasses.asdict``, about 3 ms).  The cached value cannot go stale: a Case and its sections
        are frozen dataclasses whose lists are tuples (``schema.coerce_value``), and ``dataclasses.replace``
        builds a new object.  A body config that is not frozen (a user's body model) is hashed afresh
        on every call.  The value is ``uncached_case_hash(self)``, unchanged (results are keyed by it).
        """
        h = self.__dict__.get("_case_hash")
        if h is None:
            h = uncached_case_hash(self)
            if _frozen(self.body):
                object.__setattr__(self, "_case_hash", h)  # frozen: __setattr__ refuses, __dict__ accepts
        return h

    @property
    def steps(self) -> int:
        return int(round(self.duration / self.dt))


def uncached_case_hash(case: Case) -> str:
    """``Case.case_hash`` computed from scratch: sha256 of ``json.dumps(case.to_dict(), sort_keys=True,
    separators=(",", ":"))``, first 16 hex digits."""
    blob = json.dumps(case.to_dict(), sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(blob.encode()).hexdigest()[:16]


def _frozen(obj: Any) -> bool:
    """True for an instance of a frozen dataclass (which nothing may change after it is built)."""
    params = getattr(type(obj), "__dataclass_params__", None)
    return bool(params is not None and params.frozen)


# --------------------------------------------------------------------------- files

MAX_TOML_BYTES = 10_000_000  # the largest shipped file is a few kB
MAX_TOML_DEPTH = 16  # tables and arrays nested deeper than any file of this project needs


def read_toml(path: Path) -> dict[str, Any]:
    """A TOML file as a dict; ``InputError`` naming the file for anything unreadable.

    Checked here, before any key is looked at: the file exists, is a regular file of at most
    ``MAX_TOML_BYTES``, is UTF-8, parses, and nests tables and arrays at most ``MAX_TOML_DEPTH`` deep.
    """
    src = str(path)
    p = check_input_file(path, src)  # a regular file: a FIFO would block the read
    try:
        with open(p, "rb") as fh:
            raw = fh.read(MAX_TOML_BYTES + 1)
    except FileNotFoundError:
        raise InputError(src, None, "file not found") from None
    except OSError as exc:
        raise InputError(src, None, f"cannot read file ({exc.strerror or exc})") from None
    if len(raw) > MAX_TOML_BYTES:
        raise InputError(src, None, f"larger than {MAX_TOML_BYTES:,} bytes; not a configuration file")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise InputError(src, None, f"not UTF-8: byte 0x{raw[exc.start]:02x} on line {line}; TOML files must be "
                                    "UTF-8") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(src, None, f"malformed TOML: {exc}") from None
    except RecursionError:
        raise InputError(src, None, f"malformed TOML: nested deeper than {MAX_TOML_DEPTH} levels") from None
    except ValueError as exc:  # an integer of more digits than Python converts
        raise InputError(src, None, f"a number Python cannot read ({_digits_problem(exc)})") from None
    _check_depth(data, src)
    return data


def _digits_problem(exc: ValueError) -> str:
    """What Python's integer digit limit (``sys.get_int_max_str_digits``) refused, in a few words."""
    import sys

    return f"an integer of more than {sys.get_int_max_str_digits():,} digits" if "digits" in str(exc) \
        else str(exc)[:80]


def _check_depth(data: Any, src: str, key: str = "") -> None:
    """Tables and arrays nested at most MAX_TOML_DEPTH deep (checked without recursion)."""
    stack = [(data, 0, key)]
    while stack:
        value, depth, key = stack.pop()
        if depth > MAX_TOML_DEPTH:
            raise InputError(src, key or None, f"nested deeper than {MAX_TOML_DEPTH} levels")
        if isinstance(value, dict):
            stack.extend((v, depth + 1, f"{key}.{k}" if key else str(k)) for k, v in value.items())
        elif isinstance(value, list):
            stack.extend((v, depth + 1, key) for v in value)


def read_tables(path: Path, allowed: set[str], required: str) -> dict[str, Any]:
    """A TOML file whose top-level tables must be among ``allowed`` and include ``required``."""
    data = read_toml(path)
    for table in data:
        if table not in allowed:
            raise InputError(str(path), table, f"unknown table; allowed: {', '.join(sorted(allowed))}")
    if required not in data:
        raise InputError(str(path), required, f"missing table [{required}]")
    return data


def _available(directory: Path, pattern: str) -> list[str]:
    return sorted(p.stem for p in directory.glob(pattern)) if directory.is_dir() else []


def creature_names() -> list[str]:
    return _available(models_dir(), "*.toml")


def scenario_paths() -> dict[str, Path]:
    """Scenario name -> file, for scenarios/*.toml and scenarios/paper/*.toml."""
    out: dict[str, Path] = {}
    for sub in ("", "paper"):
        d = scenarios_dir() / sub
        if d.is_dir():
            for p in sorted(d.glob("*.toml")):
                out.setdefault(p.stem, p)
    return out


def _locate(name: str, kind: str, flag: str, known: Mapping[str, Path]) -> Path:
    if name.lower().endswith(".toml"):  # a file of the user's (also FILE.TOML)
        return Path(name)
    if name not in known:
        raise InputError(flag, None, f"unknown {kind} {name!r}{did_you_mean(name, known)}; choose one of "
                                     f"{', '.join(sorted(known)) or '(none found)'}")
    return known[name]


def load_creature_file(name: str) -> tuple[Path, dict[str, Any]]:
    path = _locate(name, "creature", "--creature", {n: models_dir() / f"{n}.toml" for n in creature_names()})
    data = read_tables(path, CREATURE_FILE_TABLES, "creature")
    src = str(path)
    check_section(CreatureConfig, data["creature"], src, "creature")
    for table in ("legs", "controller", "antennae", "friction", "collision", "record", "stability", "metrics"):
        if table in data:
            check_section(SECTIONS[table], data[table], src, table)
    for table in ("gaits", "bodies"):
        if not isinstance(data.get(table, {}), dict):
            raise InputError(src, table, f"expected tables [{table}.NAME], got {data[table]!r}")
        for name, sub in data.get(table, {}).items():
            if isinstance(sub, dict) and "name" in sub:
                kind = "gait" if table == "gaits" else "body model"
                raise InputError(src, f"{table}.{name}.name", f"not allowed: the {kind} is named by the table "
                                                              f"[{table}.{name}] (and chosen with "
                                                              f"{'--gait' if table == 'gaits' else '--body'})")
    for gait, table in data.get("gaits", {}).items():
        if gait not in registry.GAITS:
            raise InputError(src, f"gaits.{gait}", f"unknown gait{did_you_mean(gait, registry.GAITS)}; choose one of "
                                                   f"{', '.join(sorted(registry.GAITS))}")
        gait_cls = registry.GAITS[gait].config_cls  # the gait's own keys (GaitSpec.config_cls)
        if not isinstance(table, dict):
            check_section(gait_cls, table, src, f"gaits.{gait}")  # names the bad value
            continue
        check_section(gait_cls, {k: v for k, v in table.items() if k != GAIT_BODY_TABLE}, src, f"gaits.{gait}")
        _check_gait_bodies(table.get(GAIT_BODY_TABLE, {}), src, gait)
    for body, table in data.get("bodies", {}).items():
        if body not in registry.BODIES:
            raise InputError(src, f"bodies.{body}", f"unknown body model{did_you_mean(body, registry.BODIES)}; "
                                                    f"choose one of {', '.join(sorted(registry.BODIES))}")
        check_section(registry.BODIES[body].config_cls, table, src, f"bodies.{body}")
    c = data["creature"]
    if isinstance(c.get("gaits"), list):  # a [gaits.X] table of a gait the creature does not list is never read
        for gait in data.get("gaits", {}):
            if gait not in c["gaits"]:
                raise InputError(src, f"gaits.{gait}", f"not among the creature's gaits ({', '.join(c['gaits'])}); "
                                                       "the table would never be used: add the gait to "
                                                       "creature.gaits or remove the table")
    if "default_gait" in c:
        _check_default_gait(c["default_gait"], c.get("gaits"), src)
    for gait in c.get("gaits", ()):
        if gait not in registry.GAITS:
            raise InputError(src, "creature.gaits", f"unknown gait {gait!r}{did_you_mean(gait, registry.GAITS)}; "
                                                    f"choose from {', '.join(sorted(registry.GAITS))}")
    return path, data


GAIT_BODY_TABLE = "bodies"  # [gaits.<gait>.bodies.<body>]: body keys that hold while the creature uses this gait


def _check_gait_bodies(tables: Any, src: str, gait: str) -> None:
    """Validate ``[gaits.<gait>.bodies.<body>]`` tables: body-model keys that replace the creature's
    ``[bodies.<body>]`` ones while it uses this gait (a sidewinder braces its body: models/snake.toml)."""
    where = f"gaits.{gait}.{GAIT_BODY_TABLE}"
    if not isinstance(tables, dict):
        raise InputError(src, where, f"expected tables [{where}.BODY], got {tables!r}")
    for body, table in tables.items():
        if body not in registry.BODIES:
            raise InputError(src, f"{where}.{body}", f"unknown body model{did_you_mean(body, registry.BODIES)}; "
                                                     f"choose one of {', '.join(sorted(registry.BODIES))}")
        if not isinstance(table, dict):
            raise InputError(src, f"{where}.{body}", f"expected a table of body keys, got {table!r}")
        if "name" in table:
            raise InputError(src, f"{where}.{body}.name", "not allowed: the body model is named by the table")
        check_section(registry.BODIES[body].config_cls, table, src, f"{where}.{body}")


def load_scenario_file(name: str) -> tuple[Path, dict[str, Any]]:
    path = _locate(name, "scenario", "--scenario", scenario_paths())
    data = read_tables(path, SCENARIO_FILE_TABLES, "scenario")
    src = str(path)
    for table in data:
        check_section(SECTIONS[table], data[table], src, table)
    return path, data


# --------------------------------------------------------------------------- overrides

def parse_set(item: str) -> tuple[str, Any]:
    """``KEY=VALUE`` with VALUE read as a TOML value, or as a bare string."""
    if "=" not in item:
        raise InputError("--set", item, "expected KEY=VALUE, e.g. --set friction.mu_transverse=0.2")
    key, raw = item.split("=", 1)
    key = key.strip()
    # exactly one value on one line: "v = {raw}" parsed as a document would take a newline and more
    # keys or tables after the value ("dt=0.001\ndt=5") and silently drop them
    if any(ord(ch) < 32 and ch != "\t" or ord(ch) == 127 for ch in raw):
        raise InputError("--set", key or item, "the value must be one line: one TOML value (a number, "
                                               "true/false, a quoted string or a list), or a bare word")
    try:
        doc = tomllib.loads(f"v = {raw}")
    except tomllib.TOMLDecodeError:
        return key, raw.strip()  # a bare word: --set friction.model=coulomb
    except RecursionError:  # 3,000 nested brackets: Python's parser recurses
        raise InputError("--set", key, f"the value nests lists or tables deeper than {MAX_TOML_DEPTH} levels") from None
    except ValueError as exc:  # an integer of more digits than Python converts (sys.get_int_max_str_digits)
        raise InputError("--set", key, f"the value is not a number Python can read ({_digits_problem(exc)})") from None
    if set(doc) != {"v"}:
        raise InputError("--set", key, f"{raw.strip()!r} is not one TOML value")
    _check_depth(doc["v"], "--set", key)
    return key, doc["v"]


def _section_cls(section: str, body_name: str, gait_name: str | None = None):
    if section == "body":
        return registry.BODIES[body_name].config_cls
    if section == "gait" and gait_name is not None:
        return registry.GAITS[gait_name].config_cls
    return SECTIONS.get(section)


def apply_override(layers: dict[str, Any], key: str, value: Any, source: str, body_name: str) -> None:
    """Validate one dotted override and write it into the nested ``layers``."""
    if key in NAME_KEYS:
        raise InputError(source, key, f"names are chosen with {NAME_KEYS[key]}, not by override")
    parts = key.split(".")
    allowed_sections = sorted(list(SECTIONS) + ["body"])
    if len(parts) == 1:
        if key not in TOP_LEVEL_SCALARS:
            raise InputError(source, key, f"unknown key{did_you_mean(key, TOP_LEVEL_SCALARS)}; allowed: "
                                          f"{', '.join(sorted(TOP_LEVEL_SCALARS))} "
                                          f"or SECTION.KEY with SECTION one of {', '.join(allowed_sections)}")
        tp, meta = TOP_LEVEL_SCALARS[key]
        v = coerce_value(value, {"float": float, "int": int}[tp], source, key)
        check_range(v, meta, source, key)
        layers[key] = v
        return
    if len(parts) != 2:
        raise InputError(source, key, "expected SECTION.KEY (one dot)")
    section, name = parts
    cls = _section_cls(section, body_name, layers.get("gait", {}).get("name"))
    if cls is None:
        raise InputError(source, key, f"unknown section {section!r}{did_you_mean(section, allowed_sections)}; "
                                      f"choose one of {', '.join(allowed_sections)}")
    checked = check_section(cls, {name: value}, source, section)
    layers.setdefault(section, {}).update(checked)


# --------------------------------------------------------------------------- resolution

def _check_after_overrides(layers: dict[str, Any], gait: str) -> None:
    """Cross-key checks that ``--set`` could break after the files passed them: the creature's gait
    names, the chosen gait still among them and still possible, and the control schedule's lengths."""
    cre = layers["creature"]
    for g in cre.get("gaits", ()):
        if g not in registry.GAITS:
            raise InputError("--set", "creature.gaits", f"unknown gait {g!r}; choose from {', '.join(sorted(registry.GAITS))}")
    if "gaits" in cre and gait not in cre["gaits"]:
        raise InputError("--set", "creature.gaits", f"{list(cre['gaits'])!r} does not include the chosen gait {gait!r}")
    if "legs" in registry.GAITS[gait].requires and cre.get("legs_per_segment", 0) == 0:
        raise InputError("--set", "creature.legs_per_segment", f"unsupported combination: gait {gait!r} needs legs")
    lens = _control_lengths(layers["scenario"])
    if len(set(lens.values())) > 1:
        raise InputError("--set", "scenario.control_*", f"the control schedule lists differ in length: {lens}")


def _check_default_gait(value: Any, gaits: Any, source: str) -> None:
    """``creature.default_gait``: a known gait, among the creature's ``gaits`` when it lists them."""
    if not isinstance(value, str) or not value:
        raise InputError(source, "creature.default_gait", f"{value!r}: expected a gait name; choose one of "
                                                          f"{', '.join(gaits or sorted(registry.GAITS))}")
    if value not in registry.GAITS:
        raise InputError(source, "creature.default_gait", f"unknown gait {value!r}{did_you_mean(value, registry.GAITS)}; "
                                                          f"choose one of {', '.join(gaits or sorted(registry.GAITS))}")
    if gaits is not None and value not in gaits:
        raise InputError(source, "creature.default_gait", f"{value!r} is not among the creature's gaits "
                                                          f"({', '.join(gaits)}); choose one of them")


def _overridden(overrides: Iterable[str], key: str) -> tuple[bool, Any]:
    """(True, value) when ``--set key=...`` is among ``overrides`` (the last one wins), else (False, None)."""
    found, value = False, None
    for item in overrides:
        if "=" in item and item.split("=", 1)[0].strip() == key:
            found, value = True, parse_set(item)[1]
    return found, value


def _control_lengths(sc: Mapping[str, Any]) -> dict[str, int]:
    """Lengths of the CONTROL schedule's three lists (a list not given has its default's length)."""
    keys = ("control_times_s", "control_speed_m_s", "control_turn_rate_deg_s")
    return {k: len(sc[k]) if k in sc else len(getattr(ScenarioConfig, k)) for k in keys}


def _froude_source(overrides: Iterable[str], spath: Path, sdata: Mapping, cpath: Path) -> str:
    """Where friction.froude was set, for an error message: --set, the scenario or the creature file."""
    if any(str(o).split("=", 1)[0].strip() == "friction.froude" for o in overrides):
        return "--set"
    return str(spath) if "froude" in sdata.get("friction", {}) else str(cpath)


def apply_froude(friction: FrictionConfig, body_length_m: float, period_s: float, gravity_m_s2: float,
                 source: str = "friction") -> FrictionConfig:
    """The friction with ``froude`` applied: mu_f = L / (T^2 g Fr), the other coefficients scaled by
    the same factor (their ratios to mu_f as given; a static -1 stays "same as kinetic").

    body_length_m: L [m]; period_s: gait period T [s]; gravity_m_s2: g [m/s^2].  Unchanged when
    froude is 0.  Idempotent.  Raises InputError when Fr > 0 cannot define mu_f (no gravity, a
    model without coefficients, or mu_forward = 0 so the ratios are undefined).
    """
    fr = friction.froude
    if fr <= 0.0:
        return friction
    if friction.model != "coulomb":
        raise InputError(source, "friction.froude", f"needs friction.model = 'coulomb' (the {friction.model!r} "
                                                    "model has no coefficients)")
    if gravity_m_s2 <= 0.0:
        raise InputError(source, "friction.froude", "needs gravity (scenario.gravity_m_s2 > 0)")
    if friction.mu_forward <= 0.0:
        raise InputError(source, "friction.froude", "needs friction.mu_forward > 0: the other coefficients "
                                                    "keep their ratios to it")
    denominator = period_s * period_s * gravity_m_s2 * fr
    scale = body_length_m / denominator / friction.mu_forward if 0.0 < denominator < math.inf else math.inf
    # an extreme gait period (gait.frequency_hz = 1e300: T^2 underflows to 0) or froude makes mu_f = L / (T^2 g Fr)
    # infinite, zero or not a number: refused here, before the run, not a ZeroDivisionError
    if not (math.isfinite(scale) and scale > 0.0 and math.isfinite(scale * max(
            friction.mu_forward, friction.mu_backward, friction.mu_transverse))):
        raise InputError(source, "friction.froude", f"Fr = {fr:g} with the gait period {period_s:g} s, body length "
                                                    f"{body_length_m:g} m and gravity {gravity_m_s2:g} m/s^2 gives "
                                                    "no finite friction coefficient mu_f = L / (T^2 g Fr); give a "
                                                    "gait.frequency_hz or friction.froude nearer 1")

    def scaled(mu: float) -> float:
        return mu if mu < 0.0 else mu * scale
    return dataclasses.replace(
        friction, mu_forward=friction.mu_forward * scale, mu_backward=friction.mu_backward * scale,
        mu_transverse=friction.mu_transverse * scale, mu_static_forward=scaled(friction.mu_static_forward),
        mu_static_backward=scaled(friction.mu_static_backward),
        mu_static_transverse=scaled(friction.mu_static_transverse))


def resolve_case(creature: str, body: str, scenario: str, gait: str | None = None, *,
                 duration: float | None = None, dt: float | None = None, seed: int | None = None,
                 overrides: Iterable[str] = ()) -> Case:
    """Resolve names, files and overrides into a validated :class:`Case`.

    Raises :class:`InputError` for anything a user could have typed wrong,
    including a (creature, body, gait) combination that is not supported.
    """
    overrides = list(overrides)  # read twice: applied, and asked where friction.froude came from
    registry.load_all()
    if body not in registry.BODIES:
        raise InputError("--body", None, f"unknown body model {body!r}{did_you_mean(body, registry.BODIES)}; "
                                         f"choose one of {', '.join(sorted(registry.BODIES))}")
    if gait is not None and gait not in registry.GAITS:
        raise InputError("--gait", None, f"unknown gait {gait!r}{did_you_mean(gait, registry.GAITS)}; "
                                         f"choose one of {', '.join(sorted(registry.GAITS))}")
    cpath, cdata = load_creature_file(creature)
    spath, sdata = load_scenario_file(scenario)
    spec = registry.BODIES[body]
    cre = dict(cdata["creature"])
    cre.setdefault("name", cpath.stem)
    given, value = _overridden(overrides, "creature.default_gait")
    if given:  # checked here, before the gait is chosen: without --gait it chooses the gait, as the file's would
        has_gaits, listed = _overridden(overrides, "creature.gaits")
        _check_default_gait(value, listed if has_gaits and isinstance(listed, list) else cre.get("gaits"), "--set")
        gait = gait or value
    gait = gait or cre.get("default_gait")
    if not gait:
        raise InputError("--gait", None, f"creature {cre['name']!r} has no default gait; pass --gait")
    supported_gaits = cre.get("gaits", [gait])
    if gait not in supported_gaits:
        raise InputError("--gait", None, f"unsupported combination: creature {cre['name']!r} does not support gait "
                                         f"{gait!r}; supported: {', '.join(supported_gaits)}")
    if not cdata.get("bodies"):  # (a truncated or unfinished file): name the file and the missing table
        raise InputError(str(cpath), f"bodies.{body}", f"missing table [bodies.{body}]: a creature file needs a "
                                                       "[bodies.BODY] table for each body model it runs on")
    if body not in cdata.get("bodies", {}) and spec.default_params is None:
        raise InputError("--body", None, f"unsupported combination: creature {cre['name']!r} has no {body!r} body "
                                         f"model; available: {', '.join(sorted(cdata.get('bodies', {}))) or 'none'}")
    if "legs" in registry.GAITS[gait].requires and cre.get("legs_per_segment", 0) == 0:
        raise InputError("--gait", None, f"unsupported combination: gait {gait!r} needs legs and creature "
                                         f"{cre['name']!r} has none")
    missing = registry.GAITS[gait].requires - spec.capabilities
    if missing:
        raise InputError("--gait", None, f"unsupported combination: body {body!r} cannot honour gait {gait!r} "
                                         f"(needs {', '.join(sorted(missing))})")

    gait_table = dict(cdata.get("gaits", {}).get(gait, {}))
    gait_bodies = gait_table.pop(GAIT_BODY_TABLE, {})
    layers: dict[str, Any] = {
        "creature": cre,
        # the gait's own body keys ([gaits.<gait>.bodies.<body>]) win over the creature's [bodies.<body>]
        # a creature that names no [bodies.<body>] table gets the backend's declared defaults (BodySpec.default_params)
        "body": {"name": body, **cdata.get("bodies", {}).get(body, spec.default_params), **gait_bodies.get(body, {})},
        "gait": {"name": gait, **gait_table},
        "scenario": {"name": spath.stem, **sdata["scenario"]},
    }
    for table in ("legs", "controller", "antennae", "food", "friction", "collision", "record", "stability", "metrics"):
        layers[table] = {**cdata.get(table, {}), **sdata.get(table, {})}
    lens = _control_lengths(layers["scenario"])
    if len(set(lens.values())) > 1:
        raise InputError(str(spath), "scenario.control_*", f"the control schedule lists differ in length: {lens}")
    friction_model = layers["friction"].get("model", FrictionConfig.model)
    if f"friction:{friction_model}" not in spec.capabilities:
        raise InputError(str(cpath), "friction.model", f"unsupported combination: body {body!r} has no "
                                                       f"{friction_model!r} friction")
    if duration is not None:
        apply_override(layers, "duration", duration, "--duration", body)
    if dt is not None:
        apply_override(layers, "dt", dt, "--dt", body)
    if seed is not None:
        apply_override(layers, "seed", seed, "--seed", body)
    for item in overrides:
        key, value = parse_set(item)
        apply_override(layers, key, value, "--set", body)
    friction_model = layers["friction"].get("model", FrictionConfig.model)
    if f"friction:{friction_model}" not in spec.capabilities:
        raise InputError("--set", "friction.model", f"unsupported combination: body {body!r} has no {friction_model!r} friction")
    _check_after_overrides(layers, gait)

    section_cls = {**SECTIONS, "gait": registry.GAITS[gait].config_cls}
    sections = {name: cls(**layers.get(name, {})) for name, cls in section_cls.items()}
    body_cfg = spec.config_cls(**layers["body"])
    scen: ScenarioConfig = sections["scenario"]
    sections["friction"] = apply_froude(sections["friction"], sections["creature"].body_length_m,
                                        sections["gait"].period_s, scen.gravity_m_s2, _froude_source(overrides, spath, sdata, cpath))
    case = Case(
        creature=sections["creature"], legs=sections["legs"], controller=sections["controller"], body=body_cfg, gait=sections["gait"], friction=sections["friction"],
        collision=sections["collision"], scenario=scen, record=sections["record"],
        stability=sections["stability"], metrics=sections["metrics"],
        dt=layers.get("dt", spec.default_dt(body_cfg)),
        duration=layers.get("duration", scen.duration_s),
        seed=layers.get("seed", 0),
        antennae=sections["antennae"], food=sections["food"],
    )
    if case.dt > case.duration:
        raise InputError("--dt", "dt", f"{case.dt} is longer than the duration {case.duration} s")
    return case
