"""``Case.case_hash``: computed once per case object, always the value of the canonical-JSON formula.

Results are keyed by this hash in SQLite (and a matrix resumes by it), so the memoised value must be exactly
the from-scratch one, for every case of the quick matrix, and must never outlive a change of the case.
"""
from __future__ import annotations

import dataclasses
import hashlib
import json
import pickle

import pytest

from bench_myriapoda.core.config import Case, resolve_case, uncached_case_hash
from bench_myriapoda.harness.matrix import expand_matrix, locate_matrix


def _formula(case: Case) -> str:
    """The hash as the store has always defined it: sha256 of the sorted, compact JSON of to_dict(), 16 hex."""
    blob = json.dumps(case.to_dict(), sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(blob.encode()).hexdigest()[:16]


def test_every_quick_matrix_case_hashes_as_the_formula_and_is_computed_once(monkeypatch):
    cases = [m.case for m in expand_matrix(locate_matrix("quick")).cases]
    assert len(cases) >= 50
    want = [_formula(c) for c in cases]
    assert [uncached_case_hash(c) for c in cases] == want
    assert [c.case_hash() for c in cases] == want
    assert len(set(want)) == len(want)

    # the second call does not walk the case again
    def no_walk(self):
        raise AssertionError("to_dict called again for a hashed case")
    monkeypatch.setattr(Case, "to_dict", no_walk)
    assert [c.case_hash() for c in cases] == want


def test_a_replaced_or_pickled_case_keeps_a_correct_hash():
    case = resolve_case("worm", "massspring", "flat", duration=0.5)
    h = case.case_hash()
    other = dataclasses.replace(case, dt=case.dt / 2)
    assert other.case_hash() == _formula(other) != h
    section = dataclasses.replace(case, friction=dataclasses.replace(case.friction, mu_forward=0.123))
    assert section.case_hash() == _formula(section) != h
    back = pickle.loads(pickle.dumps(case))  # a worker's copy of the case
    assert back == case and back.case_hash() == h == _formula(back)
    assert case == resolve_case("worm", "massspring", "flat", duration=0.5)  # the memo is not a field


@dataclasses.dataclass
class _MutableBody:  # a user's body config that is not frozen
    name: str = "massspring"
    stiffness: float = 1.0


def test_a_case_with_a_mutable_body_config_is_hashed_afresh():
    case = dataclasses.replace(resolve_case("worm", "massspring", "flat"), body=_MutableBody())
    h = case.case_hash()
    assert h == _formula(case)
    case.body.stiffness = 2.0
    assert case.case_hash() == _formula(case) != h


@pytest.mark.parametrize("creature,body,scenario", [("worm", "massspring", "flat"), ("centipede", "hybrid", "walk")])
def test_hash_of_a_resolved_case_is_the_formula(creature, body, scenario):
    case = resolve_case(creature, body, scenario)
    assert case.case_hash() == _formula(case) == uncached_case_hash(case)
