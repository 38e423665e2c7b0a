"""Measured kinematics and posture of legless bodies (issue 11): shape metrics on an exact serpenoid,
posture metrics on synthetic series, and posture_fault on a real lattice snake turned on its back."""
from __future__ import annotations

import math

import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.core.series import Series
from bench_myriapoda.harness.recorder import Recorder
from bench_myriapoda.harness.runner import Creature
from bench_myriapoda.metrics.body_shape import body_shape_metrics
from bench_myriapoda.metrics.legless import legless_metrics
from bench_myriapoda.metrics.posture import AIRBORNE_FAULT_S, posture_metrics, roll_angles_deg
from bench_myriapoda.reference.slithering import body_shape
from bench_myriapoda.world.world import build_world

SHAPE_REL = 0.03  # discrete curvature of 51 centres on a serpenoid sampled 25 times per wavelength
T_S, L_M = 2.0, 1.0


def serpenoid_series(A: float, lam: float, turn_rad_per_cycle: float = 0.0, n: int = 51, cycles: float = 3.0,
                     samples_per_cycle: int = 40) -> Series:
    """Centres (head first) of the reference model's serpenoid, on the ground plane (x, z), the
    mean axis along +x and turning left by ``turn_rad_per_cycle``."""
    ts = np.arange(int(cycles * samples_per_cycle) + 1) / samples_per_cycle * T_S
    cs = []
    for t in ts:
        X, _, _, _ = body_shape(A, lam, t / T_S, n)
        psi = turn_rad_per_cycle * t / T_S
        # body frame (x head, y left) -> world (x, z = right): left turn is a rotation about +y
        x, y = X[:, 0] * L_M, X[:, 1] * L_M
        wx = math.cos(psi) * x - math.sin(psi) * y
        wl = math.sin(psi) * x + math.cos(psi) * y
        cs.append(np.column_stack([wx, np.zeros(n), -wl]))
    cs = np.array(cs)
    k = len(ts)
    return Series(t=ts, com=cs.mean(axis=1), head=cs[:, 0], tail=cs[:, -1], segment_centers=cs,
                  energy=np.zeros((k, 3)), nodes=None)


@pytest.mark.parametrize("A, lam", [(7.0, 1.0), (10.0, 0.5), (4.0, 0.7)])
def test_shape_metrics_recover_the_commanded_serpenoid(A, lam):
    s = serpenoid_series(A, lam)
    m = body_shape_metrics(s, 0, len(s.t) - 1, T_S, L_M)
    assert m["curvature_amplitude"] == pytest.approx(A, rel=SHAPE_REL)
    assert m["body_wavelength_bl"] == pytest.approx(lam, rel=SHAPE_REL)
    assert abs(m["heading_drift_deg_per_cycle"]) < 1.0


def test_heading_drift_measures_a_turn_to_the_left():
    s = serpenoid_series(7.0, 1.0, turn_rad_per_cycle=math.radians(6.0))
    m = body_shape_metrics(s, 0, len(s.t) - 1, T_S, L_M)
    assert m["heading_drift_deg_per_cycle"] == pytest.approx(6.0, abs=0.5)


def test_a_straight_body_has_no_wavelength():
    s = serpenoid_series(0.0, 0.5)
    m = body_shape_metrics(s, 0, len(s.t) - 1, T_S, L_M)
    assert m["curvature_amplitude"] < 1e-9 and math.isnan(m["body_wavelength_bl"])


def box_and_link_series(A: float, lam: float, n_boxes: int = 51, box_share: float = 2.0 / 3.0) -> Series:
    """A hybrid-like centre line on the reference serpenoid: straight boxes (``box_share`` of the pitch) whose
    headings are the serpenoid's at their centres, joined by links bent at constant curvature between them;
    recorded as the hybrid records its centres: box, link, box, ... (2 n_boxes - 1), head first."""
    ts = np.arange(121) / 40 * T_S
    pitch = L_M / n_boxes
    cs = []
    for t in ts:
        X, _, a, _ = body_shape(A, lam, t / T_S, n_boxes)
        psi = np.arctan2(a[:, 1], a[:, 0])  # heading of each box toward the head
        pts, c = [], np.zeros(2)
        for j in range(n_boxes):
            d = np.array([math.cos(psi[j]), math.sin(psi[j])])
            if j > 0:  # the link from box j - 1's back face: an arc turning from psi[j - 1] to psi[j]
                ln = (1.0 - box_share) * pitch
                mid = np.array([math.cos(0.5 * (psi[j - 1] + psi[j])), math.sin(0.5 * (psi[j - 1] + psi[j]))])
                pts.append(c - 0.5 * ln * mid)
                c = c - ln * mid - 0.5 * box_share * pitch * d
            else:
                c = c - 0.5 * box_share * pitch * d
            pts.append(c)
            c = c - 0.5 * box_share * pitch * d
        pts = np.array(pts)
        cs.append(np.column_stack([pts[:, 0], np.zeros(len(pts)), -pts[:, 1]]))
    cs = np.array(cs)
    return Series(t=ts, com=cs.mean(axis=1), head=cs[:, 0], tail=cs[:, -1], segment_centers=cs,
                  energy=np.zeros((len(ts), 3)), nodes=None)


