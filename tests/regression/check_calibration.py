#!/usr/bin/python3
"""Calibration of the lubrication correction at d/dx 8 (docs/collisions.md): a sphere of infinite mass
closing on a wall in Stokes flow, with the cases' fluid set-up (weighted projection), at eps = h/a
= 0.01 and 0.02 (0.04 and 0.08 cells). The grid resolves only part of the squeeze there (measured:
32 % and 57 % of Brenner's exact resistance); the resolved force plus the LLCM correction from the
default activation (0.18 cells) must be within 10 % of the exact value, the calibration's accuracy
over eps 0.01-0.05 and d/dx 8-16 (measured here: +7.6 % and +9.8 %; without the correction -68 %
and -43 %). Uses scripts/validation/collisions.py."""
import sys
from study import collisions, vpsolve_argument

c = collisions(np=1, vpsolve=vpsolve_argument())

r, ok = 8, True
for eps in (0.01, 0.02):
    exact = c.brenner(eps)
    resolved = c.calib_run("normal", eps, r)
    total = resolved + c.calib_run("normal", eps, r, "llcm", c.DEFAULT_CELLS)
    print("normal approach at eps %g, d/dx %d: exact %.4f, resolved %.4f (%+.1f %%), + LLCM from %g cells %.4f (%+.1f %%)" %
          (eps, r, exact, resolved, 100 * (resolved / exact - 1), c.DEFAULT_CELLS, total, 100 * (total / exact - 1)))
    ok = ok and resolved / exact < 0.75 and abs(total / exact - 1) <= 0.10
sys.exit(0 if ok else 1)
