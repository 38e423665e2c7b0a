"""Command lines the tests build: a worm run with some flags replaced or added."""
from __future__ import annotations

# ``bench-myriapoda run`` of the lattice worm on flat ground, not stored
WORM_RUN = ["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--no-store"]


def with_flags(argv: list[str], flags: list[str]) -> list[str]:
    """A copy of ``argv`` with ``flags`` (flag, value pairs) set: a flag already there gets the new value,
    another is appended with its value."""
    out = list(argv)
    for i in range(0, len(flags), 2):
        if flags[i] in out:
            out[out.index(flags[i]) + 1] = flags[i + 1]
        else:
            out += flags[i:i + 2]
    return out