def test_a_body_with_a_box_and_a_link_per_pitch_reads_its_shape_through_its_boxes():
    """The hybrid's links bend and its boxes do not: three-point curvature through every centre alternates
    (issue 27: the hybrid snake read 8.1 at a commanded 7); one pitch apart it is the serpenoid's."""
    s = box_and_link_series(7.0, 1.0)
    pitch = L_M / 51
    m = body_shape_metrics(s, 0, len(s.t) - 1, T_S, L_M, pitch_m=pitch)
    assert m["curvature_amplitude"] == pytest.approx(7.0, rel=SHAPE_REL)
    assert m["body_wavelength_bl"] == pytest.approx(1.0, rel=SHAPE_REL)
    every = body_shape_metrics(s, 0, len(s.t) - 1, T_S, L_M)["curvature_amplitude"]
    assert abs(every - 7.0) > 3 * SHAPE_REL * 7.0, every  # what the metric read before it knew the pitch


def _rot_about_axis(roll_deg: float, pitch_deg: float = 0.0) -> np.ndarray:
    """Segment frame (columns axis, dorsal, right) pitched nose-up then rolled about its axis."""
    r, p = math.radians(roll_deg), math.radians(pitch_deg)
    axis = np.array([math.cos(p), math.sin(p), 0.0])
    dorsal0 = np.array([-math.sin(p), math.cos(p), 0.0])
    right0 = np.cross(axis, dorsal0)
    dorsal = math.cos(r) * dorsal0 + math.sin(r) * right0
    return np.column_stack([axis, dorsal, np.cross(axis, dorsal)])


def test_roll_ignores_pitch_and_measures_rotation_about_the_axis():
    R = np.array([[_rot_about_axis(0.0, 40.0), _rot_about_axis(30.0, 0.0), _rot_about_axis(120.0, 20.0)]])
    roll = roll_angles_deg(R)[0]
    assert roll == pytest.approx([0.0, 30.0, 120.0], abs=1e-9)


def _posture_series(contact: np.ndarray, heights: np.ndarray, roll_deg: float = 0.0) -> Series:
    k, n = contact.shape
    t = np.arange(k) * 0.05
    cs = np.zeros((k, n, 3))
    cs[..., 0] = np.arange(n)[None, :] * -0.05
    cs[..., 1] = heights[:, None]
    rot = np.broadcast_to(_rot_about_axis(roll_deg), (k, n, 3, 3)).copy()
    return Series(t=t, com=cs.mean(axis=1), head=cs[:, 0], tail=cs[:, -1], segment_centers=cs,
                  energy=np.zeros((k, 3)), nodes=None, segment_positions=cs, segment_rotations=rot,
                  segment_contact=contact)


def test_posture_flags_a_body_that_leaves_the_ground():
    case = resolve_case("snake", "massspring", "flat")
    k = 40
    contact = np.ones((k, 10), bool)
    heights = np.full(k, 0.025)
    contact[10:10 + 8] = False  # 0.35 s in the air after touching down
    heights[10:18] = 0.025 + np.sin(np.linspace(0, np.pi, 8)) * 0.2
    m = posture_metrics(_posture_series(contact, heights), case.scenario, 0, k - 1, build_world(case))
    assert m["airborne_max_s"] > AIRBORNE_FAULT_S and m["posture_fault"] == 1.0
    assert m["lift_max_m"] == pytest.approx(0.2 * np.sin(np.linspace(0, np.pi, 8)).max())
    contact[:] = True
    contact[::2, 5:] = False  # half the segments lift every other sample: still on the ground
    m = posture_metrics(_posture_series(contact, np.full(k, 0.025)), case.scenario, 0, k - 1,
                        build_world(case))
    assert m["posture_fault"] == 0.0 and m["segment_contact_fraction"] == pytest.approx(0.75)


def test_posture_flags_a_flip_on_flat_ground_only():
    k = 10
    s = _posture_series(np.ones((k, 10), bool), np.full(k, 0.025), roll_deg=150.0)
    flat = resolve_case("snake", "massspring", "flat")
    assert posture_metrics(s, flat.scenario, 0, k - 1, build_world(flat))["posture_fault"] == 1.0
    slope = resolve_case("snake", "massspring", "slope")
    assert posture_metrics(s, slope.scenario, 0, k - 1, build_world(slope))["posture_fault"] == 0.0


