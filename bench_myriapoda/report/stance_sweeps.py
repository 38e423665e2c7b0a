"""Figures of issue 43's dynamic-stance sweeps (docs/explanation/stance-sweeps.md): what a body model that the
legs must push shows against the papers on walking centipedes.

Three matrices, each read from its output directory (``bench-myriapoda matrix NAME``):

* ``scenarios/matrix/stance-stiffness.toml`` (sweep a): the links' stiffness (``body.youngs_modulus_pa`` of
  the hybrid and fem bodies, ``body.link_stiffness_n_m`` of the massspring) x the stepping frequency (set by
  ``controller.swing_speed_rad_s`` at the commanded speed, measured as ``stride_frequency_hz``):
  undulation amplitude, speed per stride and the legs' cost of transport against the stride frequency, one line
  per stiffness, each case marked coordinated or not (``coordinated``);
* ``scenarios/matrix/stance-speed.toml`` (sweep b): the commanded walking speed (``scenario.control_speed_m_s``)
  x the stiffness: undulation amplitude and head yaw against the speed, one line per stiffness, and the lowest
  speed at which straight walking is lost (``critical_speeds``);
* ``scenarios/matrix/stance-body-wave.toml`` (sweep c): speed per stride against the body wave's phase offset
  (``report.body_wave``'s figure).

A straight walk counts as **coordinated** (``coordinated``) when it finished (status ``ok``), its centre of mass
kept within ``SPEED_BAND`` of the commanded head speed (the legs carry the body: none of it is left behind or
overtaken), at most ``MAX_SLIDE`` of its STANCE foot-steps slid (``stance_slide_fraction``: the feet grip), and its
leg-state timeline still walks: at least ``MIN_STEPPING_LEGS`` of the legs complete a stride in the gait window
(``stepping_leg_fraction``) and the leg wave keeps its direction (``phase_lag_mean`` > 0 for a retrograde wave, < 0
for a direct one, ``controller.wave_direction``).  Straight walking is **lost** at a speed where the walk is not
coordinated or its undulation exceeds ``UNDULATION_LOST_BL``.

Run as a script to draw one sweep's figure and print its numbers as a Markdown table::

    python -m bench_myriapoda.report.stance_sweeps stiffness reports/matrix/stance-stiffness \\
        --out docs/_static/stance-stiffness.png
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from ..core.errors import InputError  # noqa: E402
from .body_wave import plot_speed_per_stride_vs_offset  # noqa: E402
from .figure_files import figure_section, report_style, save_figure  # noqa: E402

# The body's yaw (bending) stiffness in these sweeps is the one ``body.`` key a block sweeps (the links' Young's
# modulus of the FEM-linked bodies, the link springs' constant of the massspring one: the matrix file says which),
# so that no body model is named here (tests/test_bodies_closed.py).  Labels of the keys the shipped sweeps use;
# another key is labelled with its name.
STIFFNESS_PREFIX = "body."
STIFFNESS_LABELS = {"body.youngs_modulus_pa": "E = {:g} Pa", "body.link_stiffness_n_m": "k = {:g} N/m"}
SPEED_KEY = "scenario.control_speed_m_s"
SWING_KEY = "controller.swing_speed_rad_s"

SPEED_BAND = 0.1            # |body speed / commanded speed - 1| at most this [-]
MAX_SLIDE = 0.25            # share of STANCE foot-steps that slid (the defaults' walk: 5 to 12 %) [-]
MIN_STEPPING_LEGS = 0.9     # share of legs that complete a stride in the gait window [-]
UNDULATION_LOST_BL = 0.01   # an undulation this large [body lengths] is no longer a straight walk


def _metric(df: pd.DataFrame, name: str) -> pd.Series:
    col = f"metric.{name}"
    return pd.to_numeric(df[col], errors="coerce") if col in df else pd.Series(math.nan, index=df.index)


def commanded_speed(df: pd.DataFrame) -> pd.Series:
    """The head's commanded speed [m/s] of each case: the CONTROL schedule's last speed (the straight walk's one
    command), else ``controller.head_speed_m_s``."""
    out = []
    for text in df["case_json"]:
        case = json.loads(text)
        sc, ct = case["scenario"], case["controller"]
        speeds = sc.get("control_speed_m_s") or []
        out.append(float(speeds[-1]) if sc.get("brain") == "control" and speeds else float(ct["head_speed_m_s"]))
    return pd.Series(out, index=df.index, dtype=float)


def speed_ratio(df: pd.DataFrame) -> pd.Series:
    """The centre of mass's forward speed over the commanded head speed [-].  ``body_speed_ratio`` divides by
    ``controller.head_speed_m_s``; a sweep that commands its speed through the CONTROL schedule needs this."""
    head = pd.Series([float(json.loads(t)["controller"]["head_speed_m_s"]) for t in df["case_json"]],
                     index=df.index, dtype=float)
    return _metric(df, "body_speed_ratio") * head / commanded_speed(df)


def coordinated(df: pd.DataFrame) -> pd.Series:
    """True for each case that walked coordinated (module docstring): finished, kept its commanded speed within
    SPEED_BAND, at most MAX_SLIDE of its STANCE foot-steps sliding, at least MIN_STEPPING_LEGS of its legs
    stepping and its leg wave in the commanded direction."""
    ok = df["status"] == "ok"
    ratio = speed_ratio(df)
    slide = _metric(df, "stance_slide_fraction")
    stepping = _metric(df, "stepping_leg_fraction")
    sign = pd.Series([1.0 if json.loads(t)["controller"].get("wave_direction", "retrograde") == "retrograde"
                      else -1.0 for t in df["case_json"]], index=df.index)
    wave = _metric(df, "phase_lag_mean") * sign > 0
    return (ok & ((ratio - 1.0).abs() <= SPEED_BAND) & ~(slide > MAX_SLIDE) & (stepping >= MIN_STEPPING_LEGS)
            & wave).fillna(False).astype(bool)


def straight_walk_lost(df: pd.DataFrame) -> pd.Series:
    """True for each case whose straight walk is lost: not coordinated, or undulating by more than
    UNDULATION_LOST_BL body lengths."""
    return ~coordinated(df) | (_metric(df, "undulation_amplitude_bl") > UNDULATION_LOST_BL)


def _stiffness_columns(df: pd.DataFrame) -> list[str]:
    """The grid columns of ``body.`` keys: the swept stiffnesses."""
    return [c for c in df.columns if c.startswith("grid." + STIFFNESS_PREFIX)]


def stiffness_key(df: pd.DataFrame) -> pd.Series:
    """Each case's swept ``body.`` key (its block's stiffness key; "" for a case that sweeps none)."""
    out = pd.Series("", index=df.index, dtype=object)
    for col in _stiffness_columns(df):
        v = pd.to_numeric(df[col], errors="coerce")
        out[v.notna() & (out == "")] = col[len("grid."):]
    return out


def stiffness(df: pd.DataFrame) -> pd.Series:
    """Each case's link stiffness, the value of its swept ``body.`` key (NaN for a case that sweeps none)."""
    out = pd.Series(math.nan, index=df.index, dtype=float)
    for col in _stiffness_columns(df):
        v = pd.to_numeric(df[col], errors="coerce")
        out[out.isna()] = v[out.isna()]
    return out


