"""``bench-myriapoda report DIR``: the comparison report of a matrix run.

Writes ``DIR/index.html`` (self-contained: inline CSS, no scripts, images as
relative files under ``DIR/figures/``, so it opens from disk with no server
and no network) and ``DIR/summary.md`` (the same tables, for a pull request
or a terminal).  Sections, each an ``<section id=...>``:

``scorecard``     which body model for each creature: stability, fidelity, locomotion against a reference and
                  cost per creature x body, a recommendation per creature and the error-vs-cost figure
                  (``report/scorecard.py``)
``overview``      what ran: matrix, case counts by status, unsupported combinations
``comparison``    per creature, the body models side by side: stability and throughput, then speed and gait;
                  then each sweep in its own table per swept key (short runs: stability and throughput)
``gait``          leg-state diagrams (paper Fig. 10) and phase lags along the body, per legged case
``trajectories``  bodies and paths seen from above, over the terrain, per creature
``stability``     dt x stiffness heatmaps per body model (cases of a sweep over ``dt`` and a stiffness key)
``scaling``       steps/s against segment count and mesh resolution, log-log, fitted exponent
``energy``        kinetic, elastic, gravitational and total energy over time
``paper``         figure-like images next to the papers' captions, for the cases that reproduce a figure,
                  each with its verdict (``report/validation.py``)
``validation``    the latest ``validate`` verdicts and the work-precision diagrams (``report/validation.py``)
``history``       the ``regress`` history of normalized throughput (from the results store)
``baseline``      with ``--baseline DIR2``: each metric's change against DIR2, regressions highlighted

A section with nothing to show says why (e.g. no sweep over dt in this
matrix) rather than disappearing, so every report has the same outline.
The report is built in a temporary directory and moved into place, so an
interrupted build leaves the previous report intact.
"""
from __future__ import annotations

import html
import logging
import os
import shutil
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from ..core.cells import fmt
from ..harness.recorder import series_from_recording
from ..harness.store import StoreReadError
from . import body_wave, friction_sweep, schedule_section, stance_sweeps, sweeps
from .baseline import compare_runs, format_change
from .matrix_data import MatrixResults, load_matrix_dir
from .paper_figures import PAPER_STEPS_PER_S, PAPER_THROUGHPUT_NOTE, figure_for
from .figure_files import report_style
from .figure_pool import FigurePainter
from .tables import comparison_tables, footnote_marks, html_table, md_table
from .scorecard_verdicts import pair_verdicts
from .validation import figure_verdict, load_validation, section as validation_section

SECTIONS = (("scorecard", "Scorecard: which body model for each creature"), ("overview", "Overview"), ("comparison", "Comparison across body models"),
            ("gait", "Gait diagrams and phase lags"), ("trajectories", "Trajectories from above"),
            ("stability", "Stability heatmaps (dt x stiffness)"), ("scaling", "Throughput scaling"),
            ("schedule", "Matrix schedule"),
            ("energy", "Energy over time"), ("paper", "Reproduced paper figures"), ("validation", "Validation"),
            ("history", "Performance history (regress)"), ("baseline", "Changes against the baseline"))
MAX_GAIT_CASES = 12  # a matrix with many legged cases shows the first ones; the tables list all

