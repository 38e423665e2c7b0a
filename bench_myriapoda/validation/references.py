"""Analytic references: the closed-form answers the body models are checked against, and the ratios of a
body's measured static states to them.

Moved here from ``tests/fem/test_fem_physics.py`` and ``tests/test_stable_dt.py`` so that ``validate`` shows
what the test suite checks.  Every function returns plain numbers; SI units.  The systems measured (the FEM
method's bars, beams and tets, the lattice's eigenfrequency) are the bodies' own, published in their
``BodySpec.probes`` (``bodies/<name>/analytic_systems.py``): a reference names no body (issue 42).
"""
from __future__ import annotations

import numpy as np


# --------------------------------------------------------------------------- formulas

def hanging_bar_displacement(rho: float, g: float, L: float, E: float) -> float:
    """Bottom displacement [m] of a bar of length L hanging under its own weight, top fixed: rho g L^2 / (2 E)."""
    return rho * g * L**2 / (2 * E)


def cantilever_tip_deflection(P: float, L: float, E: float, I: float, nu: float, A: float) -> float:
    """Tip deflection [m] of a clamped beam under a tip load P [N]: P L^3 / (3 E I) + P L / (kappa G A).

    The shear term (Timoshenko) matters for stocky beams; kappa = 10 (1 + nu) / (12 + 11 nu) for a
    rectangular section.
    """
    G = E / (2 * (1 + nu))
    kappa = 10 * (1 + nu) / (12 + 11 * nu)
    return P * L**3 / (3 * E * I) + P * L / (kappa * G * A)


def worm_displacement_per_cycle(eps: float, wavelength_m: float) -> float:
    """Rectilinear worm with perfect anchoring: D = Lambda (mean(lambda) - min(lambda)) = eps Lambda [m]."""
    return eps * wavelength_m


def symplectic_euler_dt_limit(omega_max: float) -> float:
    """Largest stable step [s] of symplectic Euler for an undamped oscillator of angular frequency omega_max."""
    return 2.0 / omega_max


def backward_euler_damping_factor(lam: float, h: float) -> float:
    """Per-step velocity factor of a pure damping mode (D phi = lam M phi) under the implicit damping step."""
    return 1.0 / (1.0 + lam * h)


def semi_implicit_oscillator_factor(c: float, h: float) -> float:
    """Per-step amplitude factor of an underdamped mode of the App. A step (elasticity explicit, damping
    implicit): the one-step map has determinant 1 / (1 + c h), so |eigenvalue| = 1 / sqrt(1 + c h)."""
    return 1.0 / np.sqrt(1.0 + c * h)


# --------------------------------------------------------------------------- static solves

def _published(probe: str):
    """The probe ``probe`` of the first body model in the catalog that publishes it (``core.specs.BodyProbes``):
    the FEM method's own systems, looked up by what they are, not by the body's name."""
    from ..core import registry

    registry.load_all()
    for spec in registry.BODIES.values():
        fn = getattr(spec.probes, probe)
        if fn is not None:
            return fn
    raise LookupError(f"no body model publishes BodyProbes.{probe}")


def hanging_bar(n_len: int, nu: float, E: float = 1e4, rho: float = 1.0, g: float = 9.81, L: float = 1.0,
                a: float = 0.2, solve=None) -> tuple[object, float]:
    """Bar along y, top face fixed, cells (n/4, n, n/4); strain rho g L / E ~ 1e-3.

    Returns the relaxed system and the bottom displacement / ``hanging_bar_displacement``.  ``solve``: a body's
    ``BodyProbes.bar_under_own_weight`` (default: the catalog's body that publishes one, the FEM body).
    """
    s, u = (solve or _published("bar_under_own_weight"))(n_len, nu, E=E, rho=rho, g=g, L=L, a=a)
    return s, u / hanging_bar_displacement(rho, g, L, E)


def cantilever_ratio(cells, E: float = 1e4, nu: float = 0.0, L: float = 0.5, H: float = 0.1, W: float = 0.1,
                     solve=None) -> float:
    """Tip deflection / beam theory of a beam along x clamped at x = 0, tip load -P y over the tip nodes.

    L/H = 5 is stocky, so the shear term (2.3 %) is included.  The load gives a tip deflection of
    1e-4 L, small enough for the corotational model to act linearly.  nu = 0 keeps the clamped face
    from adding Poisson constraint that beam theory does not have.  ``solve``: a body's
    ``BodyProbes.cantilever_tip`` (default: the catalog's body that publishes one, the FEM body).
    """
    I = W * H**3 / 12
    A = W * H
    P = 3 * E * I * 1e-4 * L / L**3
    ref = cantilever_tip_deflection(P, L, E, I, nu, A)
    return (solve or _published("cantilever_tip"))(cells, P, E=E, nu=nu, L=L, H=H, W=W) / ref


def rotation(axis, angle: float) -> np.ndarray:
    """(3, 3) rotation matrix about ``axis`` by ``angle`` [rad] (Rodrigues)."""
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    Kx = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * Kx + (1 - np.cos(angle)) * Kx @ Kx
