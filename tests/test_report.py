"""``bench-myriapoda report``: sections, self-contained references, baseline regressions, a browser screenshot."""
from __future__ import annotations

import json
import math
import re
import shutil
import sqlite3
import subprocess
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.report.baseline import compare_runs
from bench_myriapoda.report.build import SECTIONS
from bench_myriapoda.report.matrix_data import MatrixResults
from bench_myriapoda.report.sweeps import fit_exponent

MATRIX = """
[matrix]
name = "report-test"
description = "a small matrix that fills every section of the report"
seeds = [0]

[[block]]
creatures = ["worm"]
bodies = ["massspring"]
scenarios = ["cliff"]
gaits = ["rectilinear"]
duration = 0.6

[[block]]
creatures = ["centipede"]
bodies = ["hybrid"]
scenarios = ["walk"]
duration = 1.2

[[block]]
creatures = ["worm"]
bodies = ["massspring"]
scenarios = ["flat"]
duration = 0.3
grid = { "dt" = [0.002, 0.03], "body.stiffness" = [1.5, 6.0] }

[[block]]
creatures = ["snake"]
bodies = ["massspring"]
gaits = ["lateral-undulation"]
scenarios = ["flat"]
duration = 0.1
grid = { "creature.segments" = [6, 12, 24] }
"""


class _Refs(HTMLParser):
    """Every src/href in a page, and the ids of its sections."""

    def __init__(self):
        super().__init__()
        self.refs: list[str] = []
        self.sections: list[str] = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for k in ("src", "href"):
            if a.get(k):
                self.refs.append(a[k])
        if tag == "section":
            self.sections.append(a.get("id"))


@pytest.fixture(scope="module")
def matrix_dir(tmp_path_factory):
    d = tmp_path_factory.mktemp("report")
    f = d / "m.toml"
    f.write_text(MATRIX)
    out = d / "out"
    assert main(["matrix", str(f), "--out", str(out), "--workers", "2", "--report"]) == 0
    return out


def _parse(path: Path) -> _Refs:
    p = _Refs()
    p.feed(path.read_text(encoding="utf-8"))
    return p


def test_report_has_every_section_and_only_existing_files(matrix_dir):
    index = matrix_dir / "index.html"
    refs = _parse(index)
    assert refs.sections == [sid for sid, _ in SECTIONS]
    files = [r for r in refs.refs if not r.startswith("#")]
    assert len(files) >= 8  # gait diagram, phase lags, trajectories, stability, scaling, energy, paper figures
    for r in files:
        assert not re.match(r"^[a-z]+://", r), f"network reference {r}"
        assert (matrix_dir / r).is_file(), f"index.html references a missing file {r}"
    for r in refs.refs:
        if r.startswith("#"):
            assert r[1:] in refs.sections
    # the markdown summary references the same existing images
    md = (matrix_dir / "summary.md").read_text()
    for r in re.findall(r"!\[[^\]]*\]\(([^)]+)\)", md):
        assert (matrix_dir / r).is_file()
    html = index.read_text()
    # every section has content, not only the "nothing to show" note: these sections must draw a figure here
    for sid in ("gait", "trajectories", "stability", "scaling", "energy", "paper"):
        body = html.split(f'<section id="{sid}">', 1)[1].split("</section>", 1)[0]
        assert "<img" in body, f"section {sid} drew no figure"
    # the worm and the centipede each have a comparison table; the sweeps are not in it
    comp = html.split('<section id="comparison">', 1)[1].split("</section>", 1)[0]
    assert "<h3>worm</h3>" in comp and "<h3>centipede</h3>" in comp and "<h3>snake</h3>" not in comp
    # the dt=0.03 s lattice blows up: the heatmap and the overview count it
    assert "unstable" in html.split('<section id="overview">', 1)[1].split("</section>", 1)[0]


def test_report_rebuild_replaces_figures_and_leaves_no_temporaries(matrix_dir):
    stale = matrix_dir / "figures" / "stale.png"
    stale.write_bytes(b"x")
    assert main(["report", str(matrix_dir)]) == 0
    assert not stale.exists()
    assert not [p for p in matrix_dir.iterdir() if p.name.startswith(".")]


