"""Issue 15's fuzz test: generated malformed inputs across the commands all give exit 2 and one line.

Hypothesis generates creature, scenario and matrix TOML files with one defect each (a value of the
wrong type, NaN or inf, out of range, in a list, an unknown key or table, a name key inside a body
or gait table, a non-UTF-8 byte, deep nesting, broken syntax, an unsafe matrix name, a badly typed
[[exclude]] value) and bad flags of run, stable-dt, matrix, report and regress (non-finite, out of
range, empty paths, unknown names, bad --set pairs, a case over the step budget, corrupt stores).

Every input is malformed by construction, so each must give: exit code 2, exactly one line on stderr,
no traceback, and nothing written to the fresh directory it runs in.  The CLI runs in-process
(``bench_myriapoda.cli.main``); the functions that would simulate (run_case, run_matrix,
find_stable_dt, run_suite) are replaced by stubs that fail the test, so a malformed input that slipped
through validation is reported instead of simulated -- and no numba kernel is ever compiled.

Examples: 1,000 by default (about a minute on one core); BENCH_FUZZ_EXAMPLES=N for more;
BENCH_FUZZ_LOG=FILE appends each input's exit code, command and message to FILE.
"""
import contextlib
import dataclasses
import io
import json
import math
import os
import tempfile
from collections import Counter
from pathlib import Path
from unittest import mock

import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from bench_myriapoda.cli import main  # noqa: E402
from bench_myriapoda.core import registry  # noqa: E402
from bench_myriapoda.core.config import resolve_case  # noqa: E402
from bench_myriapoda.core.schema import SECTIONS, field_types  # noqa: E402
from bench_myriapoda.harness.matrix import load_matrix  # noqa: E402
from bench_myriapoda.harness.throughput_suite import SUITE  # noqa: E402
# imported here, before any test patches runner.run_case: a module first imported under the patch would bind
# the refusing stand-in for good (stable_dt's "from .runner import run_case"), and a later test of the same
# worker would run it (seen under xdist: test_docs' stable-dt tutorial "got as far as running")
import bench_myriapoda.harness.executors  # noqa: E402,F401
import bench_myriapoda.harness.regress  # noqa: E402,F401
import bench_myriapoda.harness.stable_dt  # noqa: E402,F401

EXAMPLES = int(os.environ.get("BENCH_FUZZ_EXAMPLES", "1000"))
registry.load_all()
MS = registry.BODIES["massspring"].config_cls

# minimal valid files the generators put one defect into (checked valid by the first test below)
CREATURE = {"creature": ['default_gait = "rectilinear"', 'gaits = ["rectilinear"]', "segments = 4"],
            "bodies.massspring": [], "gaits.rectilinear": [], "friction": [], "legs": [], "controller": [],
            "antennae": [], "collision": [], "record": [], "stability": [], "metrics": []}
SCENARIO = {"scenario": ['description = "fuzz"'], "food": [], "friction": [], "record": [], "antennae": []}
MATRIX = {"matrix": ['creatures = ["worm"]', 'bodies = ["massspring"]', 'scenarios = ["flat"]', "duration = 0.05"]}
TABLE_CLASS = {"creature": SECTIONS["creature"], "bodies.massspring": MS, "gaits.rectilinear": SECTIONS["gait"],
               "scenario": SECTIONS["scenario"], "food": SECTIONS["food"], "friction": SECTIONS["friction"],
               "legs": SECTIONS["legs"], "controller": SECTIONS["controller"], "antennae": SECTIONS["antennae"],
               "collision": SECTIONS["collision"], "record": SECTIONS["record"], "stability": SECTIONS["stability"],
               "metrics": SECTIONS["metrics"]}
SKIP_KEYS = {"name", "description"}  # any string is a valid value of these


def toml_text(tables: dict[str, list[str]]) -> str:
    return "".join(f"[{t}]\n" + "".join(line + "\n" for line in lines) for t, lines in tables.items())


# --------------------------------------------------------------------------- bad values

NONFINITE = st.sampled_from(["nan", "inf", "-inf", "+nan", "-nan", "+inf"])
WRONG_SCALARS = st.sampled_from(['"text"', "true", "false", "{ a = 1 }", "1979-05-27", '""'])
NAME_TEXT = st.text(alphabet="abcdefghijklmnopqrstuvwxyz-_0123456789 ", min_size=1, max_size=12)


def _fmt(x: float) -> str:
    r = repr(float(x))
    return r if r not in ("inf", "-inf", "nan") else r


@st.composite
def bad_value(draw, cls, key: str) -> str:
    """TOML text of a value that ``cls.key`` must refuse."""
    tp = field_types(cls)[key]
    meta = {f.name: f.metadata for f in dataclasses.fields(cls)}[key]
    options = []
    if tp is float:
        options += [NONFINITE, WRONG_SCALARS, st.just("[1.0, 2.0]")]
    elif tp is int:
        options += [st.floats(0.01, 0.99).map(lambda f: _fmt(f + draw(st.integers(-5, 50)))), WRONG_SCALARS,
                    st.just("[1]"), NONFINITE, st.just(str(2 ** 70))]
    elif tp is bool:
        options += [st.sampled_from(["1", "0", '"true"', "1.0", "[true]", "nan"])]
    elif tp is str:
        options += [st.sampled_from(["5", "true", "[\"a\"]", "1.5", "{ x = 1 }"])]
        if meta.get("choices"):
            options.append(NAME_TEXT.filter(lambda v, c=meta["choices"]: v not in c).map(json.dumps))
    elif tp is list:
        n = meta.get("length") or meta.get("multiple") or 1
        options += [st.just("[]"), st.just("5"), st.just('["a", "b"]'), st.just("[[1.0]]"),
                    st.integers(0, n - 1).flatmap(lambda i: NONFINITE.map(
                        lambda v: "[" + ", ".join(v if j == i else "1.0" for j in range(n)) + "]"))]
    elif tp is tuple:
        options += [st.just("[1, 2]"), st.just('"rectilinear"'),
                    NAME_TEXT.filter(lambda v: v not in registry.GAITS).map(lambda v: json.dumps([v]))]
    for op, sign in (("gt", -1), ("ge", -1), ("lt", 1), ("le", 1)):
        b = meta.get(op)
        if b is None or tp not in (int, float):
            continue
        strict = op in ("gt", "lt")
        lo = 0.0 if strict else 1.0
        delta = draw(st.floats(lo, 1e6, allow_nan=False))
        if tp is int:
            delta = math.ceil(delta) if not strict else math.floor(delta)
            v = int(b) + sign * int(delta)
            if (op == "gt" and v > b) or (op == "ge" and v >= b) or (op == "lt" and v < b) or (op == "le" and v <= b):
                continue
            options.append(st.just(str(v)))
        else:
            v = float(b) + sign * delta
            if (op == "gt" and v > b) or (op == "ge" and v >= b) or (op == "lt" and v < b) or (op == "le" and v <= b):
                continue
            options.append(st.just(_fmt(v)))
    if meta.get("ordered") and tp is list:
        options.append(st.just("[2.0, 1.0]"))
    return draw(st.one_of(*options))


