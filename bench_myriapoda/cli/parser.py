"""The argument parser of every ``bench-myriapoda`` command: argparse whose bad flags are bad input (one line,
exit 2), with a suggestion for a misspelt subcommand or flag."""
from __future__ import annotations

import argparse
import sys

from ..core.errors import InputError
from ..core.suggest import did_you_mean


class Parser(argparse.ArgumentParser):
    """argparse that reports bad flags as an InputError (one line, exit 2, the program named once), with a
    suggestion for a misspelt subcommand or flag; ``describe`` fills the description when help is printed."""

    describe = None

    def parse_known_args(self, args=None, namespace=None):
        self._argv = list(sys.argv[1:] if args is None else args)
        return super().parse_known_args(args, namespace)

    def format_help(self) -> str:
        if self.describe is not None:
            self.description = self.describe()
        return super().format_help()

    def error(self, message: str):
        # the top-level parser's prog is the program itself, which the caller prints once already
        where = self.prog.removeprefix("bench-myriapoda").strip() or "arguments"
        if where == "arguments" and message.startswith("argument ") and ": " in message:
            where, message = message.split(": ", 1)
        commands = next((a.choices for a in self._actions if isinstance(a, argparse._SubParsersAction)), {})
        if "invalid choice" in message and commands:
            word = message.split("invalid choice: ", 1)[1].split(" (", 1)[0].strip("'\"")
            message += did_you_mean(word, commands)
        elif message.startswith("unrecognized arguments"):
            argv = getattr(self, "_argv", [])
            sub = commands.get(next((a for a in argv if a in commands), None), self)
            flags = [o for a in sub._actions for o in a.option_strings]
            word = next((w.split("=", 1)[0] for w in message.split(":", 1)[1].split() if w.startswith("-")), "")
            if sub is not self:
                where = sub.prog.removeprefix("bench-myriapoda").strip()
            message += did_you_mean(word, flags)
        raise InputError(where, None, message)
