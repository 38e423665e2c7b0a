"""A fourth body model, defined in this one file and added with one table row at run time (issue 30, item 2).

``pointchain``: a chain of point masses, one at each segment boundary (head at node 0), joined by
axial springs, with bending springs that pull each node's tail-side neighbour toward the direction
the muscles command, and the suite's ground contact and friction (``contact_kernels.advance_point``:
Miller's collision, the miller / coulomb / stick friction models) on any terrain.  It declares
everything the suite asks of a body model in one ``BodySpec`` (``BODIES`` below, the module's table
row), so the catalog reads it as a plugin (``BENCH_MYRIAPODA_PLUGINS=test_fourth_body``) and no other
file of the package or of ``models/`` changes: every legless creature (worm, snake, caterpillar) runs
on it through ``run``, ``matrix``, ``validate --quick`` and the conformance test.

Muscles (``core.protocols``' fibre reading): segment i between nodes i and i + 1 has rest length
L (1 + axial); a LATERAL strain l bends the body by the angle 2 L l / width per segment (a fibre at
the side, width / 2 from the axis, stretched by l), toward the left for l > 0; DORSAL likewise with
the height, toward the belly for d > 0.
"""
from __future__ import annotations

import dataclasses
import json
import math
import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from numba import njit

from bench_myriapoda.bodies import step_status as S
from bench_myriapoda.bodies.contact_kernels import advance_point
from bench_myriapoda.bodies.friction_kernels import CONTACT_DISTANCE, FRICTION_CAPABILITIES, friction_params
from bench_myriapoda.bodies.placement import place_points
from bench_myriapoda.bodies.point_masses import point_mass_momentum_probes
from bench_myriapoda.bodies.scene import Scene
from bench_myriapoda.core import registry
from bench_myriapoda.core.errors import InputError
from bench_myriapoda.core.feasibility import lattice_footprint
from bench_myriapoda.core.protocols import MUSCLES, Actuation, Observation
from bench_myriapoda.core.schema import rng
from bench_myriapoda.core.specs import BodyProbes, BodySpec
from bench_myriapoda.world.terrain_kernels import signed_distance

NAME = "pointchain"
ROOT = Path(__file__).resolve().parents[1]
LEGLESS = ("worm", "snake", "caterpillar")


@dataclass(frozen=True)
class PointChainConfig:
    """Keys of ``[bodies.pointchain]`` (a creature file may name none: ``BodySpec.default_params``)."""

    name: str = rng(NAME)
    axial_hz: float = rng(40.0, gt=0.0, doc="natural frequency of one node on its axial spring [Hz]")
    bending_hz: float = rng(12.0, gt=0.0, doc="natural frequency of one node on its bending spring [Hz]")
    damping_ratio: float = rng(0.5, ge=0.0, doc="damping of each spring, a fraction of its critical damping")
    dt_s: float = rng(5e-4, gt=0.0, doc="default time step [s]")


# phys vector of the kernel
K_AX, C_AX, K_B, C_B, GRAVITY, DT, R_N, R_T, MAX_SPEED, MAX_PEN, GAIN_LAT, GAIN_DORS = range(12)


