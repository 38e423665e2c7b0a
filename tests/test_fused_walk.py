"""The fused legged path (``bench_myriapoda.fused.legged_walk``) against the Python path it replaces.

The Python path (``harness.runner.Stepper`` sequencing ``MyriapodController.step``,
``apply_support`` and ``advance`` every step) is the reference.  The fused kernel runs the
same compiled kernels in the same order, consumes the same random streams and reproduces
numpy's summation order where a sum feeds a metric, so the tolerance stated and tested here
is zero: every state array is bit for bit equal after every chunk (and after every single step
in the per-step test), and so are the monitor's metrics and the controller's timeline.
"""
import numpy as np
import pytest

from bench_myriapoda.controllers.myriapod import compiled as CC
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import Creature


def pair(scenario, segments, *sets, body="hybrid"):
    case = resolve_case("centipede", body, scenario, overrides=[f"creature.segments={segments}", *sets])
    fused, ref = Creature(case, fused=True), Creature(case, fused=False)
    assert fused.stepper.fused is not None, fused.stepper.fused_reason
    assert ref.stepper.fused is None
    fused.compile()
    ref.compile()
    return case, fused, ref


def state(cr):
    """Every array the next step depends on, plus the controller's counters."""
    b, c = cr.body, cr.controller
    out = {"x": b.x, "xv": b.v, "acc": b.acc,
           "states": c.states, "angles": c.angles, "tips": c.tips, "airborne": c.airborne, "ik_failed": c.ik_failed,
           "c_T": c.c_T, "R_T": c.R_T, "brain_steps": c.brain_steps,
           "scalars": np.array([c.brain, c._step, c._turn_left, c._turn_memory, c._avoid_dir, c._avoid_until,
                                c.tracking_sq_sum, c.tracking_n, c.heading_cmd, c.heading_err_sum, c.heading_err_n,
                                c.leg_penetration_max, c.leg_stops, c.leg_stuck, c.t_walk, c.recorded,
                                c.wall_pushes], float),
           "rng": c.rng.bit_generator.state["state"]["state"],
           "act_R": cr.stepper.act.support_R, "act_c": cr.stepper.act.support_c,
           "act_kin": cr.stepper.act.support_kinematic}
    if hasattr(b, "rigid"):
        out.update(c=b.rigid.c, q=b.rigid.q, v=b.rigid.v, w=b.rigid.w, kin=b.rigid.kinematic,
                   impulse=b.rigid.impulse_cache)
    if hasattr(b, "fem"):
        out["q_ws"] = b.fem.q_ws
    if hasattr(b, "att_target"):
        out.update(att_target=b.att_target, support=b.support)
    if c.antennae is not None:
        a = c.antennae
        out.update(ant_points=a.points, ant_target=a.root_target, ant_offsets=a.offsets, ant_contact=a.contact,
                   ant_counts=np.array([a.contact_events, a.targets_drawn]),
                   ant_rng=a.rng.bit_generator.state["state"]["state"])
    return out


def assert_same(a, b, where):
    sa, sb = state(a), state(b)
    for k in sa:
        x, y = np.asarray(sa[k]), np.asarray(sb[k])
        assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), \
            f"{where}: {k} differs by {np.nanmax(np.abs(x.astype(float) - y.astype(float)))}"


def walk_both(case, fused, ref, chunks):
    """Advance both in the given chunks (continuing where they stand); returns the steps done in all."""
    done = fused.stepper.step_index
    t = done * case.dt
    for n in chunks:
        ka = fused.advance(t, n)
        kb = ref.advance(t, n)
        assert ka == kb == (n, 0)
        done += n
        t = done * case.dt
        assert_same(fused, ref, f"after {done} steps")
    return done


