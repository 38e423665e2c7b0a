"""Where the data folders are found (checkout, installed wheel, BENCH_MYRIAPODA_ROOT) and the
optional [mesh] extra: a custom surface mesh without pytetwild is bad input, not a crash."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.core import paths

ROOT = Path(__file__).resolve().parents[1]


def test_checkout_data_folders_are_found_from_the_checkout(monkeypatch):
    monkeypatch.delenv("BENCH_MYRIAPODA_ROOT", raising=False)
    assert paths.project_root() == ROOT
    assert paths.models_dir() == ROOT / "models" and paths.scenarios_dir() == ROOT / "scenarios"


def test_without_a_checkout_the_wheel_data_folder_is_used(monkeypatch, tmp_path):
    # an installed package's parent is site-packages: no pyproject.toml there, even if some other
    # distribution left folders named models/ and scenarios/ in it
    (tmp_path / "models").mkdir()
    (tmp_path / "scenarios").mkdir()
    monkeypatch.delenv("BENCH_MYRIAPODA_ROOT", raising=False)
    monkeypatch.setattr(paths, "CHECKOUT_ROOT", tmp_path)
    assert paths.project_root() == paths.WHEEL_DATA_ROOT
    assert paths.WHEEL_DATA_ROOT == Path(paths.__file__).resolve().parents[1] / "_data"


def test_bench_myriapoda_root_wins(monkeypatch, tmp_path):
    monkeypatch.setenv("BENCH_MYRIAPODA_ROOT", str(tmp_path))
    assert paths.models_dir() == tmp_path / "models"
    from bench_myriapoda.core.config import creature_names
    assert creature_names() == []  # an empty root: nothing from the checkout leaks in


@pytest.mark.parametrize("mesh", ["capsule"])
def test_custom_surface_mesh_without_the_mesh_extra_is_exit_2(capsys, monkeypatch, tmp_path, mesh):
    monkeypatch.setitem(sys.modules, "pytetwild", None)  # find_spec then reports it missing
    code = main(["run", "--creature", "worm", "--body", "fem", "--scenario", "flat", "--duration", "0.1",
                 "--set", f"body.mesh={mesh}", "--store", str(tmp_path / "r.sqlite")])
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.strip().splitlines()) == 1
    assert "body.mesh" in err and "pip install 'bench-myriapoda[mesh]'" in err and "pytetwild" in err
    assert not (tmp_path / "r.sqlite").exists()


def test_grid_mesh_needs_no_mesh_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "pytetwild", None)
    monkeypatch.setitem(sys.modules, "pyvista", None)
    from bench_myriapoda.core.config import resolve_case
    assert resolve_case("worm", "fem", "flat", duration=0.1).body.mesh == "grid"
