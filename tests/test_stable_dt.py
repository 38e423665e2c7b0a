"""stable-dt against the analytic stability limit of symplectic Euler."""
import json

import pytest

from bench_myriapoda.bodies.massspring.body import BodyMassSpring
from bench_myriapoda.cli import main
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.stable_dt import find_stable_dt
from bench_myriapoda.bodies.massspring.analytic_systems import omega_max
from bench_myriapoda.world.world import build_world

STABLE_DT_REL_TOL = 0.08  # bisection bracket 2 % plus the finite duration needed for growth to show


def test_stable_dt_matches_symplectic_euler_limit_two_over_omega_max():
    case = resolve_case("worm", "massspring", "drop", duration=2.0, overrides=[
        "creature.segments=3", "scenario.passive=true", "scenario.gravity_m_s2=0", "scenario.start_height_m=1",
        "body.damping=0", "scenario.perturbation_m=1e-6"])
    expected = 2.0 / omega_max(BodyMassSpring(case, build_world(case)))
    res = find_stable_dt(case, rel_tol=0.02)
    assert res.stable_dt_max_s == pytest.approx(expected, rel=STABLE_DT_REL_TOL)
    assert res.stable_dt_max_s < expected * 1.01 < res.unstable_dt_min_s * 1.1


def test_stable_dt_command_json(capsys, tmp_path):
    code = main(["stable-dt", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration", "1",
                 "--json", "--store", str(tmp_path / "r.sqlite")])
    d = json.loads(capsys.readouterr().out)
    assert code == 0
    m = d["metrics"]
    assert m["stable_dt_max_s"] < m["unstable_dt_min_s"] <= m["stable_dt_max_s"] * 1.06
    statuses = {t["status"] for t in d["trials"]}
    assert statuses == {"ok", "unstable"}
    for t in d["trials"]:
        assert (t["status"] == "ok") == (t["dt"] <= m["stable_dt_max_s"])
