#!/usr/bin/python3
"""What sets the immersed collapse (docs/dam_break.md): the shipped columns measured on their own, and
the main case's start against the contact stiffness.
  permeability [--res 4,6,8,12]: Darcy permeability of cases/data/column_loose.csv and column_dense.csv
      at each d/dx: the spheres fixed in a 21 d x 4 d x 18 d box (walls; periodic across the slab), the
      liquid driven across the slab by a uniform body force f (a uniform pressure gradient rho f on the
      mixture), Stokes regime; k = mu U / (rho f) from the superficial velocity U over the column's
      interior (one diameter from the walls, the face and the top), with the weighted projection
      (steady within 20 steps); against Carman-Kozeny and van der Hoef et al. 2005; and how far the
      plain projection (the collapse cases') is from it after 10, 50 and 100 steps of 1e-3 s. Table,
      docs/validation/permeability.png.
  phic: the critical solid fraction phi_c of the collapse's contact law, from dry flows down a rough
      incline at 21-24 degrees (DEM only; 10 d x 6 d periodic, about 16 d deep, a base of fixed
      spheres; 3 s each): the bulk's solid fraction phi against its inertial number
      I = gamma_dot d / sqrt(P / rho_p) from 1.5 s on, extrapolated to I = 0 (GDR MiDi 2004). Table,
      docs/validation/phi_c.png. With --spread S the flowing spheres' radii are uniform in
      a (1 - S) .. a (1 + S) (the columns' -particles_radius_spread): docs/validation/phi_c_spread.png.
  coupling: the shipped loose column to t = 0.3 s at fluid steps 1e-3, 5e-4 and 2.5e-4 s and implicit
      drags k 1, 10 and 30 (-dem_implicit_drag; the DEM sub-step kept at 6.7e-6 s; ten runs), the
      smallest step with k 3 and 30 as the reference: the front and the base excess pore pressure. Table,
      docs/validation/dam_break_coupling.png.
  stiffness: the loose column prepared and collapsed (cases/dam_break.opts to t = 0.3 s, d/dx 6) with
      contact times t_c 5e-4, 2.5e-4 and 1.25e-4 s (normal stiffness 1x, 4x, 16x; DEM sub-step
      min(6.7e-6 s, t_c / 37.5)): the base excess pore pressure's start-up dip and the front. Table,
      docs/validation/dam_break_stiffness.png.
usage: collapse.py [permeability|phic|coupling|stiffness] [--res 4,6,8,12] [--spread S] [--reuse]"""
import glob, os, subprocess, sys
import numpy as np
import h5py
from importlib.machinery import SourceFileLoader
from common import plt, root, ranks, vpsolve, scratch, outdir, chosen_study

column_phi = SourceFileLoader("column_phi", os.path.join(root, "scripts", "column_phi")).load_module()

STUDIES = ("permeability", "phic", "coupling", "stiffness")
what = chosen_study(__doc__, STUDIES, valued=("--res", "--spread"))
reuse = "--reuse" in sys.argv
res_list = [int(r) for r in sys.argv[sys.argv.index("--res") + 1].split(",")] if "--res" in sys.argv else [4, 6, 8, 12]
spread = float(sys.argv[sys.argv.index("--spread") + 1]) if "--spread" in sys.argv else 0.0
if not 0 <= spread <= 0.5:
    sys.exit("--spread must be in [0, 0.5] (the radii's relative half-width), not %g" % spread)

D = 1e-3            # sphere diameter of the columns (m)
MU, RHO = 0.1, 1000.0
F = 5.0             # body force per unit mass (m/s^2): Darcy speed about 1e-4 m/s, Re_p 1e-3
BOX = (0.021, 0.004, 0.018)
GATE = 0.019        # where the columns were settled against the gate
COLUMNS = ("loose", "dense")


def carman_kozeny(phi):
    return D**2 * (1 - phi) ** 3 / (180 * phi**2)


