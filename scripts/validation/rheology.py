#!/usr/bin/python3
"""The shear cell and the suspension stress (docs/rheology.md), on the shipped case
cases/shear_suspension.opts with changes.
  sphere: one torque-free sphere (d = 1 mm) in the middle of a cubic cell of side L sheared at
      gamma = 10 1/s: its spin over gamma/2 and its stresslet (from rheology.csv: the core's
      hydrodynamic stress minus its mean viscous stress) over (10/3) pi mu a^3 gamma, at d/dx 6, 8, 12
      (L = 6 d) and at L = 6, 8, 10 d (d/dx 8), extrapolated to an unbounded liquid in (a/L)^3.
      Table, docs/validation/rheology_sphere.png.
  dilute: phi 0.05 and 0.10 to a strain of 2 against 1 + 2.5 phi + 5.2 phi^2 (Batchelor & Green).
  fraction [--strain S]: phi 0.2, 0.3, 0.4, 0.5 with friction 0.5 and without (and 0.5 frictionless
      bidisperse, radii 1:1.4, against ordering), to strain S
      (5): eta_r against Boyer, Guazzelli & Pouliquen 2011 and Krieger-Dougherty (phi_m 0.585), its
      parts, N1 and N2, and the core's own viscosity at the core's solid fraction (eta_r_bulk /
      core_rate at phi_core). Table, docs/validation/rheology_phi.png.
  gap [--strain S]: phi 0.5, friction 0.5 to strain S (20) in the 16 d gap (the fraction study's run,
      shared with --reuse) and in a 24 d gap at the same shear rate: the walls' rate and the core's;
      the velocity and solid fraction across the gap (the last snapshot), docs/validation/rheology_gap.png.
  rough [--strain S]: phi 0.4 and 0.5, friction 0.5 to strain S (20) between rough walls (a layer of
      fixed spheres of the suspension's radius on each wall, -particles_rough_walls; the packing grown
      between the layers) against the smooth walls of the fraction study (shared with --reuse): the
      core's rate, fraction and viscosity; profiles across the gap, docs/validation/rheology_rough.png.
  packings [--strain S]: phi 0.4 and 0.5, friction 0.5, three random packings (seeds 1-3; seed 1 the
      fraction study's run, shared with --reuse) to strain S (20): the spread between packings.
  normal [--strain S]: N1 and N2 over the core's shear stress against the core's solid fraction, for
      the fraction, gap, packings and rough runs (made here when missing; shared with --reuse), against
      the measured fits of Dai et al. 2013. Table, docs/validation/rheology_normal.png.
  sensitivity [--strain S]: the shipped case (phi 0.4, friction 0.5) to strain S (3) at d/dx 6 and
      8, with half the roughness, and in a periodic cell of 12 d x 12 d instead of 8 d x 8 d. Table.
  thickening [--strain S]: cases/shear_thickening.opts (bidisperse, the critical load model) at
      phi 0.52, 0.54, 0.56 to strain S (4): eta_r against sigma / sigma* (sigma* = F_CL / (6 pi a^2),
      a the small radius) from frictionless to always frictional, and the DEM's cost per strain unit
      with the explicit and the implicit squeeze. Table, docs/validation/rheology_thickening.png.
Means over the second half of each run's strain.
usage: rheology.py [sphere|dilute|fraction|gap|rough|packings|normal|sensitivity|thickening] [--strain S] [--reuse]"""
import csv, glob, json, os, subprocess, sys
import h5py
import numpy as np
from importlib.machinery import SourceFileLoader
from common import plt, root, ranks, vpsolve, scratch, outdir, chosen_study

sphere_check = SourceFileLoader("sphere_check", os.path.join(root, "tests", "regression", "check_rheology_sphere.py")).load_module()
# The correlations and the reading of rheology.csv: scripts/plot_rheology's.
plot = SourceFileLoader("plot_rheology", os.path.join(root, "scripts", "plot_rheology")).load_module()
boyer, krieger_dougherty = plot.boyer, plot.krieger_dougherty

