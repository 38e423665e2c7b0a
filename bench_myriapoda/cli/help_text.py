"""What ``bench-myriapoda SUBCOMMAND --help`` says: a paragraph, the choices, and examples at the end.

Each subcommand's module passes ``help_text(NAME)`` to its ``add_parser``. The text is written so that
the help stands alone: what the command does, what it writes, and a few command lines to copy.
``validate``'s list of checks comes from the validation registry and is filled in only when its help is
printed (``parser.Parser.format_help``), so an ordinary command does not pay for importing the registry.
"""
from __future__ import annotations

import argparse
import textwrap
from typing import Any

from ..harness.matrix import matrix_paths

WIDTH = 100


def para(text: str) -> str:
    return textwrap.fill(" ".join(text.split()), WIDTH)


DESCRIPTIONS: dict[str, str] = {
    "list": """List what the suite can run: the creatures (models/*.toml) with their gaits and the body models
        each runs on, the body models, the gaits, the scenarios (scenarios/*.toml and scenarios/paper/) and
        every supported creature x body x gait combination. Prints a table, or one JSON object with --json.""",
    "stable-dt": """Find the largest time step for which one case stays stable over its duration: start from the
        case's own dt, double (or halve) it until the status flips, then bisect until the bracket is tighter
        than --rel-tol. Every trial is printed; the result (metrics stable_dt_max_s, unstable_dt_min_s) is
        recorded in the results store with command = 'stable-dt'. Takes the same case flags as `run`.""",
    "quick": """Run the quick matrix (scenarios/matrix/quick.toml: every creature on every body model, 18
        pairs at headline length, small dt x stiffness and size sweeps) on a local process pool, then bisect
        each headline pair's stable dt (with three timed runs at its default dt) and run the validate --quick
        checks that apply to those pairs into the same directory, and write its report,
        reports/quick/index.html, with the scorecard on top. A rerun of the same code keeps what the last
        complete run stored in DIR. This is also what `bench-myriapoda` with no arguments does.""",
    "matrix": """Run a scenario matrix: a TOML file crossing creatures x bodies x gaits x scenarios x seeds x a
        grid of any configuration keys, on a local process pool or a Dask cluster. Every case goes to
        DIR/results.sqlite (and results.csv, matrix.json, series/); --resume runs only the cases not yet
        stored, so an interrupted matrix continues where it stopped. FILE is a path or a name in
        scenarios/matrix/: {matrices}.""",
    "report": """Write DIR/index.html and DIR/summary.md from a matrix output directory: the scorecard,
        comparison tables, sweep and stability maps, time series, the reproduced paper figures with their
        validation verdicts, and the regress history. With --baseline DIR2 every metric is compared with
        another matrix run and changes beyond --threshold are highlighted (--strict: exit 1 on one).""",
    "regress": """Time the fixed throughput suite (each body model's hot path on a fixed case), store the figures
        in the results store's regress_history and compare them with a baseline run on this machine. The
        figure compared is steps/s divided by a reference kernel's speed measured in the same sitting, so
        a busier or slower machine does not read as a regression. Exit 1 on a regression larger than
        --threshold (or three times the measured noise, whichever is larger).""",
    "keys": """List every configuration key that --set accepts (and that creature and scenario files set), with
        its type, default, allowed range or choices, unit and description. SECTION limits the list to one
        section; `top` holds dt, duration and seed, `body` the body models' keys with the models that have
        each.""",
    "scorecard": """Print the scorecard of a matrix output directory: one row per creature x body model with
        its stability (the largest stable dt from the matrix's dt sweeps, else from stable-dt, and the
        default dt's margin), fidelity (the validate verdicts for the pair), locomotion against the kinematic
        or analytic reference, shape tracking and cost (CPU seconds per simulated second, steps/s), then one
        recommendation per creature (the bodies on the Pareto front of error against cost). A cell without
        data names the command that fills it. The same table heads the report.""",
    "peers": """Time the peer simulators, MuJoCo's flex and PyElastica's Cosserat snake, side by side with this
        suite's bodies on matched cases, in one process and one sitting, and print the ratios. Needs the
        optional extra: pip install "bench-myriapoda[peers]". The timings are stored as a regress run.""",
}

