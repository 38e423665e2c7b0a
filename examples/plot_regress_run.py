"""
A regress run
=============

``bench-myriapoda regress`` times a fixed throughput suite and compares it with a baseline run on
the same machine; the compared figure is steps/s divided by a reference kernel's speed timed in the
same sitting, so a busier machine does not read as a regression. The same from Python: time two
entries of the suite twice into a scratch results store, compare the second run with the first,
and draw the history as the report does.
"""
import json
import os
import tempfile
from pathlib import Path

from bench_myriapoda.harness import regress as R
from bench_myriapoda.harness.machine import machine_fingerprint
from bench_myriapoda.harness.store import record_regress_run
from bench_myriapoda.report.figure_files import show_png
from bench_myriapoda.report.regress_history import plot_regress_history

SCALE = float(os.environ.get("BENCH_MYRIAPODA_EXAMPLE_SCALE", "1"))
ENTRIES = ["rigid-boxes", "massspring-snake"]
store = Path(tempfile.mkdtemp()) / "results.sqlite"
repeats = 5 if SCALE >= 1 else 3

first = R.run_suite(ENTRIES, repeats)
base_id = record_regress_run(store, [e.row() for e in first])
second = R.run_suite(ENTRIES, repeats)
record_regress_run(store, [e.row() for e in second])

machine = json.dumps(machine_fingerprint(), sort_keys=True)
baseline = R.resolve_baseline(store, str(base_id), machine, ENTRIES)
for line in R.format_table(R.compare(second, baseline)):
    print(line)

png = plot_regress_history(R.load_history(store), Path(tempfile.mkdtemp()) / "history.png",
                           title="normalized throughput, two runs")
show_png(png)
