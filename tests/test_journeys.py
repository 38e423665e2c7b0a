"""Journeys: the suite run as a newcomer runs it, command after command, from an empty working directory.

Each journey is a scripted session: every step's exit status is checked, its stderr must hold no Python
traceback, and the files it promises must exist.  The steps are the ones the README and the tutorials
tell a newcomer to type, in that order: the main job; ``validate --quick``; the main job again; ``report``;
``scorecard`` and ``scorecard --json``; ``load_results`` on the directory and on its store; the README's
Python example as written (read from README.md, not copied); every tutorial's code blocks (read from
docs/tutorials/*.md); a matrix interrupted with Ctrl-C and resumed; ``run --record`` then ``--animate``.

The installed console script is what runs.  One fresh virtual environment per test session
(``python -m venv``, then ``pip install --no-deps -e CHECKOUT`` into it) provides ``bench-myriapoda`` exactly
as ``pip install -e .`` makes it: the entry point of pyproject.toml, a fresh ``bin/``.  Why one per session
and not one per test: a venv with the package's own dependencies installed from an index takes minutes
and the network; instead, as tests/test_wheel_install.py does, a ``.pth`` line appends the test
environment's site-packages (numpy, numba, pandas, ...) after the venv's own, so the venv's install of our
package comes first and the rest is borrowed (what ``--system-site-packages`` does, but for whichever
environment runs pytest, a venv included; ``--system-site-packages`` itself would borrow the base
interpreter's packages, not the test venv's).  The install is editable, so the kernels' numba cache is
the checkout's (a non-editable copy would compile every kernel again: minutes of CPU per journey).  Under
pytest-xdist the workers share the one venv: the first builds it under a lock in the session's shared
temporary directory (tests/newcomer_venv.py).  Every journey works in its own ``tmp_path``.

The main job from an empty directory, the first step of the main journey, is the test session's one run of
the main job (``conftest.quick_run``: this venv's ``bench-myriapoda``, no arguments, in an empty working
directory, its exit status, stdout and stderr kept), which the report and scorecard tests read too; the
journey checks that step as it checks every other and goes on in a copy of its working directory, so the
suite does not run the quick matrix twice (about 2 minutes of the test command's wall time on 2 cores).
"""
from __future__ import annotations

import json
import math
import os
import re
import shutil
import signal
import sqlite3
import subprocess
import sys
import sysconfig
import time
import tomllib
from dataclasses import dataclass
from pathlib import Path

import pytest
from newcomer_venv import newcomer_env, session_venv

ROOT = Path(__file__).resolve().parents[1]
TUTORIALS = sorted(p for p in (ROOT / "docs" / "tutorials").glob("*.md") if p.name != "index.md")
FENCE = re.compile(r"^```(\w+)[^\n]*\n(.*?)^```", re.S | re.M)
TRACEBACK = "Traceback (most recent call last)"

pytestmark = pytest.mark.slow  # whole sessions of the suite: several minutes of CPU together


# --------------------------------------------------------------------------- the fresh environment

@pytest.fixture(scope="session")
def venv_bin(tmp_path_factory, request) -> Path:
    """The bin directory of the session's fresh venv (tests/newcomer_venv.py), built once for all xdist workers."""
    return session_venv(tmp_path_factory, request.config)


@dataclass
class Step:
    argv: list[str]
    code: int
    stdout: str
    stderr: str


