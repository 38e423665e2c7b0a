"""Reference pages generated from the code at documentation build time, so they cannot drift.

``conf.py`` calls :func:`write_all` before Sphinx reads the sources. Each page is written from the
table the program itself uses:

- ``reference/cli.md``: every subcommand's ``--help``, from ``bench_myriapoda.cli.build_parser``;
- ``reference/keys.md``: every key ``--set`` accepts, from ``bench_myriapoda.core.keys.config_keys``
  (what ``bench-myriapoda keys`` prints);
- ``reference/metrics.md``: every stored metric, from ``bench_myriapoda.metrics.definitions.METRICS``;
- ``reference/checks.md``: every ``validate`` check, from ``bench_myriapoda.validation.registry.CHECKS``,
  with the tolerance of each check and body as a recorded ``validate`` run states it;
- ``explanation/validation-results.md``: the verdicts of recorded ``validate`` runs
  (``docs/_data/validation-*.json``, written by ``validate --json``).

``tests/test_docs.py`` compares the names on these pages with the program's lists.
"""
from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

DOCS = Path(__file__).resolve().parent.parent
DATA = DOCS / "_data"
# recorded `validate --json` runs the pages read: the quick set, and the checks only the full set runs (at the
# quick set's sizes). Each file carries "recorded": {"title", "command", "how"} added when it was copied here.
VALIDATION_RUNS = ("validation-quick.json", "validation-full-only.json")

GENERATED = ("reference/cli.md", "reference/keys.md", "reference/metrics.md", "reference/checks.md",
             "explanation/validation-results.md")


def _cell(value: Any) -> str:
    """A value as the text of one Markdown table cell (pipes escaped, no line breaks)."""
    if value is None:
        return "-"
    text = value if isinstance(value, str) else json.dumps(value)
    return " ".join(text.replace("|", "\\|").split()) or "-"


def _code(value: str) -> str:
    return f"`{value}`" if value else "-"


def _table(header: tuple[str, ...], rows: list[tuple[Any, ...]]) -> list[str]:
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(_cell(c) for c in r) + " |" for r in rows]
    return out + [""]


# --------------------------------------------------------------------------- CLI

def cli_commands() -> dict[str, Any]:
    """``{name: subparser}`` of every subcommand, in the parser's order."""
    import argparse

    from bench_myriapoda.cli import build_parser

    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {"": parser, **sub.choices}


def cli_page() -> str:
    os.environ["COLUMNS"] = "100"  # argparse wraps the usage and option lists at the terminal's width
    lines = ["# Command line", "",
             "Every subcommand's `--help`, as `bench-myriapoda COMMAND --help` prints it (generated from the "
             "argument parser when the documentation is built).", ""]
    for name, parser in cli_commands().items():
        lines += [f"## `bench-myriapoda{' ' + name if name else ''}`", "", "```text", parser.format_help().rstrip(),
                  "```", ""]
    return "\n".join(lines)


# --------------------------------------------------------------------------- configuration keys

def keys_page() -> str:
    from bench_myriapoda.core.keys import config_keys

    lines = ["# Configuration keys", "",
             "Every key `--set KEY=VALUE` accepts, and creature, scenario and matrix files set: the list "
             "`bench-myriapoda keys` prints (generated from the same schema when the documentation is built). "
             "`top` holds `dt`, `duration` and `seed`; a `body.*` key names the body models that have it.", ""]
    rows = config_keys()
    for section in dict.fromkeys(r["section"] for r in rows):
        lines += [f"## `{section}`", ""]
        lines += _table(("key", "type", "default", "allowed", "unit", "description"),
                        [(_code(r["key"]) + (f" ({', '.join(r['bodies'])})" if "bodies" in r else
                                              f" (gaits: {', '.join(r['gaits'])})" if "gaits" in r else ""), r["type"],
                          r["default"], r["allowed_text"] or "-", r["unit"] or "-", r["description"])
                         for r in rows if r["section"] == section])
    return "\n".join(lines)


# --------------------------------------------------------------------------- metrics

def metrics_page() -> str:
    from bench_myriapoda.metrics.definitions import GROUPS, METRICS

    lines = ["# Metrics", "",
             "Every metric a run stores (the results store's `metrics` table, the columns of "
             "`bench_myriapoda.load_results`, the `metrics` object of `--json`), with its unit and definition. "
             "Generated from the one table in `bench_myriapoda/metrics/definitions.py`. Steady-state figures are "
             "measured after `metrics.warmup_cycles` gait cycles; a figure that cannot be measured is NaN "
             "(`null` in JSON). Units: BL = body lengths, cycle = one gait period, `-` dimensionless, count = a "
             "whole number stored as a float.", ""]
    for group in GROUPS:
        lines += [f"## {group[0].upper() + group[1:]}", ""]
        lines += _table(("metric", "unit", "definition"),
                        [(_code(m.name), m.unit, m.definition) for m in METRICS.values() if m.group == group])
    return "\n".join(lines)


