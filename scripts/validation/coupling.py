#!/usr/bin/python3
"""Coupling validation (docs/coupling.md), plots into docs/validation/:
  hasimoto: fixed sphere array, Stokes drag K vs Hasimoto at d/dx = 8, 12, 16 (24 with --fine)
  rotation: fixed sphere rotating at Omega in a periodic box, torque vs 8 pi mu a^3 Omega
  falling:  the seed's falling sphere at d/dx = 8, 12 (16 with --fine), u(t) vs Schiller-Naumann
  width:    the same at d/dx = 8 in boxes 8, 12 and 16 d wide; in a 12 d wide box 16 d tall at
            d/dx = 8 and 10 d tall at d/dx = 8 (and 16 with --fine): wall effects, terminal speed
usage: coupling.py [hasimoto|rotation|falling|width|all] [--fine] [--reuse]
  --reuse: plot the runs already in /tmp/vp_val_* as they are (also ones stopped early) instead of
           running them again"""
import csv, math, os, subprocess, sys
from common import plt, root, ranks, vpsolve, outdir, chosen_study
fine = "--fine" in sys.argv
reuse = "--reuse" in sys.argv
SN, CLIFT = 0.1462, 0.1418  # terminal speeds from Schiller-Naumann and the Clift-Grace-Weber drag curve


