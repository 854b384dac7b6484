#!/usr/bin/python3
"""Solver stopping criteria by measurement (docs/fluid.md, tolerances): the same runs with the
pressure and viscous relative tolerances set together to 1e-10 (reference) ... 1e-2, default
solvers (CG + BoomerAMG, CG + Jacobi):
  cavity:  64^3 lid-driven cavity at Re 100, 50 steps: kinetic energy and max |div u| at the end
  sphere:  the seed's falling sphere (d/dx 8) up to t = 0.6 s: fall speed at t = 0.6 s
Prints a table (relative changes against 1e-10) and draws docs/validation/tolerances.png.
usage: tolerances.py [--reuse]"""
import csv, os, subprocess, sys
from common import plt, root, ranks, vpsolve, outdir, help_requested

help_requested(__doc__)
reuse = "--reuse" in sys.argv
TOLS = [1e-10, 1e-8, 1e-6, 1e-4, 1e-3, 1e-2]
CAVITY = ["-grid_n", "64,64,64", "-grid_lo", "0,0,0", "-grid_hi", "0.1,0.1,0.1", "-bc_xlo", "wall", "-bc_xhi", "wall",
          "-bc_ylo", "wall", "-bc_yhi", "velocity", "-bc_yhi_velocity", "1,0,0", "-bc_zlo", "wall", "-bc_zhi", "wall",
          "-fluid_rho", "1", "-fluid_mu", "1e-3", "-time_dt", "5e-4", "-time_max_steps", "50"]
SPHERE = ["-options_file", os.path.join(root, "cases", "falling_sphere.opts"), "-time_final", "0.6"]


def run(name, tol, opts):
    out = "/tmp/vp_val_tol_%s_%g" % (name, tol)
    rows = lambda f: list(csv.DictReader(open(os.path.join(out, f))))
    if not (reuse and os.path.exists(os.path.join(out, "diagnostics.csv"))):
        cmd = ["mpirun", "-n", ranks, vpsolve] + opts + [
            "-output_dir", out, "-output_overwrite", "-monitor_every", "0", "-output_every", "0", "-output_dt", "0",
            "-pressure_ksp_rtol", str(tol), "-pressure_ksp_atol", "0", "-velocity_ksp_rtol", str(tol),
            "-velocity_ksp_atol", "0"]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=root)
    diag = rows("diagnostics.csv")
    part = rows("particle_0.csv") if os.path.exists(os.path.join(out, "particle_0.csv")) else None
    return diag, part


def main():
    res = {}
    for tol in TOLS:
        d, _ = run("cavity", tol, CAVITY)
        ds, ps = run("sphere", tol, SPHERE)
        res[tol] = dict(ke=float(d[-1]["kinetic_energy"]), div=float(d[-1]["max_divergence"]),
                        pits=sum(float(r["pressure_iterations"]) for r in d) / len(d),
                        vits=sum(float(r["velocity_iterations"]) for r in d) / len(d),
                        sec=float(d[-1]["wall_time"]) / len(d), w=-float(ps[-1]["vz"]),
                        sdiv=max(float(r["max_divergence"]) for r in ds),
                        ssec=float(ds[-1]["wall_time"]) / len(ds))
    ref = res[TOLS[0]]
    print("| rtol | cavity KE change | cavity max div (1/s) | p its | v its | s/step | sphere w change | sphere max div (1/s) | s/step |")
    print("|---|---|---|---|---|---|---|---|---|")
    for tol in TOLS:
        r = res[tol]
        print("| %g | %.1e | %.1e | %.1f | %.1f | %.3f | %.1e | %.1e | %.3f |" % (
            tol, abs(r["ke"] / ref["ke"] - 1), r["div"], r["pits"], r["vits"], r["sec"], abs(r["w"] / ref["w"] - 1),
            r["sdiv"], r["ssec"]))
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    x = TOLS[1:]
    ax.loglog(x, [max(abs(res[t]["ke"] / ref["ke"] - 1), 1e-16) for t in x], "o-", label="cavity kinetic energy")
    ax.loglog(x, [max(abs(res[t]["w"] / ref["w"] - 1), 1e-16) for t in x], "s-", label="falling sphere speed")
    ax.axhline(1e-3, color="k", ls=":", label="0.1 % (requirement)")
    ax.set_xlabel("relative tolerance (pressure and velocity)")
    ax.set_ylabel("relative change vs rtol 1e-10")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "tolerances.png"), dpi=120)


main()
