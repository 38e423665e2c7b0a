"""``bench-myriapoda peers``: other simulators' soft bodies and snakes, timed side by side with ours.

Every entry is timed in one process and one sitting by ``regress.run_suite`` (CPU seconds of the
timing thread, the REFERENCE kernel before every repetition), so the figures and their ratios come
from the same machine state.  Entries (names as stored in ``regress_history``):

- ``peer:mujoco-flex-816`` / ``peer:mujoco-flex-2754``: MuJoCo's flex soft body (``flexcomp``
  ``type="grid" dim="3"``, linear-elastic tets whose elasticity MuJoCo applies as passive
  forces), 17 separate blocks of 1 x 1 x 1 m resting on a plane: 3 x 3 x 3 vertices per block
  (48 tets, 816 in all) or 4 x 4 x 4 (162 tets, 2,754 in all).  No self-collision, and blocks
  never collide with each other (contype/conaffinity), only with the plane; dt = 1/3000 s, one
  thread (mj_step without a thread pool), MuJoCo's default integrator (semi-implicit Euler with
  implicit joint damping) and contact solver (soft constraints, Newton).  Young's modulus 4 kPa,
  Poisson 0.4, 1 kg per block (density 1 kg/m^3): the paper's material (``fem.system``).
- ``peer:pyelastica-snake``: PyElastica's continuum snake example (one Cosserat rod of 50
  elements, 0.35 m, E = 1 MPa, muscle torques as a travelling spline wave, anisotropic Coulomb
  friction on a plane, gravity, analytical linear damping), position Verlet at dt = 1e-4 s.
- ours: the bodies publish their entries (``BodySpec.benchmarks.peers``, a ``core.specs.PeerCase`` each, in
  ``bodies/<name>/benchmarks.py``) with the peer group they are compared with, so this module names no body
  (issue 42): the FEM's 17-segment chain resting on the plane (``ours:fem-chain-816`` /
  ``ours:fem-chain-2754``, resolution 3 or 4 nodes per edge, dt = 1/3000 s, Coulomb friction 0.5) in the
  groups ``soft-816`` / ``soft-2754``, and Miller's 50-segment snake (``ours:massspring-snake``, the same work
  as its regress entry) in the group ``snake``.

``ratios(results)`` turns the timings into ns per element-step, steps/s and real-time factors, and
ours / peer ratios.  Import errors of the optional packages are reported by ``missing_packages``.
"""
from __future__ import annotations

import importlib.util
from dataclasses import dataclass

import numpy as np

from ..core import registry
from ..core.config import resolve_case
from .throughput_suite import SuiteEntry, setup_of

# import name -> pip name of the optional ``[peers]`` extra
PEER_PACKAGES = {"mujoco": "mujoco", "elastica": "pyelastica"}

FLEX_BLOCKS = 17
FLEX_DT = 1.0 / 3000.0  # [s]
FLEX_BLOCK_M = 1.0  # block edge [m], as the chain's segments
FLEX_GAP_M = 0.5  # [m] between blocks: they never touch
FLEX_RADIUS_M = 0.005  # vertex collision radius [m]
FLEX_DAMPING = 0.001  # [s] MuJoCo flex elasticity damping (stiffness-proportional); 0 is flagged unstable
FLEX_SETTLE_STEPS = 600
ELASTICA_DT = 1.0e-4  # [s]
ELASTICA_ELEMENTS = 50


def missing_packages() -> list[str]:
    """pip names of the ``[peers]`` packages that are not importable."""
    return [pip for mod, pip in PEER_PACKAGES.items() if importlib.util.find_spec(mod) is None]


@dataclass(frozen=True)
class PeerEntry:
    """A timed entry of ``peers``: ``entry.setup()`` as in the throughput suite; ``elements`` per step
    (tets or rod elements / lattice segments), ``dt`` [s] of one step, ``group`` pairs ours with peers."""

    entry: SuiteEntry
    elements: int
    element_kind: str
    dt: float
    group: str


# --------------------------------------------------------------------------- MuJoCo flex

