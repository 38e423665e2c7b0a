"""Structured grids, segment chains and the cached fTetWild meshing."""
import numpy as np
import pytest

from bench_myriapoda.bodies.fem import mesh as M

VOLUME_TOL = 1e-12   # sum of tet volumes vs box volume, relative


def faces_of(tets):
    f = np.concatenate([tets[:, [1, 2, 3]], tets[:, [0, 2, 3]], tets[:, [0, 1, 3]], tets[:, [0, 1, 2]]])
    return np.unique(np.sort(f, axis=1), axis=0, return_counts=True)


@pytest.mark.parametrize("tets_per_cell", [5, 6])
def test_box_grid_is_positive_conforming_and_fills_the_box(tets_per_cell):
    size, cells = (1.0, 2.0, 3.0), (3, 4, 5)
    nodes, tets = M.box_grid(size, cells, origin=(0.5, -1.0, 2.0), tets_per_cell=tets_per_cell)
    assert nodes.dtype == np.float64 and tets.dtype == np.int64
    assert nodes.shape == (4 * 5 * 6, 3) and tets.shape == (60 * tets_per_cell, 4)
    vol = M.signed_volumes(nodes, tets)
    assert vol.min() > 0.0
    assert abs(vol.sum() - 6.0) < VOLUME_TOL * 6.0
    np.testing.assert_allclose(nodes.min(axis=0), [0.5, -1.0, 2.0])
    # conforming: every face is shared by at most two tets, and exactly the
    # boundary triangles (2 per boundary cell face) are unshared
    _faces, counts = faces_of(tets)
    assert counts.max() == 2
    assert (counts == 1).sum() == 2 * 2 * (3 * 4 + 4 * 5 + 3 * 5)


def test_orient_tets_fixes_negative_volumes():
    nodes, tets = M.box_grid((1, 1, 1), (1, 1, 1))
    bad = tets.copy()
    bad[::2, [2, 3]] = bad[::2, [3, 2]]
    assert (M.signed_volumes(nodes, bad) < 0).sum() == 3
    np.testing.assert_array_equal(M.orient_tets(nodes, bad), tets)


def test_chain_resolution_units_and_segment_index():
    nodes, tets, seg = M.chain_grid(17, 1.0, resolution=3)  # default: 3 x 3 x 3 nodes
    assert len(tets) == 816 and len(nodes) == 35 * 3 * 3
    np.testing.assert_array_equal(np.bincount(seg), np.full(17, 48))
    nodes, tets, seg = M.chain_grid(17, 1.0, resolution=3, resolution_unit="cells")
    assert len(tets) == 2754 and len(nodes) == 52 * 4 * 4
    # segment 0 is the head, at the front (largest x)
    cx = nodes[tets].mean(axis=1)[:, 0]
    assert cx[seg == 0].min() > cx[seg == 1].max()
    assert abs(M.signed_volumes(nodes, tets).sum() - 17.0) < VOLUME_TOL * 17
    nodes_s, tets_s, seg_s = M.chain_grid(4, 0.5, cross_section=(0.2, 0.3), resolution=(3, 2, 2),
                                          shared_faces=False)
    assert len(nodes_s) == 4 * 3 * 2 * 2 and len(tets_s) == 4 * 2 * 6
    for a in range(4):  # separate segments share no node
        for b in range(a + 1, 4):
            assert not np.intersect1d(tets_s[seg_s == a], tets_s[seg_s == b]).size
    np.testing.assert_allclose(nodes_s.min(axis=0), [0.0, 0.0, -0.15])
    np.testing.assert_allclose(nodes_s.max(axis=0), [2.0, 0.2, 0.15])
    with pytest.raises(ValueError):
        M.segment_cells(1, "nodes")
    with pytest.raises(ValueError):
        M.segment_cells(3, "voxels")


def test_tetrahedralize_surface_is_oriented_and_cached(tmp_path, monkeypatch):
    trimesh = pytest.importorskip("trimesh")
    pytest.importorskip("pytetwild")
    monkeypatch.setenv("BENCH_MYRIAPODA_CACHE", str(tmp_path / "cache"))
    workdir = tmp_path / "cwd"
    workdir.mkdir()
    monkeypatch.chdir(workdir)  # fTetWild's scratch file must not land in the working directory
    path = tmp_path / "sphere.ply"
    trimesh.creation.icosphere(subdivisions=2, radius=1.0).export(path)
    surface = trimesh.load_mesh(path, force="mesh")
    nodes, tets = M.tetrahedralize_surface(path, edge_length_fac=0.2, optimize=False)
    assert len(list((tmp_path / "cache").glob("*.npz"))) == 1
    assert list(workdir.iterdir()) == []
    vol = M.signed_volumes(nodes, tets)
    assert vol.min() > 0.0
    assert abs(vol.sum() - surface.volume) < 0.02 * surface.volume
    assert np.array_equal(np.unique(tets), np.arange(len(nodes)))  # no unreferenced nodes

    def no_tetwild(*args, **kwargs):
        raise AssertionError("fTetWild ran although the mesh is cached")

    monkeypatch.setattr(M, "_run_pytetwild", no_tetwild)
    # the same surface bytes, given as a path, a Trimesh or a (vertices, faces) tuple
    for source in (path, surface, (surface.vertices, surface.faces)):
        nodes2, tets2 = M.tetrahedralize_surface(source, edge_length_fac=0.2, optimize=False)
        np.testing.assert_array_equal(nodes2, nodes)
        np.testing.assert_array_equal(tets2, tets)
    # another parameter is another key: this one would have to run fTetWild
    with pytest.raises(AssertionError, match="fTetWild ran"):
        M.tetrahedralize_surface(path, edge_length_fac=0.3, optimize=False)
