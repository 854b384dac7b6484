#!/usr/bin/env bash
# Strong scaling (docs/scaling.md): the coupled step (128^3 cells, 1,000 spheres with d/dx = 8,
# BoomerAMG pressure) and the dry DEM collapse (cases/granular_collapse_dry.opts, 2,000 spheres) on
# 1, 2, 4 and 8 ranks, each with -log_view. Ranks beyond this machine's cores run oversubscribed:
# there the results are checked against one rank and the message counts recorded, but the times
# are not speed-ups. Runs and logs go to output/scaling/; results.csv, scaling.md (tables) and
# scaling.png are written here.
# usage: benchmarks/scaling/run.sh [ranks...]   (default 1 2 4 8; STEPS, DEM_STEPS: run lengths)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
source "$root/scripts/mpienv"
ranks=("$@"); [ ${#ranks[@]} -gt 0 ] || ranks=(1 2 4 8)
vp="$root/build/vpsolve"
runs="$root/output/scaling"
mkdir -p "$runs"
a=0.03125  # d = 8 cells of 1/128
coupled=(-grid_n 128,128,128 -grid_hi 1,1,1 -fluid_rho 1000 -fluid_mu 1e-2 -gravity 0,0,-9.81
         -particles_lattice 0,0,0,1,1,1,0.1,$a,0.5,1 -particle_density 1500 -particle_radius $a -contact_tc 0.05
         -dem_substeps 10 -time_dt 0.002 -time_max_steps "${STEPS:-8}" -output_every 0 -monitor_every 0)
dem=(-options_file "$root/cases/granular_collapse_dry.opts" -particles_file "$root/cases/data/column_2000.csv"
     -time_max_steps "${DEM_STEPS:-20000}" -output_dt 0 -output_every 0)
cd "$root"
for np in "${ranks[@]}"; do
  for c in coupled dem; do
    log="$runs/${c}_np$np.log"
    echo "$c on $np rank(s) -> $log"
    if [ "$c" = coupled ]; then args=("${coupled[@]}"); else args=("${dem[@]}"); fi
    mpirun --oversubscribe -n "$np" "$vp" "${args[@]}" -output_dir "$runs/${c}_np$np" -output_overwrite \
      -log_view >"$log" 2>&1
  done
done
/usr/bin/python3 "$here/analyse.py" "$runs" "$here" "$(nproc)" "${ranks[@]}"