# Read at about 1400 px: a figure is shown at its own pixel size (every report figure is >= 800 px wide,
# figure_files.MIN_WIDTH_PX) and only shrinks to the page width, never to a fraction of it.
CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:1.5em auto;max-width:1360px;
padding:0 1em;color:#222}
h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:2em}
h3{font-size:1em;margin-bottom:.3em}
table{border-collapse:collapse;font-size:.8em;margin:.4em 0 1em;max-width:100%}
table.scorecard td,table.scorecard th{text-align:left;vertical-align:top;max-width:22em}p.recommendation{margin:.2em 0}dl.columns{margin:.3em 0}dl.columns dt{font-weight:600}dl.columns dd{margin:0 0 .3em 1.5em}
th,td{border:1px solid #ddd;padding:.2em .5em;text-align:right}th{background:#f3f3f3}
td:first-child,th:first-child{text-align:left}
tr.regression td{background:#fbd5d5;color:#8b0000;font-weight:600}tr.missing td{background:#fde8c8}
tr.improvement td{background:#d8f0dc}tr.unstable td{background:#fff3cd}tr.error td,tr.timeout td{background:#f8d7da}
figure{display:block;margin:.3em 0 1.2em 0}
figure img{max-width:100%;border:1px solid #eee}figcaption{font-size:.9em;color:#444;max-width:1000px}
td.na{color:#999}p.footnote{font-size:.85em;color:#555;margin:.1em 0}
nav a{margin-right:.8em;font-size:.9em}.note{color:#666;font-size:.85em}
.caption{font-style:italic;max-width:900px}
"""


@dataclass
class ReportSummary:
    """What ``build_report`` wrote and found."""

    index: Path
    summary: Path
    figures: list[Path] = field(default_factory=list)
    regressions: int = 0
    verdicts: dict[str, int] = field(default_factory=dict)  # the reproduced figures' verdicts, counted


class _Page:
    """Collects the HTML and Markdown of the report, and the figures it references."""

    def __init__(self, fig_dir: Path, painter: FigurePainter | None = None):
        self.fig_dir = fig_dir
        self.painter = painter or FigurePainter(1)
        self.html: list[str] = []
        self.md: list[str] = []
        self.figures: list[Path] = []
        self.verdicts: dict[str, int] = {}

    def draw(self, path: Path, fn, *args, **kwargs) -> Path:
        """Have ``fn(*args, **kwargs)`` write the figure file ``path`` (perhaps in a worker: ``figure_pool``)."""
        return self.painter.draw(path, fn, *args, **kwargs)

    def section(self, sid: str, title: str) -> None:
        if self.html:
            self.html.append("</section>")
        self.html.append(f'<section id="{sid}"><h2>{html.escape(title)}</h2>')
        self.md.append(f"\n## {title}\n")

    def p(self, text: str, cls: str = "") -> None:
        c = f' class="{cls}"' if cls else ""
        self.html.append(f"<p{c}>{html.escape(text)}</p>")
        self.md.append(text + "\n")

    def h3(self, text: str) -> None:
        self.html.append(f"<h3>{html.escape(text)}</h3>")
        self.md.append(f"\n### {text}\n")

    def table(self, df: pd.DataFrame, row_classes=None, notes=None, footnotes: dict[str, str] | None = None,
              css: str = "") -> None:
        """A table; ``notes`` / ``footnotes``: blanked cells and their reasons (``tables.ComparisonTable``)."""
        marks = footnote_marks(footnotes or {})
        t = html_table(df, row_classes, notes, marks)
        self.html.append(t.replace("<table>", f'<table class="{css}">', 1) if css else t)
        self.md.append(md_table(df, notes, marks))
        for key, text in (footnotes or {}).items():
            self.html.append(f'<p class="footnote"><sup>{marks[key]}</sup> -: {html.escape(text)}</p>')
            self.md.append(f"({marks[key]}) -: {text}\n")

    def figure(self, path: Path, caption: str) -> None:
        """Show a figure; each file once per report (a second use of the same file is a link to the first)."""
        rel = path.relative_to(self.fig_dir.parent).as_posix()
        anchor = "fig-" + _slug(path.stem)
        if path in self.figures:
            self.html.append(f'<p class="note">{html.escape(caption)}: {html.escape(path.name)}, shown above</p>')
            self.md.append(f"{caption}: see above ({rel})\n")
            return
        self.figures.append(path)
        self.html.append(f'<figure id="{anchor}"><img src="{html.escape(rel)}" alt="{html.escape(caption)}">'
                         f"<figcaption>{html.escape(caption)}</figcaption></figure>")
        self.md.append(f"![{caption}]({rel})\n")

    def link(self, path: Path, text: str, section: str) -> None:
        """A line pointing at a figure shown in another section of the report (not drawn again)."""
        self.html.append(f'<p class="note">{html.escape(text)}: <a href="#{section}">{html.escape(path.name)}'
                         f"</a> in section {html.escape(dict(SECTIONS)[section])}</p>")
        self.md.append(f"{text}: see {path.relative_to(self.fig_dir.parent).as_posix()}\n")


def _slug(*parts) -> str:
    s = "_".join(str(p) for p in parts)
    return "".join(ch if ch.isalnum() or ch in "-_." else "-" for ch in s)


def build_report(directory: Path | str, baseline: Path | str | None = None, history_store: Path | str | None = None,
                 threshold: float = 0.10, workers: int = 1) -> ReportSummary:
    """Write ``DIR/index.html``, ``DIR/summary.md`` and ``DIR/figures/``; see the module docstring.

    workers: processes drawing the figures (``figure_pool.FigurePainter``); 1 = all in this process.
    The page and its images are the same for any number.
    """
    # equal-aspect top views over an inverted axis make matplotlib log "Ignoring fixed limits" for every
    # panel: expected here (the data limits adjust), so not shown
    logging.getLogger("matplotlib.axes._base").setLevel(logging.ERROR)
    res = load_matrix_dir(directory, "DIR")
    base = load_matrix_dir(baseline, "--baseline") if baseline is not None else None
    d = res.directory
    check_report_outputs(d)
    clean_stale_temporaries(d)
    tmp = Path(tempfile.mkdtemp(prefix=f"{TMP_PREFIX}{os.getpid()}-", dir=d))
    try:
        with report_style(), FigurePainter(workers) as painter:
            return _build(res, base, history_store, threshold, d, tmp, painter)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _build(res: MatrixResults, base: MatrixResults | None, history_store, threshold: float, d: Path,
           tmp: Path, painter: FigurePainter) -> ReportSummary:
    """The body of ``build_report``: every section into ``tmp``, then moved into ``d``."""
    page = _Page(tmp / "figures", painter)
    page.fig_dir.mkdir()
    vdata = load_validation(d, Path(history_store) if history_store else None)
    # one verdict table: the scorecard's fidelity column and the figures' verdicts read the same rows
    verdicts = pair_verdicts(res, vdata)
    _scorecard(page, res, verdicts, Path(history_store) if history_store else None, d)
    _overview(page, res)
    sweep = sweeps.sweep_mask(res.df, res.grid_keys) if not res.df.empty else pd.Series(dtype=bool)
    main = res.df[~sweep] if not res.df.empty else res.df
    _comparison(page, res)
    _gait(page, res, main)
    _trajectories(page, res, main)
    _stability(page, res)
    _scaling(page, res)
    schedule_section.section(page, d)  # parallel efficiency and critical path of the run (matrix.json)
    if not res.df.empty and body_wave.has_body_wave_sweep(res.df, res.grid_keys):
        body_wave.report_section(page, res)
    if not res.df.empty and friction_sweep.has_friction_sweep(res.df, res.grid_keys):
        friction_sweep.report_section(page, res)
    if not res.df.empty:
        stance_sweeps.report_sections(page, res)
    _energy(page, res, main)
    _paper(page, res, main, vdata, verdicts)
    validation_section(page, vdata, Path(history_store) if history_store else None, verdicts)
    _history(page, Path(history_store) if history_store else None)
    regressions = _baseline(page, res, base, threshold)
    painter.finish()  # every figure file written before the page that shows it
    page.html.append("</section>")
    nav = "".join(f'<a href="#{sid}">{html.escape(t)}</a>' for sid, t in SECTIONS)
    title = f"bench-myriapoda report: matrix {res.name}"
    doc = (f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
           f"<style>{CSS}</style></head><body><h1>{html.escape(title)}</h1><nav>{nav}</nav>"
           + "\n".join(page.html) + "</body></html>\n")
    (tmp / "index.html").write_text(doc, encoding="utf-8")
    (tmp / "summary.md").write_text(f"# {title}\n" + "\n".join(page.md), encoding="utf-8")
    # move into place: figures first (the old page keeps working until index.html is replaced)
    final_fig = d / "figures"
    old = d / f"{OLD_FIGURES_PREFIX}{os.getpid()}"
    if final_fig.exists():
        final_fig.rename(old)
    (tmp / "figures").rename(final_fig)
    os.replace(tmp / "index.html", d / "index.html")
    os.replace(tmp / "summary.md", d / "summary.md")
    shutil.rmtree(old, ignore_errors=True)
    figures = [final_fig / p.name for p in page.figures]
    return ReportSummary(d / "index.html", d / "summary.md", figures, regressions, dict(page.verdicts))


TMP_PREFIX = ".report-"  # DIR/.report-PID-XXXX: the report being built by process PID
OLD_FIGURES_PREFIX = ".figures-old-"  # DIR/.figures-old-PID: the previous figures while PID swaps them


def check_report_outputs(d: Path) -> None:
    """Before anything is written: DIR is writable and index.html, summary.md are files (or absent),
    figures/ a directory (or absent).  An ``InputError`` naming DIR otherwise."""
    from ..core.errors import InputError
    from ..harness.store import check_writable_dir

    check_writable_dir(d, "DIR")
    for name in ("index.html", "summary.md"):
        p = d / name
        if p.exists() and not p.is_file():
            raise InputError("DIR", None, f"{p} exists and is not a file; move it away so the report can be written")
    if (d / "figures").exists() and not (d / "figures").is_dir():
        raise InputError("DIR", None, f"{d / 'figures'} exists and is not a directory; move it away")


def clean_stale_temporaries(d: Path) -> list[Path]:
    """Remove what an interrupted report left in DIR: ``.report-PID-*`` build directories and
    ``.figures-old-PID`` of processes that no longer run (a report killed mid-write).  Also
    ``.report-*`` of the older naming without a PID.  Returns what was removed."""
    removed = []
    for p in list(d.glob(f"{TMP_PREFIX}*")) + list(d.glob(f"{OLD_FIGURES_PREFIX}*")):
        rest = p.name[len(TMP_PREFIX):] if p.name.startswith(TMP_PREFIX) else p.name[len(OLD_FIGURES_PREFIX):]
        pid = rest.split("-", 1)[0]
        if pid.isdigit() and _alive(int(pid)) and int(pid) != os.getpid():
            continue  # another report is being built right now
        shutil.rmtree(p, ignore_errors=True)
        removed.append(p)
    return removed


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


# --------------------------------------------------------------------------- sections

def _overview(page: _Page, res: MatrixResults) -> None:
    page.section("overview", "Overview")
    page.p(f"Matrix {res.name!r}: {res.description}" if res.description else f"Matrix {res.name!r}.")
    df = res.df
    counts = df["status"].value_counts().to_dict() if not df.empty else {}
    page.p(f"{len(df)} cases: " + (", ".join(f"{n} {s}" for s, n in sorted(counts.items())) or "none stored yet")
           + f". Built {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}.")
    if not df.empty:
        unstable = df["status"] == "unstable"
        intended = unstable & sweeps.blow_up_sweep_mask(df, res.grid_keys)
        unexpected = unstable & ~intended
        if unstable.any():
            page.p(f"Blow-ups: {int(intended.sum())} intended -- cases of a dt or stiffness sweep ("
                   + ", ".join(k for k in res.grid_keys if k in sweeps.BLOW_UP_KEYS)
                   + "), which looks for where the integrator fails; see the stability heatmaps -- and "
                   f"{int(unexpected.sum())} unexpected (outside such a sweep).")
        if unexpected.any():
            page.p("Unexpected blow-ups:")
            page.table(df.loc[unexpected, ["label", "status", "metric.t_fail_s", "message"]]
                       .rename(columns={"metric.t_fail_s": "t_fail [s]"}).reset_index(drop=True),
                       ["unstable"] * int(unexpected.sum()))
    runaway = df[df["status"] == "controller_unstable"] if not df.empty else df
    if not runaway.empty:
        page.p(f"{len(runaway)} controller_unstable: the closed-loop shape tracker drove the body beyond the commanded "
               "shape and backed off to the calibrated open loop (controllers/shape_tracking.py, LoopGuard); their "
               "speeds are not of the commanded shape:")
        page.table(runaway[["label", "status", "message"]].reset_index(drop=True), ["unstable"] * len(runaway))
    bad = df[df["status"].isin(["error", "timeout"])] if not df.empty else df
    if not bad.empty:
        page.p("Cases that did not finish:")
        page.table(bad[["label", "status", "message"]].reset_index(drop=True),
                   [str(s) for s in bad["status"]])
    if res.unsupported:
        page.p("Unsupported combinations (listed before the run, not run): " + "; ".join(res.unsupported), "note")


def _scorecard(page: _Page, res: MatrixResults, verdicts, store: Path | None, d: Path) -> None:
    from ..harness.stable_dt import brackets_by_case
    from .scorecard import COLUMNS, build_scorecard, scorecard_table
    from .scorecard_figure import plot_error_vs_cost

    page.section("scorecard", "Scorecard: which body model for each creature")
    if res.df.empty:
        page.p("No case stored yet.", "note")
        return
    card = build_scorecard(res, verdicts, store, brackets_by_case(d))
    page.p("One row per creature x body model of this matrix; a cell without data says why and which command "
           "fills it. The columns, their units and definitions:", "note")
    page.html.append('<dl class="columns">' + "".join(
        f"<dt>{html.escape(c.heading)}</dt><dd>{html.escape(c.definition)}. Unit: {html.escape(c.unit)}.</dd>"
        for c in COLUMNS) + "</dl>")
    page.md.extend(f"- **{c.heading}**: {c.definition}. Unit: {c.unit}." for c in COLUMNS)
    page.md.append("")
    for creature, line in card.recommendations.items():
        page.html.append(f'<p class="recommendation"><b>Recommendation</b> -- {html.escape(line)}</p>')
        page.md.append(f"**Recommendation** -- {line}\n")
    page.table(scorecard_table(card), css="scorecard")
    points = [(r.creature, r.body, r.error, r.cost.value, r.error_kind) for r in card.rows if r.cost.value is not None]
    if points:
        path = page.fig_dir / "scorecard_error_vs_cost.png"
        page.draw(path, plot_error_vs_cost, points, path)
        page.figure(path, "Summary: each creature x body pair's error (speed error against its reference, or the "
                          "share of failed validate checks where no speed reference applies) against its cost "
                          "(CPU seconds per simulated second), log-log; colour: creature, marker: body model. "
                          "Pairs without an error measure sit on the strip below at their cost.")


def _comparison(page: _Page, res: MatrixResults) -> None:
    from .seed_spread import has_several_seeds, plot_seed_spread

    page.section("comparison", "Comparison across body models")
    if res.df.empty:
        page.p("No case stored yet.", "note")
        return
    page.p("Per creature: its headline cases (outside sweeps) in two tables -- stability and cost, then speed and "
           "gait -- then each parameter sweep in its own table, titled by its swept keys, with each row's swept "
           "values and duration (sweeps are short runs: stability and throughput only). A column appears when "
           "some case has a value; '-' with a mark = no number for that case, the reason under the table "
           "(does not apply, blew up, commanded, too short); '-' alone = not measured.", "note")
    grid_columns = [f"grid.{k}" for k in res.grid_keys]
    mask = sweeps.sweep_mask(res.df, res.grid_keys)
    for creature, tables in comparison_tables(res.df, grid_columns, mask).items():
        for title, ct in tables:
            page.h3(title)
            if ct is None:
                page.p("No headline case: this creature ran only in the sweeps below." if title == creature
                       else "No metric measured.", "note")
                continue
            page.table(ct.table, [s if s != "ok" else "" for s in ct.table["status"]], ct.notes, ct.footnotes)
        sub = res.df[res.df["creature"] == creature]
        sub = sub[~sweeps.sweep_mask(sub, res.grid_keys)]
        if has_several_seeds(sub):
            path = page.fig_dir / f"seeds_{_slug(creature)}.png"
            page.draw(path, plot_seed_spread, sub, path, f"{creature}: spread over seeds")
            page.figure(path, f"{creature}: each case's mean over its seeds with an error bar of one standard "
                              "deviation (sample, n - 1), and every seed's value as a grey dot.")


def _legged(res: MatrixResults, df: pd.DataFrame):
    for _, r in df.iterrows():
        if r["status"] == "error":
            continue
        rec = res.recording(r.case_hash)
        if rec is not None and "leg_states" in rec and len(rec["leg_t"]) > 1:
            yield r, rec


def _gait(page: _Page, res: MatrixResults, main: pd.DataFrame) -> None:
    from .gait_diagram import draw_phase_lags, phase_lag_data, plot_gait_diagram

    page.section("gait", "Gait diagrams and phase lags")
    shown = 0
    for r, rec in _legged(res, main):
        if shown >= MAX_GAIT_CASES:
            page.p(f"(further legged cases not drawn; at most {MAX_GAIT_CASES})", "note")
            break
        page.h3(r.label)
        t, states = rec["leg_t"], rec["leg_states"]
        p1 = page.fig_dir / f"gait_{_slug(r.case_hash)}.png"
        page.draw(p1, plot_gait_diagram, t, states, p1, last_seconds=1.0, title=f"{r.label}: leg states, last second")
        page.figure(p1, "Leg states over the last second (rows: legs, head at the top), as the paper's Fig. 10.")
        try:  # the lags are measured here, so that a timeline without them is a note, not a failed figure
            lags = phase_lag_data(t, states, warmup_s=min(1.0, 0.3 * float(t[-1])))
        except ValueError as exc:  # too few stance onsets to measure a lag
            page.p(f"No phase lags: {exc}", "note")
        else:
            p2 = page.fig_dir / f"lag_{_slug(r.case_hash)}.png"
            page.draw(p2, draw_phase_lags, lags, p2, title=f"{r.label}: phase lags")
            page.figure(p2, "Phase lag of each leg behind the same-side leg ahead; positive = retrograde wave.")
        shown += 1
    if shown == 0:
        page.p("No legged creature in this matrix (or none left a leg timeline).", "note")


def _trajectories(page: _Page, res: MatrixResults, main: pd.DataFrame) -> None:
    from .trajectories import plot_top_views

    page.section("trajectories", "Trajectories from above")
    drawn = 0
    # one figure per creature, scenario and body: the seeds of a case are its panels
    for (creature, scenario, body), sub in main.groupby(["creature", "scenario", "body"], sort=True):
        runs, scen, foods, worlds = [], [], [], []
        for _, r in sub.sort_values([c for c in ("gait", "seed") if c in sub]).iterrows():
            rec = res.recording(r.case_hash)
            if rec is None or len(rec["t"]) < 2:
                continue
            runs.append((f"{r.body} / {r.gait}" + ("" if pd.isna(r.get("seed")) else f" / seed {int(r.seed)}"),
                         series_from_recording(rec)))
            scen.append(res.case(r.case_hash)["scenario"])
            foods.append(res.case(r.case_hash).get("food"))
            worlds.append(res.world(r.case_hash))
        if not runs:
            continue
        path = page.fig_dir / f"top_{_slug(creature, scenario, body)}.png"
        page.draw(path, plot_top_views, runs[:6], path, scenarios=scen[:6], foods=foods[:6], worlds=worlds[:6])
        page.figure(path, f"{creature} on {scenario}, {body} body, seen from above, one row per run. Left: the "
                          "body's centre line at six times (head: dot) and the centre-of-mass path (dashed). "
                          "Right: the centre-of-mass path, zoomed, dots at the six times. Coloured by "
                          "time from dark purple (start) to yellow (end), as the colour bar shows; x forward, "
                          "z to the creature's right; equal scales.")
        drawn += 1
    if not drawn:
        page.p("No recorded trajectories in this matrix.", "note")


def _stability(page: _Page, res: MatrixResults) -> None:
    page.section("stability", "Stability heatmaps (dt x stiffness)")
    groups = sweeps.stability_groups(res.df, res.grid_keys) if not res.df.empty else []
    if not groups:
        page.p("No sweep over dt and a stiffness key (" + ", ".join(sweeps.STIFFNESS_KEYS) + ") in this matrix; "
               "add one under [matrix.grid] to get a heatmap.", "note")
        return
    dts = sweeps.shared_dt_grid(groups)
    page.p("Every heatmap has the same dt columns (all dt values of any sweep in this matrix), so the bodies' "
           "stable ranges line up; a body not run at a dt shows a blank cell.", "note")
    for creature, body, key, sub in groups:
        path = page.fig_dir / f"stability_{_slug(creature, body)}.png"
        page.draw(path, sweeps.plot_stability_heatmap, sub, key, path, f"{creature} / {body}: stable or time of blow-up",
                  dts)
        page.figure(path, f"{creature} on the {body} body: each cell a run of {sub['duration'].max():g} s at that "
                          f"dt and {sweeps.key_label(key)}; green = stable throughout; red = blew up, darker = "
                          "earlier (colour bar: t_fail / duration; t_fail in the cell); grey = error or timeout.")


def _scaling(page: _Page, res: MatrixResults) -> None:
    page.section("scaling", "Throughput scaling")
    series = sweeps.scaling_series(res.df, res.grid_keys) if not res.df.empty else []
    if not series:
        page.p("No sweep over a size key (" + ", ".join(sweeps.SIZE_KEYS) + ") in this matrix.", "note")
        return
    rows = []
    for key in sweeps.SIZE_KEYS:
        if not any(s[0] == key for s in series):
            continue
        path = page.fig_dir / f"scaling_{_slug(key)}.png"
        page.draw(path, sweeps.plot_throughput_scaling, series, path, key)
        fits = sweeps.throughput_fits(series, key)  # the exponents the figure's legend shows
        page.figure(path, f"Steps per second against {key} (log-log); p is the fitted exponent of steps/s ~ N^p "
                          "(p = -1: cost linear in size).")
        for name, p in fits.items():
            n = next(s[3] for s in series if s[0] == key and f"{s[1]}/{s[2]}" == name)
            rows.append({"sweep": key, "creature/body": name, "sizes": ", ".join(f"{x:g}" for x in n),
                         "exponent p": p})
    page.table(pd.DataFrame(rows))


def _energy(page: _Page, res: MatrixResults, main: pd.DataFrame) -> None:
    from .series_plots import plot_energy

    page.section("energy", "Energy over time")
    drawn = 0
    for creature, sub in main.groupby("creature", sort=True):
        runs = []
        for _, r in sub.iterrows():
            rec = res.recording(r.case_hash)
            if rec is not None and len(rec["t"]) > 1:
                runs.append((f"{r.body} / {r.gait} / {r.scenario}"
                             + ("" if pd.isna(r.get("seed")) else f" / seed {int(r.seed)}"), series_from_recording(rec)))
        if runs:
            path = page.fig_dir / f"energy_{_slug(creature)}.png"
            page.draw(path, plot_energy, runs[:9], path)
            page.figure(path, f"{creature}: kinetic, elastic, gravitational and total energy relative to t = 0 [J].")
            drawn += 1
    if not drawn:
        page.p("No recorded energies in this matrix.", "note")


def _paper(page: _Page, res: MatrixResults, main: pd.DataFrame, vdata=None, verdicts=None) -> None:
    from .gait_diagram import plot_gait_diagram
    from .series_plots import plot_side_strip
    from .trajectories import plot_top_views

    page.section("paper", "Reproduced paper figures")
    found = 0
    for _, r in main.iterrows():
        fig = figure_for(str(r.scenario), str(r.gait))
        if fig is None or r["status"] == "error":
            continue
        rec = res.recording(r.case_hash)
        if rec is None or len(rec["t"]) < 2:
            continue
        found += 1
        page.h3(f"{fig.figure} ({fig.paper}): {r.label}")
        page.html.append(f'<p class="caption">{html.escape(fig.caption)}</p>')
        page.md.append(f"> {fig.caption}\n")
        v = figure_verdict(page, fig, r, res, vdata, verdicts)
        page.verdicts[v] = page.verdicts.get(v, 0) + 1
        s = series_from_recording(rec)
        scen = res.case(r.case_hash)["scenario"]
        food = res.case(r.case_hash).get("food")
        slug = _slug(r.case_hash)
        if "side" in fig.images:
            side_png = page.fig_dir / f"paper_side_{slug}.png"
            page.figure(page.draw(side_png, plot_side_strip, f"{r.label}: side view", s, scen, side_png,
                                  world=res.world(r.case_hash)),
                        "Side view at six times spaced by the body's motion, coloured from dark purple (first) "
                        "to yellow (last) as the legend's times show, over the terrain.")
        # The gait and trajectory sections have drawn these already (each figure is drawn once): link to them.
        if "gait" in fig.images and "leg_states" in rec and len(rec["leg_t"]) > 1:
            gait_png = page.fig_dir / f"gait_{slug}.png"
            if gait_png in page.figures:
                page.link(gait_png, "Leg states during the last second (the right panel of Fig. 10)", "gait")
            else:  # the gait section stopped at MAX_GAIT_CASES before this case
                page.draw(gait_png, plot_gait_diagram, rec["leg_t"], rec["leg_states"], gait_png, last_seconds=1.0,
                          title=f"{r.label}: leg states, last second")
                page.figure(gait_png, "Leg states during the last second (the right panel of Fig. 10).")
        if "top" in fig.images:
            top_png = page.fig_dir / f"top_{_slug(r.creature, r.scenario, r.body)}.png"
            if top_png in page.figures:
                page.link(top_png, "Seen from above", "trajectories")
            else:
                top_png = page.fig_dir / f"paper_top_{slug}.png"
                page.figure(page.draw(top_png, plot_top_views, [(r.label, s)], top_png, scenarios=[scen], foods=[food],
                                      worlds=[res.world(r.case_hash)]),
                            "Seen from above.")
    walks = main[(main.get("scenario") == "walk") & (main.get("creature") == "centipede")] if not main.empty else main
    if not walks.empty:
        page.h3("Throughput headline (Sec. 6)")
        page.html.append(f'<p class="caption">{html.escape(PAPER_THROUGHPUT_NOTE)}</p>')
        page.md.append(f"> {PAPER_THROUGHPUT_NOTE}\n")
        rows = [{"case": r.label, "segments": res.case(r.case_hash)["creature"]["segments"],
                 "dt [s]": r["dt"], "steps/s (here)": r.steps_per_s, "steps/s (paper)": PAPER_STEPS_PER_S,
                 "ratio": r.steps_per_s / PAPER_STEPS_PER_S, "x realtime": r.realtime_factor}
                for _, r in walks.iterrows()]
        page.table(pd.DataFrame(rows))
        page.p("Here: one core of the machine that ran the matrix, a single run (see 'regress' for repeated "
               "medians); the paper: 6 cores with OpenMP.", "note")
        page.p("Verdict: INFO -- informational: a different machine and core count; the ratio is the measured "
               "figure, not a pass/fail criterion (validate: throughput.sec6-headline).", "note")
        found += 1
    if not found:
        page.p("No case of this matrix reproduces a paper figure (run scenarios/matrix/paper.toml or miller.toml).",
               "note")


def _history(page: _Page, store: Path | None) -> None:
    page.section("history", "Performance history (regress)")
    if store is None or not store.is_file():
        page.p("No results store with a regress history" + (f" at {store}" if store else "") +
               "; run `bench-myriapoda regress` to start one.", "note")
        return
    from ..harness.regress import load_history
    from .regress_history import plot_regress_history

    try:
        hist = load_history(store)
    except StoreReadError as exc:
        page.p(f"Could not read the regress history in {store}: {exc}", "note")
        return
    if hist.empty:
        page.p(f"No regress runs in {store} yet; run `bench-myriapoda regress`.", "note")
        return
    path = page.fig_dir / "regress_history.png"
    page.draw(path, plot_regress_history, hist, path)
    page.figure(path, "Normalized throughput (steps/s divided by the reference kernel's rate, timed in the same run) "
                      "per suite entry and regress run.")
    from .regress_history import peer_ratio_history
    peers = peer_ratio_history(hist)
    if not peers.empty:
        page.p("Ours against the peers (bench-myriapoda peers, one process and one sitting per run): "
               "speed-up = our steps/s / the peer's steps/s on the matched scene.")
        page.table(peers.pivot_table(index=["run_id", "commit_short"], columns="pair", values="speedup").round(2)
                   .reset_index())


def _baseline(page: _Page, res: MatrixResults, base: MatrixResults | None, threshold: float) -> int:
    page.section("baseline", "Changes against the baseline")
    if base is None:
        page.p("No baseline given; run `bench-myriapoda report DIR --baseline DIR2` to compare two matrix runs.", "note")
        return 0
    diff = compare_runs(res, base, threshold)
    n_reg = int((diff["verdict"] == "regression").sum())
    page.p(f"Baseline: {base.directory} (matrix {base.name!r}). {n_reg} regression(s); changes within "
           f"{100 * threshold:g} % (15 % for throughput) are not listed.")
    if diff.empty:
        page.p("No metric changed beyond the threshold.")
        return 0
    shown = diff.copy()
    shown["change"] = [format_change(c) if isinstance(c, float) else "-" for c in shown["change"]]
    shown["baseline"] = [fmt(v) for v in shown["baseline"]]
    shown["now"] = [fmt(v) for v in shown["now"]]
    page.table(shown, list(diff["verdict"]))
    return n_reg