def van_der_hoef(phi):
    """k from the Stokes drag of random arrays: F_d / (3 pi mu d U) = 10 phi / (1 - phi)^2 + (1 - phi)^2
    (1 + 1.5 sqrt(phi)), F_d the drag without the mean pressure gradient's share (total = F_d / (1 - phi))."""
    f = 10 * phi / (1 - phi) ** 2 + (1 - phi) ** 2 * (1 + 1.5 * np.sqrt(phi))
    return D**2 * (1 - phi) / (18 * phi * f)


def load_column(kind):
    data = np.genfromtxt(os.path.join(root, "cases", "data", "column_%s.csv" % kind), delimiter=",", names=True)
    return np.stack([data["x"], data["y"], data["z"]], axis=1), data["radius"]


def column_interior(x, r):
    """scripts/column_phi's window over the column (gate at 19 d): x and z bounds, and phi."""
    lo, hi, phi, _ = column_phi.interior(x, r, 0.0, GATE, BOX[1])
    return (lo[0], hi[0]), (lo[1], hi[1]), phi


def run(kind, res, projection):
    """k = mu U / (rho f) at each 0.01 s: the weighted projection over 20 steps of 1e-3 s (steady within
    them), the plain one over 100 (it approaches the steady flow over many steps)."""
    out = os.path.join(scratch, "vp_val_perm_%s_%d_%s" % (kind, res, projection))
    steps = 20 if projection == "weighted" else 100
    if not (reuse and glob.glob(os.path.join(out, "fields_*.h5"))):
        n = ",".join(str(round(L / D * res)) for L in BOX)
        solver = ["-pressure_pc_type", "fft"] if projection == "plain" else ["-penalization_projection", "weighted"]
        cmd = ["mpirun", "-n", ranks, vpsolve, "-grid_lo", "0,0,0", "-grid_hi", ",".join(map(str, BOX)), "-grid_n", n,
               "-bc_ylo", "periodic", "-bc_yhi", "periodic", "-fluid_rho", str(RHO), "-fluid_mu", str(MU),
               "-fluid_body_force", "0,%g,0" % F, "-particles_file", os.path.join(root, "cases", "data", "column_%s.csv" % kind),
               "-particles_fixed", "-lub_model", "none", "-time_dt", "1e-3", "-time_final", "1", "-time_max_steps", str(steps),
               # CFL up to 1.1 in the clear liquid over the dense column at d/dx 12: its cell Reynolds
               # number is below 0.05, the implicit viscous term rules the step
               "-health_cfl_max", "2",
               "-output_dt", "0.01", "-monitor_every", "0", "-output_dir", out, "-output_overwrite"] + solver
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=root)
    x, r = load_column(kind)
    wx, wz, phi = column_interior(x, r)
    ks = []
    for path in sorted(glob.glob(os.path.join(out, "fields_*.h5")))[1:]:
        with h5py.File(path, "r") as f:
            v = f["velocity"][...]          # (nz, ny, nx, 3), cell centres
            chi = f["chi"][...]
            h = f.attrs["spacing"]
        nz, ny, nx = chi.shape
        xc = (np.arange(nx) + 0.5) * h[0]
        zc = (np.arange(nz) + 0.5) * h[2]
        sub = np.ix_((zc > wz[0]) & (zc < wz[1]), np.ones(ny, bool), (xc > wx[0]) & (xc < wx[1]))
        ks.append(MU * v[..., 1][sub].mean() / (RHO * F))
        phi_mask = chi[sub].mean()
    return dict(k=np.array(ks), phi=phi, phi_mask=phi_mask)


