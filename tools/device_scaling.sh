#!/usr/bin/env bash
# Issue 31: how a matrix scales with the machine, measured in one run on a many-core machine.
#
# Run from the repository root:   OUT=/some/dir bash tools/device_scaling.sh
# Needs python3 with numpy, numba, scipy, pandas, matplotlib, tqdm, psutil, cloudpickle, toolz, msgpack,
# jinja2, click, pyyaml, sortedcontainers; trimesh and dask[distributed] come from the wheels in .devwheels/
# (installed into a private folder, never into the system).  No network is needed.
#
# Series, in order of importance; one whose estimate does not fit in what is left of BUDGET_S is skipped:
#   quick cold (fresh numba cache) on BIG workers; the probe on BIG (its caterpillar cases are new kinds);
#   worker fixed costs (spawn and forkserver, 1 and BIG workers, compile plans off and on); probe warm on BIG
#   and 1 (the 10x target: probe-warm-1 over probe-warm-BIG); quick cold on BIG again on a second fresh cache
#   with the compile plans off (BENCH_MYRIAPODA_COMPILE_PLAN=off: no kernels compiled ahead, none preloaded,
#   the executor before compile plans), so the cold target (quick-cold-BIG under 25 s) has its before beside
#   it; quick warm on BIG and 1; probe on dask with BIG workers; quick and probe warm on MID; probe warm on
#   BIG in file order (the order before issue 31); quick warm on BIG with spawned workers (the start before
#   issue 31); quick warm on BIG in file order.  Warm series start with the cold run's rows in their store,
#   so their cases are ordered by what this machine measured.  Last, the cold quick matrix simulated for 1 to
#   BIG workers from quick-warm-1's case costs and the recorded compile plans (cold_compile --simulate).
# Writes into $OUT: one folder per series (matrix.json with the schedule section, results.csv, results.sqlite,
# the run's log, process.json), summary.json and summary.md (walls, parallel efficiency, critical path,
# predicted-vs-measured r), fixed_costs.jsonl, simulated.json in the 1-worker folders, env.txt, progress.log.
#
# Local smoke test (2 cores, tiny matrices): DEVICE_TINY=1 BIG=2 MID=2 BUDGET_S=2400 OUT=/tmp/x bash tools/device_scaling.sh
# (SCALING_CACHE=DIR: use that numba cache instead of a fresh one; PY=...: another interpreter)
# One device call for the targets: OUT=$OUT BUDGET_S=420 bash tools/device_scaling.sh (about 6 minutes on 16 cores).
# PLAN=repeats: only the cold quick and probe series, then the probe on BIG five times, on 1 once, the quick
# matrix warm on BIG three times and on MID (about 4 minutes on 16 cores).  PACK=1: $OUT also gets
# scaling.tar.gz, everything in one file (the device tool returns at most 8 files).
set -u
cd "$(dirname "$0")/.."
ROOT=$PWD
OUT=${OUT:?set OUT to the output folder}
PY=${PY:-python3}
BIG=${BIG:-16}
MID=${MID:-4}
BUDGET_S=${BUDGET_S:-420}      # start no series that would end after this many seconds
WORK=${WORK:-$(mktemp -d /tmp/bench-scaling.XXXXXX)}
T0=$(date +%s)
mkdir -p "$OUT" "$WORK"
log() { echo "[$(( $(date +%s) - T0 )) s] $*" | tee -a "$OUT/progress.log"; }

