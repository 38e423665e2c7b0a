"""``bench-myriapoda``'s one entry point, :func:`main`: the arguments parsed, one subcommand run, its exit code.

Bad input gives one line on stderr naming the file or flag, the key and what is allowed, and exit code 2,
before anything is written; Ctrl-C and SIGTERM end with 130, a closed stdout with 141 (``exits``).
"""
from __future__ import annotations

import codecs
import os
import sys
from typing import Sequence

from ..core.errors import InputError
from ..core.numba_env import check_numba_env
from .exits import EXIT_BAD_INPUT, EXIT_CLOSED_PIPE, EXIT_INTERRUPTED
from .signals import sigterm_as_interrupt

PRINT_ERRORS = "bench_myriapoda_file_names"


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    terminate = sigterm_as_interrupt()
    try:
        with terminate:  # from the start: building the parser imports the body models (~1.3 s)
            check_numba_env()  # before numba is imported: it reads these variables once, at import
            if "--version" in argv[:1] and len(argv) > 1:  # argparse would print the version and ignore the rest
                raise InputError("--version", None, f"takes no other arguments; got {' '.join(argv[1:])}")
            # the subcommands only now, after the check: they import numba (the body models, the runner)
            from .commands import build_parser, command

            parser = build_parser()
            args = parser.parse_args(argv or ["quick"])
            if args.command is None:
                args = parser.parse_args(["quick", *argv])
            print_any_file_name()
            code = command(args.command)(args)
            sys.stdout.flush()  # a closed pipe shows here, inside the handler, not at interpreter exit
        if terminate.received:  # a SIGTERM whose KeyboardInterrupt something swallowed: still a terminated command
            print("bench-myriapoda: interrupted", file=sys.stderr)
            return EXIT_INTERRUPTED
        return code
    except BrokenPipeError:
        return closed_pipe()
    except InputError as exc:
        print(f"bench-myriapoda: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("bench-myriapoda: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except Exception:
        if not (terminate.received or interrupted_inside()):
            raise
        print("bench-myriapoda: interrupted", file=sys.stderr)  # an interrupt turned into another exception
        return EXIT_INTERRUPTED


def interrupted_inside() -> bool:
    """Whether the exception being handled came from a KeyboardInterrupt (Ctrl-C raised inside an import of a C
    extension comes out as that import's ImportError, the KeyboardInterrupt as its cause or context)."""
    exc, seen = sys.exc_info()[1], set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, KeyboardInterrupt):
            return True
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return False


def print_any_file_name() -> None:
    """Let stdout print a file name that is not UTF-8 (``--store $'\\xff.sqlite'``, held by Python as a lone
    surrogate): as its own bytes, as ``ls`` would, and any other unencodable character as a backslash
    escape.  With strict UTF-8 the line naming the store raised UnicodeEncodeError after the run."""
    def write_bytes_or_escape(exc):
        try:
            return codecs.lookup_error("surrogateescape")(exc)
        except UnicodeError:
            return codecs.lookup_error("backslashreplace")(exc)

    try:
        codecs.lookup_error(PRINT_ERRORS)
    except LookupError:
        codecs.register_error(PRINT_ERRORS, write_bytes_or_escape)
    stream = sys.stdout
    if getattr(stream, "errors", None) == "strict" and hasattr(stream, "reconfigure"):
        try:
            stream.reconfigure(errors=PRINT_ERRORS)
        except (ValueError, OSError):  # a stream that cannot change now: leave it
            pass


def closed_pipe() -> int:
    """stdout's reader went away (``bench-myriapoda run --json | head -c 10``): stop quietly.

    stdout is pointed at /dev/null so the interpreter's final flush does not raise again;
    the exit code is the shell's for a process ended by SIGPIPE (128 + 13).
    """
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # stdout without a file descriptor (e.g. captured in a test)
        pass
    return EXIT_CLOSED_PIPE
