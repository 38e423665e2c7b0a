"""
Load a matrix's results into pandas
===================================

A scenario matrix is a TOML file that crosses creatures, bodies, gaits, scenarios, seeds and a grid
of any configuration keys. :func:`bench_myriapoda.api.run_matrix` runs it as ``bench-myriapoda matrix``
does and returns :func:`bench_myriapoda.api.load_results` of its output directory: one row per case, one
column per metric, the swept keys as columns. Here the worm's wave frequency is swept on two body
models; Miller's rectilinear crawl should move eps x Lambda per cycle, so the speed grows in
proportion to the frequency.
"""
import os
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

import bench_myriapoda as bm

# The cases run in worker processes, which import this script again: the guard keeps them from
# running the matrix themselves.
if __name__ == "__main__":
    SCALE = float(os.environ.get("BENCH_MYRIAPODA_EXAMPLE_SCALE", "1"))
    work = Path(tempfile.mkdtemp())
    matrix = work / "frequency.toml"
    matrix.write_text(f"""
    [matrix]
    name = "frequency"
    creatures = ["worm"]
    bodies = ["massspring", "fem"]
    scenarios = ["flat"]
    duration = {max(4.0, 8.0 * SCALE)}
    set = {{ "gait.ramp_s" = 0.5, "metrics.warmup_cycles" = 0.5 }}
    [matrix.grid]
    "gait.frequency_hz" = [0.5, 1.0, 2.0]
    """)

    df = bm.run_matrix(matrix, out=work / "out", workers=1)
    print(df[["body", "gait.frequency_hz", "status", "speed_m_per_s", "displacement_per_cycle_m"]])

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for body, rows in df.sort_values("gait.frequency_hz").groupby("body"):
        ax.plot(rows["gait.frequency_hz"], rows["speed_m_per_s"] * 100, "o-", label=body)
    eps_lambda = 0.2 * 0.5 * 0.8                        # amplitude x wavelength (0.5 BL of a 0.8 m worm) [m]
    f = df["gait.frequency_hz"].sort_values().unique()
    ax.plot(f, eps_lambda * f * 100, "k--", label="eps x Lambda x f")
    ax.set(xlabel="wave frequency [Hz]", ylabel="speed [cm/s]", title="the worm's speed over its wave frequency")
    ax.legend()
    fig.tight_layout()
    plt.show()