def mujoco_flex_xml(points_per_edge: int, blocks: int = FLEX_BLOCKS) -> str:
    """MJCF of ``blocks`` flex grids (points_per_edge^3 vertices, 6 tets per cell) resting on z = 0."""
    sp = FLEX_BLOCK_M / (points_per_edge - 1)
    z = 0.5 * FLEX_BLOCK_M + FLEX_RADIUS_M + 1e-3  # the vertices' spheres start just above the plane
    flex = []
    for b in range(blocks):
        flex.append(
            f'<flexcomp name="block{b}" type="grid" dim="3" count="{points_per_edge} {points_per_edge} '
            f'{points_per_edge}" spacing="{sp} {sp} {sp}" pos="{b * (FLEX_BLOCK_M + FLEX_GAP_M)} 0 {z}" '
            f'radius="{FLEX_RADIUS_M}" mass="{FLEX_BLOCK_M ** 3 * 1.0}">'
            '<edge equality="false"/>'
            f'<elasticity young="4000" poisson="0.4" damping="{FLEX_DAMPING}"/>'
            '<contact selfcollide="none" contype="1" conaffinity="0"/>'
            '</flexcomp>')
    return (f'<mujoco model="resting-blocks"><option timestep="{FLEX_DT!r}"/><worldbody>'
            '<geom type="plane" size="50 50 0.1" contype="0" conaffinity="1"/>'
            + "".join(flex) + "</worldbody></mujoco>")


def setup_mujoco_flex(points_per_edge: int, steps: int):
    import mujoco

    model = mujoco.MjModel.from_xml_string(mujoco_flex_xml(points_per_edge))
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, FLEX_SETTLE_STEPS)  # settled on the plane: the timed steps see contacts
    if not np.all(np.isfinite(data.qpos)):
        raise RuntimeError("MuJoCo flex blocks went unstable while settling")
    qpos, qvel = data.qpos.copy(), data.qvel.copy()

    def step(n: int) -> None:
        data.qpos[:] = qpos
        data.qvel[:] = qvel
        mujoco.mj_step(model, data, n)

    return step, steps, int(model.nflexelem)


# --------------------------------------------------------------------------- PyElastica snake

def setup_elastica_snake(steps: int):
    """PyElastica's continuum snake example (its published parameters), ``steps`` Verlet steps per call."""
    import elastica as ea

    class Snake(ea.BaseSystemCollection, ea.Constraints, ea.Forcing, ea.Damping, ea.CallBacks, ea.Contact):
        pass

    sim = Snake()
    length, density, E, poisson = 0.35, 1000.0, 1e6, 0.5
    radius = 0.011 * length
    normal = np.array([0.0, 1.0, 0.0])
    rod = ea.CosseratRod.straight_rod(ELASTICA_ELEMENTS, np.zeros(3), np.array([0.0, 0.0, 1.0]), normal, length,
                                      radius, density, youngs_modulus=E, shear_modulus=E / (poisson + 1.0))
    sim.append(rod)
    g = 9.80665
    sim.add_forcing_to(rod).using(ea.GravityForces, acc_gravity=np.array([0.0, -g, 0.0]))
    period = 2.0
    b_coeff = np.array([3.4e-3, 3.3e-3, 4.2e-3, 2.6e-3, 3.6e-3, 3.5e-3])
    wave_length = 1.0  # in body lengths, as the example's optimised coefficients
    sim.add_forcing_to(rod).using(ea.MuscleTorques, base_length=length, b_coeff=b_coeff, period=period,
                                  wave_number=2.0 * np.pi / wave_length, phase_shift=0.0, direction=normal,
                                  rest_lengths=rod.rest_lengths, ramp_up_time=period, with_spline=True)
    plane = ea.Plane(plane_origin=np.array([0.0, -radius, 0.0]), plane_normal=normal)
    sim.append(plane)
    mu = length / (period * period * g * 0.1)  # Froude number 0.1
    kinetic = np.array([mu, 1.5 * mu, 2.0 * mu])  # forward, backward, sideways
    sim.detect_contact_between(rod, plane).using(ea.RodPlaneContactWithAnisotropicFriction, k=1.0, nu=1e-6,
                                                 slip_velocity_tol=1e-8, static_mu_array=2.0 * kinetic,
                                                 kinetic_mu_array=kinetic)
    sim.dampen(rod).using(ea.AnalyticalLinearDamper, damping_constant=2e-3, time_step=ELASTICA_DT)
    sim.finalize()
    stepper = ea.PositionVerlet()
    state = {"t": np.float64(0.0)}

    def step(n: int) -> None:
        t = state["t"]
        dt = np.float64(ELASTICA_DT)
        for _ in range(n):
            t = stepper.step(sim, t, dt)
        state["t"] = t
        if not np.all(np.isfinite(rod.position_collection)):
            raise RuntimeError("PyElastica snake went unstable")

    return step, steps


# --------------------------------------------------------------------------- ours, and the entries

# the peer scenes: (points per edge, steps per repetition) of MuJoCo's flex blocks
FLEX_SCENES = ((3, 600), (4, 200))


def flex_tets(points_per_edge: int) -> int:
    """Tets of the ``FLEX_BLOCKS`` flex blocks of ``points_per_edge``^3 vertices (6 per cell, as our chain's)."""
    return 6 * (points_per_edge - 1) ** 3 * FLEX_BLOCKS