# --------------------------------------------------------------------------- validation

def validation_runs() -> list[tuple[str, dict[str, Any]]]:
    """The recorded ``validate --json`` runs that are present: ``[(set name, document), ...]``."""
    out = []
    for file in VALIDATION_RUNS:
        path = DATA / file
        if path.exists():
            doc = json.loads(path.read_text())
            out.append((doc.get("recorded", {}).get("title", file), doc))
    return out


def tolerances() -> dict[tuple[str, str], str]:
    """``{(check, body): tolerance}`` from the recorded runs (the first run that has a row wins)."""
    out: dict[tuple[str, str], str] = {}
    for _, doc in validation_runs():
        for r in doc["rows"]:
            out.setdefault((r["check"], r["body"]), r["tolerance"])
    return out


def checks_page() -> str:
    from bench_myriapoda.validation.registry import CHECKS

    tol = tolerances()
    lines = ["# Validation checks", "",
             "Every check `bench-myriapoda validate` runs, from the registry "
             "(`bench_myriapoda/validation/registry.py`): its family, the quantity measured, the reference and its "
             "source, the body models it runs on (`all`: one row comparing the bodies; in bold: also in the quick "
             "set, `--quick`) and the tolerance. A tolerance is stated by the check when it runs; the ones shown "
             "are those of the recorded runs on the Validation results page (a check with `-` was not in those "
             "runs).", ""]
    for family in dict.fromkeys(c.family for c in CHECKS):
        lines += [f"## `{family}`", ""]
        rows = []
        for c in CHECKS:
            if c.family != family:
                continue
            quick = c.bodies if c.quick_bodies is None else c.quick_bodies
            bodies = ", ".join(f"**{b}**" if b in quick else b for b in c.bodies)
            tols = dict.fromkeys(tol[(c.name, b)] for b in c.bodies if (c.name, b) in tol)
            rows.append((_code(c.name), c.quantity, c.source, bodies, "; ".join(tols) or "-"))
        lines += _table(("check", "quantity", "reference (source)", "bodies", "tolerance"), rows)
    return "\n".join(lines)


def _fmt(v: Any, unit: str = "") -> str:
    if v is None:
        return "-"
    if isinstance(v, float):
        return f"{v:.4g}" + (f" {unit}" if unit else "")
    return str(v) + (f" {unit}" if unit and not isinstance(v, str) else "")


def validation_results_page() -> str:
    runs = validation_runs()
    lines = ["# Validation results", "",
             "The verdicts of recorded `bench-myriapoda validate` runs, generated from their JSON "
             "(`validate --json`, kept in `docs/_data/`). Rerun them on your machine with the command given; "
             "Validation explains each family and how the references were chosen.", ""]
    if not runs:
        raise RuntimeError(f"no recorded validate run in {DATA} ({', '.join(VALIDATION_RUNS)})")
    for title, doc in runs:
        counts = ", ".join(f"{n} {v}" for v, n in sorted(doc["counts"].items()))
        meta = doc.get("recorded", {})
        command = meta.get("command", "bench-myriapoda validate" + (" --quick" if doc["quick"] else ""))
        lines += [f"## {title}", "", f"`{command}`", "",
                  f"{len(doc['rows'])} rows, {counts}; {doc['wall_s']:.0f} s wall"
                  + (f" ({meta['how']})" if meta.get("how") else "") + ".", ""]
        lines += _table(("check", "body", "measured", "reference", "tolerance", "verdict"),
                        [(_code(r["check"]), r["body"], _fmt(r["measured"], r.get("unit", "")), _fmt(r["reference"]),
                          r["tolerance"], f"**{r['verdict']}**") for r in doc["rows"]])
    return "\n".join(lines)


PAGES = {"reference/cli.md": cli_page, "reference/keys.md": keys_page, "reference/metrics.md": metrics_page,
         "reference/checks.md": checks_page, "explanation/validation-results.md": validation_results_page}


def write_all(docs: Path = DOCS) -> list[Path]:
    """Write every generated page under ``docs``; a page whose text is unchanged is left alone (so Sphinx
    does not rebuild it)."""
    written = []
    for rel, make in PAGES.items():
        path = docs / rel
        text = make().rstrip() + "\n"
        if not path.exists() or path.read_text() != text:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        written.append(path)
    return written


if __name__ == "__main__":
    for p in write_all():
        print(p)