def bad_keys(cls) -> list[str]:
    """Keys with a value that can be made bad by type (every key except free-text strings)."""
    return [k for k in field_types(cls) if k not in SKIP_KEYS]


@st.composite
def defect_line(draw, table: str) -> tuple[str, str]:
    """(table, line) with a bad value or an unknown key for one of the table's keys."""
    cls = TABLE_CLASS[table]
    if draw(st.integers(0, 9)) == 0:
        return table, f"zz_{draw(NAME_TEXT.map(lambda s: s.replace(' ', '_').replace('-', '_')))} = 1"
    key = draw(st.sampled_from(bad_keys(cls)))
    return table, f"{key} = {draw(bad_value(cls, key))}"


# --------------------------------------------------------------------------- files

def _with_line(base: dict, table: str, line: str) -> dict:
    d = {t: list(v) for t, v in base.items()}
    key = line.split("=", 1)[0].strip()
    d[table] = [x for x in d[table] if x.split("=", 1)[0].strip() != key] + [line]
    return d


RAW_DEFECTS = st.sampled_from([
    lambda t: t.encode() + b"\n# caf\xe9\n",                                   # not UTF-8
    lambda t: (t + "\nx = " + "[" * 3000 + "]" * 3000 + "\n").encode(),         # recursion
    lambda t: (t + "\n" + "[a" + ".b" * 30 + "]\nc = 1\n").encode(),            # depth / unknown table
    lambda t: t.encode()[: max(1, len(t) // 2)] + b' = "',                     # truncated mid-string
    lambda t: ("[[creature]]\n" + t).encode(),                                 # an array of tables
    lambda t: (t + "\n[creature]\nsegments = 5\n").encode(),                   # duplicate table
])


@st.composite
def creature_input(draw):
    kind = draw(st.integers(0, 5))
    if kind <= 3:
        table, line = draw(st.sampled_from(list(CREATURE)).flatmap(defect_line))
        data = toml_text(_with_line(CREATURE, table, line)).encode()
    elif kind == 4:
        data = draw(RAW_DEFECTS)(toml_text(CREATURE))
    else:
        choice = draw(st.integers(0, 4))
        if choice == 0:  # a top-level bodies / gaits that is not a table
            base = {k: v for k, v in CREATURE.items() if k not in ("bodies.massspring", "gaits.rectilinear")}
            top = draw(st.sampled_from(["bodies = 5", 'gaits = "x"', "bodies = [1]", 'gaits = [{ a = 1 }]']))
            data = (top + "\n" + toml_text(base)).encode()
        elif choice in (1, 2):  # a name key inside a body or gait table
            table = "bodies.massspring" if choice == 1 else "gaits.rectilinear"
            value = draw(st.sampled_from(['"fem"', '"hybrid"', '"leg-wave"', '"rectilinear"', '"x"']))
            data = toml_text(_with_line(CREATURE, table, f"name = {value}")).encode()
        else:
            data = (toml_text(CREATURE) + ("[bodies.nonesuch]\n" if choice == 3 else "[gaits.nonesuch]\n")).encode()
    return {"c.toml": data}, ["run", "--creature", "{d}/c.toml", "--body", "massspring", "--scenario", "flat",
                              "--store", "{d}/r.sqlite"]


@st.composite
def scenario_input(draw):
    if draw(st.integers(0, 4)) < 4:
        table, line = draw(st.sampled_from(list(SCENARIO)).flatmap(defect_line))
        data = toml_text(_with_line(SCENARIO, table, line)).encode()
    else:
        data = draw(RAW_DEFECTS)(toml_text(SCENARIO))
    cmd = draw(st.sampled_from(["run", "stable-dt"]))
    return {"s.toml": data}, [cmd, "--creature", "worm", "--body", "massspring", "--scenario", "{d}/s.toml",
                              "--store", "{d}/r.sqlite"]


MATRIX_DEFECTS = st.sampled_from([
    ("matrix", 'creatures = "worm"'), ("matrix", "creatures = [1]"), ("matrix", 'creatures = ["nonesuch"]'),
    ("matrix", "creatures = []"), ("matrix", 'bodies = ["nonesuch"]'), ("matrix", 'gaits = ["nonesuch"]'),
    ("matrix", 'scenarios = ["nonesuch"]'), ("matrix", "seeds = [-1]"), ("matrix", "seeds = [1.5]"),
    ("matrix", 'seeds = ["a"]'), ("matrix", "seeds = [true]"), ("matrix", "duration = nan"),
    ("matrix", "duration = inf"), ("matrix", "duration = -1"), ("matrix", 'duration = "1"'),
    ("matrix", "duration = 1e300"), ("matrix", 'name = "/tmp/fuzz-abs"'), ("matrix", 'name = "../up"'),
    ("matrix", 'name = ".."'), ("matrix", "name = 5"), ("matrix", 'name = "a/b"'), ("matrix", "description = 1"),
    ("matrix", "zz_unknown = 1"), ("matrix", "set = 5"), ("matrix", 'set = { "friction.mu_transverse" = nan }'),
    ("matrix", 'set = { "friction.nonesuch" = 1 }'), ("matrix", 'set = { "x" = { a = 1 } }'),
    ("matrix", 'set = { "creature.name" = "x" }'), ("matrix", "grid = 5"), ("matrix", "grid = {}"),
    ("matrix", 'grid = { "dt" = 0.001 }'), ("matrix", 'grid = { "dt" = [] }'), ("matrix", 'grid = { "dt" = [nan] }'),
    ("matrix", 'grid = { "dt" = [{ a = 1 }] }'), ("matrix", 'grid = { "body.nonesuch" = [1] }'),
    ("matrix", 'grid = { "seed" = [-1] }'), ("matrix", 'grid = { "dt" = [1.0] }'),
    ("exclude", "creature = 5"), ("exclude", 'seed = "a"'), ("exclude", "nonesuch = 1"), ("exclude", "body = []"),
    ("exclude", 'body = ["massspring", 2]'), ("block", "creatures = 5"), ("block", "nonesuch = 1"),
    ("block", 'bodies = ["nonesuch"]'), ("zz", "a = 1"),
])


@st.composite
def matrix_input(draw):
    if draw(st.integers(0, 5)) < 5:
        table, line = draw(MATRIX_DEFECTS)
        if table == "matrix":
            text = toml_text(_with_line(MATRIX, "matrix", line))
        else:
            text = toml_text(MATRIX) + (f"[[{table}]]\n" if table in ("exclude", "block") else f"[{table}]\n") + line + "\n"
    else:
        return {"m.toml": draw(RAW_DEFECTS)(toml_text(MATRIX))}, ["matrix", "{d}/m.toml", "--out", "{d}/o"]
    return {"m.toml": text.encode()}, ["matrix", "{d}/m.toml", "--out", "{d}/o"]


# --------------------------------------------------------------------------- flags

CASE = ["--creature", "worm", "--body", "massspring", "--scenario", "flat"]
JSON = st.recursive(st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text(max_size=8),
                    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=6), inner, max_size=3),
                    max_leaves=8)
