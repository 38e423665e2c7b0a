"""The report and the scorecard read ``validate`` rows from each of their three sources (issue 40).

``report.validation.load_validation`` looks, first found wins, in the matrix directory's ``validation.json``,
in the ``validation`` table of the directory's own ``results.sqlite``, then in the history store
(``--history-store``, default ``reports/results.sqlite``, where ``validate`` records by default).  The rows
here are written by the writers ``validate`` itself uses (``validation.run.write_json``,
``harness.store.record_validation_run``) from ``validation.core.Row`` objects, so each test reads exactly
what a ``validate`` run leaves behind without paying for the checks' simulations (the journey tests,
tests/test_journeys.py, run the real ``validate`` command).  Reading from a store once ended in
``NameError: name 'run' is not defined`` for the report, the scorecard and the main job alike.
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.harness.store import record_validation_run
from bench_myriapoda.report.scorecard import scorecard_for_dir
from bench_myriapoda.report.validation import load_validation
from bench_myriapoda.validation import run as V
from bench_myriapoda.validation.core import FAIL, PASS, Row, clean

from matrix_toml import block, toml_table

MATRIX = toml_table("matrix", name="validation-sources", seeds=[0]) + block(
    creatures=["worm"], bodies=["massspring"], scenarios=["slope"], duration=0.3, set_={"creature.segments": 4})
# On the slope, not on flat ground or the cliff (Miller's Image 1): the scorecard also judges a flat rectilinear worm case of the matrix itself
# against Miller's displacement (report.scorecard_verdicts, NOT APPLICABLE for a 0.3 s run), and these tests
# count the validate rows of each source alone.


def _rows(verdict_of_worm_check: str) -> list[Row]:
    """A body check (concerns every creature on the body) and a worm check, in ``validate``'s row format."""
    return [Row("analytic.rigid-rotation", "analytic", "massspring", "elastic force under a rigid rotation",
                7.5e-15, 0.0, "analytic", "<= 1e-10", PASS, "", "", 1.0),
            Row("analytic.worm-eps-lambda", "analytic", "massspring", "worm displacement per cycle [m]",
                0.07 if verdict_of_worm_check == PASS else 0.05, 0.08, "Miller 1988", "15 % relative",
                verdict_of_worm_check, "", "m", 2.0)]


def _record(store: Path, rows: list[Row], out_dir: Path) -> int:
    """What ``validate`` records in a store (cmd_validate: ``record_validation_run`` of the rows' dicts)."""
    return record_validation_run(store, [r.to_dict() for r in rows], True, str(out_dir))


def _write_json(out_dir: Path, rows: list[Row]) -> Path:
    """What ``validate --out DIR`` writes: DIR/validation.json (cmd_validate's document)."""
    dicts = [r.to_dict() for r in rows]
    doc = clean({"quick": True, "bodies": ["massspring"], "wall_s": 3.0, "counts": V.summary(rows),
                 "rows": dicts, "work_precision": None, "run_id": None})
    return V.write_json(out_dir, doc)


@pytest.fixture(scope="module")
def matrix_dir(tmp_path_factory) -> Path:
    """A one-case matrix directory (a 0.3 s four-segment lattice worm), copied by each test before it adds rows."""
    root = tmp_path_factory.mktemp("vsources")
    f = root / "m.toml"
    f.write_text(MATRIX)
    d = root / "m"
    assert main(["matrix", str(f), "--out", str(d), "--workers", "1"]) == 0
    return d


@pytest.fixture
def fresh(matrix_dir, tmp_path, monkeypatch, capsys) -> Path:
    """A copy of the matrix directory in an empty working directory (the default history store,
    reports/results.sqlite, is then the test's own)."""
    d = tmp_path / "m"
    shutil.copytree(matrix_dir, d)
    monkeypatch.chdir(tmp_path)
    capsys.readouterr()
    return d


def _fidelity(d: Path, store: Path | None) -> dict:
    card = scorecard_for_dir(d, store)
    (row,) = [r for r in card.rows if (r.creature, r.body) == ("worm", "massspring")]
    return {"text": row.fidelity.text, **row.fidelity.details}