# --- dependencies: the wheels into a private folder, the project from this checkout
SITE=$WORK/site
if ! $PY -c "import trimesh, dask.distributed" 2>/dev/null; then
  $PY -m pip install --quiet --no-index --find-links "$ROOT/.devwheels" --no-deps --target "$SITE" \
      "$ROOT"/.devwheels/*.whl >"$OUT/pip.log" 2>&1 || {
    log "pip install failed (see pip.log); unpacking the wheels instead (they are zip files)"
    $PY -c "import sys, zipfile, glob; [zipfile.ZipFile(w).extractall(sys.argv[1]) for w in glob.glob(sys.argv[2] + '/*.whl')]" \
        "$SITE" "$ROOT/.devwheels"; }
fi
export PYTHONPATH=$ROOT:$SITE${PYTHONPATH:+:$PYTHONPATH}
export NUMBA_CACHE_DIR=${SCALING_CACHE:-$WORK/numba-cache}   # fresh: the first series compiles everything
export MPLBACKEND=Agg
{ echo "date: $(date -u)"; echo "nproc: $(nproc)"; lscpu 2>/dev/null | grep -E "Model name|^CPU\(s\)|Thread|Core|Socket|NUMA node\(s\)";
  $PY -c "import sys, numpy, numba, dask, distributed, trimesh; print(sys.version.split()[0], 'numpy', numpy.__version__, 'numba', numba.__version__, 'dask', dask.__version__, 'trimesh', trimesh.__version__)";
  git -C "$ROOT" log -1 --format='commit %H %s' 2>/dev/null; } >"$OUT/env.txt" 2>&1
cat "$OUT/env.txt"
$PY -c "import bench_myriapoda.cli" || { log "cannot import the project"; exit 1; }

QUICK=quick
PROBE=probe
if [ -n "${DEVICE_TINY:-}" ]; then  # the smoke test: two tiny matrices of the same kinds of case
  mkdir -p "$WORK/m"
  cp "$ROOT/tools/device_matrices/quick.toml" "$WORK/m/quick.toml"  # a data file: the matrix's TOML
  sed 's/name = "quick"/name = "probe"/; s/seeds = \[0\]/seeds = [0, 1]/' "$WORK/m/quick.toml" >"$WORK/m/probe.toml"
  QUICK=$WORK/m/quick.toml
  PROBE=$WORK/m/probe.toml
fi

# series NAME MATRIX WORKERS ESTIMATE_S [extra flags...]: run it if ESTIMATE_S fits in what is left
series() {
  local name=$1 matrix=$2 workers=$3 est=$4; shift 4
  local now=$(( $(date +%s) - T0 ))
  if [ $(( now + est )) -gt "$BUDGET_S" ]; then log "skip $name (needs ~$est s, $(( BUDGET_S - now )) s left)"; return; fi
  if [ -n "${SEED_FROM:-}" ] && [ -f "$WORK/$SEED_FROM/results.sqlite" ]; then
    # the cold run's rows: the cost model predicts this run's cases from what the machine measured
    mkdir -p "$WORK/$name" && cp "$WORK/$SEED_FROM/results.sqlite" "$WORK/$name/results.sqlite"
  fi
  log "start $name: $matrix on $workers worker(s) $* ${SEED_FROM:+(costs from $SEED_FROM)}"
  local t0=$(date +%s.%N)
  timeout $(( BUDGET_S - now + 30 )) $PY -m bench_myriapoda.cli matrix "$matrix" --workers "$workers" \
      --out "$WORK/$name" "$@" >"$WORK/$name.log" 2>&1
  local rc=$?
  local t1=$(date +%s.%N)
  mkdir -p "$OUT/$name"
  cp "$WORK/$name.log" "$OUT/$name/run.log"
  for f in matrix.json results.csv results.sqlite; do [ -f "$WORK/$name/$f" ] && cp "$WORK/$name/$f" "$OUT/$name/"; done
  echo "{\"name\": \"$name\", \"workers\": $workers, \"rc\": $rc, \"process_wall_s\": $(awk "BEGIN{print $t1 - $t0}")}" >"$OUT/$name/process.json"
  log "end $name rc=$rc: $(grep -E '^parallel efficiency' "$WORK/$name.log" || tail -1 "$WORK/$name.log")"
}

fixed_costs() {  # spawn and forkserver workers: 1 alone and BIG at once (warm cache)
  local now=$(( $(date +%s) - T0 ))
  if [ $(( now + 60 )) -gt "$BUDGET_S" ]; then log "skip worker fixed costs"; return; fi
  log "worker fixed costs"
  timeout 120 $PY -m bench_myriapoda.harness.worker_costs --workers 1 "$BIG" --start both --plans both \
      >"$OUT/fixed_costs.jsonl" 2>"$OUT/fixed_costs.err"
  log "end worker fixed costs rc=$?"
}

series quick-cold-$BIG  "$QUICK" "$BIG" 75
series probe-cold-$BIG  "$PROBE" "$BIG" 60
if [ "${PLAN:-full}" = repeats ]; then
  # PLAN=repeats: the two targets again, the 16-worker series several times (the first full run's probe on 16
  # read 7.5 s warm and 6.3 s in its cold series: one run each is not a figure)
  export SEED_FROM=probe-cold-$BIG
  for i in 1 2 3 4 5; do series probe-warm-$BIG-r$i "$PROBE" "$BIG" 25; done
  series probe-warm-1 "$PROBE" 1 80
  for i in 1 2 3; do SEED_FROM=quick-cold-$BIG series quick-warm-$BIG-r$i "$QUICK" "$BIG" 20; done
  SEED_FROM=quick-cold-$BIG series quick-warm-$MID "$QUICK" "$MID" 20
  BUDGET_S=0  # nothing of the full plan below starts
fi
fixed_costs
export SEED_FROM=probe-cold-$BIG
series probe-warm-$BIG  "$PROBE" "$BIG" 25
series probe-warm-1     "$PROBE" 1 80
# the cold quick matrix as before compile plans, on a cache of its own (empty)
SEED_FROM= NUMBA_CACHE_DIR=$WORK/numba-cache-plans-off BENCH_MYRIAPODA_COMPILE_PLAN=off \
  series quick-cold-$BIG-plans-off "$QUICK" "$BIG" 75
SEED_FROM=quick-cold-$BIG series quick-warm-$BIG  "$QUICK" "$BIG" 20
SEED_FROM=quick-cold-$BIG series quick-warm-1     "$QUICK" 1 35
series probe-dask-$BIG  "$PROBE" "$BIG" 35 --executor dask
SEED_FROM=quick-cold-$BIG series quick-warm-$MID  "$QUICK" "$MID" 20
series probe-warm-$MID  "$PROBE" "$MID" 35
series probe-warm-$BIG-fileorder "$PROBE" "$BIG" 25 --schedule file
SEED_FROM=quick-cold-$BIG BENCH_MYRIAPODA_WORKER_START=spawn series quick-warm-$BIG-spawn "$QUICK" "$BIG" 20
SEED_FROM=quick-cold-$BIG series quick-warm-$BIG-fileorder "$QUICK" "$BIG" 20 --schedule file

# --- the schedule simulator on the warm single-worker runs' case costs
for d in quick-warm-1 probe-warm-1; do
  [ -f "$OUT/$d/results.sqlite" ] && timeout 60 $PY -m bench_myriapoda.harness.schedule "$OUT/$d" --json \
      >"$OUT/$d/simulated.json" 2>>"$OUT/progress.log"
done

# --- the cold quick matrix simulated with and without kernels compiled ahead (recorded compile plans)
if [ -f "$OUT/quick-warm-1/results.sqlite" ] && [ -z "${DEVICE_TINY:-}" ]; then
  timeout 60 $PY -m bench_myriapoda.harness.cold_compile --simulate "$OUT/quick-warm-1" --matrix "$QUICK" \
      --workers 1 2 4 8 "$BIG" >"$OUT/quick-warm-1/simulated_cold.txt" 2>>"$OUT/progress.log"
fi

# --- summary of every series that ran
$PY - "$OUT" <<'EOF'
import json, sys
from pathlib import Path
out = Path(sys.argv[1])
rows = []
for d in sorted(p for p in out.iterdir() if p.is_dir()):
    proc = json.loads((d / "process.json").read_text()) if (d / "process.json").is_file() else {}
    m = json.loads((d / "matrix.json").read_text()) if (d / "matrix.json").is_file() else {}
    s = m.get("schedule", {})
    e = s.get("efficiency", {})
    rows.append({"series": d.name, "rc": proc.get("rc"), "process_wall_s": proc.get("process_wall_s"),
                 "matrix_wall_s": e.get("matrix_wall_s"), "workers": e.get("workers"), "cases": e.get("cases"),
                 "case_wall_sum_s": e.get("case_wall_sum_s"), "parallel_efficiency": e.get("parallel_efficiency"),
                 "critical_path_s": e.get("critical_path_s"), "critical_case": e.get("critical_case"),
                 "predicted_vs_measured_r": s.get("predicted_vs_measured_r"), "cost_sources": s.get("cost_sources"),
                 "emit_s": s.get("emit_s")})
(out / "summary.json").write_text(json.dumps(rows, indent=1))
def f(v, fmt):
    return "-" if v is None else format(v, fmt)
lines = ["| series | rc | process wall s | matrix wall s | workers | cases | sum of case walls s | efficiency | critical path s | r(pred, meas) |",
         "|---|---|---|---|---|---|---|---|---|---|"]
for r in rows:
    lines.append(f"| {r['series']} | {r['rc']} | {f(r['process_wall_s'], '.1f')} | {f(r['matrix_wall_s'], '.1f')} | {r['workers']} | "
                 f"{r['cases']} | {f(r['case_wall_sum_s'], '.1f')} | {f(r['parallel_efficiency'], '.0%')} | "
                 f"{f(r['critical_path_s'], '.1f')} | {f(r['predicted_vs_measured_r'], '.2f')} |")
(out / "summary.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
EOF
log "done in $(( $(date +%s) - T0 )) s"
# the device returns at most 8 files: with PACK=1 everything above goes back as one archive too
if [ -n "${PACK:-}" ]; then
  tar -czf "$WORK/scaling.tar.gz" -C "$OUT" . && mv "$WORK/scaling.tar.gz" "$OUT/scaling.tar.gz"
fi
