#!/usr/bin/env bash
# The immersed collapse (cases/dam_break.opts, the loose column) at d/dx 6, 8 and 12 on 1 and 2
# ranks: seconds per step by stage and the viscous iterations, for one or two builds run alternately
# (the first is "before", the second "after"), each with its own case file (default
# cases/dam_break.opts of this tree). Writes collapse.csv and collapse.png here.
# usage: benchmarks/coupling/collapse.sh [vpsolve_before[:case.opts]] vpsolve_after[:case.opts]
#        (default: build/vpsolve); STEPS=20 (STEPS12=12 at d/dx 12), CASES="6 8 12", RANKS="1 2"
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
source "$root/scripts/mpienv"
bins=("$@"); [ ${#bins[@]} -eq 0 ] && bins=("$root/build/vpsolve")
labels=(after); [ ${#bins[@]} -eq 2 ] && labels=(before after)
out="$here/collapse.csv"; scratch=${VP_SCRATCH:-/tmp/vp-bench-collapse}
echo "build,d_dx,ranks,cells,steps,step_s,advection_s,diffusion_s,pressure_s,penalization_s,hydroforce_s,dem_s,io_s,velocity_its,particle_ke" > "$out"
declare -A grid=([6]=384,24,120 [8]=512,32,160 [12]=768,48,240)
for dxd in ${CASES:-6 8 12}; do
  steps=${STEPS:-20}; [ "$dxd" = 12 ] && steps=${STEPS12:-12}
  for np in ${RANKS:-1 2}; do
    for b in "${!bins[@]}"; do
      dir="$scratch/${labels[$b]}_${dxd}_$np"; rm -rf "$dir"; mkdir -p "$dir"
      bin=${bins[$b]%%:*}; case=$root/cases/dam_break.opts; [ "$bin" != "${bins[$b]}" ] && case=${bins[$b]#*:}
      (cd "$root" && mpirun -n "$np" "$bin" -options_file "$case" -grid_n "${grid[$dxd]}" \
        -time_max_steps "$steps" -output_dt 0 -monitor_every "$steps" -output_dir "$dir" >"$dir/log" 2>&1)
      /usr/bin/python3 - "$dir" "${labels[$b]}" "$dxd" "$np" "${grid[$dxd]}" "$steps" >>"$out" <<'PY'
import re, sys, csv
d, label, dxd, np_, grid, steps = sys.argv[1:]
log = open(d + "/log").read()
sps = float(re.findall(r"\(([0-9.]+) s/step", log)[-1])
stage = {m[0]: float(m[1]) / 1e3 for m in re.findall(r"vpsolve:\s+(\w+)\s+[0-9.]+\s+[0-9.]+\s+([0-9.]+)\n", log)}
ke = re.findall(r"particle kinetic energy ([0-9.eE+-]+)", log)[-1]
rows = list(csv.DictReader(open(d + "/diagnostics.csv")))
its = sum(float(r["velocity_iterations"]) for r in rows[1:]) / max(len(rows) - 1, 1)
n = 1
for x in grid.split(","): n *= int(x)
print(",".join([label, dxd, np_, str(n), steps, "%.4f" % sps] +
               ["%.4f" % stage.get(s, 0) for s in ("Advection", "Diffusion", "Pressure", "Penalization", "HydroForce", "DEM", "IO")] +
               ["%.2f" % its, ke]))
PY
      tail -n 1 "$out"
    done
  done
done
/usr/bin/python3 "$here/plot_collapse.py" "$out" "$here/collapse.png"
