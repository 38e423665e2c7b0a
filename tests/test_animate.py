"""Animations and per-frame mesh export: ``body.scene()``, ``run --animate`` and ``run --export-frames``.

Order: the scene of every body model against the body's own state (surfaces
closed and outward, vertices where the nodes / boxes / boundary nodes are, legs
with the right link lengths and valid states), the frame selection, then the
command line: a GIF with the expected frame count, an mp4, a blow-up still
animated up to the failure, the exported meshes read back by trimesh, and bad
input exiting 2 with nothing written.
"""
from __future__ import annotations

import json
import math
import shutil
import subprocess

import numpy as np
import pytest
import trimesh
from PIL import Image

from bench_myriapoda.bodies import scene as SC
from bench_myriapoda.bodies.fem.surfaces import FEM_BLOCK_SURFACE, FEM_SURFACE
from bench_myriapoda.bodies.massspring.lattice import LATTICE_SURFACE
from bench_myriapoda.kinematics.legs import FEMUR, ROOT_X, ROOT_Z, TIBIA
from bench_myriapoda.harness.runner import Creature
from bench_myriapoda.cli import main
from bench_myriapoda.controllers.myriapod.switcher import N_STATES
from bench_myriapoda.core import registry
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.metrics.gait import STATE_COLORS
from bench_myriapoda.report.animate import (FrameRecorder, _antenna_segments, _leg_segments, _project_triangles,
                                            expected_samples, frame_stride, gif_durations_cs, playback_fps,
                                            sample_period, surface_height, view_limits, write_animation)
from bench_myriapoda.report.export_frames import TUBE_SECTIONS, export_frames, scene_mesh, tubes
from bench_myriapoda.world.terrain import terrain_from_scenario
from bench_myriapoda.world.terrain_kernels import terrain_phi_numpy

STEPS = 60            # time steps taken before a scene is checked: the body has moved and deformed a little
GEOM_TOL = 1e-9       # [m] positions copied or recomputed from the same state: equal to round-off
WORM = ["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat"]

BODIES = [("worm", "massspring", "flat"), ("worm", "fem", "flat"), ("centipede", "hybrid", "walk"),
          ("centipede", "massspring", "walk"), ("centipede", "fem", "walk")]


def cli(capsys, *argv):
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.fixture(scope="module", params=BODIES, ids=["/".join(b[:2]) for b in BODIES])
def moved_body(request):
    """A body of each model composed with its controller (``runner.Creature``) after STEPS steps."""
    creature, body_name, scenario = request.param
    registry.load_all()
    case = resolve_case(creature, body_name, scenario, duration=1.0)
    body = Creature(case)
    body.compile()
    k, status = body.advance(0.0, STEPS)
    assert (k, status) == (STEPS, 0)
    return body


def _segments(body):
    return body.body


def _surface_points(scene):
    return np.concatenate([v for v, _, _ in scene.triangles])


def test_scene_faces_index_their_vertices_and_every_surface_is_closed_and_outward(moved_body):
    scene = moved_body.scene()
    assert scene.triangles
    groups: dict[str, list] = {}
    for verts, faces, kind in scene.triangles:
        assert verts.dtype == np.float64 and verts.ndim == 2 and verts.shape[1] == 3
        assert faces.dtype == np.int64 and faces.ndim == 2 and faces.shape[1] == 3 and len(faces)
        assert faces.min() >= 0 and faces.max() < len(verts)
        assert np.array_equal(np.unique(faces), np.arange(len(verts)))  # no vertex off the surface
        assert np.all(np.isfinite(verts))
        # the legged FEM chain splits one boundary into its blocks' and its links' faces: rejoin them
        groups.setdefault("fem" if kind in (FEM_SURFACE, FEM_BLOCK_SURFACE) else kind, []).append((verts, faces))
    for parts in groups.values():
        mesh = trimesh.util.concatenate([trimesh.Trimesh(v, f, process=False) for v, f in parts])
        if len(parts) > 1:
            mesh.merge_vertices()  # the same node appears in both parts, at the same position
        assert mesh.is_winding_consistent
        # every box, FEM boundary and lattice surface is closed and wound outward: positive volume
        for piece in mesh.split(only_watertight=False):
            assert piece.is_watertight
            assert piece.volume > 0


