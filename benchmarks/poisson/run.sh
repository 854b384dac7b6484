#!/usr/bin/env bash
# Pressure Poisson benchmark: every solver, 64^3 and 128^3, 1 and 2 ranks, in one run (the
# machine's speed drifts: compare ratios within a run). Writes results.csv and poisson.png here.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
source "$root/scripts/mpienv"
bench="$root/build/benchmarks/bench_poisson"
petsc_boomeramg="-pressure_pc_hypre_boomeramg_relax_type_down symmetric-SOR/Jacobi -pressure_pc_hypre_boomeramg_relax_type_up symmetric-SOR/Jacobi
 -pressure_pc_hypre_boomeramg_relax_type_coarse Gaussian-elimination -pressure_pc_hypre_boomeramg_coarsen_type Falgout -pressure_pc_hypre_boomeramg_interp_type classical
 -pressure_pc_hypre_boomeramg_P_max 0 -pressure_pc_hypre_boomeramg_strong_threshold 0.25
 -pressure_pc_hypre_boomeramg_agg_nl 0 -pressure_pc_hypre_boomeramg_agg_num_paths 1"
out="$here/results.csv"
echo "solver,ranks,n,setup_s,solve_s,iterations" > "$out"
for n in 64 128; do
  solves=$([ "$n" -eq 64 ] && echo 5 || echo 3)
  for np in 1 2; do
    run() { mpirun -n "$np" "$bench" -n "$n" -solves "$solves" "$@" | tee -a "$out"; }
    run -label boomeramg_vpsolve_default
    # shellcheck disable=SC2086
    run -label boomeramg_petsc_default $petsc_boomeramg
    run -label gmg -pressure_pc_type mg
    run -label pfmg -pressure_pc_type pfmg
    run -label fft -pressure_pc_type fft
  done
done
/usr/bin/python3 "$here/plot.py" "$out" "$here/poisson.png"