def run_lattice_snake(flip: bool, duration_s: float = 1.0) -> dict[str, float]:
    """A lattice snake crawling on flat ground for ``duration_s``, optionally turned on its back at t = 0
    (every node rotated 180 degrees about the body's long axis through the centre of its cross-section)."""
    case = resolve_case("snake", "massspring", "flat", duration=duration_s)
    creature = Creature(case)
    creature.compile()
    body = creature.body
    if flip:
        x = body.x
        yc, zc = 0.5 * (x[:, 1].min() + x[:, 1].max()), 0.5 * (x[:, 2].min() + x[:, 2].max())
        x[:, 1] = 2.0 * yc - x[:, 1]
        x[:, 2] = 2.0 * zc - x[:, 2]
    rec = Recorder()
    rec.add(body.observe(0.0))
    chunk = max(1, int(round(1.0 / (case.record.sample_hz * case.dt))))
    done = 0
    while done < case.steps:
        k, code = creature.advance(done * case.dt, min(chunk, case.steps - done))
        assert code == 0
        done += k
        rec.add(body.observe(done * case.dt))
    return legless_metrics(rec.series(), case, body.body_length_m, creature.world)


def test_a_snake_on_its_back_is_a_posture_fault():
    m = run_lattice_snake(flip=True)
    assert m["roll_max_deg"] > 170.0
    assert m["posture_fault"] == 1.0


def test_a_normal_crawl_has_no_posture_fault():
    m = run_lattice_snake(flip=False)
    assert m["roll_max_deg"] < 20.0 and m["airborne_max_s"] == 0.0
    assert m["posture_fault"] == 0.0


def test_path_following_error_is_not_zero_by_construction_in_the_first_cycle():
    # a body that has not moved while its head swings sideways: it follows nothing.  The old metric
    # extended the head's path with the starting body line, on which these segments lie: error 0.
    from bench_myriapoda.metrics.locomotion import path_following_error
    n, k = 20, 41
    t = np.linspace(0.0, 2.0, k)
    cs = np.zeros((k, n, 3))
    cs[..., 0] = -0.05 * np.arange(n)[None, :]
    head = np.zeros((k, 3))
    head[:, 0] = 0.025 + 0.1 * t / 2.0
    head[:, 2] = 0.1 * np.sin(2 * np.pi * t / 2.0)
    s = Series(t=t, com=cs.mean(axis=1), head=head, tail=cs[:, -1], segment_centers=cs,
               energy=np.zeros((k, 3)), nodes=None)
    err = path_following_error(s, 0, k - 1, 1.0)
    assert err > 0.03


def test_path_following_error_is_small_when_segments_follow_the_head():
    # a straight body gliding along +x: every reached segment sits on the head's path
    from bench_myriapoda.metrics.locomotion import path_following_error
    n, k = 20, 41
    t = np.linspace(0.0, 4.0, k)
    cs = np.zeros((k, n, 3))
    cs[..., 0] = -0.05 * np.arange(n)[None, :] + 0.5 * t[:, None]
    head = cs[:, 0] + np.array([0.025, 0.0, 0.0])
    s = Series(t=t, com=cs.mean(axis=1), head=head, tail=cs[:, -1], segment_centers=cs,
               energy=np.zeros((k, 3)), nodes=None)
    assert path_following_error(s, 0, k - 1, 1.0) < 1e-9


@pytest.mark.parametrize("fault, expected", [(1.0, 1), (0.0, 0)])
def test_strict_run_fails_on_posture_fault(monkeypatch, capsys, fault, expected):
    # the run itself is replaced: this checks the CLI's exit rule, the metric is tested above
    from bench_myriapoda.cli import main
    from bench_myriapoda.harness import runner
    from bench_myriapoda.harness.runner import RunResult

    def fake_run_case(case, **kw):
        return RunResult(case, "ok", {"posture_fault": fault, "speed_bl_per_cycle": 0.0}, {"steps": 1})
    monkeypatch.setattr(runner, "run_case", fake_run_case)
    code = main(["run", "--creature", "snake", "--body", "massspring", "--scenario", "flat",
                 "--duration", "0.01", "--no-store", "--json", "--strict"])
    assert code == expected
    if fault:
        assert "posture fault" in capsys.readouterr().err


def test_runner_reports_the_legless_metrics():
    from bench_myriapoda.harness.runner import run_case
    res = run_case(resolve_case("worm", "massspring", "flat", duration=1.0))
    assert res.status == "ok"
    for name in ("curvature_amplitude", "body_wavelength_bl", "heading_drift_deg_per_cycle", "roll_max_deg",
                 "segment_contact_fraction", "lift_max_m", "airborne_max_s", "posture_fault"):
        assert name in res.metrics, name
    assert res.metrics["posture_fault"] == 0.0 and res.metrics["segment_contact_fraction"] > 0.9