def critical_speeds(df: pd.DataFrame) -> pd.DataFrame:
    """One row per (body, stiffness) of a speed sweep: the lowest commanded speed [m/s] at which straight walking
    is lost (``straight_walk_lost``; NaN when it holds at every speed of the sweep) and the highest swept speed."""
    d = df.assign(_k=stiffness(df), _v=commanded_speed(df), _lost=straight_walk_lost(df))
    rows = []
    for (body, k), sub in d.dropna(subset=["_k"]).groupby(["body", "_k"]):
        lost = sub[sub["_lost"]]["_v"]
        rows.append({"body": body, "stiffness": k, "key": stiffness_key(sub).iloc[0],
                     "critical_speed_m_s": float(lost.min()) if len(lost) else math.nan,
                     "max_speed_m_s": float(sub["_v"].max())})
    return pd.DataFrame(rows, columns=["body", "stiffness", "key", "critical_speed_m_s", "max_speed_m_s"])


def _bodies(df: pd.DataFrame) -> list[str]:
    """The body models of the rows, in the matrix's order."""
    return list(dict.fromkeys(df["body"]))


def _stiffness_lines(ax, d: pd.DataFrame, x: str, metric: str, order: str | None = None) -> None:
    """One line per stiffness of ``metric`` against column ``x`` on ``ax``, its points joined in the order of
    column ``order`` (the swept knob; default ``x``): filled markers where column ``_coord`` holds, hollow ones
    for the rest, a cross for a run that did not finish."""
    keys = stiffness_key(d)
    key = str(keys[keys != ""].iloc[0]) if (keys != "").any() else ""
    ks = sorted(d["_k"].dropna().unique())
    cmap = plt.get_cmap("viridis")
    for n, k in enumerate(ks):
        s = d[d["_k"] == k].sort_values(order if order in d else x)
        color = cmap(n / max(1, len(ks) - 1) * 0.9)
        y = _metric(s, metric) if metric != "_ratio" else s["_ratio"]
        ax.plot(s[x], y, "-", color=color, lw=1.2, label=STIFFNESS_LABELS.get(key, key + " = {:g}").format(k))
        good = s["_coord"]
        ax.plot(s[x][good], y[good], "o", color=color, ms=6)
        ax.plot(s[x][~good], y[~good], "o", mfc="white", mec=color, ms=6, mew=1.5)
        failed = s["status"] != "ok"
        if failed.any():
            ax.plot(s[x][failed], np.zeros(int(failed.sum())), "x", color="red", ms=8)
    ax.grid(alpha=0.3)


