"""``load_results``' ``run_kind``: headline runs told from sweep grid points and from blow-ups (issue 40).

Averaging a matrix's store over ``body`` once mixed the dt sweep's blow-ups into the headline figures
(mean ``energy_drift_rel`` 2265 for the lattice); ``run_kind`` says which rows a comparison averages.
"""
from __future__ import annotations

import shutil

import pytest

import bench_myriapoda as bm
from bench_myriapoda.cli import main

from matrix_toml import block, toml_table

SMALL = {"creature.segments": 4}
# a headline case, a dt sweep of the worm with a grid point far past its stability limit (tests/test_matrix.py's
# blow-up), and a case that raises in the body (links wider than the boxes)
MATRIX = (toml_table("matrix", name="run-kinds", seeds=[0])
          + block(creatures=["worm"], bodies=["massspring"], scenarios=["flat"], duration=0.4, set_=SMALL)
          + block(creatures=["worm"], bodies=["massspring"], scenarios=["flat"], duration=0.3,
                  grid={"dt": [0.001, 0.002, 0.05]})
          + block(creatures=["chain"], bodies=["hybrid"], scenarios=["fig4-drop"], duration=0.1,
                  set_={"body.link_width_m": 5.0}))


@pytest.fixture(scope="module")
def matrix_dir(tmp_path_factory):
    root = tmp_path_factory.mktemp("runkind")
    (root / "m.toml").write_text(MATRIX)
    d = root / "m"
    assert main(["matrix", str(root / "m.toml"), "--out", str(d), "--workers", "1"]) == 1  # the chain's error
    return d


def _kinds(df) -> dict:
    return {(r.creature, r.duration, r.dt): r.run_kind for r in df.itertuples()}


def test_a_matrix_directory_tells_headline_from_sweep_from_blow_up(matrix_dir):
    df = bm.load_results(matrix_dir)
    assert len(df) == 5 and set(df.run_kind) == set(bm.api.RUN_KINDS)
    assert list(df[df.creature == "chain"].run_kind) == ["failed"]
    head = df[df.duration == 0.4]
    assert list(head.run_kind) == ["headline"] and list(head.status) == ["ok"]
    sweep = df[df.duration == 0.3].sort_values("dt")
    assert list(sweep.status) == ["ok", "ok", "unstable"], sweep[["dt", "status", "message"]]
    assert list(sweep.run_kind) == ["sweep", "sweep", "unstable"]
    # the README's filter: only the headline case is averaged
    assert df[df.run_kind == "headline"].groupby("body").size().to_dict() == {"massspring": 1}


def test_the_store_read_directly_gives_the_same_kinds(matrix_dir, tmp_path, capsys):
    by_dir = _kinds(bm.load_results(matrix_dir))
    # the matrix directory's store: its matrix.json lies next to it
    assert _kinds(bm.load_results(matrix_dir / "results.sqlite")) == by_dir
    # the store alone, without the manifest: a grid point differs from its neighbours in dt
    lone = tmp_path / "copy.sqlite"
    shutil.copy(matrix_dir / "results.sqlite", lone)
    assert _kinds(bm.load_results(lone)) == by_dir
    # a run and an API run are headline runs; a stable-dt search is a sweep
    bm.run("worm", "massspring", "flat", duration=0.3, store=lone, creature__segments=4)
    assert main(["stable-dt", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "0.2",
                 "--set", "creature.segments=4", "--rel-tol", "0.3", "--store", str(lone)]) == 0
    capsys.readouterr()
    df = bm.load_results(lone)
    assert list(df[df.command == "api"].run_kind) == ["headline"]
    assert list(df[df.command == "stable-dt"].run_kind) == ["sweep"]
    assert _kinds(df[df.command == "matrix"]) == by_dir


def test_an_empty_store_has_the_column(tmp_path):
    import sqlite3

    from bench_myriapoda.harness.store import connect

    connect(tmp_path / "empty.sqlite").close()
    assert sqlite3.connect(tmp_path / "empty.sqlite").execute("SELECT COUNT(*) FROM runs").fetchone() == (0,)
    assert "run_kind" in bm.load_results(tmp_path / "empty.sqlite").columns


def test_a_result_too_short_for_its_speed_says_why_instead_of_nan():
    r = bm.run("worm", "massspring", "flat", duration=0.3, creature__segments=4)
    text = repr(r)
    assert "nan" not in text.lower() and "no speed: too short" in text and "run >= 8 s" in text, text
    assert "too short" in r._repr_html_()
    long_enough = repr(bm.run("worm", "massspring", "flat", duration=8.0, creature__segments=4))
    speed = float(long_enough.split("speed ")[1].split(" m/s")[0])
    assert speed > 0, long_enough
