#!/usr/bin/python3
"""The rebound converges in the fluid step (docs/collisions.md, "What sets the rebound"): the steel
sphere of the e(St) study at nominal St 40 (St 30 at the approach), d/dx 8, the cases' set-up
(contact over 2 fluid steps, weighted projection, `limit`, the departure, the history force out of
contact), at CFL 0.5, 0.25 and 0.125. The penalization's stiffness follows the flow, not the step;
when it followed the step (floor 20/dt, no departure) the rebound fell without limit as the step
shrank (e/e_dry 0.445, 0.440, 0.310, 0 at CFL 0.5 to 1/16). Measured: 0.406, 0.379, 0.366 (first
order: the differences 0.027 and 0.013). Pass: every run rebounds (e/e_dry > 0.3), the differences
shrink at an order of at least 0.5, and the finer one is below 0.02. Uses
scripts/validation/collisions.py."""
import math, sys
from study import collisions, vpsolve_argument
c = collisions(np=2, vpsolve=vpsolve_argument())
e = {}
for cfl in (0.5, 0.25, 0.125):
    out = c.restitution_run(40, c.HYDRO, r=8, cfl=cfl, label="test_rebound_step_cfl%g" % cfl)
    e[cfl] = out[1] / c.E_DRY if out else 0.0
    print("St %.1f at the approach, CFL %g: e/e_dry %.3f" % (out[0] if out else float("nan"), cfl, e[cfl]))
coarse, fine = abs(e[0.5] - e[0.25]), abs(e[0.25] - e[0.125])
order = math.log2(coarse / fine) if fine > 0 and coarse > 0 else float("inf")
print("differences %.3f and %.3f: order %.2f" % (coarse, fine, order))
ok = min(e.values()) > 0.3 and order >= 0.5 and fine <= 0.02
sys.exit(0 if ok else 1)