def run(case, out, *opts):
    rows = lambda f: list(csv.DictReader(open(os.path.join(out, f))))
    if reuse and os.path.exists(os.path.join(out, "particle_0.csv")):
        return rows("diagnostics.csv"), rows("particle_0.csv")
    cmd = ["mpirun", "-n", ranks, vpsolve, "-options_file", os.path.join(root, "cases", case), "-output_dir", out, "-output_overwrite",
           "-monitor_every", "0", "-output_every", "0", "-output_dt", "0"] + [str(o) for o in opts]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=root)
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
    if len(ks) == 4:
        # Observed order from the three finest grids (unequal ratios): solve
        # (K2 - K1) / (K3 - K2) = (h1^p - h2^p) / (h2^p - h3^p) for p by bisection, if monotone.
        (r1, r2, r3), (k1, k2, k3) = resolutions[1:], ks[1:]
        q = (k2 - k1) / (k3 - k2) if k3 != k2 else float("inf")
        f = lambda p: (r1 ** -p - r2 ** -p) / (r2 ** -p - r3 ** -p) - q
        if q > 0 and f(0.1) * f(6) < 0:
            lo, hi = 0.1, 6.0
            for _ in range(100):
                mid = (lo + hi) / 2
                lo, hi = (mid, hi) if f(lo) * f(mid) > 0 else (lo, mid)
            p = (lo + hi) / 2
            kinf = k3 - (k2 - k3) * r3 ** -p / (r2 ** -p - r3 ** -p)  # Richardson: K_h = K + C h^p
            print("hasimoto: observed order %.2f from d/dx %d, %d, %d; extrapolated K %.4f (%+.2f %% vs Hasimoto)" %
                  (p, r1, r2, r3, kinf, 100 * (kinf / kh - 1)), flush=True)
        else:
            print("hasimoto: the differences K(%d) - K(%d) = %+.4f and K(%d) - K(%d) = %+.4f change sign or vanish: "
                  "no observed order (converged to the level of the remaining oscillation)" % (r2, r1, k2 - k1, r3, r2, k3 - k2),
                  flush=True)
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
        early = " to t = %.1f s" % t[-1] if t[-1] < 2.2 - 1e-9 else ""
        ax.plot(t, w, label="d/dx = %d (max %.4f m/s%s)" % (r, max(w), early))
        print("falling: d/dx %d  max fall speed %.4f m/s (%+.1f %% vs 0.1462)" % (r, max(w), 100 * (max(w) / 0.1462 - 1)), flush=True)
    ax.axhline(SN, color="k", ls="--", label="Schiller-Naumann %.4f m/s" % SN)
    ax.axhline(CLIFT, color="k", ls=":", label="Clift-Grace-Weber drag curve %.4f m/s" % CLIFT)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("fall speed (m/s)")
    ax.set_title("Seed falling sphere (rho_p/rho = 1.14, Re 25.7)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "falling_sphere_velocity.png"), dpi=120)


def fall_speed(part, t0, t1):
    """Mean fall speed over [t0, t1] (the plateau, before the bottom wall is felt)."""
    w = [-float(p["vz"]) for p in part if t0 <= float(p["time"]) <= t1]
    return sum(w) / len(w)


def terminal_fit(part, t0, t1):
    """Terminal speed from a fit u(t) = u_inf - A exp(-t / tau) over [t0, t1] (least squares in
    u_inf and A for each tau of a scan): the sphere meets the bottom before the plateau is flat."""
    t = [float(p["time"]) for p in part if t0 <= float(p["time"]) <= t1]
    w = [-float(p["vz"]) for p in part if t0 <= float(p["time"]) <= t1]
    best = None
    for k in range(1, 400):
        tau = 0.005 * k
        e = [math.exp(-x / tau) for x in t]
        n, se, see = len(t), sum(e), sum(x * x for x in e)
        sw, sew = sum(w), sum(x * y for x, y in zip(e, w))
        det = n * see - se * se
        u, a = (sw * see - se * sew) / det, (se * sw - n * sew) / det  # w = u - a e
        res = sum((u - a * x - y) ** 2 for x, y in zip(e, w))
        if best is None or res < best[0]:
            best = (res, u, tau)
    return best[1], best[2]


def width():
    d = 0.0254
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4), sharey=True)

    def report(ax, what, part, t0, t1):
        u = fall_speed(part, t0, t1)
        uf, tau = terminal_fit(part, 0.5, t1)
        print("width: %s: mean fall speed over t = %.1f-%.1f s %.4f m/s (%+.1f %% vs SN, %+.1f %% vs Clift); fitted terminal "
              "%.4f m/s (tau %.2f s; %+.1f %% vs SN, %+.1f %% vs Clift)" % (what, t0, t1, u, 100 * (u / SN - 1),
              100 * (u / CLIFT - 1), uf, tau, 100 * (uf / SN - 1), 100 * (uf / CLIFT - 1)), flush=True)
        ax.plot([float(p["time"]) for p in part], [-float(p["vz"]) for p in part],
                label="%s: %.4f, fit %.4f m/s" % (what, u, uf))

    # d/dx 8, 12 d tall, released 10 d above the bottom: boxes 8, 12 and 16 d wide.
    for wd in (8, 12, 16):
        n, L = 8 * wd, wd * d
        diag, part = run("falling_sphere.opts", "/tmp/vp_val_width_%d" % wd, "-grid_n", "%d,%d,96" % (n, n),
                         "-grid_hi", "%g,%g,0.3048" % (L, L), "-particle_position", "%g,%g,0.254" % (L / 2, L / 2),
                         "-time_dt", 0.004, "-time_final", 1.9)
        report(a1, "%d d wide" % wd, part, 1.2, 1.7)
    a1.set_title("d/dx = 8, box 12 d tall, width varied")
    # 12 d wide: 16 d tall at d/dx 8 (released 15 d up: the longest plateau); 10 d tall (released
    # 8.5 d up) at d/dx 8 and 16.
    diag, part = run("falling_sphere.opts", "/tmp/vp_val_tall_8", "-grid_n", "96,96,128", "-grid_hi", "0.3048,0.3048,0.4064",
                     "-particle_position", "0.1524,0.1524,0.381", "-time_dt", 0.004, "-time_final", 2.5)
    report(a2, "16 d tall, d/dx 8", part, 1.5, 2.2)
    for r in [8] + ([16] if fine else []):
        diag, part = run("falling_sphere.opts", "/tmp/vp_val_wide_%d" % r, "-grid_n", "%d,%d,%d" % (12 * r, 12 * r, 10 * r),
                         "-grid_hi", "0.3048,0.3048,0.254", "-particle_position", "0.1524,0.1524,0.2159",
                         "-time_dt", 0.004, "-time_final", 1.5, *(["-checkpoint_every", 50] if r > 8 else []))
        report(a2, "10 d tall, d/dx %d" % r, part, 1.2, 1.5)
    a2.set_title("12 d wide box: height and grid varied")
    for ax in (a1, a2):
        ax.axhline(SN, color="k", ls="--", lw=1, label="Schiller-Naumann %.4f" % SN)
        ax.axhline(CLIFT, color="k", ls=":", lw=1, label="Clift-Grace-Weber %.4f" % CLIFT)
        ax.axhspan(0.95 * SN, 1.05 * SN, color="0.9", zorder=0)
        ax.set_xlabel("t (s)")
        ax.legend(fontsize=7, loc="lower right", title="plateau mean, fitted terminal", title_fontsize=7)
    a1.set_ylabel("fall speed (m/s)")
    a1.set_ylim(0.08, 0.16)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "falling_sphere_box.png"), dpi=120)


STUDIES = ("hasimoto", "rotation", "falling", "width")
what = chosen_study(__doc__, STUDIES)
for name in STUDIES:
    if what in (name, "all"):
        globals()[name]()
