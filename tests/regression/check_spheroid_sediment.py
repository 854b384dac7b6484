#!/usr/bin/python3
"""cases/spheroid_sediment.opts as shipped (t = 0.8 s) on 2 ranks: 36 prolate spheroids with random
orientations settle into a pile. At the end every body rests on others or the wall (pair and wall
contacts at least the body count), the bodies' kinetic energy has fallen below 1e-4 of its peak
(a pile at rest, not one kept jittering by unstable gaps; the last body slides off the pile near
0.5 s), and the highest centre lies below 6 mm
(they started between 6 and 24 mm; the pile is about 2-3 mm deep).
usage: check_spheroid_sediment.py VPSOLVE CASE WORKDIR"""
import csv, glob, os, subprocess, sys
import h5py

vp, case, work = sys.argv[1:4]
subprocess.run(["mpirun", "-n", "2", vp, "-options_file", case, "-output_dir", work, "-output_overwrite",
                "-output_dt", "0.8", "-monitor_every", "0"], check=True, stdout=subprocess.DEVNULL)
rows = list(csv.DictReader(open(os.path.join(work, "diagnostics.csv"))))
ke = [float(r["particle_kinetic_energy"]) for r in rows]
touching = int(rows[-1]["contacts"]) + int(rows[-1]["wall_contacts"])
with h5py.File(sorted(glob.glob(os.path.join(work, "particles_*.h5")))[-1]) as f:
    z = f["position"][:, 2]
ok = len(z) == 36 and touching >= len(z) and ke[-1] < 1e-4 * max(ke) and max(z) < 0.006
print("spheroid sediment: %d bodies, %d contacts at the end, kinetic energy %.2e of its peak, highest centre %.2f mm: %s"
      % (len(z), touching, ke[-1] / max(ke), 1000 * max(z), "ok" if ok else "FAILED"))
sys.exit(0 if ok else 1)