class Session:
    """A newcomer's shell: the venv's bin first on PATH, an empty working directory, every step checked."""

    def __init__(self, bindir: Path, cwd: Path):
        self.bindir, self.cwd = bindir, cwd
        self.env = newcomer_env(bindir)
        self.steps: list[Step] = []

    def _check(self, step: Step, ok: tuple[int, ...]) -> Step:
        self.steps.append(step)
        what = " ".join(step.argv)
        assert step.code in ok, f"`{what}` exited {step.code}:\n{step.stdout[-3000:]}\n{step.stderr[-5000:]}"
        assert TRACEBACK not in step.stderr, f"`{what}` printed a traceback:\n{step.stderr[-5000:]}"
        return step

    def run(self, *argv: str, ok: tuple[int, ...] = (0,), timeout: float = 3600) -> Step:
        """One command, as typed (``bench-myriapoda`` and ``python3`` resolve to the venv's).  ``timeout`` [s]
        only ends a hung step: it is no timing assertion (a busy 2-core machine runs a tutorial for 15 min)."""
        argv = [str(a) for a in argv]
        proc = subprocess.run(argv, cwd=self.cwd, env=self.env, capture_output=True, text=True, timeout=timeout)
        return self._check(Step(argv, proc.returncode, proc.stdout, proc.stderr), ok)

    def bench(self, *args: str, ok: tuple[int, ...] = (0,), timeout: float = 3600) -> Step:
        return self.run(str(self.bindir / "bench-myriapoda"), *args, ok=ok, timeout=timeout)

    def python(self, code: str, name: str = "step.py", ok: tuple[int, ...] = (0,), timeout: float = 3600) -> Step:
        """A script written into the working directory and run with the venv's python3."""
        (self.cwd / name).write_text(code)
        return self.run(str(self.bindir / "python3"), name, ok=ok, timeout=timeout)


@pytest.fixture
def session(venv_bin, tmp_path) -> Session:
    work = tmp_path / "newcomer"
    work.mkdir()
    return Session(venv_bin, work)


def _floats_after(pattern: str, text: str) -> list[float]:
    return [float(x) for x in re.findall(pattern, text)]


# --------------------------------------------------------------------------- the environment itself

def test_the_console_script_is_the_fresh_venvs(session):
    """What runs is the venv's entry point, importing the checkout (editable), not the test process's."""
    exe = session.run(str(session.bindir / "python3"), "-c",
                      "import sys, bench_myriapoda as b; print(sys.prefix); print(b.__file__)").stdout.split("\n")
    assert Path(exe[0]).resolve() == session.bindir.parent.resolve()
    assert Path(exe[1]).resolve().is_relative_to(ROOT.resolve())
    script = (session.bindir / "bench-myriapoda").read_text()
    assert "bench_myriapoda.cli" in script and str(session.bindir.parent) in script.splitlines()[0]
    assert "usage" in session.bench("--help").stdout


# --------------------------------------------------------------------------- the main job and what follows it