def _stiffness_figure(d: pd.DataFrame, panels, x: str, xlabel: str, legend_title: str, path: Path,
                      order: str | None = None, guides=None) -> Path:
    """A row of ``panels`` ((metric, label), ...) per body, each ``_stiffness_lines`` against column ``x``;
    ``guides(ax, metric)`` draws a panel's reference lines.  Written to ``path``."""
    bodies = _bodies(d)
    with report_style():
        fig, axes = plt.subplots(len(bodies), len(panels), figsize=(11.0, 3.2 * len(bodies)), squeeze=False)
        for i, body in enumerate(bodies):
            sub = d[d["body"] == body]
            for j, (metric, label) in enumerate(panels):
                ax = axes[i, j]
                _stiffness_lines(ax, sub, x, metric, order=order)
                ax.set_ylabel(label)
                ax.set_title(body)
                if guides is not None:
                    guides(ax, metric)
                if i == len(bodies) - 1:
                    ax.set_xlabel(xlabel)
                if j == 0:
                    ax.legend(fontsize=7, title=legend_title, title_fontsize=7)
        fig.tight_layout()
        return save_figure(fig, path)


def plot_stiffness_sweep(df: pd.DataFrame, path: Path) -> Path:
    """Sweep (a): per body (rows), undulation amplitude [BL], speed per stride [BL] and the legs' cost of
    transport [-] against the measured stride frequency [Hz], one line per link stiffness joining the swing
    speeds in order; filled markers: coordinated walks (``coordinated``), hollow: not."""
    d = df.assign(_k=stiffness(df), _coord=coordinated(df), _f=_metric(df, "stride_frequency_hz"))
    panels = (("undulation_amplitude_bl", "undulation amplitude [BL]"),
              ("speed_bl_per_stride", "speed per stride [BL]"),
              ("cost_of_transport", "legs' cost of transport [-]"))
    return _stiffness_figure(d, panels, "_f", "stride frequency [Hz]", "filled: coordinated", path,
                             order=f"grid.{SWING_KEY}")


def plot_speed_sweep(df: pd.DataFrame, path: Path) -> Path:
    """Sweep (b): per body (rows), undulation amplitude [BL], head yaw oscillation [deg] and body speed over
    commanded speed against the commanded speed [m/s], one line per link stiffness; filled markers: straight
    walking holds (``straight_walk_lost`` false), hollow: lost."""
    d = df.assign(_k=stiffness(df), _v=commanded_speed(df), _ratio=speed_ratio(df))
    d["_coord"] = ~straight_walk_lost(d)
    panels = (("undulation_amplitude_bl", "undulation amplitude [BL]"),
              ("head_yaw_osc_deg", "head yaw oscillation [deg]"),
              ("_ratio", "body speed / commanded speed"))

    def guides(ax, metric):
        if metric == "undulation_amplitude_bl":
            ax.axhline(UNDULATION_LOST_BL, color="0.5", ls=":", lw=1.0)
        if metric == "_ratio":
            ax.axhspan(1.0 - SPEED_BAND, 1.0 + SPEED_BAND, color="0.9", zorder=0)

    return _stiffness_figure(d, panels, "_v", "commanded head speed [m/s]", "filled: straight walk holds", path,
                             guides=guides)


def plot_body_wave_sweep(df: pd.DataFrame, path: Path) -> Path:
    """Sweep (c): speed per stride against the body wave's phase offset, per body (``report.body_wave``)."""
    with report_style():
        return plot_speed_per_stride_vs_offset(df, path)


