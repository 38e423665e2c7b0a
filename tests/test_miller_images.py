"""Miller's Images 1 to 4 (reference/miller_images.py): one test per described behaviour, on the
suite's presets and the lattice (mass-spring) body, Miller's own model, except where noted.

Each run is made once per module and shared by its checks.  Checks that fail today because of
physics another part of issue 11 fixes are marked xfail (strict=False) with the reason.
"""
from __future__ import annotations

import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.reference import miller_images as MI

BODY = "massspring"
_RUNS: dict[tuple[str, str], tuple] = {}


def run(key: str, body: str = BODY):
    if (key, body) not in _RUNS:
        r = MI.RUNS[key]
        case = resolve_case(r.creature, body, r.scenario, r.gait, duration=r.duration_s, overrides=list(r.overrides))
        res = run_case(case)
        assert res.status == "ok", res.message
        _RUNS[key, body] = (res.series, res.case, res.metrics)
    return _RUNS[key, body]


def check(key: str, fn, body: str = BODY) -> MI.ImageCheck:
    c = fn(*run(key, body))
    assert c.passed, c.line()
    return c


def test_image_1a_worm_nose_slides_forward_on_impact():
    check("worm-book", MI.worm_nose_slides_forward)


def test_image_1b_worm_mostly_in_contact_after_landing():
    check("worm-book", MI.worm_mostly_in_contact)


def test_image_1c_worm_front_bends_down_over_the_edge():
    check("worm-book", MI.worm_front_bends_over_edge)


def test_image_1d_worm_slides_off_the_edge():
    check("worm-book", MI.worm_slides_off_edge)


def test_image_2b_snake_head_fixed_while_coils_form():
    check("snake-undulation", MI.snake_head_fixed_while_coils_form)


def test_image_2d_snake_segments_follow_one_path():
    check("snake-undulation", MI.snake_segments_follow_one_path)


def test_image_3a_sidewinder_contact_is_localised():
    check("sidewinder", MI.sidewinder_contact_localised)


def test_image_3d_sidewinder_travels_diagonally():
    check("sidewinder", MI.sidewinder_travels_diagonally)


def test_image_3_sidewinder_does_not_roll():
    check("sidewinder", MI.sidewinder_does_not_roll)


def test_image_4b_caterpillar_arches_its_back():
    check("caterpillar-arch", MI.caterpillar_arches)


def test_image_4_caterpillar_climbs_a_steep_slope():
    check("caterpillar-up", MI.caterpillar_on_steep_slope)


@pytest.mark.parametrize("body", ["massspring", "fem"])
def test_image_4_caterpillar_descends_a_steep_slope(body):
    # the lattice caterpillar used to stand its head cube on its front ventral edge, which Miller's
    # stick rule held, and somersault over it (let go at 11.7 s, roll 180 degrees); it now holds
    # only segments resting a face on the surface (bodies/massspring/kernels.py) -- issue 11
    check("caterpillar-down", MI.caterpillar_on_steep_slope, body=body)


def test_evaluate_runs_every_check_of_a_run_and_refuses_unknown_runs():
    series, case, metrics = run("caterpillar-arch")
    out = MI.evaluate("caterpillar-arch", series, case, metrics)
    assert [c.image for c in out] == ["4b"]
    with pytest.raises(ValueError):
        MI.evaluate("no-such-run", series, case, metrics)
