#!/usr/bin/python3
"""The shear cell and the suspension stress (docs/rheology.md), on the shipped case
cases/shear_suspension.opts with changes.
  sphere: one torque-free sphere (d = 1 mm) in the middle of a cubic cell of side L sheared at
      gamma = 10 1/s: its spin over gamma/2 and its stresslet (from rheology.csv: the core's
      hydrodynamic stress minus its mean viscous stress) over (10/3) pi mu a^3 gamma, at d/dx 6, 8, 12
      (L = 6 d) and at L = 6, 8, 10 d (d/dx 8), extrapolated to an unbounded liquid in (a/L)^3.
      Table, docs/validation/rheology_sphere.png.
  dilute: phi 0.05 and 0.10 to a strain of 2 against 1 + 2.5 phi + 5.2 phi^2 (Batchelor & Green).
  fraction [--strain S]: phi 0.2, 0.3, 0.4, 0.5 with friction 0.5 and phi 0.4 without, to strain S
      (5): eta_r against Boyer, Guazzelli & Pouliquen 2011 and Krieger-Dougherty (phi_m 0.585), its
      parts, N1 and N2. Table, docs/validation/rheology_phi.png.
  sensitivity [--strain S]: the shipped case (phi 0.4, friction 0.5) to strain S (3) at d/dx 6 and
      8, with half the roughness, and in a periodic cell of 12 d x 12 d instead of 8 d x 8 d. Table.
Means over the second half of each run's strain.
usage: rheology.py [sphere|dilute|fraction|sensitivity] [--strain S] [--reuse]"""
import os, subprocess, sys
import numpy as np
from importlib.machinery import SourceFileLoader
from common import plt, root, ranks, vpsolve, scratch, outdir, chosen_study

sphere_check = SourceFileLoader("sphere_check", os.path.join(root, "tests", "regression", "check_rheology_sphere.py")).load_module()
# The correlations and the reading of rheology.csv: scripts/plot_rheology's.
plot = SourceFileLoader("plot_rheology", os.path.join(root, "scripts", "plot_rheology")).load_module()
boyer, krieger_dougherty = plot.boyer, plot.krieger_dougherty

STUDIES = ("sphere", "dilute", "fraction", "sensitivity")
what = chosen_study(__doc__, STUDIES, valued=("--strain",))
reuse = "--reuse" in sys.argv
strain = float(sys.argv[sys.argv.index("--strain") + 1]) if "--strain" in sys.argv else None
CASE = os.path.join(root, "cases", "shear_suspension.opts")
A, MU, GAMMA = sphere_check.A, sphere_check.MU, sphere_check.GAMMA

def run(name, options):
    out = os.path.join(scratch, "vp_val_rheology_" + name)
    if not (reuse and os.path.exists(os.path.join(out, "rheology.csv"))):
        cmd = ["mpirun", "-n", ranks, vpsolve, "-options_file", CASE] + options + \
              ["-output_dt", "0", "-monitor_every", "250", "-output_dir", out, "-output_overwrite"]
        print(" ".join(cmd), flush=True)
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return out, plot.load(out)


def second_half(d):
    return plot.means(d, None)


def sphere():
    cases = [(6, 6), (8, 6), (12, 6), (8, 8), (8, 10)]  # (d/dx, L/d)
    results = {}
    print("d/dx  L/d  spin/(gamma/2)  stresslet/((10/3) pi mu a^3 gamma)  bulk/wall - 1")
    for res, box in cases:
        spin, ratio, balance = sphere_check.measure(vpsolve, os.path.join(scratch, f"vp_val_rheology_sphere_{res}_{box}"),
                                                    ranks, box, res, reuse)
        results[(res, box)] = ratio
        print(f"{res:4d}  {box:3d}  {spin:14.4f}  {ratio:34.4f}  {balance:13.1e}", flush=True)
    # Extrapolation in (a/L)^3 at d/dx 8.
    x = np.array([(A / (b * 2 * A)) ** 3 for b in (6, 8, 10)])
    y = np.array([results[(8, b)] for b in (6, 8, 10)])
    slope, unbounded = np.polyfit(x, y, 1)
    print(f"d/dx 8, unbounded (fit in (a/L)^3): {unbounded:.4f}")
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot([6, 8, 12], [results[(r, 6)] for r in (6, 8, 12)], "o-")
    ax[0].axhline(1, color="k", lw=0.8)
    ax[0].set_xlabel("d/dx (L = 6 d)")
    ax[0].set_ylabel("stresslet / ((10/3) pi mu a^3 gamma)")
    ax[1].plot(x, y, "o", label="d/dx 8, L = 6, 8, 10 d")
    xs = np.linspace(0, x.max() * 1.1, 20)
    ax[1].plot(xs, unbounded + slope * xs, "--", label=f"fit: {unbounded:.3f} unbounded")
    ax[1].axhline(1, color="k", lw=0.8)
    ax[1].set_xlabel("(a/L)^3")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "rheology_sphere.png"), dpi=110)