def sweeps_in(df: pd.DataFrame, grid_keys) -> list[str]:
    """The sweeps (``PLOTS``' names, a and b) a matrix holds: a link-stiffness grid key crossed with the swing
    speed (stiffness) or with the CONTROL speed (speed).  (Sweep c is the report's body-wave section.)"""
    keys = set(grid_keys)
    if not any(k.startswith(STIFFNESS_PREFIX) for k in keys) or not _stiffness_columns(df):
        return []
    return [name for name, key in (("stiffness", SWING_KEY), ("speed", SPEED_KEY))
            if key in keys and f"grid.{key}" in df]


def report_sections(page, res) -> None:
    """The matrix report's sections of sweeps a and b (``report.build``), when the matrix holds them."""
    titles = {"stiffness": ("stance-stiffness", "Dynamic stance: body stiffness x stepping frequency",
                            "Undulation, speed per stride and the legs' cost of transport against the stride "
                            "frequency, one line per link stiffness; filled: coordinated walks (speed within "
                            f"{SPEED_BAND:.0%}, at most {MAX_SLIDE:.0%} of STANCE foot-steps sliding, every leg "
                            "stepping, the leg wave in its direction)."),
              "speed": ("stance-speed", "Dynamic stance: undulation against walking speed",
                        "Undulation, head yaw and body speed over commanded speed against the commanded speed, "
                        "one line per link stiffness; filled: straight walking holds (coordinated, undulation "
                        f"at most {UNDULATION_LOST_BL} BL).")}
    for name in sweeps_in(res.df, res.grid_keys):
        sid, title, caption = titles[name]
        figure_section(page, sid, title, f"{sid}.png", PLOTS[name], res.df, caption)


def table(df: pd.DataFrame, sweep: str) -> str:
    """The sweep's numbers as a Markdown table (one row per case), for the docs."""
    d = df.assign(k=stiffness(df), v=commanded_speed(df), ratio=speed_ratio(df), coordinated=coordinated(df))
    cols = {"stride Hz": "stride_frequency_hz", "undulation BL": "undulation_amplitude_bl",
            "yaw deg": "head_yaw_osc_deg", "BL/stride": "speed_bl_per_stride", "CoT": "cost_of_transport",
            "slide": "stance_slide_fraction", "stepping legs": "stepping_leg_fraction",
            "phase lag": "phase_lag_mean"}
    axes = {"stiffness": ["body", "k", f"grid.{SWING_KEY}"], "speed": ["body", "k", "v"],
            "body-wave": ["body", "grid.controller.body_wave_phase_rad"]}[sweep]
    axes = [a for a in axes if a in d]
    d = d.sort_values(axes)
    head = axes + ["status", "ratio", *cols, "coordinated"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for _, r in d.iterrows():
        vals = [r[a] for a in axes] + [r["status"], r["ratio"]] + [_metric(d.loc[[r.name]], m).iloc[0]
                                                                   for m in cols.values()] + [r["coordinated"]]
        lines.append("| " + " | ".join(_fmt(v) for v in vals) + " |")
    if sweep == "speed":
        lines += ["", "| body | stiffness | critical speed [m/s] | highest swept [m/s] |", "|---|---|---|---|"]
        for _, r in critical_speeds(df).iterrows():
            lines.append(f"| {r['body']} | {r['stiffness']:g} | {_fmt(r['critical_speed_m_s'])} | "
                         f"{r['max_speed_m_s']:g} |")
    return "\n".join(lines)


def _fmt(v) -> str:
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    if isinstance(v, (float, np.floating)):
        return "-" if not math.isfinite(v) else f"{v:.4g}"
    return str(v)


PLOTS = {"stiffness": plot_stiffness_sweep, "speed": plot_speed_sweep, "body-wave": plot_body_wave_sweep}


def main(argv: list[str] | None = None) -> int:
    """Draw one sweep's figure from a matrix output directory and print its table; exit 2 on bad input."""
    from .matrix_data import load_matrix_dir

    p = argparse.ArgumentParser(prog="python -m bench_myriapoda.report.stance_sweeps",
                                description="Draw a figure of issue 43's dynamic-stance sweeps from a matrix "
                                            "output directory and print its numbers as a Markdown table.")
    p.add_argument("sweep", choices=sorted(PLOTS), help="stiffness (sweep a), speed (b) or body-wave (c)")
    p.add_argument("directory", help="the matrix's output directory (reports/matrix/NAME)")
    p.add_argument("--out", required=True, help="the PNG to write")
    a = p.parse_args(argv)
    try:
        res = load_matrix_dir(a.directory)
        if res.df.empty:
            raise InputError(a.directory, None, "the matrix has no finished case to draw")
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    PLOTS[a.sweep](res.df, Path(a.out))
    print(table(res.df, a.sweep))
    return 0


if __name__ == "__main__":
    sys.exit(main())