STUDIES = ("sphere", "dilute", "fraction", "gap", "rough", "packings", "normal", "sensitivity", "thickening")
what = chosen_study(__doc__, STUDIES, valued=("--strain",))
reuse = "--reuse" in sys.argv
strain = float(sys.argv[sys.argv.index("--strain") + 1]) if "--strain" in sys.argv else None
CASE = os.path.join(root, "cases", "shear_suspension.opts")
A, MU, GAMMA = sphere_check.A, sphere_check.MU, sphere_check.GAMMA

def run(name, options, case=CASE):
    out = os.path.join(scratch, "vp_val_rheology_" + name)
    if not (reuse and os.path.exists(os.path.join(out, "rheology.csv"))):
        cmd = ["mpirun", "-n", ranks, vpsolve, "-options_file", case] + options + \
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


def save(fig, ax, xlabel, ylabel, title, name, legend_size=8):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=legend_size)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, name), dpi=110)


def block_error(d, block=0.25):
    """Standard error of eta_r's mean over the second half of the strain, from means over blocks of
    `block` strain units (successive blocks taken as independent)."""
    s, e = d["strain"], d["eta_r"]
    starts = np.arange(s[-1] / 2, s[-1] - 1e-9, block)
    means = [e[(s > a) & (s <= a + block)].mean() for a in starts]
    return np.std(means, ddof=1) / np.sqrt(len(means))


def packed(phi, friction, strain_end, name, extra=(), width=0.008, gap=0.016, seed=1):
    return run(name, ["-particles_packed", f"0,0,0,{width},{width},{gap},{phi},5e-4,{seed}", "-contact_friction", str(friction),
                      "-time_final", str(strain_end / GAMMA)] + list(extra))


def dilute():
    print("phi   eta_r  bulk   1 + 2.5 phi + 5.2 phi^2")
    for phi in (0.05, 0.1):
        _, d = packed(phi, 0.5, 2.0, f"dilute_{phi}")
        m = second_half(d)
        print(f"{phi:.2f}  {m['eta_r']:.3f}  {m['eta_r_bulk']:.3f}  {1 + 2.5 * phi + 5.2 * phi**2:.3f}")


def fraction():
    strain_end = strain or 5.0
    runs = [(phi, mu_c, 1.0) for mu_c in (0.5, 0.0) for phi in (0.2, 0.3, 0.4, 0.5)] + [(0.5, 0.0, 1.4)]
    print("phi   friction  eta_r  bulk   hydro  lub   contact  n1     n2     core_rate  /Boyer  /KD   "
          "phi_core  eta_core  /Boyer(phi_core)  /KD(phi_core; frictionless phi_m 0.64)")
    points = []
    for phi, mu_c, ratio in runs:  # ratio 1.4: bidisperse, against ordering of the monodisperse packing
        name = f"phi_{phi}_{mu_c}" + ("" if ratio == 1 else f"_bi{ratio}")
        _, d = packed(phi, mu_c, strain_end, name, [] if ratio == 1 else ["-particles_size_ratio", str(ratio)])
        m = second_half(d)
        points.append((mu_c, ratio, m))
        phi_core, eta_core = plot.core(m)
        print(f"{m['phi']:.3f}  {mu_c:8.1f}  {m['eta_r']:5.2f}  {m['eta_r_bulk']:5.2f}  {m['eta_hydro']:5.2f}  {m['eta_lub']:4.2f}  "
              f"{m['eta_contact']:7.2f}  {m['n1']:5.2f}  {m['n2']:5.2f}  {m['core_rate']:9.3f}  {m['eta_r'] / boyer(m['phi']):6.2f}  "
              f"{m['eta_r'] / krieger_dougherty(m['phi']):4.2f}  {phi_core:8.3f}  {eta_core:8.2f}  {eta_core / boyer(phi_core):16.2f}  "
              f"{eta_core / krieger_dougherty(phi_core, 0.585 if mu_c > 0 else 0.64):13.2f}"
              + ("" if ratio == 1 else f"  bidisperse 1:{ratio}"), flush=True)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    p = np.linspace(0.01, 0.55, 200)
    ax.semilogy(p, boyer(p), "k-", label="Boyer et al. 2011")
    ax.semilogy(p, krieger_dougherty(p), "k--", label="Krieger-Dougherty, phi_m 0.585")
    ax.semilogy(p, krieger_dougherty(p, 0.64), "--", color="C3", lw=0.8, label="Krieger-Dougherty, phi_m 0.64 (frictionless)")
    ax.semilogy(p, 1 + 2.5 * p + 5.2 * p**2, "k:", label="1 + 2.5 phi + 5.2 phi^2")
    for mu_c, ratio, m in points:
        c = "C0" if mu_c > 0 else ("C3" if ratio == 1 else "C1")
        ax.plot(m["phi"], m["eta_r"], "o", color=c)
        ax.plot(m["phi"], m["eta_r_bulk"], "x", color=c)
        ax.plot(*plot.core(m), "s", mfc="none", color=c)
    ax.plot([], [], "o", color="C0", label="friction 0.5 (o wall, x bulk, square: the core's own at its phi)")
    ax.plot([], [], "o", color="C3", label="frictionless")
    ax.plot([], [], "o", color="C1", label="frictionless, bidisperse 1:1.4")
    save(fig, ax, "solid fraction phi", "relative viscosity", f"d/dx 6, gap 16 d, strain {strain_end:g}", "rheology_phi.png")


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


