"""``bench-myriapoda validate``: every check as a test, broken references fail, JSON output, bad input,
the report's Validation section and figure verdicts, and the work-precision data."""
from __future__ import annotations

import json
import sqlite3

import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.validation import analytic, references
from bench_myriapoda.validation.core import FAIL, INFO, NA, PASS, Context
from bench_myriapoda.validation.registry import CHECKS
from bench_myriapoda.validation.run import run_checks, select
from matrix_toml import WORM_ON_A_CLIFF, block, toml_table

# Checks whose measured verdict is FAIL today, with the reason; the test expects the failure (strict:
# when the physics is fixed the test says so).  Everything else must PASS (or be INFO, or NOT
# APPLICABLE with a reason).
KNOWN_FAILURES: dict[tuple[str, str], str] = {}


def _cases():
    for c in CHECKS:
        quick_bodies = c.bodies if c.quick_bodies is None else c.quick_bodies
        bodies = ("all",) if c.bodies == ("all",) else (quick_bodies or c.bodies[:1])
        for b in bodies:
            marks = [] if quick_bodies else [pytest.mark.slow]
            if (c.name, b) in KNOWN_FAILURES:
                marks.append(pytest.mark.xfail(reason=KNOWN_FAILURES[(c.name, b)], strict=True))
            yield pytest.param(c, b, id=f"{c.name}[{b}]", marks=marks)


@pytest.fixture(scope="module")
def ctx():
    return Context(quick=True)  # one simulation cache for every check below


@pytest.mark.parametrize("check,body", list(_cases()))
def test_check(check, body, ctx):
    out = check.measure(ctx, body)
    assert out.verdict in (PASS, NA, INFO), (out.verdict, out.measured, out.reference, out.detail)
    if out.verdict == NA:
        assert out.detail  # a NOT APPLICABLE row says why
    assert out.tolerance and out.reference is not None or out.verdict == NA


def test_quick_json_prints_one_object_with_a_row_per_check(capsys, tmp_path, monkeypatch):
    # the quick selection, narrowed to the cheap analytic checks on the lattice so the test stays short;
    # the full quick set is the same code path (measured in the README)
    store = tmp_path / "r.sqlite"
    code = main(["validate", "--quick", "--json", "--check", "analytic", "--body", "massspring", "--out",
                 str(tmp_path / "v"), "--store", str(store)])
    out = capsys.readouterr().out
    doc = json.loads(out)  # exactly one JSON object
    assert out.count("\n") == 1
    pairs, _ = select(["analytic"], ["massspring"], True)
    assert [(r["check"], r["body"]) for r in doc["rows"]] == [(c.name, b) for c, b in pairs]
    for r in doc["rows"]:
        assert r["verdict"] in (PASS, FAIL, NA, INFO)
        assert {"quantity", "measured", "reference", "source", "tolerance", "detail"} <= set(r)
    assert code == (1 if any(r["verdict"] == FAIL for r in doc["rows"]) else 0)
    # one transaction per run in the store, and validation.json next to the diagrams
    con = sqlite3.connect(store)
    n = con.execute("SELECT COUNT(*) FROM validation WHERE run_id = ?", (doc["run_id"],)).fetchone()[0]
    assert n == len(doc["rows"])
    assert json.loads((tmp_path / "v" / "validation.json").read_text())["rows"] == doc["rows"]


def test_the_quick_set_covers_every_family():
    pairs, _ = select(None, None, True)
    assert {c.family for c, _ in pairs} == {"analytic", "miller", "paper", "throughput"} | (
        {"cross_body"} if any(c.family == "cross_body" for c, _ in pairs) else set())
    assert len(pairs) < len(select(None, None, False)[0])


def test_a_wrong_tolerance_makes_the_check_fail_and_validate_exit_1(capsys, tmp_path, monkeypatch):
    monkeypatch.setattr(analytic, "BAR_REL_TOL", 1e-6)  # the bar's discretisation error is ~3 %
    code = main(["validate", "--check", "analytic.hanging-bar", "--quick", "--json", "--no-store",
                 "--out", str(tmp_path)])
    doc = json.loads(capsys.readouterr().out)
    assert code == 1
    assert [r["verdict"] for r in doc["rows"]] == [FAIL]


def test_a_perturbed_reference_kernel_makes_the_check_fail(capsys, tmp_path, monkeypatch):
    real = references.backward_euler_damping_factor
    monkeypatch.setattr(references, "backward_euler_damping_factor", lambda lam, h: real(lam, h) * (1 + 1e-6))
    code = main(["validate", "--check", "analytic.damping-pure-mode", "--json", "--no-store", "--out", str(tmp_path)])
    doc = json.loads(capsys.readouterr().out)
    assert code == 1 and doc["rows"][0]["verdict"] == FAIL
    monkeypatch.undo()
    assert main(["validate", "--check", "analytic.damping-pure-mode", "--json", "--no-store",
                 "--out", str(tmp_path)]) == 0


