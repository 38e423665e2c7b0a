"""stable-dt against the analytic stability limit of symplectic Euler."""
import json

import numpy as np
import pytest

from bench_myriapoda.bodies.massspring import kernels as K
from bench_myriapoda.bodies.massspring.body import BodyMassSpring
from bench_myriapoda.cli import main
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.stable_dt import find_stable_dt

STABLE_DT_REL_TOL = 0.08  # bisection bracket 2 % plus the finite duration needed for growth to show


def omega_max(body: BodyMassSpring) -> float:
    """Largest angular eigenfrequency [rad/s] of the lattice linearized at rest: sqrt(max eig(M^-1 K))."""
    lat = body.lattice
    x0 = lat.rest_nodes.copy()
    n = x0.size
    h = 1e-7
    kmat = np.zeros((n, n))
    zero_v = np.zeros_like(x0)
    for col in range(n):
        xp, xm = x0.copy(), x0.copy()
        xp.flat[col] += h
        xm.flat[col] -= h
        fp, fm = np.zeros_like(x0), np.zeros_like(x0)
        K.spring_forces(xp, zero_v, lat.springs, body.stiffness, np.zeros(lat.n_springs), lat.rest_length, fp)
        K.spring_forces(xm, zero_v, lat.springs, body.stiffness, np.zeros(lat.n_springs), lat.rest_length, fm)
        kmat[:, col] = -(fp - fm).ravel() / (2 * h)
    minv = np.repeat(1.0 / body.mass, 3)
    return float(np.sqrt(np.max(np.linalg.eigvals(minv[:, None] * kmat).real)))


def test_stable_dt_matches_symplectic_euler_limit_two_over_omega_max():
    case = resolve_case("worm", "massspring", "drop", duration=2.0, overrides=[
        "creature.segments=3", "scenario.passive=true", "scenario.gravity_m_s2=0", "scenario.start_height_m=1",
        "body.damping=0", "scenario.perturbation_m=1e-6"])
    expected = 2.0 / omega_max(BodyMassSpring(case))
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