def our_entries() -> dict[str, PeerEntry]:
    """Our entries of ``peers``, as the catalogued bodies publish them (``BodySpec.benchmarks.peers``)."""
    registry.load_all()
    out: dict[str, PeerEntry] = {}
    for body, spec in registry.BODIES.items():
        for pc in spec.benchmarks.peers:
            sc = pc.case
            dt = pc.dt if pc.dt is not None else resolve_case(sc.creature, body, sc.scenario,
                                                                overrides=list(sc.overrides)).dt
            out[pc.entry] = PeerEntry(SuiteEntry(pc.entry, pc.description, setup_of(body, sc)), pc.elements,
                                      pc.element_kind, dt, pc.group)
    return out


def peer_entries() -> dict[str, PeerEntry]:
    """The entries of ``peers`` in run order (peers first within each group, then ours of that group)."""
    out: dict[str, PeerEntry] = {}

    def add(name, desc, setup, elements, kind, dt, group):
        out[name] = PeerEntry(SuiteEntry(name, desc, setup), elements, kind, dt, group)

    for ppe, steps in FLEX_SCENES:
        n = flex_tets(ppe)
        add(f"peer:mujoco-flex-{n}", f"MuJoCo flex, {FLEX_BLOCKS} resting blocks, {n} tets",
            lambda p=ppe, s=steps: setup_mujoco_flex(p, s)[:2], n, "tet", FLEX_DT, f"soft-{n}")
    add("peer:pyelastica-snake", f"PyElastica continuum snake, {ELASTICA_ELEMENTS} elements, dt 1e-4 s",
        lambda: setup_elastica_snake(2000), ELASTICA_ELEMENTS, "element", ELASTICA_DT, "snake")
    ours = our_entries()
    ordered: dict[str, PeerEntry] = {}
    for name, e in out.items():  # each peer, then ours of its group
        ordered[name] = e
        ordered.update({k: o for k, o in ours.items() if o.group == e.group and k not in ordered})
    ordered.update({k: o for k, o in ours.items() if k not in ordered})  # ours without a peer, last
    return ordered


def peer_pairs(entries: dict[str, PeerEntry] | None = None) -> dict[str, str]:
    """Peer entry -> our entry it is compared with (the same group: the same scene size), for ``ratios`` and the
    report's history; the first of ours where a group has more than one."""
    entries = peer_entries() if entries is None else entries
    pairs: dict[str, str] = {}
    for peer, e in entries.items():
        if peer.startswith("peer:"):
            ours = [k for k, o in entries.items() if k.startswith("ours:") and o.group == e.group]
            if ours:
                pairs[peer] = ours[0]
    return pairs


def ratios(entries: dict[str, PeerEntry], results) -> list[dict]:
    """Per timed entry: steps/s, ns per element-step, real-time factor, and in each group the
    ratio ours / peer of steps/s and peer / ours of ns per element-step (> 1: ours is faster)."""
    rows = []
    for r in results:
        e = entries[r.name]
        dt = e.dt
        rows.append({"entry": r.name, "group": e.group, "elements": e.elements, "element_kind": e.element_kind,
                     "dt_s": dt, "steps_per_s": r.steps_per_s, "spread": r.spread,
                     "ns_per_element_step": 1e9 / (r.steps_per_s * e.elements),
                     "realtime_factor": r.steps_per_s * dt, "normalized": r.normalized})
    for row in rows:
        if not row["entry"].startswith("ours:"):
            continue
        peers = [p for p in rows if p["group"] == row["group"] and p["entry"].startswith("peer:")]
        for p in peers:
            p["ours"] = row["entry"]
            p["speedup_steps"] = row["steps_per_s"] / p["steps_per_s"]
            p["speedup_per_element"] = p["ns_per_element_step"] / row["ns_per_element_step"]
            p["speedup_realtime"] = row["realtime_factor"] / p["realtime_factor"]
    return rows


def format_rows(rows: list[dict]) -> list[str]:
    head = ["entry", "elements", "steps/s", "ns/element-step", "x real time", "ours vs peer"]

    def vs(r):
        if "ours" not in r:
            return "-"
        return (f"{r['ours']}: {r['speedup_steps']:.2f}x steps/s, {r['speedup_per_element']:.2f}x per element, "
                f"{r['speedup_realtime']:.2f}x real time")

    table = [head] + [[r["entry"], f"{r['elements']} {r['element_kind']}s", f"{r['steps_per_s']:,.0f}",
                       f"{r['ns_per_element_step']:,.1f}", f"{r['realtime_factor']:.3g}", vs(r)] for r in rows]
    widths = [max(len(t[i]) for t in table) for i in range(len(head))]
    return ["  ".join(v.ljust(w) if i in (0, 5) else v.rjust(w) for i, (v, w) in enumerate(zip(t, widths)))
            for t in table]