def test_scene_surfaces_sit_on_the_bodys_nodes_boxes_and_segment_centres(moved_body):
    body = moved_body
    seg = _segments(body)
    scene = body.scene()
    kinds = {k: (v, f) for v, f, k in scene.triangles}
    # the bounding box of the drawn surfaces contains every observed segment centre
    pts = _surface_points(scene)
    centres = body.observe(STEPS * body.case.dt).segment_centers
    assert np.all(centres >= pts.min(axis=0) - GEOM_TOL) and np.all(centres <= pts.max(axis=0) + GEOM_TOL)
    if SC.RIGID_BOX in kinds:  # boxes: 8 corners each, centred on the rigid segment centres
        v, _ = kinds[SC.RIGID_BOX]
        np.testing.assert_allclose(v.reshape(-1, 8, 3).mean(axis=1), seg.rigid.c, atol=GEOM_TOL)
        np.testing.assert_array_equal(v, seg.box_corners())
    name = type(seg).__name__
    if name == "BodyMassSpring":  # every lattice node is on the surface; the springs join the nodes
        v, _ = kinds[LATTICE_SURFACE]
        np.testing.assert_array_equal(v, seg.x)
        np.testing.assert_array_equal(scene.springs, seg.x[seg.lattice.springs])
    elif name == "BodyRigidSpringChain":
        v, _ = kinds[LATTICE_SURFACE]
        np.testing.assert_array_equal(v, seg.x)
        assert scene.springs.shape == (len(seg.springs), 2, 3)
    else:
        # FEM: the surface vertices are the positions of the mesh's boundary nodes, found here from the
        # rest shape of the structured grid (a node on a face of its box), independently of the tets
        if name in ("BodyFEM", "BodyFEMChain"):  # one box grid (the legged chain's blocks and links alike)
            rest, boxes = seg.rest, [(seg.rest.min(axis=0), seg.rest.max(axis=0))]
            owner = np.zeros(len(rest), dtype=int)
        else:  # hybrid: each link is its own box grid
            rest, owner = seg.mesh.nodes, seg.mesh.node_link
            boxes = [(rest[owner == k].min(axis=0), rest[owner == k].max(axis=0)) for k in range(owner.max() + 1)]
        lo = np.array([boxes[o][0] for o in owner])
        hi = np.array([boxes[o][1] for o in owner])
        on_face = np.any(np.isclose(rest, lo, atol=1e-9) | np.isclose(rest, hi, atol=1e-9), axis=1)
        ids = np.flatnonzero(on_face)
        fem_kinds = [k for k in kinds if k in (FEM_SURFACE, FEM_BLOCK_SURFACE)]
        got = np.unique(np.concatenate([kinds[k][0] for k in fem_kinds]), axis=0)
        np.testing.assert_array_equal(got, np.unique(seg.x[ids], axis=0))
    assert scene.springs is None or scene.springs.shape[1:] == (2, 3)


def test_legs_are_root_knee_tip_with_the_leg_geometry_and_valid_states(moved_body):
    body = moved_body
    scene = body.scene()
    if body.monitor is None:  # no legs
        assert scene.legs is None and scene.leg_states is None
        return
    ctrl = body.controller
    c, R = body.body.segment_poses()
    n_legs = 2 * len(c)
    assert scene.legs.shape == (n_legs, 3, 3) and scene.leg_states.shape == (n_legs,)
    assert set(np.unique(scene.leg_states)) <= set(range(N_STATES))
    np.testing.assert_array_equal(scene.leg_states, ctrl.states)
    seg = np.arange(n_legs) // 2
    roots = c[seg] + np.einsum("kij,kj->ki", R[seg], ctrl.geom[:, ROOT_X:ROOT_Z + 1])
    np.testing.assert_allclose(scene.legs[:, 0], roots, atol=GEOM_TOL)
    np.testing.assert_allclose(np.linalg.norm(scene.legs[:, 1] - scene.legs[:, 0], axis=1), ctrl.geom[:, FEMUR],
                               rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(scene.legs[:, 2] - scene.legs[:, 1], axis=1), ctrl.geom[:, TIBIA],
                               rtol=1e-12)


def test_a_scene_is_a_copy_that_later_steps_do_not_change(moved_body):
    scene = moved_body.scene()
    before = [v.copy() for v, _, _ in scene.triangles]
    legs = None if scene.legs is None else scene.legs.copy()
    moved_body.advance(STEPS * moved_body.case.dt, 5)
    for (v, _, _), b in zip(scene.triangles, before):
        np.testing.assert_array_equal(v, b)
    if legs is not None:
        np.testing.assert_array_equal(scene.legs, legs)
    with pytest.raises(ValueError):
        scene.triangles[0][1][0, 0] = 0  # topology shared by every frame is read-only


