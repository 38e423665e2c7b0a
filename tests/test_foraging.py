"""Food and obstacles (paper Sec. 4.3, 5.2, 6.2): TROPHOTROPISM reaches food, AVOIDANCE keeps the body out of
random cylinders.

The centipede is built at the paper's scale (1 m segments, 0.5 m links, legs reaching 2.6 m to the side of the
midline) and walks at about 1 m/s on the hybrid body.
"""
import math

import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.world.food import FoodField, food_sources

FOOD_TIME_LIMIT_S = 6.0   # ~0.5 s ADJUSTMENT + 3.6 m of walking and turning at 1 m/s; measured 3.5-3.9 s
BODY_PENETRATION_LIMIT_M = 0.05


def run(scenario, duration, *sets, creature="centipede", seed=0):
    case = resolve_case(creature, "hybrid", scenario, duration=duration, seed=seed, overrides=list(sets))
    r = run_case(case)
    assert r.status == "ok", r.message
    return r


def heading_change(r):
    """Heading change [rad] of the head from the start to the end, + = left (from the head's end face)."""
    s = r.series
    d0 = s.head[0] - s.segment_centers[0, 0]
    d1 = s.head[-1] - s.segment_centers[-1, 0]
    a0, a1 = math.atan2(-d0[2], d0[0]), math.atan2(-d1[2], d1[0])
    return (a1 - a0 + math.pi) % (2 * math.pi) - math.pi


# --------------------------------------------------------------------------- food

def test_food_signal_falls_off_with_the_squared_distance_and_eaten_food_is_gone():
    food = FoodField(np.array([[0.0, 0.0, 0.0, 2.0], [10.0, 0.0, 0.0, 1.0]]), softening_m=0.1, reach_radius_m=1.0)
    s = food.signals(np.array([[2.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 0.0, 0.05]]))
    np.testing.assert_allclose(s[:2], [2.0 / 4 + 1.0 / 64, 2.0 / 16 + 1.0 / 36])
    assert s[2] == pytest.approx(2.0 / 0.01 + 1.0 / 100.0)          # softened at the source
    # eaten within the reach in the head's x-z plane, whatever the head's height above it
    assert food.eat(np.array([10.5, 1.5, 0.5]), np.eye(3), 3.0) == 1
    assert food.n_left == 1 and food.metrics()["time_to_first_food_s"] == 3.0
    np.testing.assert_allclose(food.signals(np.array([[4.0, 0.0, 0.0]])), [2.0 / 16])
    assert food.eat(np.array([5.0, 1.0, 0.0]), np.eye(3), 4.0) == 0


def test_random_food_is_seeded_and_keeps_clear_of_the_start_and_the_obstacles():
    case = resolve_case("centipede", "hybrid", "foraging")
    a = food_sources(case.scenario, case.food)
    b = food_sources(case.scenario, case.food)
    np.testing.assert_array_equal(a, b)
    assert len(a) == case.food.count
    assert np.all(np.hypot(a[:, 0], a[:, 2]) >= case.food.clear_radius_m)
    from bench_myriapoda.world.terrain import terrain_from_scenario
    from bench_myriapoda.world.terrain_kernels import obstacles_phi
    _, f = terrain_from_scenario(case.scenario)
    assert min(obstacles_phi(f, *p[:3])[0] for p in a) >= case.food.obstacle_clearance_m
    other = resolve_case("centipede", "hybrid", "foraging", overrides=["food.seed=1"])
    assert not np.allclose(food_sources(other.scenario, other.food), a)


@pytest.mark.parametrize("side", [2.0, -2.0], ids=["right", "left"])
def test_centipede_reaches_food_ahead_and_to_the_side(side):
    # the full 18-segment centipede walking straight (RANDOM-WALK without random turns, so that only its food
    # sense can steer it); food 3 m ahead of the head's front and 2 m to the side (z > 0: right)
    food = f"food.sources=[3.0, 0.0, {side}, 1.0]"
    r = run("walk", 8.0, food, "controller.random_turn_max_deg=0")
    m = r.metrics
    assert m["food_reached"] == 1
    assert m["time_to_first_food_s"] <= FOOD_TIME_LIMIT_S, m["time_to_first_food_s"]
    assert m["brain_trophotropism_fraction"] > 0.1
    # it turned toward the food: right (heading decreases) for food on the right
    assert heading_change(r) * side < 0
    # without its food sense it walks straight past
    blind = run("walk", 8.0, food, "controller.random_turn_max_deg=0", "food.threshold=1e9")
    assert blind.metrics["food_reached"] == 0 and math.isnan(blind.metrics["time_to_first_food_s"])


