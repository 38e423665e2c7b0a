"""The kinematic slithering reference (Hu et al. 2009) against its limits and VALIDATION.md.

Hu et al. fit their model to a measured (not sinusoidal) snake shape, so no published number
applies to a pure sine wave; the checks here are the model's exact limits and the published
qualitative findings (VALIDATION.md): near-zero speed for isotropic friction, speed growing
monotonically with mu_t / mu_f toward the no-slip serpenoid glide, and mu_b irrelevant when no
point slides backward.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import j0

from bench_myriapoda.reference.slithering import body_shape, steady_slithering

A, LAM = 7.0, 1.0  # the comparison gait: curvature amplitude 7, one wave per body
ISOTROPIC_MAX_BL = 0.01  # VALIDATION.md accepts 0.02 for a dynamic body; the model gives ~0.005
NO_SLIP_REL = 0.01  # mu_t / mu_f = 1000: slip ~ mu_f / mu_t, so within 1 % of the glide speed
BALANCE_TOL = 1e-8  # relative force/torque residual of every solve


def test_isotropic_friction_gives_almost_no_progress():
    r = steady_slithering(A, LAM, 0.3, 0.3, 0.3)
    assert abs(r.speed_bl_per_cycle) < ISOTROPIC_MAX_BL
    assert abs(r.lateral_speed_bl_per_cycle) < ISOTROPIC_MAX_BL
    assert r.max_force_residual < BALANCE_TOL


def test_isotropic_linear_drag_gives_exactly_no_translation():
    # a huge regularisation turns Coulomb friction into isotropic linear drag, for which a shape
    # change described in its centre-of-mass frame cannot translate the body: checks the kinematics
    r = steady_slithering(A, LAM, 1.0, 1.0, 1.0, velocity_regularization=1e4)
    assert abs(r.speed_bl_per_cycle) < 1e-8 and abs(r.lateral_speed_bl_per_cycle) < 1e-8


def test_speed_grows_monotonically_with_transverse_friction():
    ratios = [1.5, 2.0, 3.0, 5.0, 10.0, 100.0]
    speeds = [steady_slithering(A, LAM, 1.0, 1.5, r).speed_bl_per_cycle for r in ratios]
    assert all(b > a for a, b in zip(speeds, speeds[1:])), speeds
    assert speeds[0] > 0.05  # mu_t / mu_f = 1.5 already propels head first


def test_no_slip_limit_is_the_serpenoid_glide():
    r = steady_slithering(A, LAM, 1.0, 1.5, 1000.0)
    glide = LAM * j0(A * LAM / (2 * math.pi))
    assert r.no_slip_speed_bl_per_cycle == pytest.approx(glide)
    assert r.speed_bl_per_cycle == pytest.approx(glide, rel=NO_SLIP_REL)
    assert 0.0 <= r.slip < NO_SLIP_REL


def test_backward_friction_does_not_matter_when_nothing_slides_backward():
    speeds = [steady_slithering(A, LAM, 1.0, mb, 5.0).speed_bl_per_cycle for mb in (1.0, 1.5, 2.25)]
    assert max(speeds) - min(speeds) < 1e-6


def test_rate_independence_and_coefficient_scale():
    # Coulomb friction: only the ratios matter
    a = steady_slithering(A, LAM, 0.1, 0.15, 0.3).speed_bl_per_cycle
    b = steady_slithering(A, LAM, 1.0, 1.5, 3.0).speed_bl_per_cycle
    assert a == pytest.approx(b, rel=1e-6)


def test_symmetric_wave_keeps_its_heading():
    r = steady_slithering(A, LAM, 1.0, 1.5, 3.0)
    assert abs(r.angular_velocity_rad_per_cycle) < 1e-6


def test_converged_in_resolution():
    coarse = steady_slithering(A, LAM, 1.0, 1.5, 3.0).speed_bl_per_cycle
    fine = steady_slithering(A, LAM, 1.0, 1.5, 3.0, n_points=400, n_time=192).speed_bl_per_cycle
    assert coarse == pytest.approx(fine, rel=0.01)


def test_body_shape_is_inextensible_and_centred():
    X, W, a, w = body_shape(A, LAM, 0.3, 400)
    seg = np.linalg.norm(np.diff(X, axis=0), axis=1).sum()
    assert seg == pytest.approx(1.0, rel=1e-3)
    assert np.allclose(w @ X, 0.0, atol=1e-12) and np.allclose(w @ W, 0.0, atol=1e-12)


def test_averaged_limit_agrees_at_high_anisotropy():
    q = steady_slithering(A, LAM, 1.0, 1.5, 100.0)
    m = steady_slithering(A, LAM, 1.0, 1.5, 100.0, method="averaged")
    assert m.speed_bl_per_cycle == pytest.approx(q.speed_bl_per_cycle, rel=0.05)


@pytest.mark.parametrize("bad", [dict(mu_f=0.0), dict(mu_t=-1.0), dict(wavelength_bl=0.0), dict(method="x")])
def test_bad_input_is_refused(bad):
    kw = dict(curvature_amplitude=A, wavelength_bl=LAM, mu_f=1.0, mu_b=1.5, mu_t=3.0)
    kw.update(bad)
    with pytest.raises(ValueError):
        steady_slithering(**kw)