def _cli_reads(d: Path, capsys, *history: str) -> tuple[dict, str]:
    """``scorecard DIR --json``, ``scorecard DIR`` and ``report DIR`` through the command line, each exit 0;
    the JSON document's worm/massspring pair and the report page."""
    assert main(["scorecard", str(d), "--json", *history]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert main(["scorecard", str(d), *history]) == 0
    assert "fidelity" in capsys.readouterr().out
    assert main(["report", str(d), *history]) == 0
    capsys.readouterr()
    (pair,) = [p for p in doc["pairs"] if (p["creature"], p["body"]) == ("worm", "massspring")]
    return pair, (d / "index.html").read_text()


def test_rows_come_from_the_directorys_validation_json(fresh, capsys):
    path = _write_json(fresh, _rows(PASS))
    v = load_validation(fresh, Path("reports/results.sqlite"))
    assert v is not None and v.origin == str(path) and v.quick
    assert sorted(v.rows["check"]) == ["analytic.rigid-rotation", "analytic.worm-eps-lambda"]
    fid = _fidelity(fresh, None)
    assert fid["counts"] == {PASS: 2} and fid["text"].startswith("2 PASS"), fid
    pair, page = _cli_reads(fresh, capsys)
    assert pair["fidelity"]["details"]["counts"] == {PASS: 2}
    val = page[page.index('<section id="validation">'):]
    assert "analytic.worm-eps-lambda" in val and str(path) in val


def test_rows_come_from_the_matrix_store(fresh, capsys):
    """``validate --store DIR/results.sqlite``: the rows sit in the matrix's own store (the crash: NameError)."""
    store = fresh / "results.sqlite"
    assert _record(store, _rows(PASS), fresh / "v") == 1
    assert _record(store, _rows(FAIL), fresh / "v") == 2  # the newest run is the one shown
    v = load_validation(fresh, None)
    assert v is not None and v.origin.startswith(f"validate run 2 in {store} (") and v.out_dir == fresh / "v"
    assert set(v.rows["verdict"]) == {PASS, FAIL}
    fid = _fidelity(fresh, None)
    assert fid["counts"] == {FAIL: 1, PASS: 1} and fid["worst_check"] == "analytic.worm-eps-lambda", fid
    pair, page = _cli_reads(fresh, capsys)
    assert pair["fidelity"]["details"]["counts"] == {FAIL: 1, PASS: 1}
    assert "validate run 2 in" in page[page.index('<section id="validation">'):]


def test_rows_come_from_the_history_store(fresh, capsys):
    """Plain ``validate`` records into reports/results.sqlite of the working directory: the report, the
    scorecard and the main job find them there by default, and at any --history-store."""
    default = Path("reports") / "results.sqlite"
    default.parent.mkdir()
    assert _record(default, _rows(PASS), Path("reports/validation")) == 1
    v = load_validation(fresh, default)
    assert v is not None and v.origin.startswith(f"validate run 1 in {default} (")
    assert _fidelity(fresh, default)["counts"] == {PASS: 2}
    pair, page = _cli_reads(fresh, capsys)  # the default --history-store
    assert pair["fidelity"]["details"]["counts"] == {PASS: 2}
    assert "validate run 1 in" in page[page.index('<section id="validation">'):]
    other = Path("elsewhere.sqlite")
    _record(other, _rows(FAIL), Path("v2"))
    pair, _ = _cli_reads(fresh, capsys, "--history-store", str(other))
    assert pair["fidelity"]["details"]["counts"] == {FAIL: 1, PASS: 1}


def test_the_first_source_found_wins(fresh, capsys):
    """validation.json over the matrix store over the history store (the module docstring's order)."""
    history = Path("history.sqlite")
    _record(history, _rows(FAIL), Path("v"))
    assert load_validation(fresh, history).origin.startswith(f"validate run 1 in {history}")
    _record(fresh / "results.sqlite", _rows(PASS), Path("v"))
    assert load_validation(fresh, history).origin.startswith(f"validate run 1 in {fresh / 'results.sqlite'}")
    path = _write_json(fresh, _rows(FAIL))
    assert load_validation(fresh, history).origin == str(path)
    assert _fidelity(fresh, history)["counts"] == {FAIL: 1, PASS: 1}


def test_no_rows_anywhere_says_not_validated(fresh, capsys):
    assert load_validation(fresh, Path("reports/results.sqlite")) is None
    assert _fidelity(fresh, Path("reports/results.sqlite"))["text"] == "not validated"
    pair, page = _cli_reads(fresh, capsys)
    assert pair["fidelity"]["text"] == "not validated"
    assert "No validation results" in page