def test_baseline_regressions_are_highlighted(matrix_dir, tmp_path):
    base = tmp_path / "base"
    shutil.copytree(matrix_dir, base)
    con = sqlite3.connect(base / "results.sqlite")
    with con:
        rows = con.execute("SELECT id, metrics_json, steps_per_s, status, creature FROM runs").fetchall()
        for run_id, mj, sps, status, creature in rows:
            m = json.loads(mj)
            if creature == "worm" and status == "unstable":
                status = "ok"  # the baseline was stable: now unstable is a regression
            if m.get("energy_max_dev_rel"):
                m["energy_max_dev_rel"] = m["energy_max_dev_rel"] / 10.0  # the energy error grew 10x: a regression
            con.execute("UPDATE runs SET metrics_json = ?, steps_per_s = ?, timings_json = ?, status = ? WHERE id = ?",
                        (json.dumps(m), sps * 3.0 if sps else sps, json.dumps({"steps_per_s": sps * 3.0 if sps else sps}),
                         status, run_id))
    con.close()
    assert main(["report", str(matrix_dir), "--baseline", str(base)]) == 0
    html = (matrix_dir / "index.html").read_text()
    section = html.split('<section id="baseline">', 1)[1].split("</section>", 1)[0]
    reg_rows = re.findall(r'<tr class="regression">(.*?)</tr>', section)
    text = " ".join(reg_rows)
    assert "<td>status</td>" in text and "<td>steps_per_s</td>" in text and "<td>energy_max_dev_rel</td>" in text
    assert main(["report", str(matrix_dir), "--baseline", str(base), "--strict"]) == 1
    # against itself: nothing to flag
    assert main(["report", str(matrix_dir), "--baseline", str(matrix_dir), "--strict"]) == 0


def test_compare_runs_directions():
    def res(rows):
        df = pd.DataFrame(rows)
        return MatrixResults(Path("."), "m", "", [], df, [])

    base = res([{"case_hash": "a", "label": "A", "status": "ok", "metric.max_penetration_m": 1e-3,
                 "metric.speed_m_per_s": 1.0, "metric.min_J": 0.5, "steps_per_s": 1000.0, "realtime_factor": 1.0},
                {"case_hash": "b", "label": "B", "status": "ok", "metric.max_penetration_m": 1e-3,
                 "metric.speed_m_per_s": 1.0, "metric.min_J": 0.5, "steps_per_s": 1000.0, "realtime_factor": 1.0}])
    now = res([{"case_hash": "a", "label": "A", "status": "ok", "metric.max_penetration_m": 0.5e-3,
                "metric.speed_m_per_s": 1.5, "metric.min_J": 0.2, "steps_per_s": 900.0, "realtime_factor": 0.9},
               {"case_hash": "c", "label": "B", "status": "unstable", "metric.max_penetration_m": 1e-3,
                "metric.speed_m_per_s": 1.0, "metric.min_J": 0.5, "steps_per_s": 500.0, "realtime_factor": 0.5}])
    d = compare_runs(now, base)
    v = {(r.case, r.quantity): r.verdict for r in d.itertuples()}
    assert v[("A", "max_penetration_m")] == "improvement"
    assert v[("A", "speed_m_per_s")] == "changed"          # no better direction
    assert v[("A", "min_J")] == "regression"               # elements closer to inversion
    assert ("A", "steps_per_s") not in v                   # -10 % is within the 15 % throughput noise band
    assert v[("B", "status")] == "regression"              # matched by label although the hash changed
    assert v[("B", "steps_per_s")] == "regression"


def test_fit_exponent_recovers_power_law():
    n = np.array([5.0, 10.0, 20.0, 40.0])
    p, c = fit_exponent(n, 3.0e5 * n ** -1.3)
    assert abs(p + 1.3) < 1e-12 and abs(c - 3.0e5) < 1e-6
    assert math.isnan(fit_exponent(np.array([5.0, 5.0]), np.array([1.0, 2.0]))[0])


