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
from matrix_toml import WORM_ON_A_CLIFF, block, toml_table


# a small matrix that fills every section of the report
MATRIX = (toml_table("matrix", name="report-test", description="a small matrix that fills every section of the report",
                     seeds=[0])
          + WORM_ON_A_CLIFF
          + block(creatures=["centipede"], bodies=["hybrid"], scenarios=["walk"], duration=1.2)
          + block(creatures=["worm"], bodies=["massspring"], scenarios=["flat"], duration=0.3,
                  grid={"dt": [0.002, 0.03], "body.stiffness": [1.5, 6.0]})
          + block(creatures=["snake"], bodies=["massspring"], gaits=["lateral-undulation"], scenarios=["flat"],
                  duration=0.1, grid={"creature.segments": [6, 12, 24]}))


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
    # the worm and the centipede each have a comparison table; the sweeps are in them too (the snake's only
    # cases are a segment-count sweep), each row naming its swept values
    comp = html.split('<section id="comparison">', 1)[1].split("</section>", 1)[0]
    assert "<h3>worm</h3>" in comp and "<h3>centipede</h3>" in comp and "<h3>snake</h3>" in comp
    for n in (6, 12, 24):
        assert f"<td>creature.segments={n}</td>" in comp
    for dt in (0.002, 0.03):
        for k in (1.5, 6):
            assert f"<td>dt={dt:g}, body.stiffness={k:g}</td>" in comp
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
    from bench_myriapoda.cli import matrix  # the matrix subcommand, which quick runs

    seen = []
    monkeypatch.setattr(matrix, "cmd_matrix", lambda ns: seen.append(ns) or 0)
    assert cli.main([]) == 0
    ns = seen[0]
    assert (ns.file, Path(ns.out), ns.report, ns.executor, ns.resume) == ("quick", Path("reports/quick"), True,
                                                                          "local", False)


def test_report_plots_the_regress_history(matrix_dir, tmp_path, monkeypatch):
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
    # without a history (no --history-store, and no default reports/results.sqlite here; a named store that is
    # missing is refused since issue 41): the section says so and draws nothing
    (tmp_path / "empty").mkdir()
    monkeypatch.chdir(tmp_path / "empty")
    assert main(["report", str(matrix_dir)]) == 0
    section = (matrix_dir / "index.html").read_text().split('<section id="history">', 1)[1].split("</section>", 1)[0]
    assert "<img" not in section and "bench-myriapoda regress" in section


def _section(html: str, sid: str) -> str:
    return html.split(f'<section id="{sid}">', 1)[1].split("</section>", 1)[0]


def test_report_tables_footnote_metrics_that_do_not_apply(matrix_dir):
    html = (matrix_dir / "index.html").read_text()
    comp = _section(html, "comparison")
    # the worm and the centipede are driven: their energy drift is '-' with a mark, the reason below the table
    worm = comp.split("<h3>worm</h3>", 1)[1].split("<h3>", 1)[0]
    head = re.findall(r"<th>(.*?)</th>", worm.split("</thead>", 1)[0])
    rows = re.findall(r"<tr[^>]*>(.*?)</tr>", worm.split("<tbody>", 1)[1])
    col = head.index("energy drift [rel]")
    for row in rows:
        cells = re.findall(r"<td[^>]*>(.*?)</td>", row)
        assert cells[col] == "-<sup>a</sup>"
    assert re.search(r'<p class="footnote"><sup>a</sup> -: actively driven', worm)
    # the rules: a legged creature has no per-cycle speed; a passive chain no speed; a hanging body no speed
    from bench_myriapoda.report.tables import not_applicable_reason

    legged = {"gait": "leg-wave", "scenario": "walk", "case_json": json.dumps({"creature": {"legs_per_segment": 1}})}
    assert not_applicable_reason(legged, "metric.speed_bl_per_cycle") == "legged"
    assert not_applicable_reason(legged, "metric.speed_bl_per_s") is None
    assert not_applicable_reason(legged, "metric.energy_drift_rel") == "driven"
    chain = {"gait": "passive", "scenario": "fig4-drop"}
    assert not_applicable_reason(chain, "metric.speed_m_per_s") == "passive"
    assert not_applicable_reason(chain, "metric.travel_angle_deg") == "passive"
    assert not_applicable_reason(chain, "metric.energy_drift_rel") is None
    assert not_applicable_reason({"gait": "leg-wave", "scenario": "hang"}, "metric.speed_m_per_s") == "suspended"


