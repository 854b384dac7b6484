#!/usr/bin/python3
"""The restitution case's rebound (cases/restitution.opts: a steel sphere, d = 3 mm, driven onto the
floor through a liquid) against independent numbers, read from a finished run's particle_0.csv the
way the collision study reads it (scripts/validation/collisions.py, impact()).
  dry: the run with the fluid off must rebound with the contact's restitution, -contact_restitution
       0.97, within 1 %, both speeds read at a gap of 0.1 d (gravity between the reading and the wall
       moves it by 0.05 %);
  wet: as the experiments read it, the approach speed at a gap of 1 d and the rebound speed at 0.1 d
       on the way out: e / e_dry within 0.1 of exp(-35/St) at St = rho_p u_in d / (9 mu), the band of
       the experiments' curve (Legendre et al. 2006 over Joseph et al. 2001 and Gondret et al. 2002).
usage: anchor_restitution.py dry|wet <run folder>"""
import csv, math, os, sys
from study import collisions

kind, run = sys.argv[1], sys.argv[2]
c = collisions(scratch=os.path.join(run, "anchor"))
rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(os.path.join(run, "particle_0.csv")))]
E_DRY, A, MU = 0.97, 0.0015, 0.01
u_in, u_out, touched = c.impact(rows, A, gap_in=0.1) if kind == "dry" else c.impact(rows, A)
if u_in is None or not touched:
    sys.exit("FAIL: no impact in %s" % run)
e = u_out / u_in
if kind == "dry":
    print("dry rebound: u_in %.4f m/s, u_out %.4f m/s, e %.4f (contact restitution %.2f)" % (u_in, u_out, e, E_DRY))
    sys.exit(0 if abs(e / E_DRY - 1) <= 0.01 else "FAIL: the dry rebound %.4f is not the contact's %.2f within 1 %%" % (e, E_DRY))
st = c.STEEL * u_in * 2 * A / (9 * MU)
curve = math.exp(-35 / st)
print("wet rebound: approach St %.1f, e/e_dry %.3f, exp(-35/St) %.3f, difference %+.3f (band 0.1)" % (st, e / E_DRY, curve, e / E_DRY - curve))
sys.exit(0 if abs(e / E_DRY - curve) <= 0.1 else "FAIL: the wet rebound is outside the experiments' band")
