#!/usr/bin/env bash
# DEM throughput and runout: vpsolve -fluid_off against LAMMPS (gran/hooke/history) on the shared
# dry column collapse (the shared benchmark of README.md: data, collapse.lmp, front.py, used as they are; CASE_DIR),
# both codes back to back for each N and rank count, since the machine's speed drifts.
# usage: benchmarks/dem/run_benchmark.sh [N ...]        (default: 2000 10000 50000)
# env:   STEPS (20000), RANKS ("1 2"), CASE_DIR (shared case), WORK (a scratch directory)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
CASE_DIR=${CASE_DIR:-$root/../shared/benchmarks/dem}
STEPS=${STEPS:-20000}
RANKS=${RANKS:-"1 2"}
WORK=${WORK:-$root/build/bench_dem_work}
sizes=${*:-"2000 10000 50000"}
source "$root/scripts/mpienv"
cmake --build "$root/build" --target vpsolve bench_dem -j2 >/dev/null
mkdir -p "$WORK"
cd "$WORK"
dt=3.6e-6
printf "%-6s %-5s %10s %10s %12s %12s %7s\n" N ranks lammps_s vpsolve_s lammps_Mps vpsolve_Mps ratio
results=()
for N in $sizes; do
  W=$(python3 -c "print($N / 200 * 1.05e-3)")
  ny=$(( 32 * N / 2000 > 256 ? 256 : 32 * N / 2000 ))
  zcat "$CASE_DIR/data/column_$N.data.gz" > "column_$N.data"
  zcat "$CASE_DIR/data/column_$N.csv.gz" > "column_$N.csv"
  for P in $RANKS; do
    lmp_out=$(mpirun -np "$P" lmp -in "$CASE_DIR/collapse.lmp" -var N "$N" -var nsteps "$STEPS" -var ndump "$STEPS" \
              -var tag "_P$P" -log none)
    t_lmp=$(printf '%s\n' "$lmp_out" | awk '/^Loop time of/ {print $4}')
    rm -rf "vp_${N}_P$P"
    # Same law: kn for both contact types, damping for e = 0.9 per contact mass, kt = 2/7 kn,
    # gamma_t = gamma_n / 2, mu = 0.25. Cells only set the decomposition (split along y). Same work
    # besides: a diagnostics row every 1000 steps (LAMMPS's thermo), no orientation (nve/sphere).
    vp_out=$(mpirun -np "$P" "$root/build/vpsolve" -fluid_off -grid_lo 0,0,0 -grid_hi 0.15,"$W",0.04 -grid_n 4,"$ny",4 \
             -gravity 0,0,-9.81 -particles_file "column_$N.csv" -contact_kn 200 -contact_restitution 0.9 \
             -contact_friction 0.25 -contact_kt_ratio 0.285714286 -contact_damping_t_ratio 0.5 -time_dt $dt \
             -time_max_steps "$STEPS" -time_final 1 -output_every "$STEPS" -monitor_every 0 -output_dir "vp_${N}_P$P" \
             -series_every 1000 -dem_orientation false)
    t_vp=$(printf '%s\n' "$vp_out" | sed -n 's/.*loop time \([0-9.e+-]*\) s.*/\1/p')
    snap=$(printf "vp_%s_P%s/particles_%06d.h5" "$N" "$P" "$STEPS")
    "$root/build/benchmarks/bench_dem" "$snap" "$STEPS" > "collapse_vp_${N}_P$P.dump"
    python3 - "$N" "$P" "$t_lmp" "$t_vp" "$STEPS" <<'PY'
import sys
n, p, tl, tv, steps = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5])
print("%-6d %-5d %10.3f %10.3f %12.2f %12.2f %7.2f" % (n, p, tl, tv, n * steps / tl / 1e6, n * steps / tv / 1e6, tl / tv))
PY
    results+=("$N $W collapse_lmp_hooke_${N}_P$P.dump collapse_vp_${N}_P$P.dump")
  done
done
echo
echo "Runout after $STEPS steps ($(python3 -c "print($STEPS * $dt)") s), front.py measures in mm (last snapshot of each file):"
for r in "${results[@]}"; do
  set -- $r
  python3 "$CASE_DIR/front.py" "$dt" "$2" "$3" "$4" | awk -v s="$STEPS" 'NR == 1 || $2 == s'
done
