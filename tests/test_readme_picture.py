"""The README's picture is drawn by tools/make_readme_picture.py from a main-job output (issue 40), and the
documentation build (docs/conf.py) re-makes it when there is one and keeps the committed one when there is not."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

from bench_myriapoda.cli import main

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))

import make_readme_picture as mrp  # noqa: E402

from matrix_toml import block, toml_table  # noqa: E402

MATRIX = toml_table("matrix", name="picture", seeds=[0]) + block(
    creatures=["worm"], bodies=["massspring"], scenarios=["flat"], duration=0.3, set_={"creature.segments": 4})


def test_the_picture_is_the_scorecard_of_the_directory(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "m.toml").write_text(MATRIX)
    d = tmp_path / "reports" / "quick"
    assert main(["matrix", "m.toml", "--out", str(d), "--workers", "1"]) == 0
    out = tmp_path / "pic.png"
    assert mrp.main([str(d), "--out", str(out)]) == 0
    assert out.is_file() and out.stat().st_size > 10_000
    from bench_myriapoda.report.scorecard import scorecard_for_dir, scorecard_table

    fig = mrp.draw(scorecard_for_dir(d, None))
    texts = " ".join(t.get_text() for ax in fig.axes for t in ax.texts)
    table = scorecard_table(scorecard_for_dir(d, None))
    for column in table.columns:  # every column's header and the pair's cells, as the scorecard gives them
        assert column.split()[0] in texts
    assert "worm" in texts and "massspring" in texts and "worm: " in texts  # the row and the recommendation
    # the docs build's hook: re-made from a main-job output, and said so
    lines = []
    out.unlink()
    assert mrp.refresh(d, out, lines.append) and out.is_file() and "re-made" in lines[-1]


def test_without_a_main_job_output_the_committed_picture_stays(tmp_path, capsys):
    out = tmp_path / "scorecard.png"
    out.write_bytes(b"committed")
    lines = []
    assert not mrp.refresh(tmp_path / "reports" / "quick", out, lines.append)
    assert out.read_bytes() == b"committed" and "kept" in lines[-1] and "bench-myriapoda" in lines[-1]
    broken = tmp_path / "broken"  # an interrupted or foreign output: kept too, and the build goes on
    broken.mkdir()
    (broken / "results.sqlite").write_text("not a database")
    (broken / "matrix.json").write_text("{}")
    assert not mrp.refresh(broken, out, lines.append)
    assert out.read_bytes() == b"committed" and "not a readable matrix output" in lines[-1]
    assert mrp.main([str(broken), "--out", str(out)]) == 2
    assert "error" in capsys.readouterr().err


def test_the_docs_build_calls_the_hook_and_the_readme_shows_the_picture():
    conf = (ROOT / "docs" / "conf.py").read_text()
    assert "make_readme_picture.refresh(" in conf
    assert "docs/_static/scorecard.png" in (ROOT / "README.md").read_text()
    assert (ROOT / "docs" / "_static" / "scorecard.png").is_file()


@pytest.fixture(autouse=True)
def _agg(monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
