"""How the report presents what it shows (issue 40): round-off as 0, as on the terminal; the scorecard
figure's labels apart; the gait diagram's leg states explained where they are drawn."""
from __future__ import annotations

import pandas as pd
import pytest

from bench_myriapoda.core.cells import fmt
from bench_myriapoda.harness.terminal_table import cell
from bench_myriapoda.report.tables import HEADER_QUANTITY, html_table, md_table


@pytest.mark.parametrize("metric, header, noise, real", [
    ("max_penetration_m", "max penetration [m]", 3.388e-21, 2.5e-4),
    ("travel_angle_deg", "travel angle [deg]", 1.52e-13, 12.5),
    ("speed_m_per_s", "speed [m/s]", -4e-16, 0.0403),
])
def test_round_off_prints_as_0_in_the_report_as_on_the_terminal(metric, header, noise, real):
    assert HEADER_QUANTITY[header] == f"metric.{metric}"
    assert cell(noise, metric) == fmt(noise, metric) == fmt(noise, f"metric.{metric}") == "0"
    assert cell(real, metric) == fmt(real, metric) == f"{real:.4g}"
    df = pd.DataFrame({"body": ["fem", "hybrid"], header: [noise, real]})
    page = html_table(df)
    assert "<td>0</td>" in page and f"<td>{real:.4g}</td>" in page and "e-" not in page
    md = md_table(df)
    assert "| fem | 0 |" in md and f"| hybrid | {real:.4g} |" in md


def test_a_quantity_without_a_round_off_keeps_its_small_values():
    # an energy drift of 1e-12 is a measurement (the integrator's), not round-off of a position
    assert fmt(1e-12, "energy_drift_rel") == "1e-12" and fmt(1e-12) == "1e-12"
    assert fmt(float("nan"), "max_penetration_m") == "-" and fmt(None) == "-" and fmt(3) == "3"


# the quick matrix's 18 pairs as they fall on the figure: several nearly on top of each other (the chain's and
# the centipede's hybrid bodies once had their labels drawn over each other), and pairs with no error measure
CROWDED = [("worm", "massspring", 0.05, 0.02, "speed"), ("worm", "fem", 0.06, 0.3, "speed"),
           ("worm", "hybrid", 0.055, 1.2, "speed"), ("snake", "massspring", 0.0185, 0.05, "speed"),
           ("snake", "fem", 0.02, 0.5, "speed"), ("snake", "hybrid", 0.021, 1.9, "speed"),
           ("caterpillar", "massspring", 0.1, 0.03, "speed"), ("caterpillar", "fem", 0.11, 0.35, "speed"),
           ("caterpillar", "hybrid", 0.12, 1.5, "speed"), ("centipede", "massspring", 0.2, 0.116, "validate"),
           ("centipede", "fem", 0.21, 4.0, "validate"), ("centipede", "hybrid", 0.001, 1.91, "validate"),
           ("millipede", "massspring", 0.3, 0.2, "validate"), ("millipede", "fem", 0.31, 5.0, "validate"),
           ("millipede", "hybrid", 0.0012, 2.2, "validate"), ("chain", "hybrid", 0.001, 1.92, "validate"),
           ("chain", "massspring", None, 0.1, ""), ("chain", "fem", None, 0.12, "")]


def _text_boxes(fig):
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    return [(t.get_text(), t.get_window_extent(r)) for ax in fig.axes for t in ax.texts]


def test_the_scorecard_figures_labels_do_not_overlap(tmp_path):
    import matplotlib.pyplot as plt

    from bench_myriapoda.report.scorecard_figure import draw_error_vs_cost, plot_error_vs_cost

    fig = draw_error_vs_cost(CROWDED)
    boxes = _text_boxes(fig)
    assert sorted(t for t, _ in boxes) == sorted(f"{c}/{b}" for c, b, *_ in CROWDED)
    for i, (ta, a) in enumerate(boxes):
        for tb, b in boxes[i + 1:]:
            assert not a.overlaps(b), (ta, tb, a, b)
    frame = fig.bbox
    assert all(frame.x0 <= b.x0 and b.x1 <= frame.x1 and frame.y0 <= b.y0 and b.y1 <= frame.y1 for _, b in boxes)
    legend = fig.axes[0].get_legend().get_window_extent(fig.canvas.get_renderer())
    assert not any(legend.overlaps(b) for _, b in boxes)
    plt.close(fig)
    assert plot_error_vs_cost(CROWDED, tmp_path / "s.png").stat().st_size > 10_000


def test_the_gait_diagram_explains_its_leg_states_in_its_legend(tmp_path, monkeypatch):
    import matplotlib.pyplot as plt
    import numpy as np

    from bench_myriapoda.metrics.gait import STATE_DESCRIPTIONS, STATE_NAMES
    from bench_myriapoda.report import gait_diagram

    drawn = {}

    def keep(fig, path, *a, **k):  # the figure as saved, read before it is closed
        leg = fig.axes[0].get_legend()
        drawn["title"] = leg.get_title().get_text()
        drawn["labels"] = [t.get_text() for t in leg.get_texts()]
        plt.close(fig)
        return path

    monkeypatch.setattr(gait_diagram, "save_figure", keep)
    t = np.linspace(0.0, 2.0, 201)
    states = (np.arange(201)[:, None] // 20 + np.arange(8)[None, :]) % len(STATE_NAMES)
    gait_diagram.plot_gait_diagram(t, states, tmp_path / "g.png")
    for name, text in zip(STATE_NAMES, STATE_DESCRIPTIONS):
        assert f"{name}: {text}" in drawn["labels"]
    for abbreviation in ("PEP", "AEP", "MUP", "MDP"):  # the positions the descriptions name, spelt out
        assert abbreviation in drawn["title"]
    assert "posterior" in drawn["title"] and "middle up" in drawn["title"]