# --------------------------------------------------------------------------- obstacles

@pytest.mark.parametrize("seed", [0, 1, 2])
def test_among_random_cylinders_the_body_stays_out_of_them(seed):
    """25 tall random cylinders (radius 0.3-0.6 m) in a 30 m x 24 m field ahead, random food beyond and among
    them; a 6-segment centipede (8.5 m) forages for 25 s.

    Stated depth: the body -- segment centres and the rigid boxes' corners -- never gets deeper than 5 cm into an
    obstacle (measured: 0 for seeds 1-9, 1.4e-5 m for seed 0).  5 cm is the hybrid body's own deep-penetration
    limit (``stability.max_penetration_m``) and a tenth of the boxes' half width.  The body stays out because the
    antennae (3.6 m long, sweeping -10..60 degrees from the axis: 3.4 m to the side and 3.9 m ahead of the
    head's front) make the head turn away before it gets there, the body following the head's path, and,
    where a Follower's cut of a turn brings a carried segment against a cylinder all the same, because the
    Targeter moves it out (``targeter.keep_clear_of_walls``; seed 0 brushes one with 1,348 push-outs).
    The leg tips are not bounded: legs are kinematic, and a leg that brushes a cylinder the antennae happened
    not to touch (its surface within the legs' 2.6 m reach from the midline) swings into it up to the
    cylinder's radius (measured: up to 0.45 m); ``obstacle_penetration_max_m`` reports them with the body.
    """
    r = run("foraging", 25.0, "creature.segments=6", "scenario.obstacle_cylinders=25",
            "scenario.obstacle_region_m=[5.0, 35.0, -12.0, 12.0]", "scenario.obstacle_radius_m=[0.3, 0.6]",
            f"scenario.terrain_seed={seed}", f"food.seed={seed}", seed=seed)
    m = r.metrics
    assert m["obstacle_contacts"] >= 3 and m["brain_avoidance_fraction"] > 0.02   # it met the cylinders
    assert m["obstacle_penetration_body_max_m"] <= BODY_PENETRATION_LIMIT_M, m["obstacle_penetration_body_max_m"]
    assert m["obstacle_penetration_max_m"] >= m["obstacle_penetration_body_max_m"]
    assert m["obstacle_penetration_max_m"] <= 0.6 + 1e-9                           # no deeper than a radius
    assert m["terrain_clearance_min_m"] > 0.3                                      # centres above the ground
    assert m["path_length_m"] > 15.0                                               # and it kept walking


@pytest.mark.parametrize("body", ["hybrid", "massspring", "fem"])
def test_a_carried_body_walking_blind_into_a_wall_slides_past_it(body):
    """No antennae and no turns: the 6-segment centipede walks straight along +x past a tall cylinder (radius 0.6 m,
    3 m high) whose edge reaches 0.2 m into the path of its right side.  Nothing turns it away, so its carried
    segments meet the wall; the Targeter moves them out along the wall's normal (``targeter.keep_clear_of_walls``)
    and the body slides past.  Before that, carried segments had no collision with obstacles: the hybrid and
    mass-spring bodies ended ``unstable`` (a box corner 5 cm deep) at 4.0-4.2 s, and the FEM body ended 0.36 m
    inside the cylinder.  Measured with the push-outs: body depth 3e-16 m (hybrid), 1e-5 m (mass-spring), 1.2 cm
    (FEM: its segments are deformable blocks, only their targets are moved)."""
    case = resolve_case("centipede", body, "walk", duration=8.0,
                        overrides=["creature.segments=6", "antennae.enabled=false", "controller.random_turn_max_deg=0",
                                   "scenario.obstacle_cylinder_list=[4.0, 0.9, 0.6, 3.0]"])
    r = run_case(case)
    assert r.status == "ok", r.message
    m = r.metrics
    assert m["wall_pushes"] > 100                                                   # it met the wall
    assert m["obstacle_penetration_body_max_m"] <= BODY_PENETRATION_LIMIT_M / 2, m["obstacle_penetration_body_max_m"]
    assert r.series.head[-1][0] > 5.0                                               # and walked on past it
