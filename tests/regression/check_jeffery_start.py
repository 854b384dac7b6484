#!/usr/bin/python3
"""A prolate spheroid (aspect 2) in shear, cases/jeffery_orbit.opts to gamma t = 2, on 1 and 3 ranks:
its axis turns as Jeffery's orbit says (tan(angle) = tan(2 pi t / T) / r, T gamma = 2 pi (r + 1/r):
27.24 degrees at gamma t = 2, from a spin of gamma / (r^2 + 1) = 0.2 along the flow, not the
sphere's gamma / 2), within 5 %; and the same on both rank counts to solver tolerance.
usage: check_jeffery_start.py VPSOLVE CASE WORKDIR"""
import csv, math, os, subprocess, sys

vp, case, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)


def run(np):
    out = os.path.join(work, "np%d" % np)
    subprocess.run(["mpirun", "--oversubscribe", "-n", str(np), vp, "-options_file", case, "-time_final", "2", "-output_dir", out,
                    "-output_overwrite", "-output_dt", "0", "-monitor_every", "0"], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(out, "particle_0.csv"))))
    w, x, y, z = (float(rows[-1][k]) for k in ("qw", "qx", "qy", "qz"))
    angle = math.degrees(math.atan2(-(1 - 2 * (x * x + y * y)), 2 * (x * z + w * y)))  # from the flow, in the shear's sense
    spin = abs(float(rows[len(rows) // 10]["wy"]))  # early: the axis still near the flow direction
    return angle, spin


r, T = 2.0, 2 * math.pi * 2.5
exact = math.degrees(math.atan(math.tan(2 * math.pi * 2 / T) / r))
a1, s1 = run(1)
a3, s3 = run(3)
ok = abs(a1 / exact - 1) < 0.05 and abs(s1 / (1 / (r * r + 1)) - 1) < 0.1 and abs(a3 - a1) < 1e-4 * abs(a1)
print("jeffery start: angle %.3f deg at gamma t = 2 (Jeffery %.3f, %+.1f %%), early spin %.4f (Jeffery about 0.2, a sphere 0.5); "
      "3 ranks %.6f deg: %s" % (a1, exact, 100 * (a1 / exact - 1), s1, a3, "ok" if ok else "FAILED"))
sys.exit(0 if ok else 1)