def permeability():
    rows = {(kind, res): (run(kind, res, "weighted"), run(kind, res, "plain")) for kind in COLUMNS for res in res_list}
    print("| column | d/dx | phi (spheres) | phi (mask) | k (1e-9 m^2) | change over its last 0.01 s | "
          "k / Carman-Kozeny | k / van der Hoef | plain projection: k / k after 10 / 50 / 100 steps |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (kind, res), (w, p) in rows.items():
        k = w["k"][-1]
        print("| %s | %d | %.3f | %.3f | %.3f | %.1e | %.2f | %.2f | %.2f / %.2f / %.2f |" % (
            kind, res, w["phi"], w["phi_mask"], k * 1e9, abs(w["k"][-1] / w["k"][-2] - 1), k / carman_kozeny(w["phi"]),
            k / van_der_hoef(w["phi"]), p["k"][0] / k, p["k"][4] / k, p["k"][-1] / k))
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.6))
    for kind, mark in zip(COLUMNS, "os"):
        phi = rows[(kind, res_list[0])][0]["phi"]
        ax[0].plot(res_list, [rows[(kind, s)][0]["k"][-1] / van_der_hoef(phi) for s in res_list], mark + "-",
                   label="%s (phi %.3f)" % (kind, phi))
    ax[0].axhline(1, color="k", ls=":", label="van der Hoef et al. 2005")
    ax[0].set_xlabel("d / dx")
    ax[0].set_ylabel("k / k (van der Hoef)")
    ax[0].set_ylim(0, 1.5)
    ax[0].legend(fontsize=8)
    for (kind, res), (w, p) in rows.items():
        ax[1].plot(np.arange(1, len(p["k"]) + 1) * 10, p["k"] / w["k"][-1], "-" if kind == "loose" else "--",
                   color="C%d" % res_list.index(res), label="%s, d/dx %d" % (kind, res))
    ax[1].axhline(1, color="k", ls=":")
    ax[1].set_xlabel("steps of 1e-3 s from rest")
    ax[1].set_ylabel("k (plain projection) / k (weighted)")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "permeability.png"), dpi=120)


# The collapse cases' contact law (cases/dam_break.opts); the DEM step t_c / 20 as in cases/prepare_column.opts.
CONTACT = ["-contact_tc", "2.5e-4", "-contact_restitution", "0.3", "-contact_friction", "0.5", "-contact_roughness", "1e-2"]
CHUTE_DT = 1.25e-5
CHUTE = (0.010, 0.006, 0.030)   # periodic x (downslope) and y; a wall far above the free surface
ANGLES = (21, 22, 23, 24)


def chute_particles(path, seed=1):
    """A base of fixed spheres resting on the floor (random, non-overlapping, about 0.5 of the floor
    covered) and a loose lattice of free spheres above it, 19 layers (about 16 d when settled); the
    free spheres' radii uniform in a (1 - spread) .. a (1 + spread)."""
    rng = np.random.default_rng(seed)
    a = D / 2
    base = []
    for _ in range(20000):
        p = rng.uniform([0, 0], CHUTE[:2])
        ok = True
        for q in base:
            dx = np.abs(p - q)
            dx = np.minimum(dx, np.array(CHUTE[:2]) - dx)  # periodic
            if dx @ dx < (1.0 * D) ** 2:
                ok = False
                break
        if ok:
            base.append(p)
    rows = [(i, p[0], p[1], a, 1) for i, p in enumerate(base)]
    s = 1.05 * D * (1 + spread)
    nx, ny = int(CHUTE[0] / s), int(CHUTE[1] / s)
    for k in range(19):
        for j in range(ny):
            for i in range(nx):
                rows.append((len(rows), (i + 0.5) * CHUTE[0] / nx, (j + 0.5) * CHUTE[1] / ny, 2 * D + k * s, 0))
    with open(path, "w") as f:
        f.write("id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz,fixed\n")
        for r in rows:
            z = a if r[4] else r[3]
            radius = a if r[4] or not spread else a * (1 + spread * rng.uniform(-1, 1))
            f.write("%d,%.9g,%.9g,%.9g,%.9g,2500,0,0,0,0,0,0,%d\n" % (r[0], r[1], r[2], z, radius, r[4]))


def chute(angle):
    out = os.path.join(scratch, "vp_val_phic_%d%s" % (angle, "_spread%g" % spread if spread else ""))
    if not (reuse and glob.glob(os.path.join(out, "particles_*.h5"))):
        os.makedirs(out, exist_ok=True)
        chute_particles(os.path.join(out, "start.csv"))
        g = 9.81
        t = np.radians(angle)
        cmd = ["mpirun", "-n", ranks, vpsolve, "-fluid_off", "-grid_lo", "0,0,0", "-grid_hi", ",".join(map(str, CHUTE)),
               "-grid_n", "4,2,12", "-bc_xlo", "periodic", "-bc_xhi", "periodic", "-bc_ylo", "periodic", "-bc_yhi", "periodic",
               "-gravity", "%g,0,%g" % (g * np.sin(t), -g * np.cos(t)), "-particles_file", os.path.join(out, "start.csv"),
               "-time_dt", str(CHUTE_DT), "-time_final", "3", "-output_dt", "0.1", "-monitor_every", "0",
               "-output_dir", out, "-output_overwrite"] + CONTACT
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=root)
    return chute_bulk(out, angle)


