"""``bench-myriapoda``: the command line.

    bench-myriapoda                      run scenarios/matrix/quick.toml, write reports/quick/index.html
    bench-myriapoda list [--json]        creatures, bodies, gaits, scenarios, supported combinations
    bench-myriapoda run --creature C --body B --scenario S [...]   one case
    bench-myriapoda stable-dt --creature C --body B --scenario S [...]   largest stable dt
    bench-myriapoda matrix FILE [--executor local|dask] [--resume] [...]  a whole scenario matrix
    bench-myriapoda report DIR [--baseline DIR2]   index.html and summary.md of a matrix run
    bench-myriapoda regress [--baseline COMMIT_OR_RUN] [...]   throughput suite vs. the stored history
    bench-myriapoda keys [SECTION] [--json]   every configuration key --set accepts, described
    bench-myriapoda peers [--repeats N] [--store PATH] [--json]   MuJoCo flex and PyElastica side by side (extra [peers])
    bench-myriapoda validate [--body B ...] [--check NAME ...] [--quick] [--json] [--out DIR] [--work-precision]

One module per subcommand, each with its parser (``add_parser``) and its command (``cmd_*``): ``catalogue``
(list), ``run`` (with ``frames``: what it draws after the run), ``stable_dt``, ``quick``, ``matrix``,
``report``, ``scorecard``, ``regress``, ``peers``, ``validate``, ``keys``.  ``commands`` puts them together,
``parser`` is argparse whose errors are bad input, ``program`` runs one command (:func:`main`).  Shared:
``case_flags`` (the flags of one case and its budget), ``checks`` (path and worker flags, a store that refuses
a row after the run), ``help_text`` (each help's paragraph and examples), ``exits`` (exit codes), ``signals``
(SIGTERM as Ctrl-C).  ``python -m bench_myriapoda.cli`` is the same program.

Bad input gives one line on stderr naming the file or flag, the key and what
is allowed, and exit code 2, before anything is written.
"""
import importlib

from .program import main

# Imported on first use: the subcommands' modules import numba (the body models, the runner), and numba reads its
# NUMBA_* variables once, at import; ``main`` checks them first (``core.numba_env``), so importing this package
# must not import numba.
_LAZY = {"build_parser": "commands", "print_result_table": "run"}


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["main", "build_parser", "print_result_table"]