EXAMPLES: dict[str, str] = {
    "list": """\
  bench-myriapoda list
  bench-myriapoda list --json | python3 -m json.tool | less
""",
    "stable-dt": """\
  bench-myriapoda stable-dt --creature worm --body massspring --scenario flat --duration 5
  bench-myriapoda stable-dt --creature snake --body fem --scenario flat --set body.youngs_modulus_pa=2e5 --json
""",
    "quick": """\
  bench-myriapoda
  bench-myriapoda quick --workers 2 --out reports/quick-today
""",
    "matrix": """\
  bench-myriapoda matrix quick --report
  bench-myriapoda matrix scenarios/matrix/miller.toml --workers 2 --timeout-per-case 600
  bench-myriapoda matrix quick --executor dask --scheduler tcp://host:8786
  bench-myriapoda matrix quick --resume --retry-failed
""",
    "scorecard": """\
  bench-myriapoda scorecard reports/quick
  bench-myriapoda scorecard reports/quick --json | python3 -m json.tool
""",
    "report": """\
  bench-myriapoda report reports/quick
  bench-myriapoda report reports/quick --baseline reports/quick-yesterday --strict
""",
    "regress": """\
  bench-myriapoda regress
  bench-myriapoda regress --baseline 1a2b3c4 --repeats 9 --json
  bench-myriapoda regress --suite massspring-snake hybrid-centipede
""",
    "keys": """\
  bench-myriapoda keys
  bench-myriapoda keys friction
  bench-myriapoda keys body --json
""",
    "peers": """\
  bench-myriapoda peers
  bench-myriapoda peers --repeats 3 --json
""",
    "validate": """\
  bench-myriapoda validate --quick
  bench-myriapoda validate
  bench-myriapoda validate --body hybrid --check paper
  bench-myriapoda validate --check analytic.hanging-bar --json
  bench-myriapoda validate --quick --work-precision --out reports/validation
""",
}

# How long the two sets take (measured at commit 569a1af on the 2-core development machine, warm JIT
# cache: the quick set 21 s wall; the full set 442 s from a cold cache, 546-579 s at load 2-4). A cold
# JIT cache adds the compilation: 24 to 98 CPU s for the quick set.
QUICK_SET_TIME = "about 20 s with a warm JIT cache, 1 to 2 minutes from a cold one"
FULL_SET_TIME = "about 7 to 10 minutes"


def validate_description() -> str:
    """``validate --help``'s description: the paragraph, the families, every check with its bodies."""
    from ..validation.registry import CHECKS  # every check module: about 25 ms of CPU, paid when this help prints

    head = para("""Run the validation checks and print one row per check and body model: the quantity, the measured
        value, the reference with its source (an equation, a paper's figure or section), the tolerance and the
        verdict (PASS, FAIL, NOT APPLICABLE with the reason, or INFO). Exit 1 when a row FAILs. Rows go to the
        results store's validation table and to DIR/validation.json.""")
    times = para(f"""--quick runs each check on the bodies its registry entry lists for the quick set, at smaller
        sizes: {QUICK_SET_TIME} on 2 cores. The full set (no --quick) runs every check on every body it lists:
        {FULL_SET_TIME}. --check takes a check's name or a family's.""")
    families = list(dict.fromkeys(c.family for c in CHECKS))
    lines = [head, "", times, "", "families: " + ", ".join(families), "", "checks (bodies; * = in the quick set):"]
    for c in CHECKS:
        quick = c.bodies if c.quick_bodies is None else c.quick_bodies
        bodies = ", ".join(("all" if b in ("all", "cross") else b) + ("*" if b in quick else "") for b in c.bodies)
        lines.append(f"  {c.name:<38} {c.quantity} ({bodies})")
    return "\n".join(lines)


def help_text(name: str) -> dict[str, Any]:
    """Keyword arguments for ``add_parser(name, ...)``: description, epilog with examples, raw formatting."""
    description = None if name == "validate" else para(DESCRIPTIONS[name])
    if name == "matrix":
        description = description.format(matrices=", ".join(matrix_paths()) or "(none found)")
    return {"description": description, "epilog": "examples:\n" + EXAMPLES[name],
            "formatter_class": argparse.RawDescriptionHelpFormatter}
