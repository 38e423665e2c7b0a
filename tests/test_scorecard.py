"""The scorecard (``report/scorecard.py``), too-short locomotion metrics, commanded speeds, the main job's
terminal table and ``load_results`` on the quick matrix's output (issue 26).

Most tests read the output of one run of the main job (``conftest.quick_run``).
"""
from __future__ import annotations

import html as html_lib
import json
import math
import re
import sqlite3

import pandas as pd
import pytest

import bench_myriapoda as bm
from bench_myriapoda.cli import main
from bench_myriapoda.core.errors import InputError
from bench_myriapoda.harness.terminal_table import cell, matrix_table_lines
from bench_myriapoda.report.scorecard import pareto_front

GROUPS = ("stability", "fidelity", "locomotion", "cost")


def _section(html: str, sid: str) -> str:
    return html.split(f'<section id="{sid}">', 1)[1].split("</section>", 1)[0]


def _pairs(out) -> set[tuple[str, str]]:
    df = bm.load_results(out)
    return set(zip(df["creature"], df["body"]))


# --------------------------------------------------------------------------- too short

def test_a_2_s_snake_run_is_too_short_and_not_judged_and_a_long_one_is(capsys, tmp_path, quick_run):
    from bench_myriapoda.report.paper_figures import figure_for
    from bench_myriapoda.report.validation import case_outcome
    from bench_myriapoda.validation.miller import judge_snake_coils

    db = tmp_path / "r.sqlite"
    argv = ["run", "--creature", "snake", "--body", "massspring", "--scenario", "flat", "--duration", "2", "--json",
            "--store", str(db)]
    assert main(argv) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["status"] == "ok"
    why = d["labels"]["too_short"]
    assert why.startswith("too short: 0.00 steady cycles") and "needs >= 2" in why
    for k in ("speed_bl_per_cycle", "speed_m_per_s", "travel_angle_deg", "path_following_error_bl"):
        assert d["metrics"][k] is None, k  # not a number
    assert d["metrics"]["steady_cycles"] == 0.0
    con = sqlite3.connect(db)
    labels, metrics = con.execute("SELECT labels_json, metrics_json FROM runs").fetchone()
    con.close()
    assert json.loads(labels)["too_short"] == why and json.loads(metrics)["speed_bl_per_cycle"] is None
    # the Image 2 verdict of this run: NOT APPLICABLE with the reason, never PASS or FAIL
    m = {k: (math.nan if v is None else v) for k, v in d["metrics"].items()}
    out = judge_snake_coils({**m, "too_short": why})
    assert out.verdict == "NOT APPLICABLE" and why in out.detail
    # the same case in the quick matrix runs long enough (>= 3 steady cycles): a PASS or a FAIL
    res = bm.load_results(quick_run.out)
    from bench_myriapoda.report.matrix_data import load_matrix_dir

    mr = load_matrix_dir(quick_run.out)
    row = mr.df[(mr.df.creature == "snake") & (mr.df.body == "massspring") & mr.df["grid.creature.segments"].isna()
                & mr.df["grid.dt"].isna()]  # the headline case, not a row of the size or dt sweep
    assert len(row) == 1 and len(res) == len(mr.df)
    row = row.iloc[0]
    assert row["metric.steady_cycles"] >= 3
    verdict, check = case_outcome(figure_for("flat", "lateral-undulation"), row, mr)
    assert check == "miller.image2-snake-coils" and verdict.verdict in ("PASS", "FAIL")


# --------------------------------------------------------------------------- the quick matrix's report

def test_the_quick_report_opens_with_the_scorecard_of_every_pair(quick_run):
    assert quick_run.code == 0
    html = (quick_run.out / "index.html").read_text()
    assert html.index('<section id="scorecard">') < html.index('<section id="overview">')
    sc = _section(html, "scorecard")
    rows = re.findall(r"<tr>(.*?)</tr>", sc.split("<tbody>", 1)[1])
    shown = {tuple(re.findall(r"<td>(.*?)</td>", r)[:2]) for r in rows}
    assert shown == _pairs(quick_run.out) and len(shown) >= 8
    creatures = {c for c, _ in shown}
    recs = re.findall(r'<p class="recommendation"><b>Recommendation</b> -- ([a-z]+): ', sc)
    assert sorted(recs) == sorted(creatures)
    assert '<img src="figures/scorecard_error_vs_cost.png"' in sc
    assert (quick_run.out / "figures" / "scorecard_error_vs_cost.png").is_file()
    md = (quick_run.out / "summary.md").read_text()
    assert md.index("Scorecard") < md.index("## Overview") and md.count("**Recommendation**") == len(creatures)


