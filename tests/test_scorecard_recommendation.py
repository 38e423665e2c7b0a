"""The scorecard's recommendation survives a rerun (issue 40): costs are medians of timed repeats with their
spread, bodies within the spread are a tie, the deciding axis is named, a default dt near its stability limit
is a risk, one body gets no ranking; stable dt as a bisected bracket.  Constructed rows, no simulation."""
from __future__ import annotations

import pandas as pd
import pytest

from bench_myriapoda.report.scorecard import (
    COLUMNS, DT_RISK_MARGIN, Group, Row, bracket_group, compare, cost_group, recommend, repeat_rows)


def _timed(body: str, cpu_s_per_sim_s: list[float], creature: str = "centipede") -> pd.DataFrame:
    """A pair's headline case timed once per seed: realtime factor = 1 / CPU s per simulated s."""
    return pd.DataFrame([{"creature": creature, "body": body, "gait": "leg-wave", "scenario": "walk",
                          "duration": 10.0, "seed": i, "status": "ok", "realtime_factor": 1.0 / c,
                          "steps_per_s": 3000.0 / c, "label": f"{creature}/{body}/leg-wave/walk"}
                         for i, c in enumerate(cpu_s_per_sim_s)])


def _row(body: str, cpu: list[float], error: float | None = None, margin: float | None = None,
         creature: str = "centipede") -> Row:
    none = Group(None, "-", "no data")
    stab = none if margin is None else Group(margin * 1e-3, "", None, {
        "margin": margin, "largest_stable_dt_s": margin * 1e-3, "default_dt_s": 1e-3})
    loc = Group(error, "") if error is not None else Group(None, "speed commanded", "commanded")
    return Row(creature, body, stab, none, loc, cost_group(_timed(body, cpu, creature), creature, body), none,
               error, "speed error" if error is not None else "")


def test_cost_is_the_median_of_the_timed_repeats_with_their_range():
    g = cost_group(_timed("hybrid", [1.95, 1.91, 1.88]), "centipede", "hybrid")
    assert g.value == pytest.approx(1.91) and g.details["runs"] == 3
    assert g.details["spread_cpu_s_per_sim_s"] == pytest.approx(0.07)
    assert "median of 3 runs" in g.text
    one = cost_group(_timed("hybrid", [1.91]), "centipede", "hybrid")
    assert one.details["runs"] == 1 and "no spread" in one.details["spread_reason"]
    # a run of another duration (a sweep, a shorter case) is no repeat of the headline case
    mixed = pd.concat([_timed("hybrid", [1.9, 1.9, 1.9]), _timed("hybrid", [9.0]).assign(duration=1.0)])
    assert len(repeat_rows(mixed)) == 3 and cost_group(mixed, "centipede", "hybrid").value == pytest.approx(1.9)


def test_two_bodies_whose_costs_differ_by_less_than_their_spread_are_a_tie():
    # the README's old picture: hybrid 1.91 against massspring 1.92 CPU s/s, each over a few percent of spread
    hybrid, massspring = _row("hybrid", [1.95, 1.91, 1.88]), _row("massspring", [1.97, 1.92, 1.86])
    assert compare(1.91, 1.92, 0.07, 0.11) == 0
    line = recommend("centipede", [hybrid, massspring])
    assert "a tie on cost between" in line and "hybrid" in line and "massspring" in line, line
    assert "cheapest" not in line, line
    # the same bodies with costs beyond the spread are ranked, and the line says cost decided it
    cheap = _row("massspring", [0.117, 0.116, 0.118])
    line = recommend("centipede", [hybrid, cheap])
    assert "massspring is cheapest" in line and "decided by cost" in line, line
    # timed once each: no spread, no ranking on cost
    line = recommend("centipede", [_row("hybrid", [1.91]), _row("massspring", [0.116])])
    assert "not ranked" in line and "cheapest" not in line, line


def test_errors_and_costs_within_the_spread_tie_and_the_deciding_axis_is_named():
    a = _row("fem", [1.0, 1.02, 0.98], error=0.05, creature="snake")
    b = _row("massspring", [0.20, 0.21, 0.19], error=0.30, creature="snake")
    line = recommend("snake", [a, b])  # fem: less error, massspring: less cost: a trade-off
    assert "trade-off" in line and "neither axis decides alone" in line, line
    c = _row("hybrid", [1.01, 0.99, 1.03], error=0.05, creature="snake")  # fem's twin
    line = recommend("snake", [a, c])
    assert "a tie between" in line and "neither axis decides" in line, line
    d = _row("hybrid", [1.01, 0.99, 1.03], error=0.20, creature="snake")  # same cost, more error
    line = recommend("snake", [a, d])
    assert line.startswith("snake: fem (5 % speed error") and "decided by error" in line, line
    assert "hybrid: a tie on cost" in line, line
    e = _row("hybrid", [3.0, 3.1, 2.9], error=0.20, creature="snake")  # more error and more cost
    assert "decided by both error and cost" in recommend("snake", [a, e])


def test_a_creature_with_one_body_gets_no_cheapest_claim_and_a_dt_near_its_limit_is_a_risk():
    line = recommend("chain", [_row("hybrid", [0.17, 0.18, 0.16], creature="chain")])
    assert "only body in this matrix" in line and "no ranking" in line and "cheapest" not in line, line
    risky = _row("fem", [1.0, 1.1, 0.9], margin=1.09)
    safe = _row("massspring", [0.11, 0.12, 0.10], margin=2.5)
    line = recommend("centipede", [risky, safe])
    assert "Risk: fem's default dt 0.001 s is within 1.2x of its stability limit" in line, line
    assert "massspring's default dt" not in line
    assert DT_RISK_MARGIN == 1.2
    line = recommend("centipede", [_row("fem", [1.0, 1.1, 0.9], margin=0.7), safe])
    assert "fem's default dt 0.001 s is not stable" in line, line


def test_the_stability_cell_is_the_bisected_bracket_and_the_defaults_margin():
    entry = {"creature": "centipede", "body": "fem", "scenario": "walk", "default_dt_s": 1 / 3000,
             "trial_duration_s": 1.0, "rel_tol": 0.1, "stable_dt_max_s": 3.6e-4, "unstable_dt_min_s": 3.9e-4,
             "trials": [[1 / 3000, "ok", None], [2 / 3000, "unstable", 0.13], [3.9e-4, "unstable", 0.4],
                        [3.6e-4, "ok", None]], "error": ""}
    g = bracket_group(entry, 1 / 3000)
    assert g.text.startswith("[0.00036, 0.00039] s; default 0.000333 s, margin 1.08x (under 1.2x: a risk)"), g.text
    assert g.value == pytest.approx(3.6e-4) and g.details["bracketed"]
    assert g.details["smallest_unstable_dt_s"] / g.details["largest_stable_dt_s"] <= 1.1
    none = bracket_group({**entry, "stable_dt_max_s": None}, 1 / 3000)
    assert none.value is None and "bench-myriapoda stable-dt --creature centipede --body fem" in none.reason


def test_every_column_has_a_unit_and_a_definition():
    assert [c.key for c in COLUMNS] == ["stability", "fidelity", "locomotion", "shape", "cost"]
    for c in COLUMNS:
        assert c.unit and len(c.definition) > 40 and "[" in c.heading, c
