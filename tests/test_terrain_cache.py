"""Mesh terrains built once per machine (``world.terrain_cache``): read back bit for bit, rebuilt when the stored
file is damaged, keyed by the mesh, the settings and the code generation target, and never an error."""
from __future__ import annotations

import os

import numpy as np
import pytest

from bench_myriapoda.world import meshes, terrain, terrain_cache


@pytest.fixture
def cache_home(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    terrain._mesh_params_cached.cache_clear()
    yield tmp_path / "xdg" / "bench-myriapoda" / "terrain"
    terrain._mesh_params_cached.cache_clear()


def skull_params():
    """The Fig. 1 skull terrain at 6 subdivisions (cheap), through the scenario path."""
    return terrain._mesh_params_cached("skull", 6, 0.7, (0.0, 0.9, 0.3), 0.0)


def counting_builds(monkeypatch) -> list:
    calls = []
    build = meshes.mesh_terrain_params
    monkeypatch.setattr(meshes, "mesh_terrain_params", lambda *a, **k: calls.append(1) or build(*a, **k))
    return calls


def test_a_second_process_reads_the_stored_terrain_bit_for_bit(cache_home, monkeypatch):
    calls = counting_builds(monkeypatch)
    first = np.array(skull_params())
    assert calls == [1] and len(list(cache_home.glob("*.f8"))) == 1
    terrain._mesh_params_cached.cache_clear()  # as a new process: only the disk holds it
    second = skull_params()
    assert calls == [1]
    assert second.dtype == np.float64 and not second.flags.writeable
    np.testing.assert_array_equal(second, first)
    assert second.tobytes() == first.tobytes()


@pytest.mark.parametrize("damage", ["truncated", "flipped byte", "empty", "garbage"])
def test_a_damaged_stored_terrain_is_built_again_and_replaced(cache_home, monkeypatch, damage):
    calls = counting_builds(monkeypatch)
    good = np.array(skull_params())
    (path,) = cache_home.glob("*.f8")
    data = path.read_bytes()
    bad = {"truncated": data[:len(data) // 2], "flipped byte": data[:100] + bytes([data[100] ^ 1]) + data[101:],
           "empty": b"", "garbage": b"not a terrain"}[damage]
    path.write_bytes(bad)
    terrain._mesh_params_cached.cache_clear()
    again = skull_params()
    assert calls == [1, 1]
    assert again.tobytes() == good.tobytes()
    assert path.read_bytes() == data  # replaced by a whole, matching file


def test_a_cache_that_cannot_be_written_is_no_error(tmp_path, monkeypatch):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a directory")
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocker))
    calls = counting_builds(monkeypatch)
    terrain._mesh_params_cached.cache_clear()
    try:
        f = skull_params()
        terrain._mesh_params_cached.cache_clear()
        g = skull_params()
    finally:
        terrain._mesh_params_cached.cache_clear()
    assert calls == [1, 1] and f.tobytes() == g.tobytes()
    assert not any(p.name.startswith(".part-") for p in tmp_path.iterdir())


def test_the_key_changes_with_the_mesh_the_settings_and_the_code_generation_target(monkeypatch):
    v = np.zeros((4, 3))
    f = np.array([[0, 1, 2], [0, 2, 3]])
    base = terrain_cache.key((v, f), (4.0, 0.0))
    assert terrain_cache.key((v, f), (4.0, 0.0)) == base
    moved = v.copy()
    moved[0, 0] = 1e-12
    assert terrain_cache.key((moved, f), (4.0, 0.0)) != base
    assert terrain_cache.key((v, f), (4.0, 0.5)) != base
    assert terrain_cache.key((v, f.astype(np.int32)), (4.0, 0.0)) != base
    monkeypatch.setenv("NUMBA_CPU_NAME", "haswell")
    assert terrain_cache.key((v, f), (4.0, 0.0)) != base
    monkeypatch.delenv("NUMBA_CPU_NAME")
    monkeypatch.setenv("NUMBA_CPU_FEATURES", "+avx2")
    assert terrain_cache.key((v, f), (4.0, 0.0)) != base


def test_a_scenario_mesh_run_reads_the_stored_terrain(cache_home, monkeypatch):
    """Through the world a run builds: the second build of the Fig. 1 scenario's terrain comes from the disk."""
    from bench_myriapoda.core.config import resolve_case

    calls = counting_builds(monkeypatch)
    sc = resolve_case("worm", "massspring", "fig1-mesh", duration=0.01,
                      overrides=["scenario.mesh_subdivisions=6"]).scenario
    a = terrain._base_terrain(sc)[1]
    terrain._mesh_params_cached.cache_clear()
    b = terrain._base_terrain(sc)[1]
    assert calls == [1] and a.tobytes() == b.tobytes()
    assert os.listdir(cache_home)