# --------------------------------------------------------------------------- frame selection, terrain

def test_frame_stride_keeps_at_most_150_frames_and_at_most_30_per_simulated_second():
    assert frame_stride(61, 1 / 60) == 2        # 60 Hz samples: every 2nd, 30 fps real time
    assert frame_stride(11, 0.1) == 1           # 10 Hz samples: all, 10 fps real time
    k = frame_stride(1201, 1 / 60)              # 20 s at 60 Hz
    assert math.ceil(1201 / k) <= 150 and math.ceil(1201 / (k - 1)) > 150
    assert playback_fps([0.0, 1 / 30, 2 / 30]) == pytest.approx(30.0)
    assert playback_fps([0.0, 0.1, 0.2]) == pytest.approx(10.0)
    assert playback_fps(np.arange(10) / 120) == 30.0  # capped
    case = resolve_case("worm", "massspring", "flat", duration=1.0)
    assert expected_samples(case) == 61 and sample_period(case) == pytest.approx(1 / 60)


@pytest.mark.parametrize("scenario", ["flat", "slope", "cliff"])
def test_surface_height_is_on_the_terrain(scenario):
    case = resolve_case("worm", "massspring", scenario, duration=1.0)
    kind, f = terrain_from_scenario(case.scenario)
    x = np.linspace(-3.0, 3.0, 101)
    h = surface_height(kind, f, x)
    phi = terrain_phi_numpy(kind, f, np.column_stack([x, h, np.zeros_like(x)]))
    assert np.abs(phi).max() < 1e-9


def _unit_box_scene(centre, legs=None, states=None):
    corners = np.array([[(k & 1) - 0.5, (k >> 1 & 1) - 0.5, (k >> 2 & 1) - 0.5] for k in range(8)]) + centre
    v, f = SC.box_triangles(corners)
    return SC.Scene(triangles=[(v, f, SC.RIGID_BOX)], legs=legs, leg_states=states)


def test_a_box_shows_its_top_from_above_and_its_right_face_from_the_side():
    scene = _unit_box_scene(np.array([5.0, 7.0, 9.0]))
    for view, axis, value in (("top", 1, 7.5), ("side", 2, 9.5)):
        polys, faces, edges = _project_triangles(scene, view)
        assert polys.shape == (2, 3, 2) and faces.shape == edges.shape == (2, 4)  # back faces culled
        corners = scene.triangles[0][0]
        visible = corners[np.isclose(corners[:, axis], value)][:, [0, 1 if view == "side" else 2]]
        assert {tuple(p) for p in polys.reshape(-1, 2)} == {tuple(p) for p in visible}


def test_legs_are_drawn_root_knee_tip_in_their_state_colours_the_right_legs_separately():
    legs = np.arange(4 * 3 * 3, dtype=float).reshape(4, 3, 3)
    states = np.array([4, 0, 5, 2])
    scene = _unit_box_scene(np.zeros(3), legs, states)
    seg, cols = _leg_segments(scene, "top")
    np.testing.assert_array_equal(seg[:4], legs[:, 0:2][:, :, [0, 2]])     # root -> knee
    np.testing.assert_array_equal(seg[4:], legs[:, 1:3][:, :, [0, 2]])     # knee -> tip
    assert cols == [STATE_COLORS[s] for s in states] * 2
    seg, cols = _leg_segments(scene, "side", side=1)                        # legs 1 and 3 (right)
    np.testing.assert_array_equal(seg[:2], legs[[1, 3], 0:2][:, :, [0, 1]])
    assert cols == [STATE_COLORS[0], STATE_COLORS[2]] * 2


def test_view_limits_hold_every_frame():
    frames = [_unit_box_scene(np.array([x, 0.5, 0.0])) for x in (0.0, 3.0, 10.0)]
    xlim, ylim, zlim = view_limits(frames)
    for s in frames:
        lo, hi = s.bounds()
        assert xlim[0] < lo[0] and hi[0] < xlim[1] and ylim[0] < lo[1] and hi[1] < ylim[1]
        assert zlim[0] < lo[2] and hi[2] < zlim[1]