def test_main_job_then_validate_then_main_job_again_then_report_scorecard_and_load_results(session, quick_run):
    """The README's sequence; after it the scorecard's fidelity cells hold verdict counts."""
    s, d = session, session.cwd / "reports" / "quick"
    # the main job, from the empty directory: the session's quick_run (module docstring), checked as a step here
    first = s._check(Step(quick_run.argv, quick_run.code, quick_run.stdout, quick_run.stderr), (0,))
    assert first.argv == [str(s.bindir / "bench-myriapoda")]  # the console script, no arguments
    shutil.copytree(quick_run.work, s.cwd, dirs_exist_ok=True, symlinks=True)
    for name in ("index.html", "summary.md", "results.sqlite", "results.csv", "matrix.json"):
        assert (d / name).is_file(), name
    # validate --quick (a subset: the one check every body model declares), recorded into reports/results.sqlite
    v = s.bench("validate", "--check", "analytic.free-fall-momentum", "--quick")
    assert re.search(r"stored as validation run \d+ in reports/results.sqlite", v.stdout), v.stdout[-2000:]
    assert (s.cwd / "reports" / "validation" / "validation.json").is_file()
    s.bench()  # the main job again: it reads the validation rows (it once crashed here: NameError)
    s.bench("report", "reports/quick")
    page = (d / "index.html").read_text()
    val = page[page.index('<section id="validation">'):]
    assert "analytic.free-fall-momentum" in val and "No validation results" not in val.split("</section>")[0]
    text = s.bench("scorecard", "reports/quick").stdout
    assert "not validated" not in text
    card = json.loads(s.bench("scorecard", "reports/quick", "--json").stdout)
    pairs = card["pairs"]
    assert pairs
    for p in pairs:  # every pair: verdict counts, not "not validated" (free-fall momentum is a check of the body)
        counts = p["fidelity"]["details"].get("counts")
        assert counts and sum(counts.values()) >= 1, (p["creature"], p["body"], p["fidelity"]["text"])
        assert re.match(r"^\d+ (PASS|FAIL|INFO|NOT APPLICABLE)", p["fidelity"]["text"]), p["fidelity"]["text"]
    # the README's picture, drawn from this output by the script the docs build calls
    s.run(str(s.bindir / "python3"), str(ROOT / "tools" / "make_readme_picture.py"), "reports/quick",
          "--out", "scorecard.png")
    assert (s.cwd / "scorecard.png").stat().st_size > 10_000
    # load_results on the directory and on its store: the same cases, with the headline ones marked
    out = s.python("""
import json
import bench_myriapoda as bm

by_dir = bm.load_results("reports/quick")
by_store = bm.load_results("reports/quick/results.sqlite")
head = by_dir[by_dir.run_kind == "headline"]
print(json.dumps({"dir": len(by_dir), "store": len(by_store), "dir_cases": by_dir.case_hash.nunique(),
                  "store_cases": by_store.case_hash.nunique(),
                  "pairs": sorted({f"{c}/{b}" for c, b in zip(head.creature, head.body)}),
                  "same_kinds": sorted(set(zip(by_dir.case_hash, by_dir.run_kind)))
                                == sorted(set(zip(by_store.case_hash, by_store.run_kind))),
                  "kinds": sorted(set(by_dir.run_kind))}))
""").stdout
    got = json.loads(out.strip().splitlines()[-1])
    # the directory: each case once (its newest run); the store: every run. The second main job ran the same code,
    # so it kept the first one's stored cases (report.main_job.same_code_rerun) instead of running them again
    assert got["dir"] == got["dir_cases"] == got["store_cases"] > 0 and got["store"] == got["dir"]
    assert got["same_kinds"]
    assert "headline" in got["kinds"] and "sweep" in got["kinds"]
    assert set(got["pairs"]) == {f"{p['creature']}/{p['body']}" for p in pairs}


# --------------------------------------------------------------------------- the README's Python example

def readme_python_example() -> str:
    """The code block after ``<!-- python-api-example -->`` in README.md, as written."""
    m = re.search(r"<!-- python-api-example -->\s*```python\n(.*?)```", (ROOT / "README.md").read_text(), re.S)
    assert m, "README.md has no python block after <!-- python-api-example -->"
    return m.group(1)


def test_the_readme_python_example_prints_a_finite_speed_for_both_bodies(session):
    out = session.python(readme_python_example(), "readme_example.py").stdout
    results = re.findall(r"<Result worm / (\w+) / [^:]+: (\w+), \d+ steps, (.*)>", out)
    assert [r[0] for r in results] == ["massspring", "fem"], out
    for body, status, speed in results:
        assert status == "ok", (body, speed)
        m = re.fullmatch(r"speed (\S+) m/s", speed)
        assert m and math.isfinite(float(m.group(1))) and float(m.group(1)) > 0, (body, speed)
    # the groupby's table: one line per body, every number finite
    lines = {ln.split()[0]: ln.split()[1:] for ln in out.splitlines() if ln.split()[:1] in (["massspring"], ["fem"])}
    assert set(lines) == {"massspring", "fem"}, out
    for body, cells in lines.items():
        assert len(cells) == 3 and all(math.isfinite(float(c)) for c in cells), (body, cells)
    con = sqlite3.connect(session.cwd / "reports" / "api-example.sqlite")
    assert con.execute("SELECT COUNT(*) FROM runs WHERE command = 'api'").fetchone()[0] == 2


# --------------------------------------------------------------------------- the tutorials