def chute_bulk(out, angle, t_from=1.5):
    """Each snapshot from t_from, the bulk (3 d above the base to 2 d below the surface): solid fraction,
    and the inertial number I = gamma_dot d / sqrt(P / rho_p) at mid-depth (P = rho_p phi g cos(theta) depth)."""
    snaps = []
    for path in sorted(glob.glob(os.path.join(out, "particles_*.h5"))):
        if int(path[-9:-3]) * CHUTE_DT < t_from - 1e-9:
            continue
        with h5py.File(path, "r") as f:
            x, v, r = f["position"][...], f["velocity"][...], f["radius"][...]
        free = x[:, 2] > D  # the base's centres sit at a
        z, u, rf = x[free, 2], v[free, 0], r[free]
        top = np.percentile(z + rf, 97)
        lo, hi = 3 * D, top - 2 * D
        m = (z > lo) & (z < hi)
        phi = np.sum(4 / 3 * np.pi * rf[m] ** 3) / (CHUTE[0] * CHUTE[1] * (hi - lo))
        rate = np.polyfit(z[m], u[m], 1)[0]
        p = 2500 * phi * 9.81 * np.cos(np.radians(angle)) * (top - 0.5 * (lo + hi))
        snaps.append((phi, rate * D / np.sqrt(p / 2500), u.mean()))
    phi, I, speed = map(np.array, zip(*snaps))
    half = len(speed) // 2
    return dict(angle=angle, phi=phi, I=I, speed=speed, drift=speed[half:].mean() / speed[:half].mean() - 1)


def phic():
    """phi against I over every snapshot of the flowing runs (near the stopping angle the flows still
    speed up or slow down over seconds; phi follows the local I, GDR MiDi 2004), fitted linearly."""
    rows = [chute(a) for a in ANGLES]
    flowing = [m for m in rows if m["speed"].mean() > 1e-3]
    print("| angle | tan | mean speed (m/s) | its drift over the window | bulk phi (range) | I at mid-depth (range) |")
    print("|---|---|---|---|---|---|")
    for m in rows:
        print("| %d | %.3f | %.4f | %+.2f | %.4f (%.4f-%.4f) | %.3f (%.3f-%.3f) |" % (
            m["angle"], np.tan(np.radians(m["angle"])), m["speed"].mean(), m["drift"], m["phi"].mean(), m["phi"].min(),
            m["phi"].max(), m["I"].mean(), m["I"].min(), m["I"].max()))
    I = np.concatenate([m["I"] for m in flowing])
    phi = np.concatenate([m["phi"] for m in flowing])
    b, phi_c = np.polyfit(I, phi, 1)
    print("phi(I) = %.4f %+.3f I over %d snapshots of %d flowing angles (residual rms %.4f): phi_c = %.4f" % (
        phi_c, b, len(I), len(flowing), (phi - phi_c - b * I).std(), phi_c))
    fig, ax = plt.subplots(figsize=(5, 3.6))
    for m in flowing:
        ax.plot(m["I"], m["phi"], ".", label="incline %d deg" % m["angle"])
    ii = np.linspace(0, I.max() * 1.1, 20)
    ax.plot(ii, phi_c + b * ii, "k--", label="phi_c %.3f %+.2f I" % (phi_c, b))
    for kind, c in zip(COLUMNS if not spread else (), ("C4", "C5")):  # the shipped columns are monodisperse
        ph = column_interior(*load_column(kind))[2]
        print("column %s: phi %.3f, phi - phi_c = %+.3f" % (kind, ph, ph - phi_c))
        ax.axhline(ph, color=c, ls=":", label="shipped %s column" % kind)
    if spread:
        ax.set_title("radii uniform in a (1 - %g) .. a (1 + %g)" % (spread, spread), fontsize=9)
    ax.set_xlabel("inertial number I")
    ax.set_ylabel("solid fraction")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "phi_c_spread.png" if spread else "phi_c.png"), dpi=120)