def profiles(out):
    """The last snapshot's plane means across the gap: z (from the gap's middle), u_x and the solid
    fraction of each cell layer (the spheres' slices between its planes)."""
    last = lambda pattern: sorted(glob.glob(os.path.join(out, pattern)))[-1]
    with h5py.File(last("fields_*.h5")) as f:
        ux = f["velocity"][..., 0].mean(axis=(1, 2))
    with h5py.File(last("particles_*.h5")) as f:
        zc, a = f["position"][:, 2], f["radius"][:]
    hi = [float(x) for x in json.load(open(os.path.join(out, "run.json")))["options"]["-grid_hi"]["value"].split(",")]
    L, area = hi[2], hi[0] * hi[1]
    planes = np.linspace(0, L, len(ux) + 1)
    def slab(lo, hi):  # the spheres' volume between two planes z = lo, hi
        t0, t1 = np.clip(lo - zc, -a, a), np.clip(hi - zc, -a, a)
        return np.pi * np.sum(a * a * (t1 - t0) - (t1**3 - t0**3) / 3)
    phi = np.array([slab(planes[k], planes[k + 1]) for k in range(len(ux))]) / (area * (planes[1] - planes[0]))
    return 0.5 * (planes[1:] + planes[:-1]) - L / 2, ux, phi


def draw_profiles(ax, out, m, L, label, color):
    """The run's profiles (profiles()) on the velocity and fraction panels, z in diameters from the
    middle; the core's planes dashed (2 d from each wall)."""
    z, ux, phi = profiles(out)
    phi_core, _ = plot.core(m)
    ax[0].plot(ux / (GAMMA * L / 2), z / (2 * A), color=color, label=f"{label}: core rate {m['core_rate']:.2f}")
    ax[1].plot(phi, z / (2 * A), color=color, label=f"{label}: phi_core {phi_core:.3f}")
    for a_ in ax:
        for edge in (-1, 1):
            a_.axhline(edge * (L / (4 * A) - 2), color=color, lw=0.6, ls="--")


def finish_profiles(fig, ax, title, name):
    ax[0].plot([], [], "k--", lw=0.6, label="the core (2 d from each wall)")
    ax[0].set_xlabel("u_x / U_wall (plane mean)")
    ax[0].set_ylabel("z / d from the middle")
    ax[1].set_xlabel("solid fraction of the cell layer")
    for a_ in ax:
        a_.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, name), dpi=110)