BAD_FLOAT = st.sampled_from(["nan", "inf", "-inf", "-1", "0", "abc", "", "1e999", "-0"])


@st.composite
def set_pair(draw) -> str:
    section = draw(st.sampled_from(["creature", "friction", "gait", "scenario", "record", "stability", "metrics",
                                    "controller", "antennae", "food", "legs", "collision", "body"]))
    cls = MS if section == "body" else SECTIONS[section]
    choice = draw(st.integers(0, 12))
    if choice == 0:
        return f"{section}.zz_nonesuch=1"
    if choice == 1:
        return draw(st.sampled_from(["noequals", "a.b.c=1", "nonesuch.key=1", "creature.name=x", "body.name=fem",
                                     "gait.name=x", "scenario.name=x", "dt=nan", "duration=-1", "seed=-3",
                                     "seed=1.5", "dt=0", "duration=inf", "creature.gaits=[\"nonesuch\"]",
                                     "scenario.control_times_s=[0, 1]", "creature.legs_per_segment=2.5"]))
    key = draw(st.sampled_from([k for k in bad_keys(cls)]))
    value = draw(bad_value(cls, key))
    if value == '""':  # --set reads a bare empty string as a string: fine for a str key's choices, not a bad type
        value = "[]"
    return f"{section}.{key}={value}"


@st.composite
def run_flags(draw):
    cmd = draw(st.sampled_from(["run", "stable-dt"]))
    kind = draw(st.integers(0, 9))
    if kind == 0:
        extra = [draw(st.sampled_from(["--duration", "--dt"])), draw(BAD_FLOAT)]
    elif kind == 1:
        extra = ["--seed", draw(st.sampled_from(["-1", "1.5", "x", str(2 ** 64)]))]
    elif kind <= 4:
        extra = ["--set", draw(set_pair())]
    elif kind == 5:
        flag = draw(st.sampled_from(["--creature", "--body", "--scenario", "--gait"]))
        name = draw(NAME_TEXT.filter(lambda v: v.strip() and v not in ("worm", "massspring", "flat", "rectilinear")
                                     and v not in registry.BODIES and v not in registry.GAITS))
        argv = [cmd, *CASE, "--store", "{d}/r.sqlite"]
        i = argv.index(flag) if flag in argv else None
        if i is None:
            return {}, argv + [flag, name]
        argv[i + 1] = name
        return {}, argv
    elif kind == 6:
        extra = ["--duration", _fmt(draw(st.floats(2e6, 1e300)))]  # beyond the 1e9-step budget at dt = 1/600 s
    elif kind == 7:
        extra = [draw(st.sampled_from(["--memory-budget", "--max-steps"])), draw(BAD_FLOAT.filter(lambda v: v != "1e999"))]
    elif kind == 8:
        if cmd == "run":
            flag = draw(st.sampled_from(["--record", "--export-frames", "--plot-gait", "--animate"]))
            value = draw(st.sampled_from(["", " ", "{d}/afile", "x.txt"]))
            if flag == "--export-frames" and value == "x.txt":  # a fine folder name (as an empty folder is)
                value = "{d}/afile"
            return {"afile": b"x"}, [cmd, *CASE, "--store", "{d}/r.sqlite", flag, value]
        else:
            extra = [draw(st.sampled_from(["--rel-tol", "--max-runs"])),
                     draw(st.sampled_from(["nan", "inf", "0", "-1", "1", "x", "100000"]))]
            if extra[0] == "--rel-tol" and extra[1] == "1":
                extra[1] = "11"
    else:
        store = draw(st.sampled_from(["", "{d}", "{d}/garbage.sqlite", "{d}/empty/x.sqlite"]))
        files = {"garbage.sqlite": b"not sqlite at all" * 20} if "garbage" in store else {}
        if "empty" in store:
            files["empty"] = b"a file, not a folder"
        return files, [cmd, *CASE, "--store", store]
    return {}, [cmd, *CASE, "--store", "{d}/r.sqlite", *extra]