@njit(cache=True, error_model="numpy")
def advance_chain(x, v, inv_mass, rest, muscle, phys, fric_model, fric, terr_kind, terr, n_steps, f, acc):
    """``n_steps`` semi-implicit Euler steps of the chain x, v (n, 3) [m], [m/s] (UPDATED); muscle (rows,
    n - 1, 3): row k drives step k (later steps the last row); rest (n - 1,) [m]; f (n, 3) scratch;
    acc: ``step_status`` accumulators (UPDATED).  Returns (steps done, status)."""
    n = x.shape[0]
    dt = phys[DT]
    for step in range(n_steps):
        row = muscle[min(step, muscle.shape[0] - 1)]
        f[:, :] = 0.0
        for i in range(n):
            f[i, 1] -= phys[GRAVITY] / inv_mass[i] if inv_mass[i] > 0.0 else 0.0
        for i in range(n - 1):  # axial springs and dampers, segment i between nodes i and i + 1
            d = x[i + 1] - x[i]
            length = math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + 1e-300
            u = d / length
            vrel = (v[i + 1, 0] - v[i, 0]) * u[0] + (v[i + 1, 1] - v[i, 1]) * u[1] + (v[i + 1, 2] - v[i, 2]) * u[2]
            fs = phys[K_AX] * (length - rest[i] * (1.0 + row[i, 0])) + phys[C_AX] * vrel
            for a in range(3):
                f[i, a] += fs * u[a]
                f[i + 1, a] -= fs * u[a]
        for i in range(1, n - 1):  # bending: node i + 1 pulled toward the commanded direction from node i
            fw = x[i - 1] - x[i]
            fl = math.sqrt(fw[0] * fw[0] + fw[1] * fw[1] + fw[2] * fw[2]) + 1e-300
            fw = fw / fl
            rx, ry, rz = -fw[2], 0.0, fw[0]  # forward x up (world y): the creature's right
            rl = math.sqrt(rx * rx + rz * rz) + 1e-300
            rx, rz = rx / rl, rz / rl
            ux, uy, uz = ry * fw[2] - rz * fw[1], rz * fw[0] - rx * fw[2], rx * fw[1] - ry * fw[0]  # right x fwd
            lat = 0.5 * (row[i - 1, 1] + row[i, 1]) * phys[GAIN_LAT]
            dors = 0.5 * (row[i - 1, 2] + row[i, 2]) * phys[GAIN_DORS]
            g = x[i + 1] - x[i]
            gl = math.sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2])
            tx, ty, tz = -(fw[0] + lat * rx + dors * ux), -(fw[1] + lat * ry + dors * uy), -(fw[2] + lat * rz + dors * uz)
            tl = math.sqrt(tx * tx + ty * ty + tz * tz) + 1e-300
            for a, ta in enumerate((tx, ty, tz)):
                pull = phys[K_B] * (x[i, a] + gl * ta / tl - x[i + 1, a]) - phys[C_B] * (v[i + 1, a] - v[i, a])
                f[i + 1, a] += pull
                f[i, a] -= pull
        status = S.OK
        for i in range(n):
            if inv_mass[i] == 0.0:
                continue
            j0, j1 = max(i - 1, 0), min(i + 1, n - 1)
            sx, sy, sz = x[j0, 0] - x[j1, 0], x[j0, 1] - x[j1, 1], x[j0, 2] - x[j1, 2]
            sl = math.sqrt(sx * sx + sy * sy + sz * sz) + 1e-300
            vx = v[i, 0] + dt * f[i, 0] * inv_mass[i]
            vy = v[i, 1] + dt * f[i, 1] * inv_mass[i]
            vz = v[i, 2] + dt * f[i, 2] * inv_mass[i]
            touching, st = advance_point(x, v, i, (vx, vy, vz), (sx / sl, sy / sl, sz / sl), terr_kind, terr,
                                         fric_model, fric, (dt, phys[R_N], phys[R_T], fric[CONTACT_DISTANCE],
                                         phys[MAX_PEN], phys[MAX_SPEED] ** 2), acc, False, (0.0, 0.0, 0.0))
            if touching:
                acc[S.ACC_CONTACT_SUM] += 1.0 / n
            if st != S.OK:
                status = st
        acc[S.ACC_STEPS] += 1.0
        if status != S.OK:
            return step + 1, status
    return n_steps, S.OK


