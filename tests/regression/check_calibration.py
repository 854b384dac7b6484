#!/usr/bin/python3
"""Calibration of the lubrication correction at d/dx 8 for one gap (docs/collisions.md): a sphere of
infinite mass closing on a wall in Stokes flow at eps = h/a = 0.01 (0.04 cells). The grid resolves
only part of the squeeze there (measured: 22 % of Brenner's exact resistance); the resolved force
plus the LLCM correction from the default activation (0.2 cells) must be within 5 % of the exact
value (measured -0.4 %). Uses scripts/validation/collisions.py."""
import os, sys
root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
os.environ.setdefault("VP_ROOT", root)
os.environ["NP"] = "1"
sys.argv = sys.argv[:1]
sys.path.insert(0, os.path.join(root, "scripts", "validation"))
import collisions as c  # noqa: E402

eps, r = 0.01, 8
exact = c.brenner(eps)
resolved = c.calib_run("normal", eps, r)
total = resolved + c.calib_run("normal", eps, r, "llcm", c.DEFAULT_CELLS)
print("normal approach at eps %g, d/dx %d: exact %.4f, resolved %.4f (%+.1f %%), + LLCM from %g cells %.4f (%+.1f %%)" %
      (eps, r, exact, resolved, 100 * (resolved / exact - 1), c.DEFAULT_CELLS, total, 100 * (total / exact - 1)))
sys.exit(0 if resolved / exact < 0.5 and abs(total / exact - 1) <= 0.05 else 1)
