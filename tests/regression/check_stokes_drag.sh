#!/bin/sh
# -dem_drag_viscosity: a sphere (d = 1 mm, 2500 kg/m^3) falling under gravity in the DEM-only
# Stokes liquid (mu 0.1 Pa s) reaches the exact terminal speed m g / (3 pi mu d) after 36
# relaxation times m / (3 pi mu d). usage: check_stokes_drag.sh VPSOLVE
set -e
out=stokes_drag; rm -rf $out
"$1" -fluid_off -grid_lo 0,0,0 -grid_hi 0.004,0.004,0.01 -grid_n 2,2,4 -gravity 0,0,-9.81 \
  -particle_position 0.002,0.002,0.005 -particle_radius 5e-4 -particle_density 2500 -contact_tc 1e-4 \
  -dem_drag_viscosity 0.1 -time_dt 1e-4 -dem_substeps 4 -time_final 0.05 -track_particles all \
  -monitor_every 0 -output_dir $out >/dev/null
/usr/bin/python3 - $out <<'PY'
import csv, glob, math, sys
rows = list(csv.DictReader(open(glob.glob(sys.argv[1] + "/particle_*.csv")[0])))
m = 2500 * 4 / 3 * math.pi * 5e-4 ** 3
exact = m * 9.81 / (3 * math.pi * 0.1 * 1e-3)
vz = -float(rows[-1]["vz"])
err = abs(vz - exact) / exact
print(f"terminal speed {vz:.6e} m/s, exact {exact:.6e} m/s, relative error {err:.1e}")
sys.exit(0 if err < 1e-6 else 1)
PY
