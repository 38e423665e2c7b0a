"""Sphinx extension: render this project's docstring style as reStructuredText.

The package documents fields and arguments as ``name: text`` lines with hanging indents
(``muscle: (n_rows, n_seg, 3) fibre strains ...``), which docutils reads as broken definition lists
and block quotes. Each such run of lines becomes a bullet list (``- **name**: text``), and a ``|``
(absolute values, ``|lag|``) is escaped so that it is not read as a substitution. The docstrings
stay as they are in the code.
"""
from __future__ import annotations

import re

FIELD = re.compile(r"^(?P<key>[A-Za-z_][\w*.]*(?:, [A-Za-z_][\w*.]*)*): (?P<text>\S.*)$")


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip(" "))


def field_lists(lines: list[str]) -> list[str]:
    """The docstring ``lines`` with every run of ``name: text`` fields as a bullet list."""
    out: list[str] = []
    in_list = False
    base = None
    in_literal = False
    for line in lines:
        stripped = line.strip()
        if stripped.endswith("::") or stripped.startswith(">>>"):
            in_literal = True
        elif in_literal and stripped and _indent(line) == 0:
            in_literal = False
        if in_literal:
            out.append(line)
            continue
        m = FIELD.match(line)
        if m and _indent(line) == 0:
            if not in_list and out and out[-1].strip():
                out.append("")
            key = m["key"].replace("*", "\\*")
            out.append(f"- **{key}**: {m['text']}")
            in_list, base = True, 0
        elif in_list and stripped and _indent(line) > (base or 0):
            out.append("  " + stripped)
        else:
            if in_list and stripped:
                out.append("")
            in_list = False
            out.append(line)
    return [ln.replace("|", "\\|") if not ln.lstrip().startswith(("|", "+")) else ln for ln in out]


def _process(app, what, name, obj, options, lines):
    lines[:] = field_lists(list(lines))


def setup(app):
    app.connect("autodoc-process-docstring", _process)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
