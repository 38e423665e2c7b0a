"""Issue 43's dynamic-stance sweeps (docs/explanation/stance-sweeps.md): the three matrix files, the figures and
the definitions of a coordinated walk and of the speed at which straight walking is lost
(``report/stance_sweeps.py``), and a body's yaw stiffness deciding its undulation under the dynamic stance at the
stance's defaults (the Follower's speed feedforward on)."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bench_myriapoda.harness.matrix import expand_matrix
from bench_myriapoda.report import stance_sweeps as S

ROOT = Path(__file__).resolve().parents[1]
MATRICES = ROOT / "scenarios" / "matrix"


@pytest.mark.parametrize("name, axis", [("stance-stiffness", "controller.swing_speed_rad_s"),
                                        ("stance-speed", "scenario.control_speed_m_s"),
                                        ("stance-body-wave", "controller.body_wave_phase_rad")])
def test_each_sweep_matrix_runs_the_dynamic_stance_on_hybrid_and_massspring(name, axis):
    exp = expand_matrix(MATRICES / f"{name}.toml")
    assert not exp.unsupported and axis in exp.grid_keys
    assert {c.case.body.name for c in exp.cases} == {"hybrid", "massspring"}
    assert all(c.case.legs.stance == "dynamic" and c.case.creature.name == "centipede" for c in exp.cases)
    assert len({json.dumps(c.axes.get(axis)) for c in exp.cases} - {"null"}) >= 3
    if name != "stance-body-wave":  # sweeps a and b cross the axis with each body's link stiffness
        for body, key in (("hybrid", "body.youngs_modulus_pa"), ("massspring", "body.link_stiffness_n_m")):
            assert len({c.axes.get(key) for c in exp.cases if c.case.body.name == body}) >= 3
    assert len(exp.cases) <= 32  # minutes on two cores: the docs state each sweep's size and runtime


def _case_json(head=0.5, control=0.5, wave="retrograde"):
    return json.dumps({"controller": {"head_speed_m_s": head, "wave_direction": wave},
                       "scenario": {"brain": "control", "control_speed_m_s": [control]}})


# each body's stiffness key in the shipped sweeps (the report reads it from the grid, naming no body)
STIFFNESS_KEYS = {"hybrid": "body.youngs_modulus_pa", "fem": "body.youngs_modulus_pa",
                  "massspring": "body.link_stiffness_n_m"}


def _frame(rows):
    """Matrix rows (``report.matrix_data``'s columns) from dicts of body, stiffness, x, metrics, status."""
    out = []
    for r in rows:
        key = STIFFNESS_KEYS[r["body"]]
        out.append({"creature": "centipede", "body": r["body"], "status": r.get("status", "ok"),
                    f"grid.{key}": r["k"], "case_json": _case_json(control=r.get("v", 0.5), wave=r.get("wave", "retrograde")),
                    f"grid.{S.SWING_KEY}": r.get("swing", 4.0), f"grid.{S.SPEED_KEY}": [r.get("v", 0.5)],
                    "metric.body_speed_ratio": r.get("ratio", 1.0) * r.get("v", 0.5) / 0.5,
                    "metric.stepping_leg_fraction": r.get("legs", 1.0),
                    "metric.phase_lag_mean": r.get("lag", 0.1),
                    "metric.stance_slide_fraction": r.get("slide", 0.1),
                    "metric.undulation_amplitude_bl": r.get("und", 0.001),
                    "metric.head_yaw_osc_deg": r.get("yaw", 0.2),
                    "metric.stride_frequency_hz": r.get("f", 0.5),
                    "metric.speed_bl_per_stride": r.get("sps", 0.1),
                    "metric.cost_of_transport": r.get("cot", 0.3)})
    return pd.DataFrame(out)


def test_a_walk_is_coordinated_only_at_speed_with_its_legs_walking_and_its_feet_gripping():
    df = _frame([dict(body="hybrid", k=1000.0),                        # coordinated
                 dict(body="hybrid", k=1000.0, ratio=0.85),            # left behind
                 dict(body="hybrid", k=1000.0, ratio=1.15),            # overtaking its head
                 dict(body="hybrid", k=1000.0, legs=0.8),              # some legs stopped stepping
                 dict(body="hybrid", k=1000.0, lag=-0.1),              # the retrograde leg wave turned direct
                 dict(body="hybrid", k=1000.0, lag=-0.1, wave="direct"),  # a direct wave, as commanded
                 dict(body="hybrid", k=1000.0, slide=0.3),             # feet sliding
                 dict(body="hybrid", k=1000.0, status="unstable"),     # blew up
                 dict(body="hybrid", k=1000.0, v=2.0, ratio=0.95)])    # fast and on pace
    assert S.coordinated(df).tolist() == [True, False, False, False, False, True, False, False, True]
    # body_speed_ratio divides by controller.head_speed_m_s; the sweep's speed is the CONTROL schedule's
    assert S.speed_ratio(df).iloc[-1] == pytest.approx(0.95)
    assert S.commanded_speed(df).tolist() == [0.5] * 8 + [2.0]


def test_the_critical_speed_is_the_lowest_at_which_straight_walking_is_lost():
    rows = []
    for v in (0.25, 0.5, 1.0, 2.0):
        rows.append(dict(body="hybrid", k=250.0, v=v, und=0.02 if v >= 1.0 else 0.002))   # undulates from 1 m/s
        rows.append(dict(body="hybrid", k=4000.0, v=v, ratio=0.8 if v >= 2.0 else 1.0))    # falls behind at 2 m/s
        rows.append(dict(body="massspring", k=600.0, v=v))                                  # holds everywhere
    crit = S.critical_speeds(_frame(rows)).set_index(["body", "stiffness"])["critical_speed_m_s"]
    assert crit[("hybrid", 250.0)] == 1.0 and crit[("hybrid", 4000.0)] == 2.0
    assert math.isnan(crit[("massspring", 600.0)])


@pytest.mark.parametrize("sweep", ["stiffness", "speed", "body-wave"])
def test_each_sweep_figure_is_drawn_with_its_table(tmp_path, sweep):
    rows = [dict(body=b, k=k, swing=s, v=s / 4.0, f=0.3 + 0.05 * s, und=1e-3 * s, legs=0.9 if s < 8 else 0.5)
            for b, ks in (("hybrid", (250.0, 4000.0)), ("massspring", (150.0, 600.0))) for k in ks
            for s in (2.0, 4.0, 8.0)]
    df = _frame(rows)
    if sweep == "body-wave":
        df["grid.controller.body_wave_phase_rad"] = [np.nan if s == 2.0 else s for s in df[f"grid.{S.SWING_KEY}"]]
        df["grid.controller.body_wave_amplitude"] = [np.nan if s == 2.0 else 0.1 for s in df[f"grid.{S.SWING_KEY}"]]
    path = S.PLOTS[sweep](df, tmp_path / f"{sweep}.png")
    assert path.stat().st_size > 10_000
    text = S.table(df, sweep)
    assert text.count("\n") >= len(df) + 1 and "| hybrid |" in text
    if sweep == "speed":
        assert "critical speed" in text


def test_the_sweep_script_refuses_a_directory_that_is_no_matrix_output(tmp_path, capsys):
    assert S.main(["speed", str(tmp_path / "nonesuch"), "--out", str(tmp_path / "x.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "nonesuch" in err
    assert not (tmp_path / "x.png").exists()


def test_the_report_finds_sweeps_a_and_b_by_their_grid_keys():
    df = _frame([dict(body="hybrid", k=1000.0), dict(body="massspring", k=600.0)])
    assert S.sweeps_in(df, ["body.youngs_modulus_pa", S.SWING_KEY]) == ["stiffness"]
    assert S.sweeps_in(df, ["body.link_stiffness_n_m", S.SPEED_KEY]) == ["speed"]
    assert S.sweeps_in(df, [S.SWING_KEY, S.SPEED_KEY]) == []           # no stiffness axis: no sweep a or b
    assert S.sweeps_in(df, ["body.youngs_modulus_pa", "dt"]) == []      # a stability sweep is not one of them


@pytest.mark.parametrize("name, axis", [("stance-fem-stiffness", "controller.swing_speed_rad_s"),
                                        ("stance-fem-speed", "scenario.control_speed_m_s"),
                                        ("stance-fem-body-wave", "controller.body_wave_phase_rad")])
def test_each_sweep_has_an_fem_matrix_with_the_same_grid(name, axis):
    """The fem body's sweeps (its dynamic stance came after the hybrid and massspring ones): the same grid as the
    two-body file, on fem alone."""
    fem = expand_matrix(MATRICES / f"{name}.toml")
    both = expand_matrix(MATRICES / f"{name.replace('-fem', '')}.toml")
    assert not fem.unsupported and axis in fem.grid_keys
    assert {c.case.body.name for c in fem.cases} == {"fem"}
    assert all(c.case.legs.stance == "dynamic" and c.case.creature.name == "centipede" for c in fem.cases)
    def grid(cases, body):
        return sorted(json.dumps({k: v for k, v in c.axes.items() if k != "body"}, sort_keys=True)
                      for c in cases if c.case.body.name == body)

    assert grid(fem.cases, "fem") == grid(both.cases, "hybrid")
    assert len({json.dumps(c.axes.get(axis)) for c in fem.cases} - {"null"}) >= 3