def test_write_animation_leaves_nothing_when_it_fails(tmp_path):
    with pytest.raises(ValueError):
        write_animation([], [], None, tmp_path / "a.gif")
    assert list(tmp_path.iterdir()) == []


# --------------------------------------------------------------------------- the command line: animations

def test_run_animate_gif_has_one_frame_per_kept_sample_played_in_real_time(capsys, tmp_path):
    gif = tmp_path / "sub" / "worm.gif"
    code, out, err = cli(capsys, *WORM, "--duration", "1", "--animate", gif, "--no-store")
    assert code == 0, err
    with Image.open(gif) as im:
        # 1 s at 60 samples/s = 61 samples (t = 0 included); a GIF keeps every 3rd (50 ms = 5 whole cs:
        # every 2nd would be 33.3 ms, which a GIF can only show as 30 or 40 ms)
        assert im.n_frames == 21
        assert im.info["duration"] == 50  # [ms]
        im.seek(10)
        assert len(im.convert("RGB").getcolors(1 << 20)) > 10  # drawn, not blank
    assert "21 frames" in out
    assert [p.name for p in gif.parent.iterdir()] == ["worm.gif"]  # no temporary file left


@pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not installed")
def test_run_animate_mp4_with_ffmpeg(capsys, tmp_path):
    mp4 = tmp_path / "worm.mp4"
    code, _, err = cli(capsys, *WORM, "--duration", "0.5", "--animate", mp4, "--no-store", "--json")
    assert code == 0, err
    assert mp4.stat().st_size > 1000
    if shutil.which("ffprobe"):
        probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                "stream=nb_read_frames", "-of", "csv=p=0", str(mp4)],
                               capture_output=True, text=True, check=True)
        assert int(probe.stdout.strip()) == 16  # 31 samples in 0.5 s, every 2nd


