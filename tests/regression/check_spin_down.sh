#!/bin/sh
# -dem_implicit_drag: a free sphere (d = 1 mm, 2500 kg/m^3) spinning at 100 rad/s in a still liquid
# (mu 0.1 Pa s; spin relaxation time rho_p d^2 / (60 mu) = 0.42 ms), d/dx 6, 6 d box. With the
# implicit drag the spin decays without reversing at fluid steps of 0.3 ms, and at 0.1 ms it is
# within 5 % of the converged spin-down at 1.2 ms (8.38 rad/s: both forms extrapolated to dt -> 0 from
# 1e-5 and 5e-6 s (held) and 3e-5 and 1e-5 s (implicit); docs/coupling.md).
# Without it the spin reverses at 0.3 ms. usage: check_spin_down.sh VPSOLVE
set -e
run() {
  rm -rf spin_down
  "$VP" -grid_lo 0,0,0 -grid_hi 0.006,0.006,0.006 -grid_n 36,36,36 -fluid_rho 1000 -fluid_mu 0.1 \
    -particle_position 0.003,0.003,0.003 -particle_radius 5e-4 -particle_density 2500 -particle_angular_velocity 0,100,0 \
    -time_final 0.0024 -track_particles all -output_every 0 -monitor_every 0 -output_dir spin_down "$@" >/dev/null
  /usr/bin/python3 -c "
import csv, glob
r = list(csv.DictReader(open(glob.glob('spin_down/particle_*.csv')[0])))
print(' '.join(q['time'] + ':' + q['wy'] for q in r))"
}
VP=$1
damped=$(run -time_dt 3e-4)
fine=$(run -time_dt 1e-4)
held=$(run -time_dt 3e-4 -dem_implicit_drag 0)
/usr/bin/python3 - "$damped" "$fine" "$held" <<'PY'
import sys
series = [[tuple(map(float, p.split(":"))) for p in s.split()] for s in sys.argv[1:]]
damped, fine, held = series
w = [v for _, v in damped]
monotone = all(0 <= b <= a for a, b in zip(w, w[1:]))
w12 = min(fine, key=lambda p: abs(p[0] - 0.0012))[1]
reverses = min(v for _, v in held) < 0
print(f"dt 0.3 ms, implicit drag: {' '.join('%.3g' % v for v in w)} (monotone decay: {monotone}); "
      f"dt 0.1 ms at 1.2 ms: {w12:.3f} rad/s vs 8.38 ({(w12 / 8.38 - 1) * 100:+.1f} %); held torque at 0.3 ms reverses: {reverses}")
sys.exit(0 if monotone and abs(w12 / 8.38 - 1) < 0.05 and reverses else 1)
PY