def test_report_of_a_non_matrix_directory_is_bad_input(tmp_path, capsys):
    assert main(["report", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "results.sqlite" in err and str(tmp_path) in err
    assert not (tmp_path / "index.html").exists()
    assert main(["report", str(tmp_path / "missing")]) == 2


CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


@pytest.mark.skipif(CHROMIUM is None, reason="Debian's chromium is not installed (.ci/run installs it)")
def test_report_renders_in_headless_chromium(matrix_dir, tmp_path):
    from PIL import Image

    shot = tmp_path / "shot.png"
    cmd = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync",
           f"--user-data-dir={tmp_path / 'profile'}", f"--screenshot={shot}", "--window-size=1200,2400",
           (matrix_dir / "index.html").as_uri()]
    subprocess.run(cmd, check=True, timeout=120, capture_output=True)
    img = np.asarray(Image.open(shot).convert("L"), dtype=float)
    assert img.shape == (2400, 1200)
    # a rendered page with tables and figures, not a blank or error page: many distinct grey levels, dark text
    assert len(np.unique(img)) > 50 and (img < 100).mean() > 0.005


def test_no_arguments_run_the_quick_matrix_with_its_report(monkeypatch):
    import bench_myriapoda.cli as cli

    seen = []
    monkeypatch.setattr(cli, "cmd_matrix", lambda ns: seen.append(ns) or 0)
    assert cli.main([]) == 0
    ns = seen[0]
    assert (ns.file, Path(ns.out), ns.report, ns.executor, ns.resume) == ("quick", Path("reports/quick"), True,
                                                                          "local", False)


def test_report_plots_the_regress_history(matrix_dir, tmp_path):
    from bench_myriapoda.harness.store import record_regress_run

    store = tmp_path / "history.sqlite"
    for scale in (1.0, 0.5):  # a second run at half the throughput
        record_regress_run(store, [{"entry": "massspring-snake", "steps_per_rep": 1000, "repeats": 3,
                                    "steps_per_s": 4e4 * scale, "spread": 0.01, "reference_ops_per_s": 1e8,
                                    "reference_spread": 0.01, "normalized": 4e-4 * scale, "samples_json": "[]"}])
    assert main(["report", str(matrix_dir), "--history-store", str(store)]) == 0
    section = (matrix_dir / "index.html").read_text().split('<section id="history">', 1)[1].split("</section>", 1)[0]
    src = re.findall(r'<img src="([^"]+)"', section)
    assert src == ["figures/regress_history.png"] and (matrix_dir / src[0]).is_file()
    # without a history: the section says so and draws nothing
    assert main(["report", str(matrix_dir), "--history-store", str(tmp_path / "none.sqlite")]) == 0
    section = (matrix_dir / "index.html").read_text().split('<section id="history">', 1)[1].split("</section>", 1)[0]
    assert "<img" not in section and "bench-myriapoda regress" in section


def test_report_history_lists_the_peer_speedups(matrix_dir, tmp_path):
    from bench_myriapoda.harness.store import record_regress_run

    store = tmp_path / "history.sqlite"
    for ours in (2e4, 3e4):  # two peers runs: ours gets faster, MuJoCo stays at 1,000 steps/s
        record_regress_run(store, [{"entry": e, "steps_per_rep": 100, "repeats": 3, "steps_per_s": sps,
                                    "spread": 0.01, "reference_ops_per_s": 1e8, "reference_spread": 0.01,
                                    "normalized": sps / 1e8, "samples_json": "[]"}
                                   for e, sps in (("peer:mujoco-flex-816", 1e3), ("ours:fem-chain-816", ours))])
    assert main(["report", str(matrix_dir), "--history-store", str(store)]) == 0
    section = (matrix_dir / "index.html").read_text().split('<section id="history">', 1)[1].split("</section>", 1)[0]
    assert "ours:fem-chain-816 vs peer:mujoco-flex-816" in section
    assert "<td>20</td>" in section and "<td>30</td>" in section
