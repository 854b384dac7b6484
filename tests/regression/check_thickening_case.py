#!/usr/bin/python3
"""The shipped shear-thickening case (cases/shear_thickening.opts, phi 0.54, the critical load model)
to a strain of 0.6 on 2 ranks, three ways: frictionless (-contact_friction 0), as shipped
(sigma / sigma* of a few) and with friction on every contact (-contact_critical_load 0). Over strains
0.3-0.6 the relative viscosity rises from the first to the last, and the frictional suspension is at
least twice the frictionless one (the thickening's two plateaus, docs/rheology.md).
usage: check_thickening_case.py VPSOLVE CASE OUTDIR"""
import os, shutil, subprocess, sys
from importlib.machinery import SourceFileLoader

# The reading of rheology.csv: scripts/plot_rheology's.
plot = SourceFileLoader("plot_rheology", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts",
                                                       "plot_rheology")).load_module()
vpsolve, case, out = sys.argv[1:4]
eta = {}
for name, extra in (("frictionless", ["-contact_friction", "0"]), ("shipped", []), ("frictional", ["-contact_critical_load", "0"])):
    run = os.path.join(out, name)
    shutil.rmtree(run, ignore_errors=True)
    subprocess.run(["mpirun", "-n", "2", vpsolve, "-options_file", case, "-time_final", "0.06", "-output_dt", "0",
                    "-monitor_every", "0", "-output_dir", run] + extra, check=True, stdout=subprocess.DEVNULL)
    eta[name] = plot.means(plot.load(run), 0.3)["eta_r"]
print("eta_r over strains 0.3-0.6: " + ", ".join(f"{k} {v:.1f}" for k, v in eta.items()))
ok = eta["frictionless"] < eta["shipped"] < eta["frictional"] and eta["frictional"] >= 2 * eta["frictionless"]
sys.exit(0 if ok else 1)
