"""friction.froude (issue 11): mu_f = L / (T^2 g Fr), the other coefficients keep their ratios to mu_f."""
from __future__ import annotations

import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.core.config import apply_froude, resolve_case


def test_froude_sets_mu_forward_and_keeps_the_ratios():
    plain = resolve_case("snake", "massspring", "flat")
    case = resolve_case("snake", "fem", "flat", overrides=["friction.froude=0.1"])
    L, T, g = case.creature.body_length_m, case.gait.period_s, case.scenario.gravity_m_s2
    f = case.friction
    assert f.mu_forward == pytest.approx(L / (T * T * g * 0.1))
    assert f.mu_backward / f.mu_forward == pytest.approx(plain.friction.mu_backward / plain.friction.mu_forward)
    assert f.mu_transverse / f.mu_forward == pytest.approx(plain.friction.mu_transverse / plain.friction.mu_forward)
    assert f.mu_static_forward == -1.0  # "same as kinetic" stays so
    # every body sees the same coefficients, and applying it again changes nothing
    other = resolve_case("snake", "hybrid", "flat", overrides=["friction.froude=0.1"]).friction
    assert (other.mu_forward, other.mu_backward, other.mu_transverse) == (f.mu_forward, f.mu_backward, f.mu_transverse)
    assert apply_froude(f, L, T, g) == f


def test_froude_scales_given_static_coefficients():
    case = resolve_case("snake", "massspring", "flat",
                        overrides=["friction.mu_static_transverse=1.0", "friction.froude=0.2"])
    f = case.friction
    assert f.mu_static_transverse / f.mu_forward == pytest.approx(1.0 / 0.1)


def test_froude_without_coefficients_is_refused(capsys):
    code = main(["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat",
                 "--set", "friction.froude=0.1", "--duration", "0.01", "--no-store"])
    err = capsys.readouterr().err
    assert code == 2 and "--set" in err and "friction.froude" in err and "coulomb" in err
