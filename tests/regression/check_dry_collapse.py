#!/usr/bin/python3
"""The dry collapse case (cases/granular_collapse_dry.opts, 2000 spheres) on 2 ranks to t = 0.072 s
(20,000 steps) against LAMMPS gran/hooke/history on the same column and contact law
(benchmarks/RESULTS.md, "DEM" runout table; front.py's measures): centre of mass x 9.392 / 9.399 mm and
z 4.449 / 4.436 mm, 99th-percentile front (+ d/2) 25.92 / 25.91 mm on 1 / 2 ranks. The spread of such
a collapse between runs that differ only in the order of floating-point sums is about 0.1 mm in the
front and 0.02 (x) and 0.04 mm (z) in the centre of mass (vpsolve measured 9.38-9.41, 4.41-4.45 and
25.91-26.01 mm); a change of 5 % in how far the column has moved (4.1 mm in x and 4.2 mm in z for the
centre of mass, 15.4 mm for the front) is 0.2 and 0.8 mm. Pass: the centre of mass within 0.06 mm
(x) and 0.1 mm (z), the front within 0.3 mm of LAMMPS's mean. Also the output contract: the initial and final snapshots listed in
particles.xmf, a diagnostics row every 100 steps and tracked particles' rows.
usage: check_dry_collapse.py <vpsolve> <scratch dir>"""
import csv, math, os, shutil, subprocess, sys
import h5py
import numpy as np

vpsolve, out = sys.argv[1], os.path.join(sys.argv[2], "dry_collapse")
root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STEPS, D = 20000, 1e-3
LAMMPS = {"x_com": (9.392, 9.399), "z_com": (4.449, 4.436), "xf_99": (25.92, 25.91)}  # mm, 1 and 2 ranks
TOL = {"x_com": 0.06, "z_com": 0.1, "xf_99": 0.3}
shutil.rmtree(out, ignore_errors=True)
cmd = ["mpirun", "-n", "2", "--oversubscribe", vpsolve, "-options_file", os.path.join(root, "cases", "granular_collapse_dry.opts"),
       "-particles_file", os.path.join(root, "cases", "data", "column_2000.csv"), "-time_max_steps", str(STEPS),
       "-output_dt", "0", "-output_every", str(STEPS), "-monitor_every", "0", "-output_dir", out]
r = subprocess.run(cmd, capture_output=True, text=True)
if r.returncode != 0:
    sys.exit("FAIL: vpsolve exited with %d\n%s%s" % (r.returncode, r.stdout[-2000:], r.stderr[-2000:]))
fail = []
for f in ("particles_000000.h5", "particles_%06d.h5" % STEPS):
    if f not in open(os.path.join(out, "particles.xmf")).read():
        fail.append("particles.xmf does not list " + f)
diag = list(csv.DictReader(open(os.path.join(out, "diagnostics.csv"))))
if [int(r["step"]) for r in diag] != list(range(100, STEPS + 1, 100)):
    fail.append("diagnostics.csv rows are not every 100 steps to %d" % STEPS)
tracked = list(csv.DictReader(open(os.path.join(out, "particle_1000.csv"))))
if len(tracked) != STEPS // 100 + 1:
    fail.append("particle_1000.csv has %d rows, %d expected" % (len(tracked), STEPS // 100 + 1))
with h5py.File(os.path.join(out, "particles_%06d.h5" % STEPS), "r") as h:
    x = np.array(h["position"]).reshape(-1, 3)
if len(x) != 2000:
    fail.append("%d particles in the final snapshot" % len(x))
xs = np.sort(x[:, 0])
got = {"x_com": x[:, 0].mean() * 1e3, "z_com": x[:, 2].mean() * 1e3,
       "xf_99": (xs[max(0, math.ceil(0.99 * len(xs)) - 1)] + D / 2) * 1e3}  # front.py's nearest-rank percentile
for k, v in got.items():
    ref = sum(LAMMPS[k]) / 2
    print("%s after %d steps: %.3f mm, LAMMPS %.3f / %.3f mm (difference %+.3f mm, tolerance %.2f)" % (k, STEPS, v, *LAMMPS[k], v - ref, TOL[k]))
    if abs(v - ref) > TOL[k]:
        fail.append("%s %.3f mm is %.3f mm from LAMMPS's %.3f" % (k, v, v - ref, ref))
if fail:
    sys.exit("FAIL: " + "; ".join(fail))
print("ok: the dry collapse matches LAMMPS at t = 0.072 s")