def test_mp4_without_ffmpeg_exits_2_naming_animate(capsys, tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    db = tmp_path / "r.sqlite"
    code, _, err = cli(capsys, *WORM, "--duration", "0.5", "--animate", tmp_path / "w.mp4", "--store", db)
    assert code == 2
    assert "--animate" in err and "ffmpeg" in err and len(err.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def test_a_blow_up_is_animated_up_to_the_failure(capsys, tmp_path):
    gif, rec = tmp_path / "snake.gif", tmp_path / "snake.npz"
    code, out, _ = cli(capsys, "run", "--creature", "snake", "--body", "massspring", "--scenario", "flat",
                         "--duration", "2", "--dt", "0.01", "--json", "--no-store", "--animate", gif, "--record", rec)
    assert code == 0
    assert json.loads(out)["status"] == "unstable"
    with np.load(rec) as z:
        n_samples = len(z["t"])
    assert n_samples < 100  # stopped early (a full run would have 101 samples)
    with Image.open(gif) as im:
        # samples every 2 steps of 0.01 s = 0.02 s; every 2nd kept for <= 30 frames per simulated second
        assert im.n_frames == math.ceil(n_samples / 2)


# --------------------------------------------------------------------------- the command line: frame export

def test_run_export_frames_writes_one_mesh_per_sample_matching_the_scene(capsys, tmp_path):
    out_dir = tmp_path / "frames"
    code, _, err = cli(capsys, *WORM, "--duration", "0.5", "--export-frames", out_dir, "--no-store")
    assert code == 0, err
    meta = json.loads((out_dir / "frames.json").read_text())
    files = sorted(p.name for p in out_dir.glob("frame_*.obj"))
    assert len(files) == 31 == meta["n_frames"] == len(meta["times_s"])
    assert files[0] == "frame_00000.obj" and meta["files"] == files
    np.testing.assert_allclose(meta["times_s"], np.arange(31) / 60, atol=1e-12)
    assert meta["case"]["creature"]["name"] == "worm"
    # the same deterministic case again, recording the scenes in the test
    rec = FrameRecorder(1)
    run_case(resolve_case("worm", "massspring", "flat", duration=0.5), on_sample=rec)
    for i in (0, 15, 30):
        mesh = trimesh.load(out_dir / files[i], process=False)
        verts, faces, _ = rec.frames[i].triangles[0]
        assert len(mesh.faces) == len(faces) > 0
        np.testing.assert_allclose(mesh.vertices, verts, atol=1e-9)
        np.testing.assert_array_equal(mesh.faces, faces)
    assert [p.name for p in tmp_path.iterdir()] == ["frames"]  # the temporary directory was renamed away


def test_export_frames_ply_into_an_existing_empty_directory(capsys, tmp_path):
    out_dir = tmp_path / "empty"
    out_dir.mkdir()
    code, _, err = cli(capsys, *WORM, "--duration", "0.1", "--export-frames", out_dir, "--frame-format", "ply",
                       "--no-store")
    assert code == 0, err
    files = sorted(out_dir.glob("frame_*.ply"))
    assert len(files) == 7 and json.loads((out_dir / "frames.json").read_text())["format"] == "ply"
    mesh = trimesh.load(files[-1], process=False)
    assert len(mesh.faces) == 8 * 20 + 4 and mesh.is_watertight


def test_exported_legged_frame_has_the_body_then_two_closed_tubes_per_leg(tmp_path):
    registry.load_all()
    case = resolve_case("centipede", "massspring", "walk", duration=1.0)
    body = Creature(case)
    body.compile()
    scenes, times = [body.scene()], [0.0]
    body.advance(0.0, 20)
    scenes.append(body.scene())
    times.append(20 * case.dt)
    export_frames(scenes, times, case.to_dict(), tmp_path / "legged", "obj")
    n_legs = scenes[1].legs.shape[0]
    surf = np.concatenate([v for v, _, _ in scenes[1].triangles])
    mesh = trimesh.load(tmp_path / "legged" / "frame_00001.obj", process=False)
    per_tube = 2 * TUBE_SECTIONS + 2
    ant = scenes[1].antennae  # (2, n_links + 1, 3): one thinner tube per antenna link, after the legs
    n_ant = 2 * (ant.shape[1] - 1)
    assert ant.shape == (2, case.antennae.n_links + 1, 3)
    assert len(mesh.vertices) == len(surf) + (2 * n_legs + n_ant) * per_tube
    np.testing.assert_allclose(mesh.vertices[:len(surf)], surf, atol=1e-8)
    ant_v = mesh.vertices[len(surf) + 2 * n_legs * per_tube:].reshape(n_ant, per_tube, 3)
    np.testing.assert_allclose(ant_v[:, -2], ant[:, :-1].reshape(-1, 3), atol=1e-8)
    np.testing.assert_allclose(ant_v[:, -1], ant[:, 1:].reshape(-1, 3), atol=1e-8)
    # antenna links keep their length
    np.testing.assert_allclose(np.linalg.norm(np.diff(ant, axis=1), axis=2), case.antennae.link_length_m, rtol=1e-9)
    tube_v = mesh.vertices[len(surf):len(surf) + 2 * n_legs * per_tube].reshape(2 * n_legs, per_tube, 3)
    legs = scenes[1].legs
    # tube centre-line ends (the cap centres) are the leg points: root-knee tubes then knee-tip tubes
    np.testing.assert_allclose(tube_v[:n_legs, -2], legs[:, 0], atol=1e-8)
    np.testing.assert_allclose(tube_v[:n_legs, -1], legs[:, 1], atol=1e-8)
    np.testing.assert_allclose(tube_v[n_legs:, -1], legs[:, 2], atol=1e-8)
    # a tube is closed and outward
    v, f = tubes(legs[:1, 0], legs[:1, 1], 0.05)
    tube = trimesh.Trimesh(v, f, process=False)
    assert tube.is_watertight and tube.volume > 0
    assert len(scene_mesh(scenes[1]).faces) == len(mesh.faces)


@pytest.mark.parametrize("flag, value, message", [
    ("--animate", "w.avi", ".gif or .mp4"),
    ("--animate", "w", ".gif or .mp4"),
    ("--export-frames", "full", "not empty"),
    ("--export-frames", "afile", "not a directory"),
])
def test_bad_frame_output_exits_2_and_writes_nothing(capsys, tmp_path, flag, value, message):
    (tmp_path / "full").mkdir()
    (tmp_path / "full" / "keep.txt").write_text("mine")
    (tmp_path / "afile").write_text("x")
    before = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*"))
    code, _, err = cli(capsys, *WORM, "--duration", "0.5", flag, tmp_path / value, "--store", tmp_path / "r.sqlite")
    assert code == 2
    assert flag in err and message in err and len(err.strip().splitlines()) == 1
    assert sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*")) == before
    assert (tmp_path / "full" / "keep.txt").read_text() == "mine"


def test_frame_format_needs_export_frames(capsys, tmp_path):
    code, _, err = cli(capsys, *WORM, "--frame-format", "ply", "--no-store")
    assert code == 2 and "--frame-format" in err
    code, _, err = cli(capsys, *WORM, "--frame-format", "stl", "--export-frames", tmp_path / "x", "--no-store")
    assert code == 2 and "--frame-format" in err
    assert list(tmp_path.iterdir()) == []


# --------------------------------------------------------------------------- real-time GIFs, size, 3-D view

def _gif_durations(path) -> list[int]:
    with Image.open(path) as im:
        out = []
        for i in range(im.n_frames):
            im.seek(i)
            out.append(im.info["duration"])
    return out


def test_gif_frame_durations_equal_the_recordings_sample_interval(capsys, tmp_path):
    gif, rec = tmp_path / "w.gif", tmp_path / "w.npz"
    code, _, err = cli(capsys, *WORM, "--duration", "1.5", "--animate", gif, "--record", rec, "--no-store")
    assert code == 0, err
    with np.load(rec) as z:
        t = z["t"]
    durations = np.array(_gif_durations(gif), dtype=float)  # [ms]
    stride = (len(t) - 1) // (len(durations) - 1)
    assert stride * (len(durations) - 1) == len(t) - 1       # every stride-th sample, the last one included
    interval_ms = 1000.0 * np.diff(t[::stride])               # the simulated time each frame stands for
    assert np.abs(durations[:-1] - interval_ms).max() <= 1.0
    assert abs(durations[-1] - interval_ms[-1]) <= 1.0
    assert abs(durations.sum() - 1000.0 * (t[-1] - t[0]) - durations[-1]) <= 1.0  # real time overall


def test_gif_durations_spread_the_rounding_when_no_stride_is_whole_centiseconds():
    # 16.8 ms samples (dt = 0.7 ms, 24 steps a sample): 2 samples = 33.6 ms, never whole centiseconds
    assert frame_stride(200, 0.0168, tick_s=0.01) == 2
    times = np.arange(60) * 0.0336
    cs = np.array(gif_durations_cs(times))
    assert set(cs) <= {3, 4}
    assert np.abs(np.cumsum(cs[:-1]) * 10.0 - 1000.0 * times[1:]).max() <= 5.0  # never more than 5 ms off
    assert frame_stride(61, 1 / 60, tick_s=0.01) == 3 and frame_stride(101, 0.02, tick_s=0.01) == 2
    assert gif_durations_cs(np.arange(5) / 60, fps=20) == [5] * 5


@pytest.fixture(scope="module")
def centipede_outputs(tmp_path_factory):
    """A short centipede run animated in 3-D at a given size, its frames exported, and its frame recorder."""
    d = tmp_path_factory.mktemp("centipede")
    argv = ["run", "--creature", "centipede", "--body", "massspring", "--scenario", "walk", "--duration", "0.2",
            "--no-store", "--animate", str(d / "c.gif"), "--view", "3d", "--size", "640x400",
            "--export-frames", str(d / "frames")]
    assert main(argv) == 0
    rec = FrameRecorder(1)
    run_case(resolve_case("centipede", "massspring", "walk", duration=0.2), on_sample=rec)
    return d, rec


def test_antennae_have_their_length_in_frame_0(centipede_outputs):
    d, rec = centipede_outputs
    case = resolve_case("centipede", "massspring", "walk", duration=0.2)
    ant = rec.frames[0].antennae
    assert rec.times[0] == 0.0
    np.testing.assert_allclose(np.linalg.norm(np.diff(ant, axis=1), axis=2), case.antennae.link_length_m, rtol=1e-9)
    seg, _ = _antenna_segments(rec.frames[0], "side")       # what the 2-D GIF draws
    assert min(np.linalg.norm(s[-1] - s[0]) for s in seg) > 0.5 * case.antennae.link_length_m
    # the antenna roots sit on the head: the same place as in the next frame, to within its motion
    assert np.abs(rec.frames[0].antennae[:, 0] - rec.frames[1].antennae[:, 0]).max() < 0.05
    # the exported frame 0: the antenna tubes span the antennae
    groups = _obj_groups(d / "frames" / "frame_00000.obj")
    verts = groups["__vertices__"]
    r = json.loads((d / "frames" / "frames.json").read_text())["leg_tube_radius_m"]  # antenna tubes: r / 2
    for a in (0, 1):
        used = verts[np.unique(groups[f"antenna_{a}"]) - 1]
        np.testing.assert_allclose(used.min(axis=0), ant[a].min(axis=0), atol=0.5 * r + 1e-9)
        np.testing.assert_allclose(used.max(axis=0), ant[a].max(axis=0), atol=0.5 * r + 1e-9)


def _obj_groups(path) -> dict:
    """{group name: (F, 3) 1-based face indices} of an OBJ file, and its vertices under '__vertices__'."""
    groups, verts, current = {}, [], None
    for line in path.read_text().splitlines():
        if line.startswith("v "):
            verts.append([float(x) for x in line.split()[1:4]])
        elif line.startswith("g "):
            current = line[2:].strip()
            groups[current] = []
        elif line.startswith("f "):
            groups[current].append([int(x) for x in line.split()[1:4]])
    out = {k: np.array(v, dtype=int) for k, v in groups.items()}
    out["__vertices__"] = np.array(verts)
    return out


def test_exported_obj_frames_name_one_group_per_part(centipede_outputs):
    d, rec = centipede_outputs
    scene = rec.frames[-1]
    n_legs = len(scene.legs)
    groups = _obj_groups(d / "frames" / sorted(p.name for p in (d / "frames").glob("*.obj"))[-1])
    names = [k for k in groups if k != "__vertices__"]
    assert names == ["body"] + [f"leg_{k:02d}" for k in range(n_legs)] + ["antenna_0", "antenna_1"]
    per_tube = len(tubes(np.zeros((1, 3)), np.ones((1, 3)), 0.1)[1])
    assert len(groups["body"]) == sum(len(f) for _, f, _ in scene.triangles)
    links = scene.antennae.shape[1] - 1
    assert all(len(groups[f"leg_{k:02d}"]) == 2 * per_tube for k in range(n_legs))
    assert len(groups["antenna_0"]) == len(groups["antenna_1"]) == links * per_tube
    # leg k's tubes run from its root to its tip
    verts = groups["__vertices__"]
    for k in (0, n_legs - 1):
        used = verts[np.unique(groups[f"leg_{k:02d}"]) - 1]
        for p in scene.legs[k]:
            assert np.linalg.norm(used - p, axis=1).min() < 0.1
    # trimesh still reads it as one mesh with the vertices in order
    mesh = trimesh.load(d / "frames" / "frame_00000.obj", process=False)
    assert len(mesh.faces) == sum(len(v) for k, v in groups.items() if k != "__vertices__")


def test_view_3d_writes_a_gif_of_the_requested_size_with_a_following_camera(centipede_outputs):
    d, rec = centipede_outputs
    with Image.open(d / "c.gif") as im:
        assert im.size == (640, 400)
        assert im.n_frames == math.ceil(len(rec.frames) / 3)  # 60 Hz samples, every 3rd: 50 ms frames
        im.seek(im.n_frames - 1)
        last = np.asarray(im.convert("RGB"), dtype=float)
    # shaded: many distinct colours, not flat fills; the body (dark browns) is near the middle of the picture
    colors = {tuple(c) for c in last.reshape(-1, 3)[::7]}
    assert len(colors) > 40
    dark = (last.sum(axis=2) < 300).nonzero()
    assert len(dark[0]) > 100
    assert 0.2 < np.median(dark[1]) / 640 < 0.8 and 0.2 < np.median(dark[0]) / 400 < 0.8


def test_size_is_honoured_by_the_2d_view_and_bad_sizes_exit_2(capsys, tmp_path):
    gif = tmp_path / "w.gif"
    code, out, err = cli(capsys, *WORM, "--duration", "0.2", "--animate", gif, "--size", "800x600", "--no-store")
    assert code == 0, err
    with Image.open(gif) as im:
        assert im.size == (800, 600)
    assert "800x600 px" in out
    for flags, message in ((["--animate", tmp_path / "a.gif", "--size", "800"], "WIDTHxHEIGHT"),
                           (["--animate", tmp_path / "a.gif", "--size", "20x20"], "160 to 7680"),
                           (["--animate", tmp_path / "a.mp4", "--size", "801x600"], "even"),
                           (["--size", "800x600"], "only meaningful with --animate"),
                           (["--view", "3d"], "only meaningful with --animate")):
        code, _, err = cli(capsys, *WORM, "--duration", "0.2", "--no-store", *flags)
        assert code == 2 and flags[-2] in err and message in err and len(err.strip().splitlines()) == 1
    assert [p.name for p in tmp_path.iterdir()] == ["w.gif"]
