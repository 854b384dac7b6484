#!/usr/bin/python3
"""The shipped shear case (cases/shear_suspension.opts, phi 0.4) to a strain of 0.6 on 2 ranks: over
strains 0.3-0.6 the relative viscosity from the wall traction lies within 0.6-1.6x of Boyer,
Guazzelli & Pouliquen 2011 and the core's bulk stress within 15 % of it (the momentum balance);
the contacts carry a positive shear stress. usage: check_shear_case.py VPSOLVE CASE OUTDIR"""
import os, shutil, subprocess, sys
from importlib.machinery import SourceFileLoader

# The correlation and the reading of rheology.csv: scripts/plot_rheology's.
plot = SourceFileLoader("plot_rheology", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts",
                                                       "plot_rheology")).load_module()
vpsolve, case, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
subprocess.run(["mpirun", "-n", "2", vpsolve, "-options_file", case, "-time_final", "0.06", "-output_dt", "0",
                "-monitor_every", "0", "-output_dir", out], check=True, stdout=subprocess.DEVNULL)
m = plot.means(plot.load(out), 0.3)
phi, eta, bulk, contact = m["phi"], m["eta_r"], m["eta_r_bulk"], m["eta_contact"]
boyer = plot.boyer(phi)
print(f"phi {phi:.3f}: eta_r {eta:.2f} ({eta / boyer:.2f} of Boyer et al. {boyer:.2f}), bulk {bulk:.2f} "
      f"({bulk / eta - 1:+.3f}), contacts {contact:.2f}")
sys.exit(0 if 0.6 <= eta / boyer <= 1.6 and abs(bulk / eta - 1) <= 0.15 and contact > 0 else 1)