def test_a_check_that_raises_is_a_fail_row():
    import dataclasses

    def boom(ctx, body):
        raise RuntimeError("kernel exploded")
    c = next(c for c in CHECKS if c.name == "analytic.rigid-rotation")
    broken = dataclasses.replace(c, measure=boom)
    [row] = run_checks([(broken, "fem")], quick=True)
    assert row.verdict == FAIL and "kernel exploded" in row.detail


@pytest.mark.parametrize("argv,flag", [(["--body", "nope"], "--body"), (["--check", "analytic.nope"], "--check")])
def test_bad_input_is_one_line_exit_2_nothing_written(argv, flag, capsys, tmp_path):
    out, store = tmp_path / "v", tmp_path / "r.sqlite"
    code = main(["validate", *argv, "--out", str(out), "--store", str(store)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and flag in err
    assert not out.exists() and not store.exists()


def test_fig10d_window_note_explains_a_3_second_walk():
    from bench_myriapoda.validation.paper import judge_walk_cycle, walking_window_note
    m = {"time_to_walk_s": 0.41, "stride_frequency_hz": 0.82, "walking_cycle_leg_fraction": 0.0}
    note = walking_window_note(m, 3.0)
    assert note is not None and "3 s run" in note
    assert judge_walk_cycle(m, 3.0).verdict == NA
    assert walking_window_note(m, 10.0) is None
    assert judge_walk_cycle({**m, "walking_cycle_leg_fraction": 0.69}, 10.0).verdict == PASS
    assert judge_walk_cycle(m, 10.0).verdict == FAIL


# --------------------------------------------------------------------------- work-precision and the report

WP_NOISE = 0.1  # an error may rise by 10 % of itself (plus 1e-4) from one dt to the next smaller: timing-free noise


@pytest.fixture(scope="module")
def work_precision(tmp_path_factory):
    from bench_myriapoda.report.work_precision import run_work_precision
    from bench_myriapoda.validation.work_precision import Quantity
    out = tmp_path_factory.mktemp("wp")
    # a small hanging worm (6 segments, 0.4 s, weak gravity) on every body: the same code as the full diagrams
    q = Quantity("hanging_elongation", "hanging worm (test size)", "worm", "hang", None, "hanging_elongation_m",
                 0.4, 0.4, ("scenario.gravity_m_s2=1.0", "creature.segments=6"))
    return out, run_work_precision(out, quick=True, quantities=(q,))


def test_work_precision_plots_have_one_curve_per_body_and_error_falls_with_dt(work_precision):
    out, doc = work_precision
    png = out / "work_precision_hanging_elongation.png"
    assert png.is_file() and png.stat().st_size > 5000
    on_disk = json.loads((out / "work_precision.json").read_text())
    curves = on_disk["quantities"]["hanging_elongation"]["curves"]
    assert [c["body"] for c in curves] == ["massspring", "fem", "hybrid"]  # one curve per body
    for c in curves:
        pts = sorted(c["dt_points"], key=lambda p: -p["dt"])  # coarse to fine
        errs = [p["error"] for p in pts]
        assert all(p["status"] == "ok" for p in pts) and all(e is not None for e in errs), c
        for a, b in zip(errs, errs[1:]):
            assert b <= a * (1 + WP_NOISE) + 1e-4, (c["body"], errs)
        assert errs[-1] < errs[0], (c["body"], errs)
        assert all(p["cpu_s_per_sim_s"] > 0 for p in pts)
    assert {p["resolution"] for p in curves[1]["resolution_points"]} == {2, 4}  # fem: both neighbours
    assert {p["resolution"] for p in curves[2]["resolution_points"]} == {4}     # hybrid: >= 3 nodes


REPORT_MATRIX = (toml_table("matrix", name="validation-report-test", seeds=[0])
                 + WORM_ON_A_CLIFF
                 + block(creatures=["snake"], bodies=["massspring"], gaits=["lateral-undulation"], scenarios=["flat"],
                         duration=1.0)
                 + block(creatures=["centipede"], bodies=["hybrid"], scenarios=["walk", "hang"], duration=1.2,
                         set_={"creature.segments": 6}))


def test_report_has_a_validation_section_and_a_verdict_next_to_every_paper_figure(tmp_path, work_precision, capsys):
    import re
    import shutil
    d = tmp_path / "m"
    f = tmp_path / "m.toml"
    f.write_text(REPORT_MATRIX)
    assert main(["matrix", str(f), "--out", str(d), "--workers", "1"]) == 0
    # verdicts: validate --out DIR puts validation.json into the matrix directory, next to the diagrams
    wp_dir, _ = work_precision
    for p in wp_dir.iterdir():
        shutil.copy(p, d / p.name)
    assert main(["validate", "--check", "analytic.rigid-rotation", "--no-store", "--out", str(d)]) == 0
    capsys.readouterr()
    assert main(["report", str(d)]) == 0
    page = (d / "index.html").read_text()
    assert '<section id="validation">' in page
    val = page[page.index('<section id="validation">'):]
    assert "analytic.rigid-rotation" in val and "PASS" in val
    assert "work_precision_hanging_elongation.png" in val and (d / "figures" / "work_precision_hanging_elongation.png").is_file()
    paper = page[page.index('<section id="paper">'):page.index('<section id="validation">')]
    blocks = re.split(r"<h3>", paper)[1:]
    # every paper figure carries a verdict; a figure shows its images, or links to the gait section's
    # diagram it would otherwise repeat (issue 14), so the walk's entry has a link, not an image
    figs = [b for b in blocks if "<img" in b or 'href="#gait"' in b]
    assert len(figs) >= 3  # cliff, walk, hang (and the snake where its images exist)
    for b in figs:
        m = re.search(r'<p class="verdict" data-verdict="([A-Z ]+)"', b)
        assert m, b[:300]
        first = b.index("<img") if "<img" in b else b.index('href="#gait"')
        assert b.index('class="verdict"') < first  # next to the caption, before the images
    verdicts = dict(re.findall(r"<h3>([^<]*)</h3>.*?data-verdict=\"([A-Z ]+)\"", paper, re.S))
    walk = next(v for k, v in verdicts.items() if "walk" in k)
    assert walk == NA  # a 1.2 s walk cannot show two complete cycles: says why instead of a false FAIL
    # a case that does not reproduce its figure says so in red
    assert all(('DOES NOT REPRODUCE' in b and "#b00000" in b) for b in figs if 'data-verdict="FAIL"' in b)
    md = (d / "summary.md").read_text()
    assert "## Validation" in md and "**Verdict:" in md


def test_hanging_bar_elongation_is_rho_g_l2_over_2e_piece_by_piece():
    import numpy as np

    from bench_myriapoda.validation.cross_body import bar_elongation

    L, E, A, rho, g = 2.0, 1000.0, 0.1, 3.0, 9.81
    s = np.linspace(0.0, L, 4001)
    m = np.full(s.size, rho * A * L / s.size)
    assert bar_elongation(s, m, np.array([0.0, L]), np.array([E * A]), 0.0, L, g) == pytest.approx(
        rho * g * L ** 2 / (2 * E), rel=1e-3)
    # a rigid top half stretches nothing: only the tension g m (> s) over the lower, elastic half counts
    half = bar_elongation(s, m, np.array([0.0, 1.0, L]), np.array([np.inf, E * A]), 0.0, L, g)
    assert half == pytest.approx(rho * g * 1.0 ** 2 / (2 * E), rel=1e-3)
    # one point mass M at the bottom of a massless elastic bar: M g L / (E A)
    assert bar_elongation(np.array([L]), np.array([2.0]), np.array([0.0, L]), np.array([E * A]), 0.0, L, g) == \
        pytest.approx(2.0 * g * L / (E * A))


def test_hanging_bar_reference_counts_each_bodys_own_masses():
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.validation.cross_body import hanging_bar_reference

    # hybrid centipede, 3 nodes per edge: 0.5 kg boxes, links 0.5 m of E A = 4000 x 0.5 N whose free
    # middle node layer carries half a link's 0.25 kg; link j (0 at the head) holds 17 - j boxes, 16 - j
    # links' free mass and half its own: g l / (E A) x sum_j (0.5 (17 - j) + 0.125 (16 - j) + 0.0625)
    by_hand = 9.81 * 0.5 / 2000.0 * (0.5 * 153 + 0.125 * 136 + 0.0625 * 17)
    bar, lower = hanging_bar_reference(resolve_case("centipede", "hybrid", "hang", None, duration=3.0))
    assert bar == pytest.approx(by_hand, rel=1e-3)
    assert lower == pytest.approx(1.4 * 0.2 / 0.6)  # E / M at nu = 0.4
    # at 5 nodes per edge three of four node layers are free: the links carry 3/4 of their mass
    bar5, _ = hanging_bar_reference(resolve_case("centipede", "hybrid", "hang", None, duration=3.0,
                                                 overrides=["body.resolution=5"]))
    assert bar5 == pytest.approx(9.81 * 0.5 / 2000.0 * (0.5 * 153 + 0.1875 * 136 + 0.09375 * 17), rel=1e-3)
    # fem: the whole 0.25 kg link mass, and blocks 20x stiffer: more than the hybrid's
    fem, _ = hanging_bar_reference(resolve_case("centipede", "fem", "hang", None, duration=3.0))
    assert fem > bar5 > bar
