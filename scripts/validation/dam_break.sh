#!/usr/bin/env bash
# The full immersed dam breaks (docs/dam_break.md): the loose and the dense column at N cells per
# diameter (default 8) until they come to rest (the 99th-percentile front slower than 0.1 d/s over
# 0.5 s: -collapse_rest_speed) or time T (default 30 s; at d/dx 6 the dense column rested at 14.9 s),
# then scripts/plot_dam_break into docs/validation. Checkpoints every 250 steps; run again, the
# script continues each column from its latest checkpoint (a run cut short by a job's time limit
# loses at most 250 steps) and skips a column that came to rest (marked DIR/at_rest); the console
# goes to DIR.log as well; delete output/validate_dam_break_* to start afresh.
# usage (through scripts/validate): scripts/validate dam_break [N [T]]
# Cost on 2 cores (measured 2026-11-23): d/dx 6 about 0.3 s per step of 1e-3 s (5 minutes per
# simulated second), d/dx 8 about 0.84 s (14 minutes per simulated second), for each column.
set -euo pipefail
n=${1:-8}; t=${2:-30}
cd "$VP_ROOT"
grid="$((64 * n)),$((4 * n)),$((20 * n))"
labels=()
for kind in loose dense; do
  case_file=cases/dam_break.opts; [ "$kind" = dense ] && case_file=cases/dam_break_dense.opts
  out=output/validate_dam_break_${kind}_d$n
  labels+=("${kind}_d$n=$out")
  # A column at rest is done: a restart would begin a new rest window and run on for 0.5 s.
  if [ -e "$out/at_rest" ]; then echo "dam break $kind, d/dx $n: at rest ($(cat "$out/at_rest")); delete $out to run it again"; continue; fi
  start=(-output_overwrite)
  if [ -e "$out/checkpoint_latest.h5" ]; then start=(-restart "$out/checkpoint_latest.h5"); fi
  echo "dam break $kind, d/dx $n ($grid cells), to rest or t = $t s -> $out (${start[*]})"
  mpirun -n "$NP" build/vpsolve -options_file "$case_file" -grid_n "$grid" -time_final "$t" -output_dir "$out" \
    "${start[@]}" -monitor_every 200 -output_dt 0.1 -checkpoint_every 250 \
    -collapse_rest_speed 1e-4 -collapse_rest_window 0.5 | tee -a "$out.log"
  if stopped=$(grep "stopped at step" "$out.log" | tail -1) && [[ $stopped == *"came to rest"* ]]; then echo "${stopped#vpsolve: }" > "$out/at_rest"; fi
done
scripts/plot_dam_break --out docs/validation "${labels[@]}"