def packed(phi, friction, strain_end, name, extra=(), width=0.008):
    return run(name, ["-particles_packed", f"0,0,0,{width},{width},0.016,{phi},5e-4,1", "-contact_friction", str(friction),
                      "-time_final", str(strain_end / GAMMA)] + list(extra))


def dilute():
    print("phi   eta_r  bulk   1 + 2.5 phi + 5.2 phi^2")
    for phi in (0.05, 0.1):
        _, d = packed(phi, 0.5, 2.0, f"dilute_{phi}")
        m = second_half(d)
        print(f"{phi:.2f}  {m['eta_r']:.3f}  {m['eta_r_bulk']:.3f}  {1 + 2.5 * phi + 5.2 * phi**2:.3f}")


def fraction():
    strain_end = strain or 5.0
    runs = [(phi, 0.5) for phi in (0.2, 0.3, 0.4, 0.5)] + [(0.4, 0.0)]
    print("phi   friction  eta_r  bulk   hydro  lub   contact  n1     n2     core_rate  /Boyer  /KD")
    points = []
    for phi, mu_c in runs:
        _, d = packed(phi, mu_c, strain_end, f"phi_{phi}_{mu_c}")
        m = second_half(d)
        points.append((phi, mu_c, m))
        print(f"{m['phi']:.3f}  {mu_c:8.1f}  {m['eta_r']:5.2f}  {m['eta_r_bulk']:5.2f}  {m['eta_hydro']:5.2f}  {m['eta_lub']:4.2f}  "
              f"{m['eta_contact']:7.2f}  {m['n1']:5.2f}  {m['n2']:5.2f}  {m['core_rate']:9.3f}  {m['eta_r'] / boyer(m['phi']):6.2f}  "
              f"{m['eta_r'] / krieger_dougherty(m['phi']):4.2f}")
    fig, ax = plt.subplots(figsize=(6, 4.5))
    p = np.linspace(0.01, 0.55, 200)
    ax.semilogy(p, boyer(p), "k-", label="Boyer et al. 2011")
    ax.semilogy(p, krieger_dougherty(p), "k--", label="Krieger-Dougherty, phi_m 0.585")
    ax.semilogy(p, 1 + 2.5 * p + 5.2 * p**2, "k:", label="1 + 2.5 phi + 5.2 phi^2")
    for phi, mu_c, m in points:
        c = "C0" if mu_c > 0 else "C3"
        ax.plot(m["phi"], m["eta_r"], "o", color=c)
        ax.plot(m["phi"], m["eta_r_bulk"], "x", color=c)
    ax.plot([], [], "o", color="C0", label="friction 0.5 (o wall, x bulk)")
    ax.plot([], [], "o", color="C3", label="frictionless")
    ax.set_xlabel("solid fraction phi")
    ax.set_ylabel("relative viscosity")
    ax.set_title(f"d/dx 6, gap 16 d, strain {strain_end:g}")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "rheology_phi.png"), dpi=110)


def sensitivity():
    strain_end = strain or 3.0
    variants = [("d/dx 6 (the case)", "base", [], 0.008), ("d/dx 8", "res8", ["-grid_n", "64,64,128"], 0.008),
                ("roughness 0.5 % of d", "rough005", ["-contact_roughness", "5e-3"], 0.008),
                ("cell 12 d x 12 d", "wide", ["-grid_hi", "0.012,0.012,0.016", "-grid_n", "72,72,96"], 0.012)]
    print("variant                eta_r  bulk   hydro  lub   contact  n1     n2     core_rate  /Boyer")
    for label, name, extra, width in variants:
        _, d = packed(0.4, 0.5, strain_end, "sens_" + name, extra, width)
        m = second_half(d)
        print(f"{label:22s} {m['eta_r']:5.2f}  {m['eta_r_bulk']:5.2f}  {m['eta_hydro']:5.2f}  {m['eta_lub']:4.2f}  {m['eta_contact']:7.2f}  "
              f"{m['n1']:5.2f}  {m['n2']:5.2f}  {m['core_rate']:9.3f}  {m['eta_r'] / boyer(m['phi']):6.2f}", flush=True)


for study in STUDIES:
    if what in (study, "all"):
        globals()[study]()
