#!/usr/bin/python3
"""cases/spheroid_settling.opts to t = 0.25 s on 2 ranks: a prolate spheroid released at 45 degrees
settles at Re about 10 and turns broadside on (its axis more than 80 degrees from the vertical by
then; a body with its torque wrongly placed or absent keeps 45), at a steady speed (the last
0.05 s within 3 %).
usage: check_spheroid_settling.py VPSOLVE CASE WORKDIR"""
import csv, math, os, subprocess, sys

vp, case, work = sys.argv[1:4]
subprocess.run(["mpirun", "-n", "2", vp, "-options_file", case, "-time_final", "0.25", "-output_dir", work, "-output_overwrite",
                "-output_dt", "0", "-monitor_every", "0"], check=True, stdout=subprocess.DEVNULL)
rows = list(csv.DictReader(open(os.path.join(work, "particle_0.csv"))))
w, x, y, z = (float(rows[-1][k]) for k in ("qw", "qx", "qy", "qz"))
tilt = math.degrees(math.acos(min(1.0, abs(1 - 2 * (x * x + y * y)))))
late = [float(r["vz"]) for r in rows if float(r["time"]) >= 0.2]
steady = (max(late) - min(late)) / abs(sum(late) / len(late))
ok = tilt > 80 and steady < 0.03
print("spheroid settling: axis %.1f deg from the vertical at t = 0.25 s (from 45), speed %.4f m/s varying %.1f %% over the last 0.05 s: %s"
      % (tilt, -late[-1], 100 * steady, "ok" if ok else "FAILED"))
sys.exit(0 if ok else 1)