def gap():
    """phi 0.5, friction 0.5 in gaps of 16 d (the fraction study's run) and 24 d at the same shear rate."""
    strain_end = strain or 20.0
    print("gap (d)  phi    eta_r  bulk   core_rate  /Boyer  phi_core  eta_core  /Boyer(phi_core)")
    fig, ax = plt.subplots(1, 2, figsize=(10, 4.5), sharey=True)
    for width in (16, 24):
        L = width * 2 * A
        extra = [] if width == 16 else ["-grid_hi", f"0.008,0.008,{L}", "-grid_n", f"48,48,{6 * width}",
                                        "-bc_zlo_velocity", f"{-GAMMA * L / 2},0,0", "-bc_zhi_velocity", f"{GAMMA * L / 2},0,0"]
        out, d = packed(0.5, 0.5, strain_end, "phi_0.5_0.5" if width == 16 else f"gap_{width}", extra, gap=L)
        m = second_half(d)
        phi_core, eta_core = plot.core(m)
        print(f"{width:7d}  {m['phi']:.3f}  {m['eta_r']:5.2f}  {m['eta_r_bulk']:5.2f}  {m['core_rate']:9.3f}  "
              f"{m['eta_r'] / boyer(m['phi']):6.2f}  {phi_core:8.3f}  {eta_core:8.2f}  {eta_core / boyer(phi_core):16.2f}", flush=True)
        c = "C0" if width == 16 else "C1"
        draw_profiles(ax, out, m, L, f"gap {width} d", c)
        ax[0].plot([-1, 1], [-width / 2, width / 2], ":", color=c, lw=0.8)
    ax[0].plot([], [], "k:", lw=0.8, label="the walls' rate")
    finish_profiles(fig, ax, f"phi 0.5, friction 0.5: the last snapshot (strain {strain_end:g}) across the gap", "rheology_gap.png")


def rough():
    """phi 0.4 and 0.5, friction 0.5, between rough walls (a layer of fixed spheres of the suspension's
    radius on each wall) against the smooth walls of the fraction study."""
    strain_end = strain or 20.0
    L = 0.016
    print("phi   walls   phi(free)  eta_r  bulk   core_rate  phi_core  eta_core  /Boyer(phi_core)  n1     n2")
    fig, ax = plt.subplots(1, 2, figsize=(10, 4.5), sharey=True)
    for k, phi in enumerate((0.4, 0.5)):
        for walls in ("smooth", "rough"):
            if walls == "smooth":
                out, d = packed(phi, 0.5, strain_end, f"phi_{phi}_0.5")
            else:  # the packing grown between the layers' tops
                out, d = run(f"rough_{phi}", ["-particles_packed", f"0,0,{2 * A},0.008,0.008,{L - 2 * A},{phi},{A},1",
                                              "-particles_rough_walls", str(A), "-contact_friction", "0.5",
                                              "-time_final", str(strain_end / GAMMA)])
            m = second_half(d)
            phi_core, eta_core = plot.core(m)
            print(f"{phi:.1f}  {walls:6s}  {m['phi']:9.3f}  {m['eta_r']:5.2f}  {m['eta_r_bulk']:5.2f}  {m['core_rate']:9.3f}  "
                  f"{phi_core:8.3f}  {eta_core:8.2f}  {eta_core / boyer(phi_core):16.2f}  {m['n1']:5.2f}  {m['n2']:5.2f}", flush=True)
            draw_profiles(ax, out, m, L, f"phi {phi}, {walls}", f"C{2 * k + (walls == 'rough')}")
    finish_profiles(fig, ax, f"friction 0.5, 16 d gap, smooth and rough walls: the last snapshot (strain {strain_end:g})",
                    "rheology_rough.png")


def packings():
    """phi 0.4 and 0.5, friction 0.5: three packings (seeds 1-3; seed 1 is the fraction study's run)."""
    strain_end = strain or 20.0
    print("phi   seed  eta_r  bulk   n1     n2     core_rate  phi_core  eta_core  /Boyer(phi_core)")
    for phi in (0.4, 0.5):
        cores = []
        for seed in (1, 2, 3):
            _, d = packed(phi, 0.5, strain_end, f"phi_{phi}_0.5" if seed == 1 else f"phi_{phi}_0.5_seed{seed}", seed=seed)
            m = second_half(d)
            phi_core, eta_core = plot.core(m)
            cores.append(eta_core / boyer(phi_core))
            print(f"{phi:.1f}  {seed:4d}  {m['eta_r']:5.2f}  {m['eta_r_bulk']:5.2f}  {m['n1']:5.2f}  {m['n2']:5.2f}  {m['core_rate']:9.3f}  "
                  f"{phi_core:8.3f}  {eta_core:8.2f}  {eta_core / boyer(phi_core):16.2f}", flush=True)
        print(f"phi {phi}: eta_core / Boyer(phi_core) {np.mean(cores):.2f} +- {np.std(cores, ddof=1):.2f} over the packings")