@st.composite
def other_flags(draw, cmd: str):
    if cmd == "matrix":
        extra = draw(st.sampled_from([
            ["--workers", "0"], ["--workers", "-3"], ["--workers", "99999"], ["--timeout-per-case", "inf"],
            ["--timeout-per-case", "nan"], ["--timeout-per-case", "0"], ["--timeout-per-case", "-5"],
            ["--scheduler", "tcp://x:1"], ["--retry-failed"], ["--dask-timeout", "5"], ["--executor", "ray"],
            ["--out", ""], ["--out", "{d}/afile"], ["--memory-budget", "0"], ["--max-steps", "nan"],
            ["--nonesuch"], ["--duration", "0.1"]]))
        name = draw(st.sampled_from(["quick", "{d}/nonesuch.toml", "nonesuch-matrix", "{d}"]))
        if name != "quick" and extra == ["--duration", "0.1"]:
            extra = ["--workers", "0"]
        files = {"afile": b"x"} if "{d}/afile" in extra else {}
        return files, ["matrix", name, *[e for e in extra], *([] if "--out" in extra else ["--out", "{d}/o"])]
    if cmd == "report":
        choice = draw(st.integers(0, 5))
        if choice == 0:
            return {}, ["report", "{d}/" + draw(NAME_TEXT.map(lambda v: v.strip() or "x"))]  # no such directory
        if choice == 1:
            return {"notdir": draw(st.binary(max_size=50))}, ["report", "{d}/notdir"]
        if choice == 2:  # ({d} is no matrix directory either)
            return {}, ["report", "{d}", "--threshold", draw(st.one_of(
                st.sampled_from(["nan", "inf", "x", ""]), st.floats(max_value=0.0).map(_fmt),
                st.floats(min_value=10.0).map(_fmt)))]
        if choice == 3:  # a store that is not SQLite next to any matrix.json
            store = draw(st.binary(max_size=300).filter(lambda b: not b.startswith(b"SQLite format 3")))
            manifest = draw(st.one_of(st.binary(max_size=100), JSON.map(lambda v: json.dumps(v).encode())))
            return {"results.sqlite": store, "matrix.json": manifest}, ["report", "{d}"]
        if choice == 4:
            store = draw(st.binary(min_size=1, max_size=300).filter(lambda b: not b.startswith(b"SQLite format 3")))
            return {"h.sqlite": store}, ["report", "{d}", "--history-store", draw(st.sampled_from(["", "{d}/h.sqlite"]))]
        return {}, ["report", "{d}", "--baseline", "{d}/nonesuch"]
    extra = draw(st.one_of(
        st.sampled_from([["--repeats", "x"], ["--threshold", "x"], ["--suite"], ["--store", ""], ["--store", "{d}"],
                         ["--store", "{d}/g.sqlite"], ["--baseline", "nonesuch-run"], ["--nonesuch"]]),
        st.one_of(st.integers(max_value=2), st.integers(min_value=1001)).map(lambda n: ["--repeats", str(n)]),
        st.one_of(st.floats(max_value=-1e-9), st.floats(min_value=1.0), st.sampled_from([math.nan])).map(
            lambda x: ["--threshold", _fmt(x)]),
        NAME_TEXT.filter(lambda v: v not in SUITE and v.strip()).map(lambda v: ["--suite", v])))
    files = {"g.sqlite": draw(st.binary(min_size=1, max_size=300).filter(
        lambda b: not b.startswith(b"SQLite format 3")))} if "{d}/g.sqlite" in extra else {}
    store = [] if "--store" in extra else ["--store", "{d}/r.sqlite"]
    return files, ["regress", *extra, *store]


INPUTS = st.one_of(creature_input(), scenario_input(), matrix_input(), run_flags(), other_flags("matrix"),
                   other_flags("report"), other_flags("regress"))


# --------------------------------------------------------------------------- the test

def test_the_fuzzer_base_files_are_valid(tmp_path):
    """The files the fuzzer puts one defect into are valid without it (so every defect is the cause)."""
    (tmp_path / "c.toml").write_text(toml_text(CREATURE))
    (tmp_path / "s.toml").write_text(toml_text(SCENARIO))
    (tmp_path / "m.toml").write_text(toml_text(MATRIX))
    resolve_case(str(tmp_path / "c.toml"), "massspring", "flat")
    resolve_case("worm", "massspring", str(tmp_path / "s.toml"))
    load_matrix(tmp_path / "m.toml")


def _refuse(*a, **k):
    raise AssertionError("a malformed input got as far as running")


OUTCOMES: Counter = Counter()


def _listing(d: Path) -> dict:
    return {str(p.relative_to(d)): (p.stat().st_size if p.is_file() else -1, p.stat().st_mtime_ns)
            for p in sorted(d.rglob("*"))}


