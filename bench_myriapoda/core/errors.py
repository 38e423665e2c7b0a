"""The one error type for bad input.

Every problem with what a user typed or wrote in a file (unknown name, unknown
key, wrong type, out-of-range value, unreadable TOML, unsupported combination)
becomes an ``InputError`` that names where it came from (a file path or a
command-line flag), the key, and what is allowed.  The CLI prints it as one
line and exits with code 2 before anything is written.
"""
from __future__ import annotations


class InputError(Exception):
    """Bad user input.  ``source`` is a file path or a flag such as ``--set``."""

    def __init__(self, source: str, key: str | None, message: str):
        self.source = source
        self.key = key
        self.message = message
        where = f"{source}: {key}" if key else source
        super().__init__(one_line(f"{where}: {message}"))


def one_line(text: str, limit: int = 2000) -> str:
    """``text`` as one printable line: control characters escaped (a key or file name may hold a newline),
    cut to ``limit`` characters so a huge value cannot flood the terminal."""
    out = "".join(ch if ch.isprintable() or ch == " " else repr(ch)[1:-1] for ch in text)
    return out if len(out) <= limit else out[: limit - 3] + "..."