# Shell lines of the tutorials that the journey does not run, and why.  Everything else runs as written
# (a ``python3 examples/...`` line runs the checkout's file, as it would from the checkout's root).
NOT_RUN = {
    ("compare-bodies.md", "bench-myriapoda matrix worm-bodies.toml --workers 2 --report"):
        "12 cases of 8 s, four of them on the hybrid body (about 90 CPU s with warm kernels); the same command "
        "path, `matrix FILE --report`, runs in the stability-sweep tutorial and the interrupted-matrix journey, and "
        "the page's TOML block is written and expanded here",
    ("dask-cluster.md", 'python3 -m pip install "bench-myriapoda[dask]"'):
        "installs from an index (network); the test environment has the extra",
    ("dask-cluster.md", "dask scheduler --port 8786"): "a server that runs until stopped; the Python block starts a "
                                                       "LocalCluster instead",
    ("dask-cluster.md", "dask worker tcp://scheduler-host:8786 --nworkers 4 --nthreads 1"):
        "a server that runs until stopped, at a placeholder host",
    ("dask-cluster.md", "bench-myriapoda matrix quick --executor dask --scheduler tcp://scheduler-host:8786"):
        "a placeholder scheduler host",
    ("dask-cluster.md", "bench-myriapoda matrix scenarios/matrix/paper.toml --executor dask --scheduler "
                        "tcp://scheduler-host:8786 --report"): "a placeholder scheduler host",
    ("dask-cluster.md", "bench-myriapoda matrix quick --executor dask --workers 2"):
        "the whole quick matrix again (the main-job journey runs it); the Python block runs the same executor "
        "on a LocalCluster with a small matrix",
    ("regressions-in-ci.md", "bench-myriapoda regress"): "times the whole throughput suite, repeated (minutes "
                                                         "of CPU by design); the Python block times one entry "
                                                         "through the same code and store",
    ("regressions-in-ci.md", "bench-myriapoda regress --baseline e05706a"):
        "a commit of the maintainers' history, with no run in a newcomer's store",
    ("regressions-in-ci.md", "bench-myriapoda regress --suite fem-chain hybrid-chain --repeats 11 --threshold 0.05 "
                             "--json"): "11 timed repetitions of two entries (a timing run, minutes of CPU)",
    ("regressions-in-ci.md", "python3 -m pytest tests/benchmarks --benchmark-enable --benchmark-only "
                             "--benchmark-save=NAME"): "the checkout's own micro benchmarks, timed: minutes of CPU",
    ("regressions-in-ci.md", "python3 -m pytest tests/benchmarks --benchmark-enable --benchmark-only "
                             "--benchmark-compare=0001 --benchmark-compare-fail=median:15%"):
        "compares with a saved benchmark run the line above would make",
}
# pages whose printed output includes speeds: every number they print must be finite
PRINTS_SPEEDS = {"compare-bodies.md", "own-controller.md", "own-creature.md"}

DRIVER = r'''
"""Runs a tutorial's blocks in order, as a reader pastes them: Python blocks into one interpreter (one
namespace), shell lines in a shell, TOML blocks into the file the page's commands name."""
import contextlib, io, json, subprocess, sys, traceback
steps = json.load(open(sys.argv[1]))
ns = {"__name__": "tutorial"}
out = []
for kind, text in steps:
    if kind == "python":
        buf, err = io.StringIO(), io.StringIO()
        code = 0
        with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(err):
            try:
                exec(compile(text, "tutorial-block", "exec"), ns)
            except BaseException:
                code = 1
                err.write(traceback.format_exc())
        out.append([kind, text, code, buf.getvalue(), err.getvalue()])
    elif kind == "file":
        name, body = text
        open(name, "w").write(body)
        out.append([kind, name, 0, "", ""])
    else:
        p = subprocess.run(["bash", "-c", text], capture_output=True, text=True)
        out.append([kind, text, p.returncode, p.stdout, p.stderr])
    if out[-1][2] != 0:
        break
json.dump(out, open(sys.argv[2], "w"))
'''