def prepared_column(tc, out):
    """The loose column settled as cases/prepare_column.opts does, with contact time tc (DEM step tc / 20)."""
    csv_path = os.path.join(out, "column.csv")
    if not (reuse and os.path.exists(csv_path)):
        subprocess.run(["mpirun", "-n", ranks, vpsolve, "-options_file", "cases/prepare_column.opts", "-contact_tc", str(tc),
                        "-time_dt", str(tc / 20), "-output_dir", os.path.join(out, "prepare"), "-output_overwrite",
                        "-monitor_every", "0"], check=True, stdout=subprocess.DEVNULL, cwd=root)
        last = sorted(glob.glob(os.path.join(out, "prepare", "particles_*.h5")))[-1]
        subprocess.run([os.path.join(root, "scripts", "column_phi"), last, "--x0", "0", "--x1", "0.019", "--width", "0.004",
                        "--to-csv", csv_path], check=True, stdout=subprocess.DEVNULL, cwd=root)
    return csv_path


def deepest_overlap(x, r, roughness=0.01):
    """The deepest contact overlap of a settled column, beyond the roughness gap (contact begins at a
    gap of roughness (a_i + a_j)), over d."""
    gap = np.full(len(r), np.inf)
    for i in range(len(r)):
        d = x[i + 1:] - x[i]
        d[:, 1] -= BOX[1] * np.round(d[:, 1] / BOX[1])  # periodic across the slab
        if len(d):
            g = np.sqrt((d**2).sum(1)) - (r[i] + r[i + 1:]) * (1 + roughness)
            gap[i] = g.min()
    return -np.min(gap) / D


def base_pressure(out):
    data = np.genfromtxt(os.path.join(out, "probes.csv"), delimiter=",", names=True)
    p = data["p_0"] - data["p_1"]
    return data["time"], p - p[0]


def front(out):
    data = np.genfromtxt(os.path.join(out, "collapse.csv"), delimiter=",", names=True)
    return data["time"], (data["front"] - data["front"][0]) / data["front"][0]


def pressure_means(t, p, at):
    """10-ms means of the base excess pressure ending at each time in at."""
    return [p[(t > a - 0.01) & (t <= a + 1e-9)].mean() for a in at]


