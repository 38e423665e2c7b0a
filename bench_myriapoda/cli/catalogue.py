"""``bench-myriapoda list``: the creatures, body models, gaits, scenarios and supported combinations."""
from __future__ import annotations

import json
from typing import Any

from ..core import registry
from ..core.config import creature_names, load_creature_file, read_toml, scenario_paths
from .exits import EXIT_OK
from .help_text import help_text


def add_parser(sub) -> None:
    ls = sub.add_parser("list", help="creatures, bodies, gaits, scenarios and supported combinations",
                        **help_text("list"))
    ls.add_argument("--json", action="store_true", help="print one JSON object")


def catalogue() -> dict[str, Any]:
    """Everything ``list`` reports, as plain data."""
    registry.load_all()
    creatures, combos = {}, []
    for name in creature_names():
        path, data = load_creature_file(name)
        c = data["creature"]
        gaits = list(c.get("gaits", [c.get("default_gait")]))
        bodies = sorted(data.get("bodies", {}))
        creatures[name] = {"description": c.get("description", ""), "default_gait": c.get("default_gait"),
                           "gaits": gaits, "bodies": bodies, "file": str(path)}
        for b in bodies:
            for g in gaits:
                if not (registry.GAITS[g].requires - registry.BODIES[b].capabilities):
                    combos.append({"creature": name, "body": b, "gait": g})
    scenarios = {}
    for name, path in scenario_paths().items():
        scenarios[name] = {"description": read_toml(path).get("scenario", {}).get("description", ""), "file": str(path)}
    return {
        "creatures": creatures,
        "bodies": {n: {"description": s.description, "capabilities": sorted(s.capabilities)}
                   for n, s in sorted(registry.BODIES.items())},
        "gaits": {n: {"description": s.description, "requires": sorted(s.requires)} for n, s in sorted(registry.GAITS.items())},
        "scenarios": scenarios,
        "supported": combos,
    }


def cmd_list(args) -> int:
    cat = catalogue()
    if args.json:
        print(json.dumps(cat, indent=2))
        return EXIT_OK
    print("creatures:")
    for n, c in cat["creatures"].items():
        print(f"  {n:<14} gaits: {', '.join(c['gaits'])} (default {c['default_gait']}); bodies: {', '.join(c['bodies'])}")
    for section, width in (("bodies", 14), ("gaits", 20), ("scenarios", 14)):
        print(f"{section}:")
        for n, entry in cat[section].items():
            print(f"  {n:<{width}} {entry['description']}")
    print("supported (creature, body, gait):")
    for c in cat["supported"]:
        print(f"  {c['creature']}, {c['body']}, {c['gait']}")
    return EXIT_OK
