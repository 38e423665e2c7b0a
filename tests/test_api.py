"""The Python API: run() resolves and runs exactly as the CLI, results load into pandas, and the
README's example runs as written."""
from __future__ import annotations

import json
import re
import sqlite3
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import bench_myriapoda as bm
from bench_myriapoda.cli import main
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.core.errors import InputError
from cli_argv import WORM_RUN, with_flags

ROOT = Path(__file__).resolve().parents[1]
CASE = ("worm", "massspring", "flat")


def test_import_stays_light_and_exposes_the_api():
    code = ("import sys, bench_myriapoda as b; heavy = [m for m in ('numba', 'pandas', 'bench_myriapoda.api') "
            "if m in sys.modules]; print(heavy, callable(b.run), callable(b.load_results), callable(b.run_matrix))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True).stdout
    assert out.split() == ["[]", "True", "True", "True"]


def test_overrides_as_keywords_or_a_dict_resolve_as_the_cli_set():
    cli = resolve_case(*CASE, duration=2.0, overrides=["friction.mu_transverse=0.2", "gait.direction=\"tail-to-head\"",
                                                        "scenario.obstacle_region_m=[-1, 1, -2, 2]"])
    a = bm.resolve(*CASE, duration=2.0, friction__mu_transverse=0.2, gait__direction="tail-to-head",
                   scenario__obstacle_region_m=(-1, 1, -2, 2))
    b = bm.resolve(*CASE, duration=2.0, set={"friction.mu_transverse": 0.2, "gait.direction": "tail-to-head",
                                             "scenario.obstacle_region_m": np.array([-1.0, 1.0, -2.0, 2.0])})
    assert a.case_hash() == b.case_hash() == cli.case_hash()


@pytest.mark.parametrize("kwargs, flags", [
    ({"creature": "wrom"}, ["--creature", "wrom"]),
    ({"friction__mu_transverse": -1.0}, ["--set", "friction.mu_transverse=-1.0"]),
    ({"frcition__mu": 1}, ["--set", "frcition.mu=1"]),
])
def test_bad_input_raises_input_error_with_the_cli_message(capsys, kwargs, flags):
    args = {"creature": "worm", "body": "massspring", "scenario": "flat", **kwargs}
    with pytest.raises(InputError) as exc:
        bm.run(**args)
    assert main(with_flags(WORM_RUN, flags)) == 2
    assert capsys.readouterr().err.strip() == f"bench-myriapoda: error: {exc.value}"


def test_controller_is_passed_to_run_case_only_when_given(monkeypatch):
    from bench_myriapoda.harness import runner

    seen = []

    def fake_run_case(case, **kw):
        seen.append(kw)
        return runner.RunResult(case, "ok", {"speed_m_per_s": 0.0}, {"steps": 0})

    monkeypatch.setattr(runner, "run_case", fake_run_case)
    bm.run(*CASE, duration=0.1)
    marker = object()
    bm.run(*CASE, duration=0.1, controller=marker)
    assert "controller" not in seen[0] and seen[1]["controller"] is marker


def test_run_matches_the_cli_and_gives_series_and_html(capsys, tmp_path):
    r = bm.run(*CASE, duration=1.0, friction__mu_transverse=0.3)
    assert main(["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "1.0",
                 "--set", "friction.mu_transverse=0.3", "--json", "--no-store"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert r.status == d["status"] == "ok"
    mine = json.loads(json.dumps(r.to_dict()))  # tuples become lists, as in the CLI's JSON
    assert mine["case"] == d["case"]
    assert mine["metrics"] == d["metrics"]  # deterministic: the same case gives the same numbers
    s = r.series
    n = len(s)
    assert n == int(round(1.0 * r.case.record.sample_hz)) + 1
    assert s.t.shape == (n,) and s.com.shape == (n, 3) and s.energy.shape == (n, 3)
    assert s.segment_centers.shape == (n, r.case.creature.segments, 3) and s.nodes is None
    df = r.series_frame()
    assert list(df.columns[:4]) == ["t_s", "com_x_m", "com_y_m", "com_z_m"] and len(df) == n
    np.testing.assert_array_equal(df.com_x_m.to_numpy(), s.com[:, 0])
    page = r._repr_html_()
    assert "worm / massspring / rectilinear / flat" in page and "speed_m_per_s" in page and "<table>" in page
    assert r.run_id is None and not list(tmp_path.iterdir())  # nothing stored unless asked


def test_load_results_from_a_store_one_row_per_run_metrics_as_columns(tmp_path):
    store = tmp_path / "api.sqlite"
    runs = [bm.run(*CASE, duration=0.5, friction__mu_transverse=mu, store=store) for mu in (0.2, 0.5)]
    runs.append(bm.run("snake", "massspring", "flat", duration=0.5, store=store))
    df = bm.load_results(store)
    assert len(df) == 3 and list(df.run_id) == [r.run_id for r in runs]
    for col in ("creature", "body", "gait", "scenario", "seed", "dt", "status", "steps_per_s"):
        assert col in df.columns
    # swept: differs between runs of the same creature/body/gait/scenario; creature keys that differ
    # only because worm and snake differ are not
    assert "friction.mu_transverse" in df.columns and "creature.segments" not in df.columns
    assert list(df["friction.mu_transverse"][:2]) == [0.2, 0.5]
    for r, (_, row) in zip(runs, df.iterrows()):
        for k, v in r.metrics.items():
            assert (np.isnan(row[k]) and np.isnan(v)) if isinstance(v, float) and np.isnan(v) else row[k] == v
    assert list(df.creature) == ["worm", "worm", "snake"]
    more = bm.load_results(store, keys=["gait.frequency_hz"])
    assert "gait.frequency_hz" in more.columns


def test_run_matrix_and_load_results_of_its_directory(tmp_path):
    mfile = tmp_path / "tiny.toml"
    mfile.write_text('[matrix]\nname = "tiny"\ncreatures = ["worm"]\nbodies = ["massspring"]\nscenarios = ["flat"]\n'
                     'duration = 0.5\nseeds = [0, 1]\n[matrix.grid]\n"friction.mu_transverse" = [0.2, 0.5]\n')
    out = tmp_path / "out"
    df = bm.run_matrix(mfile, out=out, workers=1)
    assert (out / "results.sqlite").is_file() and (out / "matrix.json").is_file()
    assert len(df) == 4 and set(df.status) == {"ok"}
    assert sorted(zip(df.seed, df["friction.mu_transverse"])) == [(0, 0.2), (0, 0.5), (1, 0.2), (1, 0.5)]
    assert {"creature", "body", "gait", "scenario", "speed_m_per_s", "contact_fraction"} <= set(df.columns)
    again = bm.load_results(out)
    pd.testing.assert_frame_equal(df, again)


def test_load_results_bad_input(tmp_path):
    with pytest.raises(InputError, match="no such file"):
        bm.load_results(tmp_path / "missing.sqlite")
    junk = tmp_path / "junk.sqlite"
    junk.write_text("not a database")
    with pytest.raises(InputError, match="not a bench-myriapoda results store"):
        bm.load_results(junk)
    with pytest.raises(InputError, match="results.sqlite"):
        bm.load_results(tmp_path)
    with pytest.raises(InputError, match="workers"):
        bm.run_matrix("quick", workers=0)


def readme_python_example() -> str:
    """The code block after ``<!-- python-api-example -->`` in README.md."""
    text = (ROOT / "README.md").read_text()
    m = re.search(r"<!-- python-api-example -->\s*```python\n(.*?)```", text, re.S)
    assert m, "README.md has no python block after <!-- python-api-example -->"
    return m.group(1)


@pytest.mark.slow
def test_readme_python_example_runs(tmp_path, monkeypatch, capsys):
    code = readme_python_example()
    assert "load_results" in code and "groupby(\"body\")" in code
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    exec(compile(code, "README.md:python-api-example", "exec"), {"__name__": "readme_example"})
    out = capsys.readouterr().out
    assert "massspring" in out and "fem" in out and "<Result worm / massspring" in out
    con = sqlite3.connect(tmp_path / "reports" / "api-example.sqlite")
    assert con.execute("SELECT COUNT(*) FROM runs WHERE command = 'api'").fetchone()[0] == 2