@settings(max_examples=EXAMPLES, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much, HealthCheck.data_too_large])
@given(INPUTS)
def _fuzz_one(example):
    files, argv = example
    cwd = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="bench-fuzz-") as tmp:
        d = Path(tmp)
        for name, data in files.items():
            (d / name).write_bytes(data)
        args = [a.replace("{d}", tmp) for a in argv]
        before = _listing(d)
        err, out = io.StringIO(), io.StringIO()
        with contextlib.ExitStack() as stack:
            for target in ("bench_myriapoda.harness.runner.run_case", "bench_myriapoda.harness.executors.run_matrix",
                           "bench_myriapoda.harness.stable_dt.find_stable_dt",
                           "bench_myriapoda.harness.regress.run_suite"):
                stack.enter_context(mock.patch(target, _refuse))
            stack.enter_context(contextlib.redirect_stderr(err))
            stack.enter_context(contextlib.redirect_stdout(out))
            os.chdir(tmp)
            try:
                code = main(args)
            except SystemExit as exc:  # argparse --help and the like: not expected here
                code = exc.code
            finally:
                os.chdir(cwd)
        text = err.getvalue()
        OUTCOMES[code] += 1
        if os.environ.get("BENCH_FUZZ_LOG"):  # every input's one line, to see what the fuzzer reached
            with open(os.environ["BENCH_FUZZ_LOG"], "a", encoding="utf-8") as fh:
                fh.write(f"{code}\t{argv[0]}\t{text.strip().replace(tmp, '{d}')}\n")
        assert code == 2, (args, code, text[-2000:])
        assert text.count("\n") == 1 and text.startswith("bench-myriapoda: error: "), (args, text)
        assert "Traceback" not in text
        assert _listing(d) == before, (args, "wrote", set(_listing(d)) - set(before))
    assert not Path("/tmp/fuzz-abs").exists()


def compiled_signatures() -> int:
    """How many (function, signature) pairs numba has compiled or loaded from its cache in this process."""
    import sys

    from numba.core.dispatcher import Dispatcher

    seen, n = set(), 0
    for name, mod in list(sys.modules.items()):
        if not name.startswith("bench_myriapoda") or mod is None:
            continue
        for obj in vars(mod).values():
            if isinstance(obj, Dispatcher) and id(obj) not in seen:
                seen.add(id(obj))
                n += len(obj.signatures)
    return n


def test_generated_malformed_inputs_all_exit_2_with_one_line_and_write_nothing(capsys):
    OUTCOMES.clear()
    compiled = compiled_signatures()
    _fuzz_one()
    assert compiled_signatures() == compiled  # validation refused every input before any kernel was compiled
    total = sum(OUTCOMES.values())
    with capsys.disabled():
        print(f"\nfuzz: {total} generated malformed inputs; exit codes {dict(OUTCOMES)}; "
              f"{100.0 * OUTCOMES[2] / max(1, total):.1f} % exit 2")
    assert total >= min(EXAMPLES, 1000) * 0.95  # hypothesis ran (about) the budget
    assert OUTCOMES[2] == total


# =========================================================================== issue 28 part 4 and issue 32
# Every input of the two issues' lists, one parametrized case each.  The same contract as the
# generated inputs above: exit 2, exactly one line on stderr that names the flag, file or key (the
# ``words``), no traceback, nothing written to the fresh directory the command runs in (its listing
# with sizes and mtimes compared before and after), and no simulation (the stubs above fail the test).

import sqlite3  # noqa: E402
import stat  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

from bench_myriapoda.harness.store import SCHEMA, connect  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
RUN = ["run", *CASE, "--duration", "0.05"]
LONG = "x" * 300  # one path component longer than the 255 bytes a Linux file system allows


def _suite_store(p: Path, *extra_sql: str) -> None:
    """A results store of this suite (every table), with ``extra_sql`` run on it afterwards."""
    connect(p).close()
    con = sqlite3.connect(p)
    for sql in extra_sql:
        con.executescript(sql)
    con.commit()
    con.close()


def _plain_db(p: Path, *sql: str) -> None:
    con = sqlite3.connect(p)
    for s in sql:
        con.executescript(s)
    con.commit()
    con.close()


def _extra_not_null(p: Path) -> None:
    """``runs`` with one more column, NOT NULL without a default: every insert of the suite fails."""
    _plain_db(p, SCHEMA.replace("timestamp TEXT NOT NULL\n);", "timestamp TEXT NOT NULL,\n    owner_id INTEGER NOT NULL\n);", 1))