class BodyPointChain(S.AccumulatedContact):  # contact_fraction_mean, max_penetration
    """The chain of ``segments + 1`` point masses (module docstring); ``x``, ``v`` (n, 3) [m], [m/s]."""

    name = NAME
    capabilities = frozenset({MUSCLES})

    def __init__(self, case, world):
        cre, cfg = case.creature, case.body
        n = cre.segments + 1
        self.case, self.dt = case, case.dt
        self.n_segments = self.n_muscle_segments = cre.segments
        self.muscle_s = (np.arange(cre.segments) + 0.5) * cre.segment_length_m
        self.body_length_m = cre.body_length_m
        self.segment_pitch_m = cre.segment_length_m
        self.mass = np.full(n, cre.mass_kg / n)
        self.inv_mass = 1.0 / self.mass
        if case.scenario.suspended:
            self.inv_mass[0] = 0.0
        m = self.mass[0]
        self.rest = np.full(cre.segments, cre.segment_length_m)
        rest_nodes = np.zeros((n, 3))
        rest_nodes[:, 0] = -np.arange(n) * cre.segment_length_m
        rest_nodes[:, 1] = 0.5 * cre.height_m
        self.x = place_points(rest_nodes, case, world)
        self.v = np.zeros_like(self.x)
        self.terr_kind, self.terr = world.terrain  # the run's world (``world.world.World``), built once by the runner
        self.fric_model, self.fric = friction_params(case.friction)
        k_ax, k_b = m * (2 * math.pi * cfg.axial_hz) ** 2, m * (2 * math.pi * cfg.bending_hz) ** 2
        self.phys = np.array([k_ax, 2 * cfg.damping_ratio * math.sqrt(k_ax * m), k_b,
                              2 * cfg.damping_ratio * math.sqrt(k_b * m), case.scenario.gravity_m_s2, case.dt,
                              case.collision.r_n, case.collision.r_t, case.stability.max_speed_m_s,
                              case.stability.max_penetration_m, 2 * cre.segment_length_m / cre.width_m,
                              2 * cre.segment_length_m / cre.height_m])
        self.half = np.tile([0.5 * cre.segment_length_m, 0.5 * cre.height_m, 0.5 * cre.width_m], (cre.segments, 1))
        self.segment_half_extents = self.half
        self.acc = np.zeros(S.N_ACC)
        self._f = np.zeros((n, 3))
        self._muscle = np.zeros((1, cre.segments, 3))

    def compile(self) -> None:
        x, v, acc = self.x.copy(), self.v.copy(), self.acc.copy()
        self.advance(0.0, 1, Actuation.for_body(self))
        self.x[:], self.v[:], self.acc[:] = x, v, acc

    def advance(self, t0: float, n_steps: int, act: Actuation | None = None) -> tuple[int, int]:
        muscle = self._muscle if act is None else act.muscle
        done, code = advance_chain(self.x, self.v, self.inv_mass, self.rest, muscle, self.phys, self.fric_model,
                                   self.fric, self.terr_kind, self.terr, n_steps, self._f, self.acc)
        self._muscle = muscle[min(done, muscle.shape[0] - 1):][:1].copy()  # the actuation it now holds
        return done, code

    def _frames(self):
        x = self.x
        fwd = x[:-1] - x[1:]
        fwd /= np.linalg.norm(fwd, axis=1, keepdims=True) + 1e-300
        right = np.cross(fwd, [0.0, 1.0, 0.0])
        flat = np.linalg.norm(right, axis=1) < 1e-9  # a segment standing upright: any horizontal right
        right[flat] = [0.0, 0.0, 1.0]
        right /= np.linalg.norm(right, axis=1, keepdims=True)
        up = np.cross(right, fwd)
        return 0.5 * (x[:-1] + x[1:]), np.stack([fwd, up, right], axis=2)

    def sense(self, obs: Observation, t: float) -> None:
        obs.t = t
        obs.seg_pos, obs.seg_rot = self._frames()
        obs.seg_vel = 0.5 * (self.v[:-1] + self.v[1:])
        obs.seg_half = self.half

    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        obs = Observation(com=(self.mass[:, None] * self.x).sum(axis=0) / self.mass.sum(), head=self.x[0].copy(),
                          tail=self.x[-1].copy(), energy=np.array(self.energy(t)),
                          nodes=self.x.copy() if with_nodes else None)
        self.sense(obs, t)
        obs.segment_centers = obs.seg_pos
        phi = np.array([signed_distance(self.terr_kind, self.terr, *p) for p in self.x])
        near = phi < self.fric[CONTACT_DISTANCE]
        obs.seg_contact = near[:-1] | near[1:]
        return obs

    def energy(self, t: float) -> tuple[float, float, float]:
        d = np.linalg.norm(self.x[1:] - self.x[:-1], axis=1)
        elastic = 0.5 * self.phys[K_AX] * float(((d - self.rest) ** 2).sum())
        return (0.5 * float((self.mass * (self.v ** 2).sum(axis=1)).sum()), elastic,
                float((self.mass * self.phys[GRAVITY] * self.x[:, 1]).sum()))

    def status_text(self, code: int) -> str:
        return S.STATUS_TEXT.get(code, f"status {code}")

    def extra_metrics(self) -> dict[str, float]:
        return {}

    def scene(self) -> Scene:
        return Scene(springs=np.stack([self.x[:-1], self.x[1:]], axis=1))


