"""The obstacle grid of terrain_kernels (issue 16): exact against the loop, cost independent of the count.

``obstacles_below`` answers through a uniform x-z grid built once per terrain by
``with_obstacles``; ``obstacles_below_brute`` is the loop over every record it
replaced.  The grid must give the loop's (phi, record) bit for bit -- ties
included -- for points inside and outside obstacles, outside the grid, and for
any cutoff; and the number of records a query examines (a counter, not a timer)
must stay flat from 10 to 1,000 obstacles at the density of Fig. 13 while the
loop's grows with the count.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from bench_myriapoda.world import terrain_kernels as TK

FIG13_DENSITY = 120 / 30.0 ** 2       # cylinders per m^2: 120 in the 30 m x 30 m region of fig13-cylinders
EXAMINED_GROWTH_MAX = 1.5             # mean records examined at 1,000 / at 10 obstacles (seen: 1.18)
EXAMINED_MEAN_MAX = 12.0              # mean records examined per ground query at any count (seen: 3.2-3.8)


def random_obstacles(n: int, half: float, seed: int, boxes: bool = True) -> np.ndarray:
    """f of a plane with n random cylinders (and boxes) in |x|, |z| <= half [m]."""
    rng = np.random.default_rng(seed)
    recs = []
    for _ in range(n):
        if boxes and rng.random() < 0.3:
            recs.append(TK.box_record(rng.uniform(-half, half), rng.uniform(0, 1), rng.uniform(-half, half),
                                      *rng.uniform(0.1, 1.0, 3), rng.uniform(0, 2 * math.pi)))
        else:
            recs.append(TK.cylinder_record(rng.uniform(-half, half), rng.uniform(-half, half),
                                           rng.uniform(0.3, 0.8), -1.0, rng.uniform(0.1, 3.0)))
    return TK.with_obstacles(TK.header(0.0), recs)


@pytest.mark.parametrize("n", [1, 7, 60, 400])
def test_grid_query_equals_the_loop_bit_for_bit(n):
    f = random_obstacles(n, 12.0, seed=n)
    rng = np.random.default_rng(100 + n)
    # inside and far outside the grid, below and above the obstacles' tops
    p = np.column_stack([rng.uniform(-30, 30, 4000), rng.uniform(-1.5, 4.0, 4000), rng.uniform(-30, 30, 4000)])
    for x, y, z in p:
        for best in (math.inf, y, 0.25, -0.05, 1e9):
            assert TK.obstacles_below(f, x, y, z, best) == TK.obstacles_below_brute(f, x, y, z, best), (x, y, z, best)


def test_ties_go_to_the_lowest_record_as_in_the_loop():
    # the same cylinder three times and a box exactly as far: the loop keeps the first
    cyl = TK.cylinder_record(1.0, 0.0, 0.5, 0.0, 1.0)
    f = TK.with_obstacles(TK.header(-5.0), [TK.box_record(5.0, 0.5, 0.0, 0.5, 0.5, 0.5), cyl, cyl, cyl])
    for x, y, z in [(1.0, 2.0, 0.0), (2.0, 0.5, 0.0), (1.0, 0.5, 0.0), (3.0, 0.5, 0.0)]:
        for best in (math.inf, 0.5, 1.0):
            assert TK.obstacles_below(f, x, y, z, best) == TK.obstacles_below_brute(f, x, y, z, best)


def test_scenario_terrain_queries_go_through_the_grid_unchanged():
    """signed_distance / surface_normal on a cylinder-paved plane equal a grid-less evaluation."""
    f = random_obstacles(120, 15.0, seed=3, boxes=False)
    rng = np.random.default_rng(4)
    for x, y, z in np.column_stack([rng.uniform(-20, 20, 3000), rng.uniform(-0.5, 2.0, 3000),
                                    rng.uniform(-20, 20, 3000)]):
        d, _ = TK.obstacles_below_brute(f, x, y, z, y)
        assert TK.signed_distance(TK.PLANE, f, x, y, z) == d


def mean_examined(n: int, seed: int = 1) -> tuple[float, float]:
    """(grid, loop) mean records examined per ground query among n cylinders at Fig. 13's density.

    Queries as the bodies and legs make them: points 0-1.5 m above the ground, cutoff
    = the ground's phi, uniform over the central half of the paved square (so that the
    small scenes are not mostly border).
    """
    half = 0.5 * math.sqrt(n / FIG13_DENSITY)
    f = random_obstacles(n, half, seed, boxes=False)
    rng = np.random.default_rng(seed)
    m = 5000
    p = np.column_stack([rng.uniform(-half / 2, half / 2, m), rng.uniform(0.0, 1.5, m),
                         rng.uniform(-half / 2, half / 2, m)])
    grid = np.mean([TK.obstacles_below_counted(f, x, y, z, y)[2] for x, y, z in p])
    return float(grid), float(n)  # the loop examines every record


def test_records_examined_per_query_do_not_grow_with_the_obstacle_count():
    counts = {n: mean_examined(n) for n in (10, 100, 1000)}
    print({n: round(g, 2) for n, (g, _) in counts.items()})
    for n, (grid, loop) in counts.items():
        assert grid <= EXAMINED_MEAN_MAX, (n, grid)
    assert counts[1000][0] <= EXAMINED_GROWTH_MAX * counts[10][0]
    assert counts[1000][1] == 100 * counts[10][1]  # the loop: 100x the work for 100x the obstacles


def test_grid_of_a_single_obstacle_and_of_far_apart_obstacles_stays_small():
    f = TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(0.0, 0.0, 0.5, -1.0, 1.0),
                                           TK.cylinder_record(1e4, 1e4, 0.5, -1.0, 1.0)])
    g = int(f[TK.H_OBST]) + 2 * TK.OBST_STRIDE
    # the footprints' square in at most GRID_MIN_CELLS cells, plus the reach around it
    assert f[g + 4] * f[g + 5] <= (math.sqrt(TK.GRID_MIN_CELLS) + 2 * TK.GRID_REACH_CELLS + 1) ** 2
    assert TK.obstacles_below(f, 1e4, 0.5, 1e4 + 0.6, 1.0) == TK.obstacles_below_brute(f, 1e4, 0.5, 1e4 + 0.6, 1.0)


@pytest.mark.parametrize("n", [1, 30, 300])
def test_obstacles_within_a_radius_equal_the_loop_in_record_order(n):
    """The antennae's near list (``obstacles_within``) through the grid: the loop's set, in record order."""
    f = random_obstacles(n, 10.0, seed=7 + n)
    off = int(f[TK.H_OBST])
    rng = np.random.default_rng(n)
    out = np.empty(n, dtype=np.int64)
    for x, y, z in np.column_stack([rng.uniform(-15, 15, 500), rng.uniform(-1, 4, 500), rng.uniform(-15, 15, 500)]):
        for radius in (0.0, 0.5, 3.0, 12.0):
            want = [off + TK.OBST_STRIDE * k for k in range(n)
                    if TK._obstacle_phi(f, off + TK.OBST_STRIDE * k, x, y, z) < radius]
            m = TK.obstacles_within(f, x, y, z, radius, out)
            assert list(out[:m]) == want


def threshold_scene(n: int, seed: int, m: int):
    """(f, hf, p) for the threshold queries' tests: n random obstacles on a plane (f) and the same on a height
    field (hf, whose base phi is not the plane's), and m points (m, 3) [m] inside and outside the grid, inside
    obstacles, a quarter exactly at and just off the obstacles' tops, the first three with a NaN coordinate."""
    f = random_obstacles(n, 12.0, seed=n)
    hf = TK.with_obstacles(TK.heightfield_params(0.0, [[0.0, 0.0], [5.0, -3.0]], [0.5, -0.3], [2.0, 3.0]),
                           TK.obstacle_records(f))
    rng = np.random.default_rng(seed)
    p = np.column_stack([rng.uniform(-30, 30, m), rng.uniform(-1.5, 4.0, m), rng.uniform(-30, 30, m)])
    tops = TK.obstacle_records(f)[:, 5]
    p[: m // 4, 1] = rng.choice(tops, m // 4) + rng.choice([0.0, 1e-12, -1e-12, 0.01, 0.3], m // 4)
    p[:3] = [[np.nan, 0.5, 0.0], [0.0, np.nan, 0.0], [0.0, 0.5, np.nan]]
    return f, hf, p


@pytest.mark.parametrize("n", [1, 7, 60, 400])
def test_threshold_query_equals_the_full_query(n):
    """``distance_at_least(p, d)`` is ``signed_distance(p) >= d`` for every p and d (issue 30): inside and
    outside the grid, inside obstacles, exactly at and just off the obstacles' tops, NaN, on a plane and on a
    height field (its base phi is not the plane's)."""
    f, hf, p = threshold_scene(n, 200 + n, 3000)
    for kind, terr in ((TK.PLANE, f), (TK.HEIGHTFIELD, hf)):
        for x, y, z in p:
            for d in (0.0, 0.01, -0.002, 0.3, 1.0, -0.5, 50.0):
                assert TK.distance_at_least(kind, terr, x, y, z, d) == (TK.signed_distance(kind, terr, x, y, z) >= d), \
                    (kind, x, y, z, d)


@pytest.mark.parametrize("n", [1, 60, 400])
def test_clearance_and_distance_with_normal_answer_as_the_full_queries(n):
    """The hot loops' forms of the queries (issue 30) give the full queries' answers: ``clearance`` (a loop's
    terrain scalars read once by ``clearance_view``) is ``distance_at_least`` wherever it answers (1 or 0), and
    answers on the plane without obstacles always; ``distance_and_normal`` is (``signed_distance``,
    *``surface_normal``) to the bit, on planes with and without obstacles, a slope and a height field with
    obstacles, inside and outside the grid, at and just off the obstacles' tops, NaN."""
    m = 2000
    f, hf, p = threshold_scene(n, 300 + n, m)
    for kind, terr in ((TK.PLANE, f), (TK.HEIGHTFIELD, hf), (TK.PLANE, TK.header(0.3)),
                       (TK.SLOPE, TK.header(0.1, 0.2))):
        V = TK.clearance_view(kind, terr)
        answered = 0
        for x, y, z in p:
            for d in (0.0, 0.01, -0.002, 0.3, 50.0):
                k = TK.clearance_cell(V, x, z, d)
                c = TK.clearance(V, terr[k] if k >= 0 else 0.0, y, d, k)
                if c != TK.CLEAR_UNKNOWN:
                    assert (c == 1) == TK.distance_at_least(kind, terr, x, y, z, d), (kind, x, y, z, d)
                    answered += 1
            want = np.array([TK.signed_distance(kind, terr, x, y, z), *TK.surface_normal(kind, terr, x, y, z)])
            got = np.array(TK.distance_and_normal(kind, terr, x, y, z))
            assert want.tobytes() == got.tobytes(), (kind, x, y, z)
        if kind == TK.PLANE and terr[TK.H_NOBST] == 0.0:
            assert answered == 5 * m
        elif kind == TK.PLANE:
            assert answered > 0


def test_threshold_query_skips_the_search_above_low_obstacles():
    """The cell tops answer a body node's contact test without the search: points 0.65-1.1 m up (the walking
    centipede's underside and nodes) among Fig. 13's cylinders (at most 0.4 m high), every one of them."""
    half = 0.5 * math.sqrt(120 / FIG13_DENSITY)
    rng = np.random.default_rng(5)
    recs = [TK.cylinder_record(rng.uniform(-half, half), rng.uniform(-half, half), rng.uniform(0.3, 0.8), -1.0,
                               rng.uniform(0.1, 0.4)) for _ in range(120)]
    f = TK.with_obstacles(TK.header(0.0), recs)
    p = np.column_stack([rng.uniform(-half, half, 2000), rng.uniform(0.65, 1.1, 2000), rng.uniform(-half, half, 2000)])
    clear = [TK._obstacles_clear(f, x, y, z, 0.01) for x, y, z in p]
    assert all(clear)
    # and near the ground, where the search is needed, it does not claim clearance it cannot show
    low = [TK._obstacles_clear(f, x, 0.05, z, 0.01) for x, _, z in p]
    assert not all(low)
