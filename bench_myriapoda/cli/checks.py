"""Checks shared by several subcommands, run before a case is built or a file is written (issue 15): a bad
flag or an output that cannot be written is one line and exit 2, not a traceback after the simulation ran;
and a store that refuses a row after the run keeps the result elsewhere instead of losing it."""
from __future__ import annotations

from typing import Any

from ..core.errors import InputError
from ..core.userpaths import check_path_text
from ..harness.store import UnstoredError, store_or_keep

MAX_WORKERS = 1024


def check_workers(workers: int | None) -> None:
    """``--workers N``: 1 to ``MAX_WORKERS`` when given."""
    if workers is not None and not 1 <= workers <= MAX_WORKERS:
        raise InputError("--workers", None, f"{workers} is out of range; must be 1 to {MAX_WORKERS}")


def check_path_flags(args, *flags: str) -> None:
    """A path flag given as an empty (or blank) string is an error, not 'use the default'."""
    for flag in flags:
        value = getattr(args, flag.lstrip("-").replace("-", "_"), None)
        if value is not None:  # empty, NUL, a name longer than the file system allows
            check_path_text(value, flag)


def store_after_the_run(store, what: str, write, doc) -> tuple[Any, str | None]:
    """(``write()``'s run id, None), or when the store refused the insert after the run (a full disk, a
    store changed meanwhile): (None, the line saying why and which fallback file keeps ``doc()``)."""
    try:
        return store_or_keep(store, what, write, doc), None
    except UnstoredError as exc:
        return None, str(exc)