def assert_same_record(fused, ref):
    cf, cr = fused.controller, ref.controller
    for a, b in zip(cf.timeline(), cr.timeline()):
        assert np.array_equal(a, b)
    assert np.array_equal(cf.brain_timeline(), cr.brain_timeline())
    assert np.array_equal(cf.contact_timeline(), cr.contact_timeline())
    assert np.array_equal(np.stack(cf.timeline_centers), np.stack(cr.timeline_centers))
    assert np.array_equal(np.array(fused.monitor._com), np.array(ref.monitor._com))
    mf, mr = fused.monitor.metrics(), ref.monitor.metrics()
    assert mf.keys() == mr.keys()
    for k in mf:
        assert mf[k] == mr[k] or (np.isnan(mf[k]) and np.isnan(mr[k])), (k, mf[k], mr[k])
    of, orf = fused.body.observe(1.0), ref.body.observe(1.0)
    for k in ("segment_centers", "com", "head", "tail", "energy", "seg_contact"):
        assert np.array_equal(getattr(of, k), getattr(orf, k)), k


@pytest.fixture(scope="module")
def walking_pair():
    """The benchmark case: the 18-segment centipede on the walk scenario."""
    return pair("walk", 18)


def test_fused_equals_python_every_step_at_the_start(walking_pair):
    case, fused, ref = walking_pair
    walk_both(case, fused, ref, [1] * 150)  # one step per call: equal after every single step


def test_fused_equals_python_over_two_seconds_of_walking(walking_pair):
    # chunk sizes of the runner (50 steps at 60 Hz) and odd ones, so chunk ends fall anywhere in the
    # timeline's record period; ADJUSTMENT ends at about 0.41 s, then RANDOM-WALK with new random turns
    case, fused, ref = walking_pair
    done = walk_both(case, fused, ref, [50] * 60 + [7, 13, 993, 1, 3000])
    assert done * case.dt >= 2.0 + 150 * case.dt - 1e-9
    c = fused.controller
    assert np.isfinite(c.t_walk) and c.brain == 3  # RANDOM-WALK
    assert c.brain_steps[0] > 0 and c.brain_steps[3] > 0
    assert c.antennae.targets_drawn > 2            # the antennae's random targets were redrawn on the way
    assert_same_record(fused, ref)


@pytest.mark.parametrize("scenario", ["control", "fig13-cylinders", "drop-adjust"])
def test_fused_equals_python_in_other_scenarios(scenario):
    # CONTROL brain mode and its heading error; low cylinders (obstacle queries of the antennae, the
    # leg collisions and the Balancer's walkable terrain); a drop into ADJUSTMENT
    case, fused, ref = pair(scenario, 6)
    walk_both(case, fused, ref, [50] * 50)
    assert_same_record(fused, ref)


def test_fused_equals_python_without_antennae_and_leg_collisions():
    case, fused, ref = pair("walk", 6, "antennae.enabled=false", "legs.collide=false")
    assert fused.controller.antennae is None
    walk_both(case, fused, ref, [50] * 40)
    assert_same_record(fused, ref)


def test_fused_equals_python_while_carried_segments_are_pushed_out_of_a_wall():
    # test_foraging's blind walk past a tall cylinder: from about 3.5 s the carried segments meet it
    # (targeter.keep_clear_of_walls); 4.5 s in chunks of the runner's 50 steps and odd ones
    case, fused, ref = pair("walk", 6, "antennae.enabled=false", "controller.random_turn_max_deg=0",
                            "scenario.obstacle_cylinder_list=[4.0, 0.9, 0.6, 3.0]")
    walk_both(case, fused, ref, [50] * 200 + [7, 13, 993, 1, 2486])
    assert fused.controller.wall_pushes > 100
    assert_same_record(fused, ref)


@pytest.mark.parametrize("sets, reason", [(["controller.body_wave_amplitude=0.2"], "body wave"),
                                          (["food.count=3"], "food")])
def test_cases_that_are_not_fused_keep_the_python_path(sets, reason):
    case = resolve_case("centipede", "hybrid", "walk", overrides=["creature.segments=6", *sets])
    cr = Creature(case)
    assert cr.stepper.fused is None
    assert reason in cr.stepper.fused_reason


def test_fused_equals_python_on_the_massspring_centipede():
    case, fused, ref = pair("walk", 18, body="massspring")
    walk_both(case, fused, ref, [50] * 45 + [7, 993, 1, 2000])   # 2.3 s: ADJUSTMENT, then RANDOM-WALK
    assert fused.controller.brain == 3 and fused.controller.brain_steps[0] > 0
    assert_same_record(fused, ref)