def dai(phi):
    """N1 / sigma and N2 / sigma measured by Dai, Bertevas, Qi & Tanner 2013 (J. Rheol. 57, 493;
    "Viscometric functions for noncolloidal sphere suspensions with Newtonian matrices"): -0.8 phi^3
    and -4.4 phi^3, their fits over 0.1 <= phi <= 0.45."""
    return -0.8 * phi**3, -4.4 * phi**3


def normal():
    """N1 and N2 over the core's shear stress, against phi_core: the fraction, packings and rough runs
    (run here when missing) against Dai et al.'s measured fits."""
    strain_end = strain or 20.0
    runs = [(f"phi_{phi}_0.5", "friction 0.5", "C0") for phi in (0.2, 0.3, 0.4, 0.5)]
    runs += [(f"phi_{phi}_0.5_seed{s}", "friction 0.5, other packings", "C2") for phi in (0.4, 0.5) for s in (2, 3)]
    runs += [("phi_0.4_0.0", "frictionless", "C3"), ("gap_24", "friction 0.5, 24 d gap", "C4")]
    runs += [(f"rough_{phi}", "friction 0.5, rough walls", "C1") for phi in (0.4, 0.5)]
    print("run                   phi_core  N1/sigma  N2/sigma  Dai: N1/sigma  N2/sigma")
    fig, ax = plt.subplots(figsize=(6, 4.5))
    p = np.linspace(0.1, 0.45, 50)
    for k, style in ((0, "k--"), (1, "k-")):
        ax.plot(p, dai(p)[k], style)
        ax.plot(np.linspace(0.45, 0.53, 10), dai(np.linspace(0.45, 0.53, 10))[k], style, lw=0.6)
    ax.plot([], [], "k-", label="Dai et al. 2013, N2 (fit 0.1-0.45, thin: beyond)")
    ax.plot([], [], "k--", label="Dai et al. 2013, N1")
    labelled = set()
    for name, label, color in runs:
        if name.startswith("rough_"):
            phi = float(name.split("_")[1])
            _, d = run(name, ["-particles_packed", f"0,0,{2 * A},0.008,0.008,{0.016 - 2 * A},{phi},{A},1",
                              "-particles_rough_walls", str(A), "-contact_friction", "0.5", "-time_final", str(strain_end / GAMMA)])
        else:
            parts = name.split("_")
            L = 0.024 if name == "gap_24" else 0.016
            extra = ["-grid_hi", f"0.008,0.008,{L}", "-grid_n", "48,48,144", "-bc_zlo_velocity", f"{-GAMMA * L / 2},0,0",
                     "-bc_zhi_velocity", f"{GAMMA * L / 2},0,0"] if name == "gap_24" else []
            phi = 0.5 if name == "gap_24" else float(parts[1])
            seed = int(parts[3][4:]) if len(parts) > 3 else 1
            _, d = packed(phi, 0.0 if name == "phi_0.4_0.0" else 0.5, strain_end, name, extra, gap=L, seed=seed)
        m = second_half(d)
        n1, n2 = m["n1"] / m["eta_r_bulk"], m["n2"] / m["eta_r_bulk"]
        r1, r2 = dai(m["phi_core"])
        print(f"{name:20s}  {m['phi_core']:8.3f}  {n1:8.3f}  {n2:8.3f}  {r1:13.3f}  {r2:8.3f}", flush=True)
        ax.plot(m["phi_core"], n2, "o", color=color, label=None if label in labelled else label)
        ax.plot(m["phi_core"], n1, "^", mfc="none", color=color)
        labelled.add(label)
    ax.plot([], [], "k^", mfc="none", label="N1 (open triangles); N2 (dots)")
    ax.axhline(0, color="0.6", lw=0.6)
    save(fig, ax, "the core's solid fraction phi_core", "normal stress difference / shear stress",
         f"N1, N2 over the core's shear stress, d/dx 6, strain {strain_end:g}", "rheology_normal.png", 7)


THICKENING = os.path.join(root, "cases", "shear_thickening.opts")
A_SMALL = 5e-4                   # the small spheres' radius in cases/shear_thickening.opts
F_CL = (1e-3, 3e-4, 1e-4, 3e-5, 1e-5)  # N: sigma / sigma* from about 0.1 to 50