def test_report_overview_separates_intended_blow_ups(matrix_dir):
    overview = _section((matrix_dir / "index.html").read_text(), "overview")
    # the two dt = 0.03 s runs of the dt x stiffness sweep blow up, as the sweep intends
    assert "Blow-ups: 2 intended" in overview and "0 unexpected" in overview


def test_report_draws_each_figure_once_with_captions_that_match_the_colours(matrix_dir):
    html = (matrix_dir / "index.html").read_text()
    srcs = re.findall(r'<img src="([^"]+)"', html)
    assert len(srcs) == len(set(srcs)), "a figure is shown twice"
    # the paper section links to the walk's gait diagram instead of showing it again
    paper = _section(html, "paper")
    gait_srcs = re.findall(r'<img src="(figures/gait_[^"]+)"', _section(html, "gait"))
    assert gait_srcs and all(f'<a href="#gait">{Path(g).name}</a>' in paper for g in gait_srcs)
    # viridis runs dark purple -> yellow: the captions say so (not "light to dark")
    assert "light to dark" not in html
    assert "from dark purple (start) to yellow (end)" in _section(html, "trajectories")


def test_seed_spread_and_shared_dt_grid():
    from bench_myriapoda.report.seed_spread import has_several_seeds, seed_spread
    from bench_myriapoda.report.sweeps import shared_dt_grid

    df = pd.DataFrame({"creature": "worm", "body": ["massspring"] * 3 + ["fem"], "gait": "rectilinear",
                       "scenario": "flat", "seed": [0, 1, 2, 0], "status": "ok",
                       "metric.speed_bl_per_s": [1.0, 2.0, 3.0, 5.0]})
    assert has_several_seeds(df)
    st = seed_spread(df, "metric.speed_bl_per_s").set_index("body")
    assert st.loc["massspring", "n"] == 3 and st.loc["massspring", "mean"] == 2.0
    assert st.loc["massspring", "std"] == pytest.approx(1.0)  # sample std (n - 1)
    assert st.loc["fem", "n"] == 1 and math.isnan(st.loc["fem", "std"])
    assert not has_several_seeds(df[df.seed == 0])
    groups = [("worm", "massspring", "body.stiffness", pd.DataFrame({"dt": [0.002, 0.01]})),
              ("worm", "fem", "body.youngs_modulus_pa", pd.DataFrame({"dt": [0.001, 0.01]}))]
    assert shared_dt_grid(groups) == [0.001, 0.002, 0.01]


_PROBE = """<script>window.addEventListener('load', () => {
  const imgs = [...document.images].map(i => [i.getAttribute('src'), i.getBoundingClientRect().width, i.naturalWidth,
                                              i.complete]);
  const secs = [...document.querySelectorAll('section')].map(s => [s.id, s.getBoundingClientRect().height,
                                                                   s.querySelector('h2').getBoundingClientRect().height]);
  const p = document.createElement('pre'); p.id = 'probe';
  const tables = [...document.querySelectorAll('table')].map(t => [t.closest('section').id,
                                                                   t.getBoundingClientRect().right,
                                                                   t.closest('section').getBoundingClientRect().right]);
  p.textContent = JSON.stringify({imgs, secs, tables, width: document.documentElement.clientWidth});
  document.body.appendChild(p);
});</script>"""


