#!/usr/bin/env bash
# Coupling benchmark: 1, 100 and 1000 spheres (d/dx = 8, density 1500 in water-like fluid) at 128^3
# on 1 and 2 ranks, in one run. Writes results.csv and coupling.png here.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
source "$root/scripts/mpienv"
bench="$root/build/benchmarks/bench_coupling"
out="$here/results.csv"
a=0.03125  # d = 8 cells of 1/128
common="-particle_density 1500 -particle_radius $a -contact_tc 0.05 -dem_substeps 10 -time_dt 0.002"
echo "ranks,n,particles,step_s,advection_s,diffusion_s,pressure_s,penalization_s,hydroforce_s,dem_s,exchange_s" > "$out"
for np in 1 2; do
  # shellcheck disable=SC2086
  mpirun -n "$np" "$bench" -n 128 $common -particle_position 0.5,0.5,0.5 | tee -a "$out"
  mpirun -n "$np" "$bench" -n 128 $common -particles_lattice 0,0,0,1,1,0.8,0.2,$a,0.5,1 | tee -a "$out"
  mpirun -n "$np" "$bench" -n 128 $common -particles_lattice 0,0,0,1,1,1,0.1,$a,0.5,1 | tee -a "$out"
done
/usr/bin/python3 "$here/plot.py" "$out" "$here/coupling.png"
