#!/usr/bin/python3
"""The sign of the immersed collapse's base excess pore pressure (docs/dam_break.md): a loose column
contracts as it fails and the liquid carries part of its weight (positive), a dense one must dilate
and sucks liquid in (negative), as in Rondon, Pouliquen & Aussillous 2011. Reads probes.csv (probe 0
at the base under the column minus probe 1 in clear liquid, as scripts/plot_dam_break does) and
collapse.csv, over t0 <= t <= t1.
Pass, loose: the mean pressure over the window above +LIMIT Pa; dense: below -LIMIT Pa and its front
at t1 short of FRONT (x_f - L0)/L0 (it creeps while the suction holds it).
usage: anchor_pore_pressure.py loose|dense T0 T1 LIMIT [FRONT] <run folder>"""
import csv, os, sys

kind, t0, t1, limit = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
run = sys.argv[-1]
rows = list(csv.DictReader(open(os.path.join(run, "probes.csv"))))
p = [(float(r["time"]), float(r["p_0"]) - float(r["p_1"])) for r in rows]
window = [v - p[0][1] for t, v in p if t0 - 1e-9 <= t <= t1 + 1e-9]
if not window:
    sys.exit("FAIL: probes.csv has no row in [%g, %g] s" % (t0, t1))
mean = sum(window) / len(window)
print("%s column: base excess pore pressure over %g-%g s: mean %+.2f Pa (limit %s%g Pa)" %
      (kind, t0, t1, mean, "+" if kind == "loose" else "-", limit))
ok = mean > limit if kind == "loose" else mean < -limit
if kind == "dense":
    c = list(csv.DictReader(open(os.path.join(run, "collapse.csv"))))
    L0 = float(c[0]["front"])
    at = min(c, key=lambda r: abs(float(r["time"]) - t1))
    front = (float(at["front"]) - L0) / L0
    print("dense front (x_f - L0)/L0 at %s s: %.4f (limit %g)" % (at["time"], front, float(sys.argv[5])))
    ok = ok and front < float(sys.argv[5])
sys.exit(0 if ok else "FAIL: the %s column's base pressure or front is off its sign" % kind)