@pytest.mark.skipif(CHROMIUM is None, reason="Debian's chromium is not installed (.ci/run installs it)")
def test_report_in_chromium_at_1400_px_shows_every_section_and_images_at_least_800_px_wide(matrix_dir, tmp_path):
    """Laid out by headless chromium in a 1400 px window: every section there with its heading, every image
    loaded and drawn at least 800 px wide (the report's pages carry no script; a copy gets a probe)."""
    data = chromium_probe(matrix_dir / "index.html", tmp_path)
    assert 1300 <= data["width"] <= 1400
    assert [s[0] for s in data["secs"]] == [sid for sid, _ in SECTIONS]
    for sid, height, h2 in data["secs"]:
        assert h2 > 10 and height > h2, f"section {sid} not shown"
    assert len(data["imgs"]) >= 8
    for src, shown, natural, complete in data["imgs"]:
        assert complete and natural >= 800, f"{src}: {natural} px wide"
        assert shown >= 800, f"{src} drawn {shown} px wide"
    # issue 26: every table within the page (its right edge inside the window, no horizontal scrolling)
    assert data["tables"] and all(right <= page + 0.5 for _, right, page in data["tables"]), data["tables"]


def chromium_probe(index: Path, tmp_path: Path) -> dict:
    """Lay ``index`` out in headless chromium at 1400 px with the probe: images, sections, tables, page width."""
    import html as html_lib

    probe = index.parent / ".probe.html"
    probe.write_text(index.read_text().replace("</body>", _PROBE + "</body>"))
    try:
        cmd = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
               "--disable-background-networking", "--disable-component-update", "--disable-sync",
               f"--user-data-dir={tmp_path / 'profile'}", "--window-size=1400,1000", "--virtual-time-budget=20000",
               "--dump-dom", probe.as_uri()]
        dom = subprocess.run(cmd, check=True, timeout=120, capture_output=True, text=True).stdout
    finally:
        probe.unlink()
    return json.loads(html_lib.unescape(re.search(r'<pre id="probe">(.*?)</pre>', dom, re.S).group(1)))


@pytest.mark.skipif(CHROMIUM is None, reason="Debian's chromium is not installed (.ci/run installs it)")
def test_the_quick_report_at_1400_px_has_no_table_wider_than_the_page(quick_run, tmp_path):
    """The main job's report (issue 26): the scorecard and every detailed table fit a 1400 px window."""
    data = chromium_probe(quick_run.out / "index.html", tmp_path)
    assert 1300 <= data["width"] <= 1400
    sections = {sid for sid, _, _ in data["tables"]}
    assert {"scorecard", "comparison"} <= sections
    wide = [(sid, right, page) for sid, right, page in data["tables"] if right > page + 0.5]
    assert not wide, wide
    assert [s[0] for s in data["secs"]][0] == "scorecard"


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


def test_report_is_the_same_drawn_in_worker_processes(matrix_dir, tmp_path):
    """Figures drawn by forked workers (figure_pool) are the files one process draws, byte for byte; the page
    is the same apart from its build time."""
    from bench_myriapoda.report.build import build_report
    from bench_myriapoda.report.figure_pool import fork_context

    pages = {}
    for workers in (1, 2):
        d = tmp_path / f"w{workers}"
        shutil.copytree(matrix_dir, d, ignore=shutil.ignore_patterns("figures", "index.html", "summary.md"))
        summary = build_report(d, workers=workers)
        pages[workers] = (re.sub(r"Built [^.]*UTC", "Built", (d / "index.html").read_text()),
                          re.sub(r"Built [^.]*UTC", "Built", (d / "summary.md").read_text()),
                          {p.name: p.read_bytes() for p in summary.figures})
    one, two = pages[1], pages[2]
    assert len(one[2]) >= 8 and sorted(one[2]) == sorted(two[2])
    for name in one[2]:
        assert one[2][name] == two[2][name], f"{name} differs when drawn in a worker process"
    assert one[:2] == two[:2]
    if fork_context() is None:
        pytest.skip("no fork on this platform: both reports were drawn in this process")