def shell_lines(code: str) -> list[str]:
    """The commands of a shell block, continuation lines joined, comments dropped."""
    return [" ".join(c.split()) for c in code.replace("\\\n", " ").splitlines() if c.strip() and not
            c.lstrip().startswith("#")]


def tutorial_steps(page: Path) -> tuple[list, list[str]]:
    """(the page's steps for DRIVER, the shell lines not run): Python blocks, shell lines, TOML matrix files."""
    steps, skipped = [], []
    for m in FENCE.finditer(page.read_text(encoding="utf-8")):
        lang, code = m.group(1), m.group(2)
        if lang == "python":
            steps.append(["python", code])
        elif lang == "bash":
            for line in shell_lines(code):
                if (page.name, line) in NOT_RUN:
                    skipped.append(line)
                    continue
                if line.startswith("python3 examples/"):  # the checkout's file, as run from the checkout's root
                    line = line.replace("python3 examples/", f"python3 {ROOT / 'examples'}/", 1)
                steps.append(["bash", line])
        elif lang == "toml":
            name = tomllib.loads(code)["matrix"]["name"]  # the page's commands name it NAME.toml
            steps.append(["file", [f"{name}.toml", code]])
        else:
            assert lang in ("yaml", "text"), (page.name, lang)  # shown, not run (a CI file, an output)
    return steps, skipped


@pytest.mark.parametrize("page", TUTORIALS, ids=lambda p: p.stem)
def test_every_tutorial_runs_as_written(page, session):
    steps, skipped = tutorial_steps(page)
    assert sorted(skipped) == sorted(line for (name, line) in NOT_RUN if name == page.name), \
        "a NOT_RUN line is no longer on the page: update NOT_RUN"
    (session.cwd / "steps.json").write_text(json.dumps(steps))
    (session.cwd / "driver.py").write_text(DRIVER)
    session.run(str(session.bindir / "python3"), "driver.py", "steps.json", "results.json")
    ran = json.loads((session.cwd / "results.json").read_text())
    assert len(ran) == len(steps), f"{page.name}: stopped at step {len(ran)}: {ran[-1][1][:200]}\n{ran[-1][4][-4000:]}"
    for kind, text, code, out, err in ran:
        assert code == 0, f"{page.name}: `{text[:200]}` exited {code}:\n{out[-2000:]}\n{err[-4000:]}"
        assert TRACEBACK not in err, f"{page.name}: `{text[:200]}` printed a traceback:\n{err[-4000:]}"
        if kind == "bash" and " run " in f" {text} ":
            assert "too short" not in out, f"{page.name}: `{text}` ran too short to measure:\n{out}"
        if kind == "python" and page.name in PRINTS_SPEEDS:
            assert not re.search(r"\bnan\b", out, re.I), f"{page.name}: a block printed NaN:\n{out}"
    if page.name in PRINTS_SPEEDS:
        printed = "".join(r[3] for r in ran if r[0] == "python")
        speeds = _floats_after(r"speed ([-0-9.e+]+) m/s", printed) + _floats_after(r"([-0-9.e+]+) BL/(?:s|cycle)",
                                                                                    printed)
        assert speeds and all(math.isfinite(v) for v in speeds), (page.name, printed)


# --------------------------------------------------------------------------- a matrix interrupted and resumed

SMALL_MATRIX = """
[matrix]
name = "journey"
creatures = ["worm"]
bodies = ["massspring"]
scenarios = ["flat"]
duration = 150.0
seeds = [0]
set = { "creature.segments" = 5 }
[matrix.grid]
"scenario.perturbation_m" = [0.0, 0.0001, 0.0002, 0.0003, 0.0004, 0.0005, 0.0006, 0.0007]
"""