def test_fused_equals_python_on_the_fem_centipede():
    case, fused, ref = pair("walk", 18, body="fem")
    walk_both(case, fused, ref, [50] * 30 + [7, 13, 480, 1, 1500])   # 1.5 s: ADJUSTMENT, then RANDOM-WALK
    assert fused.controller.brain == 3 and fused.controller.brain_steps[0] > 0
    assert np.array_equal(fused.body.att_target, ref.body.att_target)
    assert np.array_equal(fused.body.support, ref.body.support)
    assert_same_record(fused, ref)


def test_a_controller_of_another_class_keeps_the_python_path():
    from bench_myriapoda.controllers.myriapod.controller import MyriapodController

    class Tweaked(MyriapodController):
        pass

    case = resolve_case("centipede", "hybrid", "walk", overrides=["creature.segments=6"])
    cr = Creature(case, controller=Tweaked(case))
    assert cr.stepper.fused is None and "has no compiled step" in cr.stepper.fused_reason


def test_numpys_einsum_order_that_the_fem_support_reproduces():
    # fused.legged_walk.fem_chunk adds the products of BodyFEMChain.set_support's einsums in numpy's order
    rng = np.random.default_rng(0)
    R, d = rng.normal(size=(50, 3, 3)), rng.normal(size=(50, 3))
    a = [R[:, j, :] * d[:, j, None] for j in range(3)]
    assert np.array_equal(np.einsum("nji,nj->ni", R, d), (a[0] + a[1]) + a[2])
    a = [R[:, :, j] * d[:, j, None] for j in range(3)]
    assert np.array_equal(np.einsum("nij,nj->ni", R, d), (a[0] + a[2]) + a[1])


@pytest.mark.parametrize("n", [0, 1, 7, 8, 9, 18, 127, 128, 129, 200, 300, 1000, 5000])
def test_numpy_sum_reproduces_numpys_order(n):
    a = np.random.default_rng(n).normal(size=n) * np.random.default_rng(n + 1).uniform(0.0, 1e6, size=n)
    assert CC.numpy_sum(a, n) == a.sum()


@pytest.mark.parametrize("terrain_none", [False, True])
def test_the_chunk_replay_samples_equal_per_sample_calls(terrain_none):
    # fused.legged_walk replays a chunk's timeline samples with LeggedMonitor.sample_many: the same
    # doubles as one sample() per row (centre of mass, clearance, head path), on random poses
    from types import SimpleNamespace

    from bench_myriapoda.harness.legged import LeggedMonitor
    from bench_myriapoda.metrics.behaviour import BehaviourSampler
    from bench_myriapoda.world import terrain_kernels as T

    rng = np.random.default_rng(3)
    f = np.zeros(T.N_TERRAIN_PARAMS)
    for n_seg in (1, 6, 18, 57):
        k, n_legs = 13, 2 * n_seg
        c = rng.normal(size=(k, n_seg, 3)) * rng.uniform(0.1, 30.0)
        R = rng.normal(size=(k, n_seg, 3, 3))
        centres = rng.normal(size=(k, 2 * n_seg - 1, 3)) * 3.0
        tips = rng.normal(size=(k, n_legs, 3))
        mons = []
        for _ in range(2):
            m = LeggedMonitor.__new__(LeggedMonitor)
            m.body = SimpleNamespace(segment_half_extents=np.full((n_seg, 3), 0.5))
            m._com = []
            m.behaviour = BehaviourSampler(T.PLANE, f, terrain_none)
            mons.append(m)
        one, many = mons
        for r in range(k):
            one.sample(c[r], R[r], centres[r], tips[r])
        many.sample_many(c[:5], R[:5], centres[:5], tips[:5])  # two chunks: the path continues across them
        many.sample_many(c[5:], R[5:], centres[5:], tips[5:])
        assert np.array_equal(np.array(one._com), np.array(many._com))
        a, b = one.behaviour.metrics(), many.behaviour.metrics()
        assert a["path_length_m"] == b["path_length_m"] and a["path_length_m"] > 0
        assert np.array_equal(a["terrain_clearance_min_m"], b["terrain_clearance_min_m"], equal_nan=True)