def coupling():
    """The shipped loose column to 0.3 s over the fluid step and the implicit drag; the DEM sub-step kept."""
    sub = 1e-3 / 150
    grid = [(1e-3, 1), (1e-3, 10), (1e-3, 30), (5e-4, 10), (5e-4, 30), (2.5e-4, 1), (2.5e-4, 10), (2.5e-4, 30),
            (1.25e-4, 3), (1.25e-4, 30)]
    runs = []
    for dt, k in grid:
        out = os.path.join(scratch, "vp_val_collapse_dt%g_k%g" % (dt, k))
        if not (reuse and os.path.exists(os.path.join(out, "probes.csv"))):
            subprocess.run(["mpirun", "-n", ranks, vpsolve, "-options_file", "cases/dam_break.opts", "-time_dt_max", str(dt),
                            "-dem_substeps", str(round(dt / sub)), "-dem_implicit_drag", str(k), "-time_final", "0.3",
                            "-output_dt", "0", "-monitor_every", "0", "-output_dir", out, "-output_overwrite"],
                           check=True, stdout=subprocess.DEVNULL, cwd=root)
        runs.append((dt, k, out))
    at = (0.05, 0.1, 0.2, 0.3)
    print("| fluid step (s) | k | front at 0.05 / 0.1 / 0.2 / 0.3 s | base excess pressure, 10-ms means at "
          "0.02 / 0.05 / 0.1 / 0.2 / 0.3 s (Pa) | mean over 0-0.1 / 0.1-0.3 s |")
    print("|---|---|---|---|---|")
    fig, ax = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True)
    for dt, k, out in runs:
        t, p = base_pressure(out)
        tf, xf = front(out)
        print("| %g | %g | %s | %s | %+.1f / %+.1f |" % (
            dt, k, " / ".join("%.3f" % np.interp(a, tf, xf) for a in at),
            " / ".join("%+.1f" % v for v in pressure_means(t, p, (0.02,) + at)), p[t <= 0.1].mean(), p[t > 0.1].mean()))
        style = dict(color="C%d" % (1, 10, 30, 3).index(k), ls={1e-3: ":", 5e-4: "--", 2.5e-4: "-", 1.25e-4: "-"}[dt],
                     lw=2.5 if dt == 1.25e-4 else 1, label="dt %g s, k %g" % (dt, k))
        ax[0].plot(tf, xf, **style)
        tm = np.arange(0.01, t[-1] + 1e-9, 0.01)
        ax[1].plot(tm, pressure_means(t, p, tm), **style)
    ax[0].set_ylabel("front (x_f - L0) / L0")
    ax[0].legend(fontsize=7, ncol=2)
    ax[1].axhline(0, color="k", lw=0.5)
    ax[1].set_ylabel("base excess pressure, 10-ms means (Pa)")
    ax[1].set_xlabel("t (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "dam_break_coupling.png"), dpi=120)


def stiffness():
    runs = []
    for tc in (5e-4, 2.5e-4, 1.25e-4):
        out = os.path.join(scratch, "vp_val_collapse_tc%g" % tc)
        col = prepared_column(tc, out)
        substeps = int(round(1e-3 / min(1e-3 / 150, tc / 37.5)))
        if not (reuse and os.path.exists(os.path.join(out, "probes.csv"))):
            subprocess.run(["mpirun", "-n", ranks, vpsolve, "-options_file", "cases/dam_break.opts", "-particles_file", col,
                            "-contact_tc", str(tc), "-dem_substeps", str(substeps), "-time_final", "0.3", "-output_dt", "0",
                            "-monitor_every", "0", "-output_dir", out, "-output_overwrite"],
                           check=True, stdout=subprocess.DEVNULL, cwd=root)
        data = np.genfromtxt(col, delimiter=",", names=True)
        x = np.stack([data["x"], data["y"], data["z"]], axis=1)
        runs.append(dict(tc=tc, out=out, substeps=substeps, overlap=deepest_overlap(x, data["radius"])))
    print("| t_c (s) | DEM sub-steps | deepest contact overlap (of d) | base excess pressure: lowest over 0-0.03 s "
          "| 10-ms means at 0.05 / 0.1 / 0.2 / 0.3 s (Pa) | mean over 0-0.3 s | front at 0.1 / 0.2 / 0.3 s |")
    print("|---|---|---|---|---|---|---|")
    fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for m in runs:
        t, p = base_pressure(m["out"])
        tf, xf = front(m["out"])
        means = pressure_means(t, p, (0.05, 0.1, 0.2, 0.3))
        print("| %g | %d | %.4f | %.1f | %s | %+.1f | %s |" % (
            m["tc"], m["substeps"], m["overlap"], p[t <= 0.03].min(), " / ".join("%+.1f" % v for v in means),
            p.mean(), " / ".join("%.3f" % np.interp(a, tf, xf) for a in (0.1, 0.2, 0.3))))
        ax[0].plot(t, p, lw=0.8, label="t_c %g s" % m["tc"])
        ax[1].plot(tf, xf, label="t_c %g s" % m["tc"])
    ax[0].axhline(0, color="k", lw=0.5)
    ax[0].set_ylabel("base excess pore pressure (Pa)")
    ax[0].legend(fontsize=8)
    ax[1].set_xlabel("t (s)")
    ax[1].set_ylabel("front (x_f - L0) / L0")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "dam_break_stiffness.png"), dpi=120)


if what in ("permeability", "all"):
    permeability()
if what in ("phic", "all"):
    phic()
if what in ("coupling", "all"):
    coupling()
if what in ("stiffness", "all"):
    stiffness()
