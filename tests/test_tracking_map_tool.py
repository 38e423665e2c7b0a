"""tools/tracking_map.py (issue 44, item 4): the tracking map is drawn from one matrix output directory or from
several (a map run in parts: the lattice's cheap cases in one, the fem and hybrid cases in another), and a directory
that is not a matrix output directory is refused with exit 2."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _tool():
    spec = importlib.util.spec_from_file_location("tracking_map_tool", ROOT / "tools" / "tracking_map.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _map_part(tmp_path: Path, name: str, mu_t: float) -> Path:
    """A real matrix output directory: one 0.05 s case of the map's first block (wavelength x friction ratio)."""
    from bench_myriapoda.cli import main

    f = tmp_path / f"{name}.toml"
    f.write_text(f'[matrix]\nname = "{name}"\ncreatures = ["snake"]\nbodies = ["massspring"]\nscenarios = ["flat"]\n'
                 'gaits = ["lateral-undulation"]\nduration = 0.05\n'
                 'set = { "friction.model" = "coulomb", "friction.mu_forward" = 0.1, "friction.mu_backward" = 0.3 }\n'
                 f'grid = {{ "gait.wavelength_bl" = [0.5], "friction.mu_transverse" = [{mu_t}] }}\n')
    out = tmp_path / name
    assert main(["matrix", str(f), "--out", str(out), "--workers", "1"]) == 0
    return out


def test_the_map_is_drawn_from_the_cases_of_several_directories(tmp_path):
    tool = _tool()
    a, b = _map_part(tmp_path, "part-a", 0.2), _map_part(tmp_path, "part-b", 0.5)
    from bench_myriapoda.report.matrix_data import load_matrix_dir

    ratios = sorted(r["ratio"] for d in (a, b) for r in tool.cells(load_matrix_dir(d).df))
    assert ratios == [2.0, 5.0]  # one cell from each directory
    out = tmp_path / "map.png"
    assert tool.main([str(a), str(b), "--out", str(out)]) == 0
    assert out.stat().st_size > 10_000
    assert tool.main([str(a)]) == 0 and (a / "tracking-map.png").is_file()  # one directory, as the docs write it


def test_a_directory_that_is_not_a_matrix_output_is_refused_with_exit_2(tmp_path, capsys):
    tool = _tool()
    (tmp_path / "empty").mkdir()
    assert tool.main([str(tmp_path / "empty"), "--out", str(tmp_path / "x.png")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("tracking_map: error:")
    assert not (tmp_path / "x.png").exists()