def _truncated_store(p: Path) -> None:
    _suite_store(p)
    con = sqlite3.connect(p)
    con.execute("INSERT INTO regress_history VALUES (1, 'e', 'c', 0, '{}', '2026-01-01T00:00:00Z', 1, 1, 1, 0, 1, 0, 1, '{}')")
    con.commit()
    con.close()
    data = p.read_bytes()
    p.write_bytes(data[: len(data) // 3 + 10])


STORE_DEFECTS = {
    # name: (make(path), words in the message)
    "foreign-runs-schema": (lambda p: _plain_db(p, "CREATE TABLE runs (id INTEGER PRIMARY KEY, x TEXT)"), "runs"),
    "extra-not-null-column": (_extra_not_null, "owner_id"),
    "runs-is-a-view": (lambda p: _plain_db(p, "CREATE TABLE t (id INTEGER); CREATE VIEW runs AS SELECT id FROM t"),
                       "view"),
    "aborting-trigger": (lambda p: _suite_store(p, "CREATE TRIGGER no_insert BEFORE INSERT ON runs BEGIN "
                                                   "SELECT RAISE(ABORT, 'refused'); END;"), "trigger"),
    "validation-trigger": (lambda p: _suite_store(p, "CREATE TRIGGER no_v BEFORE INSERT ON validation BEGIN "
                                                     "SELECT RAISE(ABORT, 'refused'); END;"), "trigger"),
    "index-name-taken-by-a-table": (lambda p: _plain_db(p, "CREATE TABLE runs_case_hash (a INTEGER)"), "runs_case_hash"),
    "unique-index-on-runs": (lambda p: _suite_store(p, "CREATE UNIQUE INDEX one_per_case ON runs(case_hash)"),
                             "one_per_case"),
    "only-a-users-table": (lambda p: _plain_db(p, "CREATE TABLE users (id INTEGER PRIMARY KEY, name TEXT)"), "users"),
    "foreign-validation-table": (lambda p: _plain_db(p, "CREATE TABLE validation (id INTEGER, x TEXT)"), "validation"),
    "nullable-figure-column": (lambda p: _plain_db(p, SCHEMA.replace("normalized REAL NOT NULL", "normalized REAL")),
                               "normalized"),
    "random-bytes": (lambda p: p.write_bytes(b"\x8f" + os.urandom(4095)), "not a SQLite"),
    "truncated": (_truncated_store, "SQLite"),
    "dangling-symlink": (lambda p: os.symlink(p.parent / "gone" / "r.sqlite", p), "symbolic link"),
}
STORE_COMMANDS = {
    "run": lambda s: [*RUN, "--store", s],
    "stable-dt": lambda s: ["stable-dt", *CASE, "--duration", "0.05", "--store", s],
    "validate": lambda s: ["validate", "--check", "analytic", "--quick", "--store", s, "--out", "{d}/v"],
    "regress": lambda s: ["regress", "--repeats", "3", "--store", s],
}


@dataclasses.dataclass
class Bad:
    """One listed input: ``argv`` (``{d}`` is the fresh directory), ``words`` the one line must hold,
    ``setup(d)`` what the directory holds first."""

    argv: list
    words: tuple
    setup: object = None
    patches: dict = dataclasses.field(default_factory=dict)  # target -> value while the command runs


def _store_cases() -> dict[str, Bad]:
    cases = {}
    for defect, (make, word) in STORE_DEFECTS.items():
        for cmd, argv in STORE_COMMANDS.items():
            cases[f"{cmd}-store-{defect}"] = Bad(argv("{d}/r.sqlite"), ("--store", word),
                                                 lambda d, make=make: make(d / "r.sqlite"))
        cases[f"matrix-out-store-{defect}"] = Bad(
            ["matrix", "quick", "--out", "{d}/o"], ("--out", word),
            lambda d, make=make: ((d / "o").mkdir(), make(d / "o" / "results.sqlite")))
    for cmd, argv in STORE_COMMANDS.items():
        cases[f"{cmd}-store-empty"] = Bad(argv(""), ("--store", "empty"))
        cases[f"{cmd}-store-blank"] = Bad(argv(" "), ("--store", "empty"))
        cases[f"{cmd}-store-long-name"] = Bad(argv("{d}/" + LONG + ".sqlite"), ("--store", "255"))
        cases[f"{cmd}-store-read-only"] = Bad(argv("{d}/ro/r.sqlite"), ("--store", "not writable"), "ro")
        cases[f"{cmd}-store-fifo"] = Bad(argv("{d}/fifo"), ("--store", "not a regular file"),
                                         lambda d: os.mkfifo(d / "fifo"))
    cases["report-history-store-foreign"] = Bad(["report", "{d}/m", "--history-store", "{d}/h.sqlite"],
                                                ("--history-store", "users"),
                                                lambda d: _plain_db(d / "h.sqlite", "CREATE TABLE users (id INTEGER)"))
    return cases


def _fifo(name):
    return lambda d: os.mkfifo(d / name)


def _matrix_file(text: str):
    return lambda d: (d / "m.toml").write_text(text)


def _seeds(n: int) -> str:
    return "[" + ", ".join(str(i) for i in range(n)) + "]"


def _history(timestamp: str) -> object:
    def make(d):
        _suite_store(d / "r.sqlite")
        con = sqlite3.connect(d / "r.sqlite")
        con.execute("INSERT INTO regress_history VALUES (1, 'e', 'c', 0, '{}', ?, 1, 1, 1, 0, 1, 0, 1, '{}')",
                    (timestamp,))
        con.commit()
        con.close()
    return make


def _validation_out_json_dir(d):
    (d / "v" / "validation.json").mkdir(parents=True)


def _truncated_creature(d):
    text = (ROOT / "models" / "snake.toml").read_text()
    (d / "c.toml").write_text(text[: text.index("[bodies")])


OTHER_CASES = {
    # output paths, checked before the run
    "run-record-long-name": Bad([*RUN, "--store", "{d}/r.sqlite", "--record", "{d}/" + LONG + ".npz"], ("--record", "255")),
    "run-animate-long-name": Bad([*RUN, "--store", "{d}/r.sqlite", "--animate", "{d}/" + LONG + ".gif"], ("--animate", "255")),
    "run-plot-gait-long-name": Bad(["run", "--creature", "centipede", "--body", "massspring", "--scenario", "flat",
                                    "--store", "{d}/r.sqlite", "--plot-gait", "{d}/" + LONG + ".png"],
                                   ("--plot-gait", "255")),
    "run-record-long-folder": Bad([*RUN, "--store", "{d}/r.sqlite", "--record", "{d}/" + LONG + "/r.npz"], ("--record", "255")),
    "run-record-only-a-suffix": Bad([*RUN, "--store", "{d}/r.sqlite", "--record", ".npz"], ("--record", "suffix")),
    "run-record-only-a-suffix-in-a-folder": Bad([*RUN, "--store", "{d}/r.sqlite", "--record", "{d}/.npz"],
                                                ("--record", "suffix")),
    "run-animate-only-a-suffix": Bad([*RUN, "--store", "{d}/r.sqlite", "--animate", ".gif"], ("--animate", "suffix")),
    "run-record-fifo": Bad([*RUN, "--store", "{d}/r.sqlite", "--record", "{d}/f.npz"], ("--record", "not a regular file"),
                           _fifo("f.npz")),
    "run-animate-fifo": Bad([*RUN, "--store", "{d}/r.sqlite", "--animate", "{d}/f.gif"],
                            ("--animate", "not a regular file"), _fifo("f.gif")),
    "run-record-root": Bad([*RUN, "--store", "{d}/r.sqlite", "--record", "/"], ("--record",)),
    "validate-out-long-name": Bad(["validate", "--check", "analytic", "--quick", "--no-store", "--out", "{d}/" + LONG],
                                  ("--out", "255")),
    "validate-out-read-only": Bad(["validate", "--check", "analytic", "--quick", "--no-store", "--out", "{d}/ro/v"],
                                  ("--out", "not writable"), "ro"),
    "validate-out-under-a-file": Bad(["validate", "--check", "analytic", "--quick", "--no-store", "--out", "{d}/afile/v"],
                                     ("--out", "not a directory"), lambda d: (d / "afile").write_text("x")),
    "validate-out-json-is-a-directory": Bad(["validate", "--check", "analytic", "--quick", "--no-store", "--out", "{d}/v"],
                                            ("--out", "validation.json"), _validation_out_json_dir),
    "validate-out-root": Bad(["validate", "--check", "analytic", "--quick", "--no-store", "--out", "/"],
                             ("--out", "root")),
    "validate-out-empty": Bad(["validate", "--check", "analytic", "--quick", "--no-store", "--out", ""], ("--out", "empty")),
    "validate-out-blank": Bad(["validate", "--check", "analytic", "--quick", "--no-store", "--out", " "], ("--out", "empty")),
    "matrix-out-root": Bad(["matrix", "quick", "--out", "/"], ("--out", "root")),
    "matrix-out-long-name": Bad(["matrix", "quick", "--out", "{d}/" + LONG], ("--out", "255")),
    "matrix-out-read-only": Bad(["matrix", "quick", "--out", "{d}/ro/o"], ("--out", "not writable"), "ro"),
    "matrix-file-long-name": Bad(["matrix", "{d}/" + LONG + ".toml", "--out", "{d}/o"], ("255",)),
    "matrix-file-empty": Bad(["matrix", "", "--out", "{d}/o"], ("matrix", "empty")),
    # inputs only from regular files (a FIFO would block the read)
    "creature-fifo": Bad(["run", "--creature", "{d}/c.toml", "--body", "massspring", "--scenario", "flat",
                          "--store", "{d}/r.sqlite"], ("c.toml", "not a regular file"), _fifo("c.toml")),
    "scenario-fifo": Bad(["run", "--creature", "worm", "--body", "massspring", "--scenario", "{d}/s.toml",
                          "--store", "{d}/r.sqlite"], ("s.toml", "not a regular file"), _fifo("s.toml")),
    "matrix-fifo": Bad(["matrix", "{d}/m.toml", "--out", "{d}/o"], ("m.toml", "not a regular file"), _fifo("m.toml")),
    "creature-truncated": Bad(["run", "--creature", "{d}/c.toml", "--body", "massspring", "--scenario", "flat",
                               "--store", "{d}/r.sqlite"], ("c.toml", "bodies"), _truncated_creature),
    # sizes bounded before expansion or building
    "matrix-200000-seeds": Bad(["matrix", "{d}/m.toml", "--out", "{d}/o"], ("m.toml", "cases"), _matrix_file(
        f'[matrix]\ncreatures = ["worm"]\nbodies = ["massspring"]\nscenarios = ["flat"]\nseeds = {_seeds(200_000)}\n')),
    "matrix-9M-grid-cases": Bad(["matrix", "{d}/m.toml", "--out", "{d}/o"], ("m.toml", "cases"), _matrix_file(
        '[matrix]\ncreatures = ["worm"]\nbodies = ["massspring"]\nscenarios = ["flat"]\n'
        f"seeds = {_seeds(300)}\n[matrix.grid]\n\"friction.mu_transverse\" = {[0.1 + i * 1e-4 for i in range(300)]}\n"
        f"\"gait.frequency_hz\" = {[0.1 + i * 1e-3 for i in range(100)]}\n")),
    "matrix-200-blocks-of-1000-duplicates": Bad(["matrix", "{d}/m.toml", "--out", "{d}/o"], ("m.toml", "cases"),
                                                _matrix_file('[matrix]\ncreatures = ["worm"]\nbodies = ["massspring"]\n'
                                                             'scenarios = ["flat"]\n' + "[[block]]\n[block.grid]\n"
                                                             f"\"gait.frequency_hz\" = {[0.5] * 1000}\n" * 200)),
    "fem-1000-segments-resolution-12": Bad(["run", "--creature", "worm", "--body", "fem", "--scenario", "flat",
                                            "--set", "creature.segments=1000", "--set", "body.resolution=12",
                                            "--store", "{d}/r.sqlite"], ("memory", "body.resolution"),
                                           # a 16 GB machine with 12 GB available (this one may hold the case)
                                           patches={"bench_myriapoda.core.feasibility.machine_memory_bytes": 16e9,
                                                    "bench_myriapoda.core.feasibility.available_memory_bytes": 12e9,
                                                    "bench_myriapoda.core.feasibility._cgroup_limit_bytes": 0.0}),
    # flags
    "regress-baseline-superscript-two": Bad(["regress", "--repeats", "3", "--store", "{d}/r.sqlite", "--baseline", "²"],
                                            ("--baseline",), _history("2026-01-01T00:00:00Z")),
    "regress-history-bad-timestamp": Bad(["regress", "--repeats", "3", "--store", "{d}/r.sqlite"],
                                         ("r.sqlite", "regress_history.timestamp"),
                                         _history("yesterday-ish")),
    "regress-threshold-underflow": Bad(["regress", "--threshold", "5e-400", "--store", "{d}/r.sqlite"], ("--threshold",)),
    "stable-dt-rel-tol-1": Bad(["stable-dt", *CASE, "--rel-tol", "1", "--store", "{d}/r.sqlite"], ("--rel-tol",)),
    "stable-dt-rel-tol-2": Bad(["stable-dt", *CASE, "--rel-tol", "2", "--store", "{d}/r.sqlite"], ("--rel-tol",)),
    "version-with-another-flag": Bad(["--version", "--bogus"], ("--bogus",)),
    "dt-1e-300": Bad([*RUN, "--dt", "1e-300", "--store", "{d}/r.sqlite"], ("--dt", "out of range")),
    # --set: exactly one TOML value of the key's type
    "set-two-lines": Bad([*RUN, "--set", "dt=0.001\ndt=5", "--store", "{d}/r.sqlite"], ("--set", "dt")),
    "set-value-and-a-table": Bad([*RUN, "--set", "friction.mu_forward=0.2\n[x]", "--store", "{d}/r.sqlite"],
                                 ("--set", "friction.mu_forward")),
    "set-float-for-an-int-key": Bad([*RUN, "--set", "creature.segments=3.0", "--store", "{d}/r.sqlite"],
                                    ("--set", "creature.segments", "integer")),
    "set-default-gait-empty-quoted": Bad([*RUN, "--set", 'creature.default_gait=""', "--store", "{d}/r.sqlite"],
                                         ("--set", "creature.default_gait")),
    "set-default-gait-empty": Bad([*RUN, "--set", "creature.default_gait=", "--store", "{d}/r.sqlite"],
                                  ("--set", "creature.default_gait")),
    "set-default-gait-not-the-worms": Bad([*RUN, "--set", 'creature.default_gait="sidewinding"', "--store", "{d}/r.sqlite"],
                                          ("--set", "creature.default_gait", "sidewinding")),
    "set-default-gait-unknown": Bad([*RUN, "--set", 'creature.default_gait="bogus"', "--store", "{d}/r.sqlite"],
                                    ("--set", "creature.default_gait", "bogus")),
    "set-gravity-1e300": Bad([*RUN, "--set", "scenario.gravity_m_s2=1e300", "--store", "{d}/r.sqlite"],
                             ("--set", "scenario.gravity_m_s2")),
    # buildability, checked with the other checks before a body is built
    "mesh-subdivisions-hash-grid": Bad([*RUN, "--set", 'scenario.terrain="mesh"', "--set", "scenario.mesh_subdivisions=400",
                                        "--store", "{d}/r.sqlite"], ("scenario.mesh_subdivisions", "cells")),
    "body-mesh-unsupported-file-type": Bad(["run", "--creature", "worm", "--body", "fem", "--scenario", "flat",
                                            "--set", 'body.mesh="/etc/passwd"', "--store", "{d}/r.sqlite"],
                                           ("body.mesh", "passwd")),
}

LISTED = {**_store_cases(), **OTHER_CASES}


def _lstat_listing(d: Path) -> dict:
    """Every entry under ``d`` (a symbolic link itself, not its target) with its size and mtime."""
    out = {}
    for p in sorted(d.rglob("*")):
        st = p.lstat()
        out[str(p.relative_to(d))] = (st.st_size if stat.S_ISREG(st.st_mode) else -1, st.st_mtime_ns)
    return out


@contextlib.contextmanager
def _read_only_dir(path: Path):
    """``path`` as a directory that cannot be written: a read-only tmpfs as root (for whom permission bits
    do not count), else mode 0555.  Skips when neither holds."""
    path.mkdir()
    if os.geteuid() == 0:
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", "ro,size=64k", "tmpfs", str(path)], capture_output=True)
        if r.returncode != 0:
            path.rmdir()
            pytest.skip("cannot mount a read-only tmpfs as root here")
        try:
            yield path
        finally:
            subprocess.run(["umount", str(path)], check=False)
    else:
        path.chmod(0o555)
        try:
            yield path
        finally:
            path.chmod(0o755)


@pytest.mark.parametrize("name", sorted(LISTED))
def test_every_listed_input_is_refused_with_one_line_before_anything_runs_or_is_written(name, tmp_path):
    case = LISTED[name]
    d = tmp_path / "work"
    d.mkdir()
    with contextlib.ExitStack() as stack:
        if case.setup == "ro":
            stack.enter_context(_read_only_dir(d / "ro"))
        elif case.setup is not None:
            case.setup(d)
        args = [a.replace("{d}", str(d)) for a in case.argv]
        before = _lstat_listing(d)
        err, out = io.StringIO(), io.StringIO()
        for target in ("bench_myriapoda.harness.runner.run_case", "bench_myriapoda.harness.executors.run_matrix",
                       "bench_myriapoda.harness.stable_dt.find_stable_dt", "bench_myriapoda.harness.regress.run_suite",
                       "bench_myriapoda.validation.run.run_checks"):
            stack.enter_context(mock.patch(target, _refuse))
        for target, value in case.patches.items():
            stack.enter_context(mock.patch(target, lambda v=value: v))
        stack.enter_context(contextlib.redirect_stderr(err))
        stack.enter_context(contextlib.redirect_stdout(out))
        cwd = os.getcwd()
        os.chdir(d)
        compiled = compiled_signatures()
        t0 = time.perf_counter()
        try:
            code = main(args)
        except SystemExit as exc:
            code = exc.code
        finally:
            os.chdir(cwd)
        wall = time.perf_counter() - t0
        text = err.getvalue()
        assert code == 2, (name, code, text[-2000:], out.getvalue()[-500:])
        assert text.count("\n") == 1 and text.startswith("bench-myriapoda: error: "), (name, text)
        assert "Traceback" not in text
        for w in case.words:
            assert w in text, (name, w, text)
        assert _lstat_listing(d) == before, (name, "wrote", set(_lstat_listing(d)) ^ set(before))
        assert wall < 10.0, (name, wall)  # refused at once (a matrix counted, not expanded): a hang guard
        assert compiled_signatures() == compiled  # refused before any numba kernel was compiled
    assert not Path("/" + "validation.json").exists() and not Path("/results.sqlite").exists()