def test_millers_lattice_snake_does_not_fail_its_figure_in_the_quick_matrix(quick_run):
    paper = _section((quick_run.out / "index.html").read_text(), "paper")
    block = paper.split("Images 2a-2d (Miller, SIGGRAPH 1988): snake/massspring/", 1)[1].split("<h3>", 1)[0]
    verdict = re.search(r'data-verdict="([A-Z ]+)"', block).group(1)
    assert verdict != "FAIL", block[:600]
    # and the walks are long enough for the walking-cycle check: no centipede verdict is NOT APPLICABLE
    for body in ("hybrid", "massspring", "fem"):
        walk = paper.split(f"Figure 10 (D) and Sec. 6 (Fang, Jiang &amp; Terzopoulos, SCA 2013): centipede/{body}/",
                           1)[1]
        assert re.search(r'data-verdict="([A-Z ]+)"', walk).group(1) in ("PASS", "FAIL"), body


def test_scorecard_json_gives_each_pair_four_groups_each_a_number_or_a_reason(quick_run, capsys):
    assert main(["scorecard", str(quick_run.out), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    pairs = {(p["creature"], p["body"]) for p in doc["pairs"]}
    assert pairs == _pairs(quick_run.out)
    for p in doc["pairs"]:
        for g in GROUPS:
            group = p[g]
            assert isinstance(group["value"], (int, float)) or (isinstance(group["reason"], str) and group["reason"]), \
                (p["creature"], p["body"], g, group)
        assert p["cost"]["value"] > 0 and p["cost"]["details"]["steps_per_s"] > 0
        assert p["shape"]["text"] == "not measured" or isinstance(p["shape"]["value"], float)
    assert set(doc["recommendations"]) == {c for c, _ in pairs}
    # the dt sweeps give the worm's largest stable dt on both bodies, with the default dt's margin
    worm = {p["body"]: p for p in doc["pairs"] if p["creature"] == "worm"}
    for body in ("massspring", "fem"):
        st = worm[body]["stability"]
        assert st["value"] > 0 and st["details"]["margin"] >= 1.0, st
    # every headline pair of the quick matrix has a dt sweep: every stability cell is a number
    assert all(isinstance(p["stability"]["value"], float) for p in doc["pairs"]), [
        (p["creature"], p["body"], p["stability"]) for p in doc["pairs"]]
    # where a cell has no data, the reason names the command that fills it
    assert all("bench-myriapoda validate" in p["fidelity"]["reason"] for p in doc["pairs"]
               if p["fidelity"]["value"] is None and "no validate results" in p["fidelity"]["reason"])
    # the snake's speed is compared with the kinematic reference; the centipede's speed is commanded
    snake = [p for p in doc["pairs"] if p["creature"] == "snake"]
    assert all(isinstance(p["locomotion"]["value"], float) for p in snake)
    cent = [p for p in doc["pairs"] if p["creature"] == "centipede"]
    assert cent and all("command" in p["locomotion"]["reason"] for p in cent)
    # the text form names every pair too
    assert main(["scorecard", str(quick_run.out)]) == 0
    text = capsys.readouterr().out
    assert all(f"  {b}\n" in text for _, b in pairs)


def test_centipede_speed_is_commanded_and_its_emergent_measures_differ_between_bodies(quick_run):
    df = bm.load_results(quick_run.out)
    walks = df[(df.creature == "centipede") & (df.scenario == "walk")]
    walks = walks[walks.duration == walks.duration.max()]  # the headline walks, not the 0.5 s size sweep
    assert set(walks.body) == {"hybrid", "massspring", "fem"}
    # the speed is the command on every body (1 m/s, the body behind the head a few % slower) ...
    speed = walks.speed_m_per_s.astype(float)
    assert (abs(speed - 1.0) < 0.1).all() and speed.max() - speed.min() < 0.03 * speed.max(), list(speed)
    # ... the emergent measures are not the same numbers: each differs between the bodies, two by over 10 %
    spread = {}
    for k in ("body_speed_ratio", "lateral_sway_bl", "body_stretch_rel", "cost_of_transport_mech"):
        v = walks[k].astype(float)
        assert v.notna().all(), k
        spread[k] = (v.max() - v.min()) / abs(v).max()
        assert spread[k] > 1e-3, (k, list(v))
    assert sum(x > 0.1 for x in spread.values()) >= 2, spread
    comp = _section((quick_run.out / "index.html").read_text(), "comparison")
    cent = comp.split("<h3>centipede: locomotion and gait</h3>", 1)[1].split("<h3>", 1)[0]
    assert "commanded: a legged walk's speed is the head speed the controller commands" in html_lib.unescape(cent)
    head = re.findall(r"<th>(.*?)</th>", cent.split("</thead>", 1)[0])
    col = head.index("speed [m/s]")
    for row in re.findall(r"<tr[^>]*>(.*?)</tr>", cent.split("<tbody>", 1)[1].split("</tbody>", 1)[0]):
        assert re.findall(r"<td[^>]*>(.*?)</td>", row)[col].startswith("-<sup>")


def test_load_results_reads_the_quick_matrix_one_row_per_case(quick_run):
    manifest = json.loads((quick_run.out / "matrix.json").read_text())
    df = bm.load_results(quick_run.out)
    assert len(df) == len(manifest["cases"]) and df.case_hash.is_unique
    # a key swept on the FEM worm only is an empty cell on the lattice worm, not an error
    assert "body.youngs_modulus_pa" in df and "body.stiffness" in df
    ms = df[(df.creature == "worm") & (df.body == "massspring")]
    assert ms["body.youngs_modulus_pa"].isna().all() and ms["body.stiffness"].notna().any()
    with pytest.raises(InputError, match="not a configuration key of any run"):
        bm.load_results(quick_run.out, keys=["body.no_such_key"])


def test_the_main_jobs_terminal_table_explains_itself(quick_run):
    out = quick_run.stdout
    head = next(line for line in out.splitlines() if line.startswith("creature"))
    assert "swept values" in head and "duration [s]" in head
    assert "-- sweep over dt x body.stiffness (16 cases): blow-ups are intended" in out
    assert "unstable (intended)" in out and "e-1" not in out.split("report written", 1)[0].split(head, 1)[1]
    assert "(cmd)" in out  # the centipede's commanded speed
    last = out.strip().splitlines()[-1]
    assert re.match(r"\d+ cases: \d+ ok, \d+ unstable \(\d+ intended\), 0 error, 0 timeout; figure verdicts: .*; "
                    r"report: file:///.*/index\.html$", last), last


# --------------------------------------------------------------------------- units

def test_pareto_front_and_round_off_cells():
    pts = {"a": (0.1, 10.0), "b": (0.2, 1.0), "c": (0.3, 5.0), "d": (0.1, 12.0)}
    assert pareto_front(pts) == ["b", "a"]  # c: worse than b in both; d: worse than a in cost
    assert cell(9.043e-15, "speed_m_per_s") == "0" and cell(0.25, "speed_m_per_s") == "0.25"
    assert cell(9.043e-15) == "9.043e-15" and cell(float("nan")) == "-"


def test_terminal_table_groups_sweeps_and_labels_intended_blow_ups():
    rows = [{"creature": "worm", "body": "massspring", "gait": "rectilinear", "scenario": "flat", "duration": 10.0,
             "status": "ok", "metric.speed_bl_per_cycle": 0.1, "metric.speed_m_per_s": 1e-16, "steps_per_s": 1e4},
            {"creature": "worm", "body": "massspring", "gait": "rectilinear", "scenario": "flat", "duration": 1.0,
             "dt": 0.02, "status": "unstable", "metric.speed_m_per_s": 3.0, "metric.t_fail_s": 0.1},
            {"creature": "snake", "body": "massspring", "gait": "lateral-undulation", "scenario": "flat",
             "duration": 2.0, "status": "ok", "labels_json": json.dumps({"too_short": "too short: 0.00 steady"}),
             "creature.segments": 6}]
    lines = matrix_table_lines(rows, ["dt", "creature.segments"])
    text = "\n".join(lines)
    assert lines[0].split()[:5] == ["creature", "body", "gait", "scenario", "swept"]
    assert text.index("-- sweep over creature.segments (1 cases)") > text.index("rectilinear")
    assert "-- sweep over dt (1 cases): blow-ups are intended" in text
    unstable = next(line for line in lines if "unstable" in line)
    assert "unstable (intended)" in unstable and "dt=0.02" in unstable and " 3 " not in unstable
    assert "too short" in next(line for line in lines if "segments=6" in line)
    assert "1e-16" not in text


def test_the_report_tables_split_sweeps_and_blank_unstable_speeds():
    from bench_myriapoda.report.tables import comparison_tables

    base = {"creature": "worm", "body": "massspring", "gait": "rectilinear", "scenario": "flat"}
    df = pd.DataFrame([{**base, "duration": 10.0, "status": "ok", "metric.speed_m_per_s": 0.01,
                        "metric.t_fail_s": math.nan, "steps_per_s": 1e4, "grid.dt": math.nan},
                       {**base, "duration": 1.0, "status": "unstable", "metric.speed_m_per_s": 5.0,
                        "metric.t_fail_s": 0.2, "steps_per_s": 1e4, "grid.dt": 0.02}])
    tables = comparison_tables(df, ["grid.dt"], df["grid.dt"].notna())["worm"]
    titles = [t for t, _ in tables]
    assert titles == ["worm", "worm: locomotion and gait", "worm: sweep over dt"]
    sweep = tables[2][1].table
    assert list(sweep.columns[:4]) == ["body", "swept values", "duration [s]", "status"]
    assert "speed [m/s]" not in sweep and sweep["t_fail [s]"].iloc[0] == 0.2


def test_scorecard_of_something_that_is_not_a_matrix_directory_is_bad_input(tmp_path, capsys):
    assert main(["scorecard", str(tmp_path / "missing")]) == 2
    assert main(["scorecard", str(tmp_path)]) == 2  # a directory without results.sqlite and matrix.json
    err = capsys.readouterr().err
    assert err.count("bench-myriapoda: error: DIR:") == 2 and capsys.readouterr().out == ""


def test_fidelity_counts_the_pairs_verdicts_and_names_the_worst_deviation():
    from bench_myriapoda.report.scorecard import fidelity_group
    from bench_myriapoda.report.validation import ValidationData

    rows = pd.DataFrame([
        {"check": "analytic.worm-eps-lambda", "body": "fem", "measured": 0.09, "reference": 0.1, "verdict": "PASS"},
        {"check": "cross_body.worm-speed", "body": "fem", "measured": 0.5, "reference": 0.1, "verdict": "FAIL"},
        {"check": "analytic.cantilever", "body": "fem", "measured": 1.01, "reference": 1.0, "verdict": "PASS"},
        {"check": "miller.image2-snake-coils", "body": "fem", "measured": "x", "reference": "y", "verdict": "FAIL"},
        {"check": "analytic.worm-eps-lambda", "body": "massspring", "measured": 0.2, "reference": 0.1,
         "verdict": "FAIL"}])
    g = fidelity_group(ValidationData(rows, "test rows"), "worm", "fem")
    # the worm's two checks and the body's own cantilever; not the snake's check, not the other body's row
    assert g.details["counts"] == {"PASS": 2, "FAIL": 1}
    assert g.value == pytest.approx(1 / 3) and g.details["worst_check"] == "cross_body.worm-speed"
    assert g.details["worst_deviation_rel"] == pytest.approx(4.0) and "cross_body.worm-speed (400 % off)" in g.text
    none = fidelity_group(None, "worm", "fem")
    assert none.value is None and "bench-myriapoda validate --body fem" in none.reason


def test_shape_tracking_is_shown_when_measured_and_marks_the_speed_comparison():
    """Issue 27's metric.shape_tracking_error and metric.shape_not_achieved, when the results have them."""
    from bench_myriapoda.report.scorecard import locomotion_group, shape_group

    case = {"gait": {"amplitude": 0.2, "wavelength_bl": 1.0}, "creature": {"segments": 10, "segment_length_m": 0.1}}
    row = pd.Series({"creature": "worm", "body": "fem", "gait": "rectilinear", "scenario": "flat", "status": "ok",
                     "case_json": json.dumps(case), "labels_json": "{}", "metric.body_length_m": 1.0,
                     "metric.speed_bl_per_cycle": 0.15})
    plain = locomotion_group(row)
    assert plain.value == pytest.approx(0.25) and "[shape not achieved]" not in plain.text  # 0.15 against 0.2
    assert shape_group(row).text == "not measured"
    flagged = row.copy()
    flagged["metric.shape_tracking_error"], flagged["metric.shape_not_achieved"] = 0.4, 1.0
    assert "[shape not achieved]" in locomotion_group(flagged).text
    g = shape_group(flagged)
    assert g.value == 0.4 and g.details["shape_not_achieved"] and "shape not achieved" in g.text
    short = row.copy()
    short["labels_json"] = json.dumps({"too_short": "too short: 1.00 steady cycles"})
    assert locomotion_group(short).value is None and "too short: 1.00" in locomotion_group(short).reason


def test_fidelity_ranks_rows_by_the_share_of_their_tolerance_not_by_an_error_against_a_bound():
    """A row whose measured value is itself an error ("<= 1e-10") has no deviation from its reference; the row
    closest to its own tolerance is named, with the share of it used."""
    from bench_myriapoda.report.scorecard import fidelity_group, tolerance_used
    from bench_myriapoda.report.validation import ValidationData

    assert tolerance_used(8.9e-16, 0.458, "<= 1e-10")[:2] == (pytest.approx(8.9e-6), None)
    assert tolerance_used(0.956, 1.0, "5 % relative")[:2] == (pytest.approx(0.88), pytest.approx(0.044))
    assert tolerance_used(0.694, 0.5, ">= 0.5")[0] == pytest.approx(0.5 / 0.694)
    assert tolerance_used("4/4 behaviours", "all 4", "every described behaviour")[0] is None
    rows = pd.DataFrame([
        {"check": "analytic.damping-pure-mode", "body": "fem", "measured": 8.9e-16, "reference": 0.458,
         "tolerance": "<= 1e-10", "verdict": "PASS"},
        {"check": "analytic.cantilever", "body": "fem", "measured": 0.956, "reference": 1.0,
         "tolerance": "5 % relative", "verdict": "PASS"},
        {"check": "analytic.hanging-bar", "body": "fem", "measured": 0.99, "reference": 1.0,
         "tolerance": "5 % relative", "verdict": "PASS"}])
    g = fidelity_group(ValidationData(rows, "test rows"), "worm", "fem")
    assert g.details["worst_check"] == "analytic.cantilever" and g.value == 0.0
    assert g.details["worst_tolerance_used"] == pytest.approx(0.88)
    assert "closest to its tolerance: analytic.cantilever (4.4 % off), 88 % of its tolerance" in g.text


def test_the_snakes_speed_is_judged_at_the_commanded_wave_and_a_missed_shape_is_named_in_the_recommendation():
    """Issue 27: a body that bent less than commanded is compared with the speed of the commanded wave; the
    reference at its own measured wave is a detail, and the recommendation warns that the motions differ."""
    from bench_myriapoda.reference.slithering import steady_slithering
    from bench_myriapoda.report.scorecard import Group, Row, locomotion_group, recommend

    fr = {"model": "coulomb", "mu_forward": 0.05, "mu_backward": 0.075, "mu_transverse": 0.25}
    case = {"gait": {"curvature_amplitude": 7.0, "wavelength_bl": 1.0}, "friction": fr}
    row = pd.Series({"creature": "snake", "body": "massspring", "gait": "lateral-undulation", "scenario": "flat",
                     "status": "ok", "case_json": json.dumps(case), "labels_json": "{}",
                     "metric.speed_bl_per_cycle": 0.01, "metric.curvature_amplitude": 1.4,
                     "metric.body_wavelength_bl": 1.0, "metric.shape_tracking_error": 0.6,
                     "metric.shape_not_achieved": 1.0})
    at = lambda curv: steady_slithering(curv, 1.0, 0.05, 0.075, 0.25, n_points=100, n_time=48).speed_bl_per_cycle  # noqa: E731
    g = locomotion_group(row)
    assert g.details["reference_bl_per_cycle"] == pytest.approx(at(7.0))
    assert g.details["reference_at_measured_shape_bl_per_cycle"] == pytest.approx(at(1.4))
    assert "commanded wave" in g.details["reference"] and g.value == pytest.approx(abs(0.01 - at(7.0)) / at(7.0))
    raw = row.copy()  # a raw-strain gait commands no shape: its own measured wave is the reference
    raw["case_json"] = json.dumps({"gait": {"curvature_amplitude": 0.0, "wavelength_bl": 1.0}, "friction": fr})
    assert locomotion_group(raw).details["reference_bl_per_cycle"] == pytest.approx(at(1.4))

    def pair(body, err, cost, shape_err):
        none = Group(None, "-")
        shape = Group(shape_err, "", None, {"shape_not_achieved": shape_err > 0.1})
        return Row("snake", body, none, none, Group(err, ""), Group(cost, ""), shape, err, "speed error")

    line = recommend("snake", [pair("fem", 0.05, 1.0, 0.04), pair("massspring", 0.9, 0.1, 0.6)])
    assert "Caution: not at the commanded shape (massspring 0.6 shape_tracking_error" in line
    assert "fem 0.04" not in line
    assert "Caution" not in recommend("snake", [pair("fem", 0.05, 1.0, 0.04)])


# --------------------------------------------------------------------------- issue 40: every pair, with fidelity

ALL_PAIRS = {(c, b) for c in ("worm", "snake", "caterpillar", "centipede", "millipede", "chain")
             for b in ("massspring", "fem", "hybrid")}


def test_the_quick_matrix_scorecard_has_all_18_pairs_each_with_verdict_counts_and_a_stable_dt_bracket(
        quick_run, capsys):
    """Over the real main job's output (conftest.quick_run): the matrix, the bisections and the validate checks."""
    assert main(["scorecard", str(quick_run.out), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert {(p["creature"], p["body"]) for p in doc["pairs"]} == ALL_PAIRS and len(doc["pairs"]) == 18
    for p in doc["pairs"]:
        fid, st = p["fidelity"], p["stability"]
        assert re.match(r"\d+ (PASS|FAIL|INFO|NOT APPLICABLE)", fid["text"]), (p["creature"], p["body"], fid)
        assert "not validated" not in fid["text"] and sum(fid["details"]["counts"].values()) >= 1
        lo, hi = st["details"]["largest_stable_dt_s"], st["details"]["smallest_unstable_dt_s"]
        assert lo > 0 and hi > lo and hi / lo <= 1.1 + 1e-9, (p["creature"], p["body"], st)
        assert st["details"]["source"].startswith("bisection to 10 %") and st["text"].startswith("[")
        assert st["details"]["margin"] == pytest.approx(lo / st["details"]["default_dt_s"])
    # the verdicts went into the matrix directory, as `validate --out DIR` writes them
    v = json.loads((quick_run.out / "validation.json").read_text())
    assert v["quick"] and v["main_job"] and {r["body"] for r in v["rows"]} == {"massspring", "fem", "hybrid"}
    # every column's unit and definition, in the JSON, the terminal text and the page
    assert set(doc["columns"]) == {"stability", "fidelity", "locomotion", "shape", "cost"}
    assert main(["scorecard", str(quick_run.out)]) == 0
    text = capsys.readouterr().out
    assert "columns:" in text and "shape_tracking_error: RMS" in text and "[CPU s per simulated s" in text
    sc = _section((quick_run.out / "index.html").read_text(), "scorecard")
    assert sc.count("<dt>") == 5 and "Unit: CPU s per simulated s" in html_lib.unescape(sc)


def test_the_figures_verdicts_and_the_fidelity_column_agree_in_the_quick_report(quick_run, capsys):
    """One source (report.scorecard_verdicts): every figure's verdict is a row of its pair's fidelity cell."""
    assert main(["scorecard", str(quick_run.out), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    checks = {(p["creature"], p["body"]): p["fidelity"]["details"].get("checks", []) for p in doc["pairs"]}
    paper = _section((quick_run.out / "index.html").read_text(), "paper")
    blocks = re.findall(r"<h3>[^<]*?\): ([a-z]+)/([a-z]+)/[^<]*</h3>(.*?)(?=<h3>|$)", paper, re.S)
    judged = 0
    for creature, body, block in blocks:
        m = re.search(r'data-verdict="([A-Z ]+)"(?: data-check="([^"]+)")?', block)
        verdict, check = m.group(1), m.group(2)
        if check is None:
            assert verdict == "NOT VALIDATED"
            continue
        judged += 1
        assert {"check": check, "verdict": verdict, "kind": "figure"} in checks[(creature, body)], (creature, body)
    assert judged >= 12  # the snakes, centipedes, millipedes and chains


def test_the_quick_report_fills_its_validation_section_and_says_how_to_fill_its_regress_history(quick_run):
    page = (quick_run.out / "index.html").read_text()
    val = _section(page, "validation")
    assert "No validation results" not in val and "validation.json" in val
    assert len(re.findall(r"<tr", val)) > 15
    hist = html_lib.unescape(_section(page, "history"))
    assert '<img src="figures/regress_history.png"' in hist or "run `bench-myriapoda regress`" in hist