def check_buildable(case, source: str) -> None:
    """Refuse a time step the axial springs cannot be stable at: symplectic Euler needs dt omega_max < 2, and
    the chain's highest axial mode is omega_max = 2 sqrt(k / m) = 2 (2 pi axial_hz)."""
    omega_max = 2.0 * 2.0 * math.pi * case.body.axial_hz
    if not case.dt * omega_max < 2.0:
        raise InputError(source, "dt", f"{case.dt} s: the point chain's axial springs are unstable above "
                                       f"{2.0 / omega_max:.3g} s; must be smaller (or lower body.axial_hz)")


# The one table row: what the suite knows of this body model.  The legless creatures' validation checks
# run on it in ``validate --quick``.
BODIES = {NAME: BodySpec(
    name=NAME, description="a chain of point masses joined by axial and bending springs (tests/test_fourth_body.py)",
    config_cls=PointChainConfig, factory=BodyPointChain, default_dt=lambda cfg: cfg.dt_s,
    capabilities=frozenset({MUSCLES}) | FRICTION_CAPABILITIES,
    footprint=lambda case: lattice_footprint(case.creature.segments + 1.0), check_buildable=check_buildable,
    default_params={},
    checks={"analytic.free-fall-momentum": True, "analytic.worm-eps-lambda": True,
            "miller.image1-worm-book": True, "miller.image2-snake-coils": True,
            "miller.image4-caterpillar-arch": True},
    # the free-fall check's momentum of the point masses (validation reads no body's attributes)
    probes=BodyProbes(**point_mass_momentum_probes(lambda body: body.mass)))}


# --------------------------------------------------------------------------- the tests

MODULE = "test_fourth_body"  # this file as the plugin module (pytest puts tests/ on sys.path)
QUICK_CHECKS = tuple(c for c, quick in BODIES[NAME].checks.items() if quick)


@pytest.fixture
def plugin(monkeypatch):
    """The fourth body in the lookups, read by the catalog's plugin mechanism as the CLI does (the env var);
    removed again afterwards so no other test sees it."""
    monkeypatch.setenv(registry.PLUGINS_ENV, MODULE)
    registry.load_all()
    assert registry.BODIES[NAME] is sys.modules[MODULE].BODIES[NAME]
    yield registry.BODIES[NAME]
    registry.BODIES.pop(NAME, None)


def _gaits():
    from bench_myriapoda.core.config import load_creature_file
    registry.load_all()
    for creature in LEGLESS:
        _, data = load_creature_file(creature)
        for gait in data["creature"]["gaits"]:
            yield creature, gait


