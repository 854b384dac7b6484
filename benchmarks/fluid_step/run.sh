#!/usr/bin/env bash
# Fluid step benchmark: seconds per step by stage, 3-D cavity, 64^3 and 128^3 on 1 and 2 ranks, in
# one run. Writes results.csv and fluid_step.png here.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
source "$root/scripts/mpienv"
bench="$root/build/benchmarks/bench_fluid_step"
out="$here/results.csv"
echo "ranks,n,steps,step_s,advection_s,diffusion_s,pressure_s,us_per_cell_step_core" > "$out"
for n in 64 128; do
  for np in 1 2; do
    mpirun -n "$np" "$bench" -n "$n" -warmup 5 -steps 10 "$@" | tee -a "$out"
  done
done
/usr/bin/python3 "$here/plot.py" "$out" "$here/fluid_step.png"
