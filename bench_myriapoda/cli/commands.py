"""The subcommands of ``bench-myriapoda``: the program's description and examples, each subcommand's parser (added
by the subcommand's own module, ``add_parser``, in the order ``--help`` lists them) and the command each runs."""
from __future__ import annotations

import argparse
from typing import Callable

from .. import __version__
from . import catalogue, keys, matrix, peers, quick, regress, report, run, scorecard, stable_dt, validate
from .help_text import para
from .parser import Parser

MAIN_DESCRIPTION = """A research benchmark suite for simulated creatures: Miller's worms and snakes (SIGGRAPH 1988) and
    Fang, Jiang and Terzopoulos's myriapods (SCA 2013) on interchangeable body models (mass-spring lattice, FEM,
    rigid/FEM hybrid). It measures speed, gait quality, stability and throughput and stores every run. With no
    arguments it runs the quick matrix and writes reports/quick/index.html. `bench-myriapoda COMMAND --help`
    describes each command."""
MAIN_EPILOG = """examples:
  bench-myriapoda
  bench-myriapoda list
  bench-myriapoda run --creature worm --body massspring --scenario flat
  bench-myriapoda validate --quick
  bench-myriapoda run --help
"""

# the subcommands' modules, in the order of ``--help``
SUBCOMMANDS = (catalogue, run, stable_dt, quick, matrix, report, regress, scorecard, keys, peers, validate)


def build_parser() -> argparse.ArgumentParser:
    p = Parser(prog="bench-myriapoda", description=para(MAIN_DESCRIPTION), epilog=MAIN_EPILOG,
               formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--version", action="version", version=f"bench-myriapoda {__version__}")
    sub = p.add_subparsers(dest="command", parser_class=Parser)
    for module in SUBCOMMANDS:
        module.add_parser(sub)
    return p


def command(name: str) -> Callable[[argparse.Namespace], int]:
    """The function that runs subcommand ``name``, looked up when called (a test may stand in for one:
    ``monkeypatch.setattr(matrix, "cmd_matrix", ...)``)."""
    return {"list": catalogue.cmd_list, "run": run.cmd_run, "quick": quick.cmd_quick,
            "stable-dt": stable_dt.cmd_stable_dt, "matrix": matrix.cmd_matrix, "report": report.cmd_report,
            "regress": regress.cmd_regress, "keys": keys.cmd_keys, "peers": peers.cmd_peers,
            "validate": validate.cmd_validate, "scorecard": scorecard.cmd_scorecard}[name]
