"""Types shared by every validation check: the check, its outcome, one result row, verdict rules.

A check measures one quantity on one body model (or on several, for cross-body checks) and
compares it with a reference that names its source (an equation, a paper's figure or section,
or an analytic formula) under a stated tolerance.  Verdicts:

``PASS``            the measured value is within the tolerance of the reference
``FAIL``            it is not (``validate`` exits 1)
``NOT APPLICABLE``  the check cannot be made here (missing reference module, body lacks the
                    feature, run too short to measure); the reason is in ``detail``
``INFO``            informational: shown against a reference that is not comparable as a
                    pass/fail criterion (the paper's throughput on another machine); never fails
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from typing import Any, Callable

from ..core import registry

PASS, FAIL, NA, INFO = "PASS", "FAIL", "NOT APPLICABLE", "INFO"
VERDICTS = (PASS, FAIL, NA, INFO)
CROSS = "all"  # the body column of a cross-body row


def all_bodies() -> tuple[str, ...]:
    """Every registered body model, in the catalog's order (``core.registry``)."""
    registry.load_all()
    return tuple(registry.BODIES)


@dataclass(frozen=True)
class Outcome:
    """What a check's measure function returns for one body.

    measured / reference: numbers (SI units named in ``unit``) or short strings (a state sequence);
    tolerance: how close counts, in words (``"5 % relative"``, ``"< 1e-10"``);
    detail: the evidence or the reason for NOT APPLICABLE; figures: extra measured numbers.
    """

    verdict: str
    measured: Any
    reference: Any
    tolerance: str
    detail: str = ""
    unit: str = ""
    figures: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Check:
    """One entry of the registry.

    name: ``family.slug``, unique; family: the module; quantity: what is measured, in words;
    source: where the reference comes from; measure(ctx, body) -> Outcome; cross: one row comparing
    all bodies (``cross_quick``: also in ``validate --quick``).

    Which body models a check runs on is declared by the bodies, not here: each backend's
    ``BodySpec.checks`` names the checks it runs and whether ``--quick`` does (``bodies``,
    ``quick_bodies``), so a new body model brings its own rows.
    """

    name: str
    family: str
    quantity: str
    source: str
    measure: Callable[["Context", str], Outcome]
    cross: bool = False
    cross_quick: bool = False

    @property
    def bodies(self) -> tuple[str, ...]:
        """The registered body models that declare this check, in the catalog's order, or ``(CROSS,)``."""
        if self.cross:
            return (CROSS,)
        return tuple(b for b in all_bodies() if self.name in registry.BODIES[b].checks)

    @property
    def quick_bodies(self) -> tuple[str, ...]:
        """The bodies ``validate --quick`` runs this check on (a cross check: ``(CROSS,)`` or none)."""
        if self.cross:
            return (CROSS,) if self.cross_quick else ()
        return tuple(b for b in self.bodies if registry.BODIES[b].checks[self.name])


@dataclass
class Row:
    """One line of ``validate``'s table and of the store's ``validation`` table."""

    check: str
    family: str
    body: str
    quantity: str
    measured: Any
    reference: Any
    source: str
    tolerance: str
    verdict: str
    detail: str = ""
    unit: str = ""
    seconds: float = math.nan
    figures: dict[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        return clean(asdict(self))


class Context:
    """What checks share within one ``validate`` run: the size (quick or full) and a run cache.

    Several checks read the same simulation (the centipede walk feeds Fig. 10 D, the wave
    direction, the cross-body comparison and the throughput row); ``run`` simulates each
    distinct case once.
    """

    def __init__(self, quick: bool, bodies: tuple[str, ...] | None = None):
        self.quick = quick
        self.bodies = all_bodies() if bodies is None else bodies
        self._runs: dict[tuple, Any] = {}

    def run(self, creature: str, body: str, scenario: str, gait: str | None = None, duration: float | None = None,
            overrides: tuple[str, ...] = (), dt: float | None = None, keep_nodes: bool = False):
        """``harness.runner.run_case`` of the resolved case, cached by its arguments."""
        from ..core.config import resolve_case
        from ..harness.runner import run_case

        key = (creature, body, scenario, gait, duration, tuple(overrides), dt, keep_nodes)
        if key not in self._runs:
            case = resolve_case(creature, body, scenario, gait, duration=duration, dt=dt, overrides=list(overrides))
            self._runs[key] = run_case(case, keep_nodes=keep_nodes)
        return self._runs[key]


# --------------------------------------------------------------------------- verdict rules

def _finite(x) -> bool:
    return isinstance(x, (int, float)) and math.isfinite(x)


def relative(measured: float, reference: float, rel_tol: float, unit: str = "", detail: str = "",
             **figures) -> Outcome:
    """PASS when |measured - reference| <= rel_tol |reference|."""
    tol = f"{100 * rel_tol:g} % relative"
    if not (_finite(measured) and _finite(reference)):
        return Outcome(FAIL, measured, reference, tol, detail or "not measured (non-finite)", unit, figures)
    err = abs(measured - reference) / abs(reference) if reference != 0 else abs(measured)
    figures = {"rel_error": err, **figures}
    return Outcome(PASS if err <= rel_tol else FAIL, measured, reference, tol,
                   detail or f"relative error {err:.3g}", unit, figures)


def absolute(measured: float, reference: float, abs_tol: float, unit: str = "", detail: str = "",
             **figures) -> Outcome:
    """PASS when |measured - reference| <= abs_tol."""
    tol = f"+/- {abs_tol:g}{' ' + unit if unit else ''}"
    if not (_finite(measured) and _finite(reference)):
        return Outcome(FAIL, measured, reference, tol, detail or "not measured (non-finite)", unit, figures)
    err = abs(measured - reference)
    return Outcome(PASS if err <= abs_tol else FAIL, measured, reference, tol,
                   detail or f"error {err:.3g}{' ' + unit if unit else ''}", unit, figures)


def at_most(measured: float, bound: float, unit: str = "", detail: str = "", reference=None, **figures) -> Outcome:
    """PASS when measured <= bound."""
    ok = _finite(measured) and measured <= bound
    return Outcome(PASS if ok else FAIL, measured, bound if reference is None else reference,
                   f"<= {bound:g}{' ' + unit if unit else ''}", detail, unit, figures)


def at_least(measured: float, bound: float, unit: str = "", detail: str = "", reference=None, **figures) -> Outcome:
    """PASS when measured >= bound."""
    ok = _finite(measured) and measured >= bound
    return Outcome(PASS if ok else FAIL, measured, bound if reference is None else reference,
                   f">= {bound:g}{' ' + unit if unit else ''}", detail, unit, figures)


def holds(ok: bool, measured, reference, tolerance: str, detail: str = "", unit: str = "", **figures) -> Outcome:
    """PASS when a qualitative criterion ``ok`` holds."""
    return Outcome(PASS if ok else FAIL, measured, reference, tolerance, detail, unit, figures)


def not_applicable(reason: str, reference: Any = None, tolerance: str = "-") -> Outcome:
    return Outcome(NA, None, reference, tolerance, reason)


def failed_run(result, reference: Any = None, tolerance: str = "-") -> Outcome:
    """A run that ended unstable or in an error cannot reproduce anything: FAIL with its message."""
    return Outcome(FAIL, None, reference, tolerance, f"run {result.status}: {result.message}")


def clean(v):
    """``v`` with every non-finite float replaced by None, tuples as lists (strict JSON)."""
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [clean(x) for x in v]
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if hasattr(v, "item") and not isinstance(v, (str, bytes)):  # numpy scalars
        return clean(v.item())
    return v
