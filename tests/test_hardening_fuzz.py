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