def thickening():
    strain_end = strain or 4.0
    sigma_unit = MU * GAMMA * 6 * np.pi * A_SMALL**2  # mu gamma / sigma* per unit F_CL (N)
    print("phi    F_CL (N)  sigma/sigma*  eta_r (+- block error)  bulk   hydro  lub   contact  n1     n2")
    curves = {}
    for phi in (0.52, 0.54, 0.56):
        # Plateaus: frictionless (sigma* infinite) and friction on every contact (sigma* = 0).
        loads = [None] + (list(F_CL) if phi == 0.54 else []) + [0.0]
        for load in loads:
            friction = ["-contact_friction", "0"] if load is None else ["-contact_critical_load", str(load)]
            name = f"thick_{phi}_" + ("none" if load is None else f"{load:g}")
            _, d = run(name, [f"-particles_packed", f"0,0,0,0.008,0.008,0.016,{phi},{A_SMALL},1",
                              "-time_final", str(strain_end / GAMMA)] + friction, THICKENING)
            m = second_half(d)
            ratio = 0.0 if load is None else (np.inf if load == 0 else m["eta_r"] * sigma_unit / load)
            curves.setdefault(phi, []).append((ratio, m, block_error(d)))
            print(f"{m['phi']:.3f}  {'-' if load is None else f'{load:8.0e}':>8s}  {ratio:12.3g}  {m['eta_r']:5.1f} +- "
                  f"{block_error(d):4.1f}          "
                  f"{m['eta_r_bulk']:5.1f}  {m['eta_hydro']:5.2f}  {m['eta_lub']:4.2f}  {m['eta_contact']:7.1f}  {m['n1']:5.1f}  "
                  f"{m['n2']:5.1f}", flush=True)
    # The DEM's cost per strain unit: explicit and implicit squeeze at the case's sub-step (phi 0.54,
    # sigma* from 1e-4 N), a strain unit each.
    print("integration  DEM s per strain unit  whole step s per strain unit  eta_r")
    for integration in ("explicit", "implicit"):
        out, d = run(f"thick_cost_{integration}", ["-particles_packed", f"0,0,0,0.008,0.008,0.016,0.54,{A_SMALL},1",
                                                    "-contact_critical_load", "1e-4", "-lub_integration", integration,
                                                    "-time_final", str(1 / GAMMA)], THICKENING)
        record = json.load(open(os.path.join(out, "run.json")))
        print(f"{integration:11s}  {record['stage_seconds']['DEM']:21.1f}  {record['wall_seconds']:28.1f}  "
              f"{second_half(d)['eta_r']:5.1f}", flush=True)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for k, (phi, pts) in enumerate(sorted(curves.items())):
        c = f"C{k}"
        finite = sorted((r, m["eta_r"], err) for r, m, err in pts if 0 < r < np.inf)
        if finite:
            x, y, err = zip(*finite)
            ax.errorbar(x, y, yerr=err, fmt="o-", color=c, capsize=2, label=f"phi {phi}")
        for r, m, _ in pts:
            if r == 0 or r == np.inf:
                ax.axhline(m["eta_r"], color=c, ls="--" if r == 0 else ":", lw=1)
        ax.plot([], [], color=c, ls="--", lw=1, label=f"phi {phi}: frictionless (--), always frictional (..)")
    peer = os.path.join(root, "benchmarks", "lf_dem", "results_thickening.csv")  # benchmarks/lf_dem/README.md
    if os.path.exists(peer):
        rows = [r for r in csv.DictReader(open(peer)) if float(r["friction"]) == 0.5]
        for k, phi in enumerate(sorted(curves)):
            pts = sorted((float(r["sigma_over_sigma_star"]), float(r["eta_r"])) for r in rows if abs(float(r["phi"]) - phi) < 1e-6)
            if pts:
                ax.plot(*zip(*pts), "s", mfc="none", color=f"C{k}", label=f"LF_DEM, phi {phi}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    save(fig, ax, "sigma / sigma*  (sigma* = F_CL / (6 pi a^2))", "relative viscosity (walls)",
         f"critical load model, friction 0.5, bidisperse 1:1.4, strain {strain_end:g}", "rheology_thickening.png", 7)


for study in STUDIES:
    if what in (study, "all"):
        globals()[study]()
