"""``bench-myriapoda keys``: every configuration key ``--set`` accepts, with its type, default, range and unit."""
from __future__ import annotations

import json

from ..core.keys import config_keys, sections
from .exits import EXIT_OK
from .help_text import help_text


def add_parser(sub) -> None:
    k = sub.add_parser("keys", help="every configuration key --set accepts: type, default, range, unit, meaning",
                       **help_text("keys"))
    k.add_argument("section", nargs="?", metavar="SECTION", default=None,
                   help=f"only this section: {', '.join(sections())} (default: all)")
    k.add_argument("--json", action="store_true", help='print one JSON object {"keys": [...]}')


def cmd_keys(args) -> int:
    rows = config_keys(args.section)
    if args.json:
        print(json.dumps({"keys": rows}, indent=1))
        return EXIT_OK
    section = None
    for r in rows:
        if r["section"] != section:
            section = r["section"]
            print(f"[{section}]" + ("  (dt, duration, seed: --dt, --duration, --seed or --set)" if section == "top"
                                    else ""))
        default = "-" if r["default"] is None else json.dumps(r["default"])
        bodies = (f"  ({', '.join(r['bodies'])})" if "bodies" in r
                  else f"  (gaits: {', '.join(r['gaits'])})" if "gaits" in r else "")
        print(f"  {r['key']}{bodies}")
        print(f"      {r['type']}; default {default}" + (f"; {r['allowed_text']}" if r["allowed_text"] else "")
              + (f"; unit {r['unit']}" if r["unit"] else ""))
        print(f"      {r['description']}")
    return EXIT_OK