@pytest.mark.parametrize("creature, gait", list(_gaits()))
def test_every_legless_creature_runs_on_the_fourth_body_through_the_api(plugin, creature, gait):
    from bench_myriapoda import api
    res = api.run(creature, NAME, "flat", gait, duration=1.0)
    assert res.status == "ok", res.message
    assert res.case.body == PointChainConfig()  # no creature file names [bodies.pointchain]: the declared defaults
    assert res.case.dt == PointChainConfig().dt_s
    assert np.all(np.isfinite(res.series.energy))
    assert res.metrics["body_length_m"] > 0


@pytest.mark.parametrize("creature, gait", list(_gaits()))
def test_the_fourth_body_passes_the_conformance_test(plugin, creature, gait):
    from test_controllers import SCENARIO, test_conformance
    test_conformance(creature, NAME, gait, SCENARIO[False])


def test_the_fourth_body_runs_through_the_cli_run_and_matrix(plugin, tmp_path, capsys):
    from bench_myriapoda.cli import main
    for creature in LEGLESS:
        code = main(["run", "--creature", creature, "--body", NAME, "--scenario", "flat", "--duration", "0.3",
                     "--json", "--no-store"])
        assert code == 0
        out = json.loads(capsys.readouterr().out)
        assert out["status"] == "ok"
    matrix = tmp_path / "fourth.toml"
    matrix.write_text('[matrix]\nname = "fourth"\nseeds = [0]\n\n[[block]]\ncreatures = ["worm", "snake", '
                      f'"caterpillar"]\nbodies = ["{NAME}"]\nscenarios = ["flat"]\nduration = 0.3\n')
    code = main(["matrix", str(matrix), "--workers", "1", "--out", str(tmp_path / "out")])
    assert code == 0
    from bench_myriapoda.api import load_results
    df = load_results(tmp_path / "out")
    assert sorted(zip(df["creature"], df["body"], df["status"])) == [(c, NAME, "ok") for c in sorted(LEGLESS)]


def test_the_fourth_body_runs_through_validate_quick(plugin, tmp_path, capsys):
    from creature_runs import validate_quick_rows

    code, rows = validate_quick_rows(NAME, tmp_path, capsys, QUICK_CHECKS)  # its quick checks, none broke on it
    for r in rows:  # a verdict on the physics
        assert r["verdict"] in ("PASS", "FAIL"), r
    assert code == (1 if any(r["verdict"] == "FAIL" for r in rows) else 0)


def test_the_cli_finds_the_fourth_body_through_the_plugin_variable(tmp_path):
    env = dict(os.environ, **{registry.PLUGINS_ENV: MODULE},
               PYTHONPATH=os.pathsep.join([str(ROOT), str(ROOT / "tests"), os.environ.get("PYTHONPATH", "")]))
    cmd = [sys.executable, "-m", "bench_myriapoda.cli", "run", "--creature", "worm", "--body", NAME, "--scenario",
           "flat", "--duration", "0.2", "--json", "--no-store"]
    out = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout)["status"] == "ok"
    env.pop(registry.PLUGINS_ENV)
    out = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=600)
    assert out.returncode == 2 and "unknown body model 'pointchain'" in out.stderr


def test_the_fourth_body_declares_its_own_limits(plugin, capsys):
    from bench_myriapoda.cli import main
    code = main(["run", "--creature", "worm", "--body", NAME, "--scenario", "flat", "--dt", "0.01", "--no-store"])
    assert code == 2 and "unstable above" in capsys.readouterr().err


def test_a_plugin_row_is_checked(monkeypatch):
    monkeypatch.setenv(registry.PLUGINS_ENV, "no_such_module_here")
    with pytest.raises(InputError, match="cannot import the plugin module"):
        registry.load_all()
    bad = type(sys)("bad_plugin_rows")
    bad.BODIES = {"fem": dataclasses.replace(BODIES[NAME], name="fem")}
    monkeypatch.setitem(sys.modules, "bad_plugin_rows", bad)
    monkeypatch.setenv(registry.PLUGINS_ENV, "bad_plugin_rows")
    with pytest.raises(InputError, match="name already taken"):
        registry.load_all()
