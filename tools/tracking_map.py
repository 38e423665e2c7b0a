"""Draw where the shape tracker holds (issue 44): a matrix run of scenarios/matrix/tracking-map.toml (or its lattice
part, tracking-map-lattice.toml) as heat maps of ``shape_tracking_error``, one column per body.

    bench-myriapoda matrix tracking-map-lattice --out reports/tracking-map
    python tools/tracking_map.py reports/tracking-map --out reports/tracking-map/map.png

A map run in parts (the lattice's cheap cases in one directory, the fem and hybrid cases in another) is drawn from
all of them: ``python tools/tracking_map.py DIR1 DIR2 --out map.png``.

Top row: wavelength [BL] x friction ratio mu_t / mu_f; bottom row: commanded curvature amplitude x frequency [Hz].
Each cell is coloured by the shape error (0 to 1, clipped) and labelled with it; a cell whose run the guard backed
off (status ``controller_unstable``: the loop drove the shape away) is marked "R", a blown-up one "X", and a cell
flagged ``shape_not_achieved`` has its number in brackets.  A cell not run is blank.  Exit 2 on a directory that is
not a matrix output directory.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

SECOND_BLOCK_RAMP_S = 1.0  # the amplitude x frequency block sets gait.ramp_s = 1 (the first keeps the snake's 2 s)


def cells(df):
    """One dict per case: body, wavelength, ratio, amplitude, frequency, error, status, flagged."""
    out = []
    for _, r in df.iterrows():
        case = json.loads(r["case_json"])
        g, f = case["gait"], case["friction"]
        err = r.get("metric.shape_tracking_error")
        out.append({"body": r["body"], "wavelength": float(g["wavelength_bl"]),
                    "ratio": round(float(f["mu_transverse"]) / float(f["mu_forward"]), 6),
                    "amplitude": float(g["curvature_amplitude"]), "frequency": float(g["frequency_hz"]),
                    "block": 2 if float(g["ramp_s"]) == SECOND_BLOCK_RAMP_S else 1,
                    "error": float(err) if err is not None and np.isfinite(err) else math.nan,
                    "status": str(r["status"]), "flagged": r.get("metric.shape_not_achieved") == 1.0})
    return out


def panel(ax, rows, xkey, ykey, xlabel, ylabel, title):
    xs = sorted({r[xkey] for r in rows})
    ys = sorted({r[ykey] for r in rows})
    grid = np.full((len(ys), len(xs)), np.nan)
    for r in rows:
        grid[ys.index(r[ykey]), xs.index(r[xkey])] = min(r["error"], 1.0) if np.isfinite(r["error"]) else np.nan
    im = ax.imshow(grid, origin="lower", cmap="viridis_r", vmin=0.0, vmax=1.0, aspect="auto")
    for r in rows:
        i, j = ys.index(r[ykey]), xs.index(r[xkey])
        text = "X" if r["status"] == "unstable" else (f"{r['error']:.2f}" if np.isfinite(r["error"]) else "-")
        if r["flagged"] and r["status"] != "unstable":
            text = f"({text})"
        if r["status"] == "controller_unstable":
            text = "R " + text
        ax.text(j, i, text, ha="center", va="center", fontsize=7,
                color="white" if np.isfinite(grid[i, j]) and grid[i, j] > 0.5 else "black")
    ax.set_xticks(range(len(xs)), [f"{x:g}" for x in xs])
    ax.set_yticks(range(len(ys)), [f"{y:g}" for y in ys])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    return im


def draw(directories, out: Path) -> Path:
    """The figure of the matrix output directories ``directories`` (one Path, or several whose cases are drawn
    together) written to ``out``."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from bench_myriapoda.report.matrix_data import load_matrix_dir

    dirs = [directories] if isinstance(directories, (str, Path)) else list(directories)
    rows = [row for d in dirs for row in cells(load_matrix_dir(Path(d)).df)]
    bodies = [b for b in ("massspring", "fem", "hybrid") if any(r["body"] == b for r in rows)]
    fig, axes = plt.subplots(2, len(bodies), figsize=(max(6.5, 4.5 * len(bodies)), 8.0), squeeze=False,
                             constrained_layout=True)
    im = None
    for k, body in enumerate(bodies):
        mine = [r for r in rows if r["body"] == body]
        wave = [r for r in mine if r["block"] == 1]  # wavelength x friction at the snake's amplitude and frequency
        amp = [r for r in mine if r["block"] == 2]  # amplitude x frequency at mu_t / mu_f = 5
        base_amp = wave[0]["amplitude"] if wave else math.nan
        if wave:
            im = panel(axes[0, k], wave, "ratio", "wavelength", "mu_t / mu_f", "wavelength [BL]",
                       f"{body}: shape error, curvature {base_amp:g}, 0.5 Hz")
        if amp:
            im = panel(axes[1, k], amp, "frequency", "amplitude", "frequency [Hz]", "curvature x L",
                       f"{body}: shape error, mu_t / mu_f = 5, 0.5 BL")
    if im is not None:
        fig.colorbar(im, ax=axes.ravel().tolist(), shrink=0.6, label="shape_tracking_error (clipped at 1)")
    fig.suptitle("Where the shape tracker holds\nR: guard backed off (controller_unstable); X: blew up; "
                 "(n): shape_not_achieved", fontsize=9)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("directory", nargs="+", help="matrix output directories of tracking-map(-lattice), drawn together")
    p.add_argument("--out", default=None, help="the figure (.png; default FIRST_DIRECTORY/tracking-map.png)")
    a = p.parse_args(argv)
    from bench_myriapoda.core.errors import InputError

    try:
        dirs = [Path(d) for d in a.directory]
        path = draw(dirs, Path(a.out) if a.out else dirs[0] / "tracking-map.png")
    except InputError as exc:
        print(f"tracking_map: error: {exc}", file=sys.stderr)
        return 2
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
