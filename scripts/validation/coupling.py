#!/usr/bin/python3
"""Coupling validation (docs/coupling.md), plots into docs/validation/:
  hasimoto: fixed sphere array, Stokes drag K vs Hasimoto at d/dx = 8, 12, 16 (24 with --fine)
  rotation: fixed sphere rotating at Omega in a periodic box, torque vs 8 pi mu a^3 Omega
  falling:  the seed's falling sphere at d/dx = 8, 12 (16 with --fine), u(t) vs Schiller-Naumann
usage: coupling.py [hasimoto|rotation|falling|all] [--fine]"""
import csv, math, os, subprocess, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

root = os.environ.get("VP_ROOT", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
ranks = os.environ.get("NP", "2")
vpsolve = os.path.join(root, "build", "vpsolve")
outdir = os.path.join(root, "docs", "validation")
os.makedirs(outdir, exist_ok=True)
fine = "--fine" in sys.argv


def run(case, out, *opts):
    cmd = ["mpirun", "-n", ranks, vpsolve, "-options_file", os.path.join(root, "cases", case), "-output_dir", out,
           "-monitor_every", "0", "-output_every", "0", "-output_dt", "0"] + [str(o) for o in opts]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=root)
    rows = lambda f: list(csv.DictReader(open(os.path.join(out, f))))
    return rows("diagnostics.csv"), rows("particle_0.csv")


def hasimoto():
    resolutions = [8, 12, 16] + ([24] if fine else [])
    ks = []
    for r in resolutions:
        n = 4 * r  # box 4 d
        diag, part = run("sphere_array.opts", "/tmp/vp_val_array_%d" % r, "-grid_n", "%d,%d,%d" % (n, n, n),
                         "-time_dt", 0.5, "-time_final", 60)
        F, U = float(part[-1]["fx"]), float(diag[-1]["mean_u"])
        ks.append(F / (6 * math.pi * 1 * 0.5 * U))
        print("hasimoto: d/dx %d  F %.5f  U %.6f  K %.4f" % (r, F, U, ks[-1]), flush=True)
    c = math.pi / 6 / 64
    kh = 1 / (1 - 1.7601 * c ** (1 / 3) + c - 1.5593 * c * c)
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(resolutions, ks, "o-", label="vpsolve")
    ax.axhline(kh, color="k", ls="--", label="Hasimoto %.3f" % kh)
    for r, k in zip(resolutions, ks):
        ax.annotate("%+.1f %%" % (100 * (k / kh - 1)), (r, k), textcoords="offset points", xytext=(4, 6), fontsize=8)
    ax.set_xlabel("d / dx")
    ax.set_ylabel("K = F / (6 pi mu a U)")
    ax.set_title("Fixed sphere array, c = %.5f, Stokes" % c)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "sphere_array_drag.png"), dpi=120)
    return ks, kh


def rotation():
    resolutions = [8, 12, 16]
    ratios = []
    omega, a, mu = 1.0, 0.5, 1.0
    for r in resolutions:
        n = 4 * r
        run("sphere_array.opts", "/tmp/vp_val_rot_%d" % r, "-grid_n", "%d,%d,%d" % (n, n, n), "-fluid_body_force", "0,0,0",
            "-particle_angular_velocity", "0,0,%g" % omega, "-time_dt", 0.5, "-time_final", 30)
        part = list(csv.DictReader(open("/tmp/vp_val_rot_%d/particle_0.csv" % r)))
        T = float(part[-1]["thz"])
        ratios.append(-T / (8 * math.pi * mu * a ** 3 * omega))
        print("rotation: d/dx %d  T %.5f  T / (8 pi mu a^3 Omega) %.4f" % (r, T, ratios[-1]), flush=True)
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(resolutions, ratios, "o-", label="vpsolve (periodic box 4 d, c = 0.0082)")
    ax.axhline(1, color="k", ls="--", label="unbounded 8 pi mu a^3 Omega")
    ax.set_xlabel("d / dx")
    ax.set_ylabel("T / (8 pi mu a^3 Omega)")
    ax.set_ylim(0.9, 1.1)
    ax.set_title("Fixed sphere rotating at Omega, Stokes")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "sphere_rotation_torque.png"), dpi=120)
    return ratios


def falling():
    resolutions = [8, 12] + ([16] if fine else [])
    fig, ax = plt.subplots(figsize=(6, 4))
    for r in resolutions:
        n = 8 * r
        dt = 0.004 * 8 / r
        diag, part = run("falling_sphere.opts", "/tmp/vp_val_fall_%d" % r, "-grid_n", "%d,%d,%d" % (n, n, 12 * r),
                         "-time_dt", dt, "-time_final", 2.2)
        t = [float(p["time"]) for p in part]
        w = [-float(p["vz"]) for p in part]
        ax.plot(t, w, label="d/dx = %d (max %.4f m/s)" % (r, max(w)))
        print("falling: d/dx %d  max fall speed %.4f m/s (%+.1f %% vs 0.1462)" % (r, max(w), 100 * (max(w) / 0.1462 - 1)), flush=True)
    ax.axhline(0.1462, color="k", ls="--", label="Schiller-Naumann 0.1462 m/s")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("fall speed (m/s)")
    ax.set_title("Seed falling sphere (rho_p/rho = 1.14, Re 25.7)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "falling_sphere_velocity.png"), dpi=120)


what = [a for a in sys.argv[1:] if not a.startswith("--")] or ["all"]
if what[0] in ("hasimoto", "all"):
    hasimoto()
if what[0] in ("rotation", "all"):
    rotation()
if what[0] in ("falling", "all"):
    falling()
