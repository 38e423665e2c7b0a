"""Checks on a path a user typed, before anything is read from it or written to it.

An input file (creature, scenario, matrix) is read only when it is a regular file: a FIFO
would block the read forever, a device would be read without end.  An output path is
refused when the operating system could never create it (an empty name, a component
longer than the file system's ``NAME_MAX`` bytes, the file-system root as an output
folder, a file name that is only a suffix such as ``.npz``).  Every refusal is an
:class:`~.errors.InputError` naming the flag or file, raised before any simulation.
"""
from __future__ import annotations

import os
import stat
from pathlib import Path

from .errors import InputError

NAME_MAX = 255  # bytes in one path component (ext4, xfs, btrfs, tmpfs)
PATH_MAX = 4095  # bytes in a whole path (Linux)


def check_path_text(path: Path | str, flag: str) -> Path:
    """``path`` can name a file at all: not empty or blank, no NUL, every component at most
    ``NAME_MAX`` bytes and the whole at most ``PATH_MAX`` (nothing on disk is looked at)."""
    text = str(path)
    if not text.strip():
        raise InputError(flag, None, "empty path; give a path or leave the flag out")
    if "\x00" in text:
        raise InputError(flag, None, "a path cannot contain a NUL character")
    raw = os.fsencode(text)
    if len(raw) > PATH_MAX:
        raise InputError(flag, None, f"the path is {len(raw):,} bytes long; at most {PATH_MAX} bytes")
    for part in raw.split(b"/"):
        if len(part) > NAME_MAX:
            shown = os.fsdecode(part[:24])
            raise InputError(flag, None, f"the path component {shown!r}... is {len(part)} bytes long; a file or "
                                         f"folder name has at most {NAME_MAX} bytes")
    return Path(text)


def check_input_file(path: Path | str, source: str | None = None) -> Path:
    """An input file that exists and is a regular file (a FIFO, a socket or a device is refused:
    reading it could block or never end).  ``source`` names the file in the message (default: the path)."""
    src = source or str(path)
    p = check_path_text(path, src)
    try:
        st = os.stat(p)
    except FileNotFoundError:
        raise InputError(src, None, "file not found") from None
    except NotADirectoryError:
        raise InputError(src, None, "file not found (a folder on its path is a file)") from None
    except OSError as exc:
        raise InputError(src, None, f"cannot read file ({exc.strerror or exc})") from None
    if stat.S_ISDIR(st.st_mode):
        raise InputError(src, None, "is a directory; expected a .toml file")
    if not stat.S_ISREG(st.st_mode):
        raise InputError(src, None, "not a regular file (a FIFO, socket or device); give a .toml file")
    return p


def is_only_a_suffix(name: str) -> bool:
    """A file name such as ``.npz`` or ``.gif``: a suffix with nothing before it."""
    return name.startswith(".") and name.count(".") == 1 and len(name) > 1


def is_root(path: Path | str) -> bool:
    """The file-system root (``/``, ``//``, ``/..``): never an output folder."""
    try:
        return Path(path).resolve() == Path(Path(path).resolve().anchor)
    except (OSError, RuntimeError):
        return False