def _ctrl_c_as_in_a_terminal() -> None:
    """In the child before it runs: SIGINT delivered and handled by default, as a shell's foreground job has it.

    Ignored and blocked signals are inherited across fork and exec, and Python installs its KeyboardInterrupt
    handler only where SIGINT was not ignored; the test process (a pytest-xdist worker, after whatever ran in it
    before) is no terminal.  A fresh-clone run once saw the matrix finish with exit 0 after the SIGINT, without
    a word of "interrupted": the signal never reached Python's handler."""
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _signal_state(pid: int) -> str:
    """The SigBlk / SigIgn / SigCgt masks of a running process (Linux ``/proc``; empty elsewhere)."""
    try:
        lines = Path(f"/proc/{pid}/status").read_text().splitlines()
    except OSError:
        return ""
    return " ".join(ln.replace("\t", "") for ln in lines if ln.startswith(("SigBlk", "SigIgn", "SigCgt")))


def test_a_matrix_interrupted_with_ctrl_c_resumes_and_reports(session):
    """Ctrl-C reaches the whole foreground process group (the pool's workers too), as in a terminal.

    Each case must outlast the 50 ms poll on any machine: with 1.5 s cases (a few ms each with warm kernels)
    a fast machine once finished all 8 between two polls; 150 s of the 5-segment worm take about 0.5 s."""
    s = session
    (s.cwd / "journey.toml").write_text(SMALL_MATRIX)
    out = s.cwd / "reports" / "matrix" / "journey"
    db = out / "results.sqlite"
    argv = [str(s.bindir / "bench-myriapoda"), "matrix", "journey.toml", "--workers", "2"]
    proc = subprocess.Popen(argv, cwd=s.cwd, env=s.env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True, preexec_fn=_ctrl_c_as_in_a_terminal)
    stored, deadline = 0, time.monotonic() + 1800
    while time.monotonic() < deadline and proc.poll() is None:
        if db.exists():
            try:
                stored = sqlite3.connect(db).execute("SELECT COUNT(*) FROM runs").fetchone()[0]
            except sqlite3.OperationalError:  # the table is being created
                stored = 0
            if stored >= 1:
                break
        time.sleep(0.05)
    assert proc.poll() is None, "the matrix ended before it could be interrupted"
    sig_state = _signal_state(proc.pid)  # what the kernel will do with the SIGINT, for the message below
    os.killpg(proc.pid, signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=1800)  # a hung shutdown, not a timing check
    assert proc.returncode == 130, (proc.returncode, sig_state, stdout[-2000:], stderr[-3000:])
    assert "interrupted" in stderr and TRACEBACK not in stderr, stderr[-5000:]
    n = sqlite3.connect(db).execute("SELECT COUNT(*) FROM runs").fetchone()[0]
    assert 1 <= n < 8
    resumed = s.bench("matrix", "journey.toml", "--workers", "2", "--resume", "--report")
    assert "8 of 8 cases stored" in resumed.stdout
    runs = sqlite3.connect(db).execute("SELECT case_hash, status FROM runs").fetchall()
    assert len(runs) == 8 and len({h for h, _ in runs}) == 8 and {st for _, st in runs} == {"ok"}
    assert (out / "index.html").is_file() and (out / "summary.md").is_file()


# --------------------------------------------------------------------------- a recording, then an animation

def test_run_record_then_animate(session):
    s = session
    case = ["--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "1"]
    s.bench("run", *case, "--record", "worm.npz")
    rec = s.cwd / "worm.npz"
    assert rec.is_file() and rec.stat().st_size > 1000
    keys = s.python("import numpy as np; d = np.load('worm.npz'); print(sorted(d.files)); "
                    "print(d['t'].shape[0], d['t'][-1])", "read_recording.py").stdout.splitlines()
    assert "'t'" in keys[0] and "'com'" in keys[0]
    samples, t_end = keys[1].split()
    assert int(samples) > 10 and float(t_end) == pytest.approx(1.0, abs=0.05)
    s.bench("run", *case, "--animate", "worm.gif")
    gif = s.cwd / "worm.gif"
    assert gif.is_file() and gif.read_bytes()[:6] in (b"GIF87a", b"GIF89a") and gif.stat().st_size > 10_000
