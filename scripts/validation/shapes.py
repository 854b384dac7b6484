#!/usr/bin/python3
"""Non-spherical particles (docs/shapes.md), plots into docs/validation/:
  drag: Stokes drag of a fixed spheroid (aspect 2, 3 and 1/2; axis along and across the flow) and
        of the sphere of equal volume in a periodic box, against Oberbeck's exact values, the box
        removed with two box sizes; the sphere, whose periodic drag is known (Hasimoto), measures
        the error the runs share (about 30 minutes on 2 cores at the default --res 12)
  jeffery: cases/jeffery_orbit.opts, prolate spheroids (aspect 2, and 3 in a wider box) in shear at
        Re_p 0.01: the axis angle against Jeffery's orbit and its period 2 pi (r + 1/r) / gamma (about
        5 minutes)
  bounce: a spheroid (aspect 2, tilted 30 degrees) driven onto a wall as in cases/restitution.opts
        (steel in oil, St about 150 on the equal-volume diameter, d/dx 8 on 2a): dry, in the liquid
        without lubrication, and with the LLCM: rebound and spin (about 3 minutes)
  settling: cases/spheroid_settling.opts, a prolate spheroid released at 45 degrees settling at
        Re about 10, an oblate one and a sphere of the same volume: their tilt and speed until they
        lie on the bottom, the speeds over the sphere's against Hoelzer & Sommerfeld's correlation
        (about 2 minutes)
  pair: drafting, kissing and tumbling of two prolate spheroids (aspect 2) in the liquid of the
        settling case, one 3 d_v above the other, against two spheres of the same volume: the
        centres' distance, the time they spend close, their tilt (about 12 minutes)
  zigzag: an oblate spheroid (aspect 1/3, density ratio 1.5) at Galileo number 250, above the
        threshold of secondary motions, released 5 degrees from flat: its tilt, spin and drift
        (d_v/dx 10, a coarse demonstration; about 20 minutes)
  threshold: an oblate spheroid of aspect 2/3, density ratio 1.5, at Ga 111 and 152, either side of
        the onset of a steady oblique path (Moriche, Uhlmann & Dusek): path angle and tilt
        (d_v/dx 10 or --res N; about an hour at 10, 20 minutes at 8)
usage: shapes.py [drag|jeffery|bounce|settling|pair|zigzag|threshold|all] [--res N] [--reuse]
  --res N: equal-volume diameter in cells (12)
  --reuse: plot the runs already in $VP_SCRATCH/vp_val_shape_* instead of running them again"""
import csv, math, os, subprocess, sys
from common import plt, root, ranks, vpsolve, outdir, scratch, chosen_study

what = chosen_study(__doc__, ("drag", "jeffery", "bounce", "settling", "pair", "zigzag", "threshold"), valued=("--res",))
res = int(sys.argv[sys.argv.index("--res") + 1]) if "--res" in sys.argv else 12
reuse = "--reuse" in sys.argv
RV = 0.126            # equal-volume radius (m) in the box of side 1
HASIMOTO = 2.8373     # 1.7601 (4 pi / 3)^(1/3): the first-order periodic correction of the mobility, per R_v / L


def oberbeck(r):
    """Drag / (6 pi mu U R_v) of a spheroid of aspect r = c/a in an unbounded Stokes flow, along and
    across its axis (Oberbeck 1876; Happel & Brenner, section 4-26)."""
    rv = r ** (1 / 3)
    if r == 1:
        return 1.0, 1.0
    if r > 1:
        c, e = r, math.sqrt(1 - 1 / r ** 2)
        L = math.log((1 + e) / (1 - e))
        return 16 * c * e ** 3 / ((1 + e * e) * L - 2 * e) / (6 * rv), 32 * c * e ** 3 / (2 * e + (3 * e * e - 1) * L) / (6 * rv)
    e = math.sqrt(1 - r * r)
    s, q = math.asin(e), math.sqrt(1 - e * e)
    return 8 * e ** 3 / (e * q - (1 - 2 * e * e) * s) / (6 * rv), 16 * e ** 3 / ((1 + 2 * e * e) * s - e * q) / (6 * rv)


def run(aspect, axis, L):
    """K = F / (6 pi mu R_v U) in a periodic box of side L driven by a body force, U the mean velocity."""
    n = int(round(res * L / (2 * RV)))
    out = os.path.join(scratch, "vp_val_shape_%g_%s_%g_%d" % (aspect, axis, L, res))
    # Three momentum times rho L^3 / (6 pi mu R_v K) (about 0.3 L^3 s here): F / U is then within
    # about 1 % of its steady value, the rest of the way a slow creep of many steps (the stiff
    # viscous modes of Crank-Nicolson at nu dt / h^2 = 23 decay slowly), the same for every shape
    # at the same step: the sphere measures it.
    tf = 1.0 * L ** 3
    done = os.path.exists(os.path.join(out, "particle_0.csv")) and \
        float(list(csv.DictReader(open(os.path.join(out, "particle_0.csv"))))[-1]["time"]) >= tf - 1e-9
    if not (reuse and done):
        shape = ["-particle_shape", "sphere", "-particle_radius", RV] if aspect == 1 else \
            ["-particle_shape", "spheroid", "-particle_radius", RV / aspect ** (1 / 3), "-particle_aspect", aspect,
             "-particle_axis", "1,0,0" if axis == "along" else "0,1,0"]
        cmd = ["mpirun", "-n", ranks, vpsolve, "-grid_n", "%d,%d,%d" % (n, n, n), "-grid_lo", "0,0,0", "-grid_hi", "%g,%g,%g" % (L, L, L)]
        for f in ("x", "y", "z"):
            cmd += ["-bc_%slo" % f, "periodic", "-bc_%shi" % f, "periodic"]
        cmd += ["-fluid_rho", 1, "-fluid_mu", 1, "-fluid_body_force", "1,0,0", "-particle_position", "%g,%g,%g" % (L / 2, L / 2, L / 2),
                "-particle_density", 1, "-particle_fixed", "-time_dt", 0.01, "-time_final", tf, "-track_particles", "all",
                "-output_every", 0, "-output_dt", 0, "-monitor_every", 0, "-output_dir", out, "-output_overwrite"] + shape
        subprocess.run([str(c) for c in cmd], check=True, stdout=subprocess.DEVNULL)
    part = list(csv.DictReader(open(os.path.join(out, "particle_0.csv"))))
    diag = list(csv.DictReader(open(os.path.join(out, "diagnostics.csv"))))
    F, U = float(part[-1]["fx"]), float(diag[-1]["mean_u"])
    return F / (6 * math.pi * RV * U)


def drag():
    boxes = (1.0, 1.5)
    cases = [(1, "along"), (2, "along"), (2, "across"), (3, "along"), (3, "across"), (0.5, "along"), (0.5, "across")]
    x = [RV / L for L in boxes]

    def unbounded(K):
        """1/K(L) = 1/K_inf - HASIMOTO R_v/L + beta (R_v/L)^3: the point-force image term is the same
        for any body; the next one (the particle's finite size) is fitted from the two boxes."""
        beta = ((1 / K[0] + HASIMOTO * x[0]) - (1 / K[1] + HASIMOTO * x[1])) / (x[0] ** 3 - x[1] ** 3)
        return 1 / (1 / K[0] + HASIMOTO * x[0] - beta * x[0] ** 3)

    def hasimoto(L):
        c = 4 * math.pi / 3 * (RV / L) ** 3
        return 1 / (1 - 1.7601 * c ** (1 / 3) + c - 1.5593 * c * c)

    sphere = [run(1, "along", L) for L in boxes]
    shared = [s / hasimoto(L) for s, L in zip(sphere, boxes)]  # the runs' common error, per box
    print("drag: sphere K(L=1) %.4f (Hasimoto %.4f, %+.2f %%), K(L=1.5) %.4f (%.4f, %+.2f %%)" %
          (sphere[0], hasimoto(1), 100 * (shared[0] - 1), sphere[1], hasimoto(1.5), 100 * (shared[1] - 1)), flush=True)
    rows = []
    for aspect, axis in cases:
        K = sphere if aspect == 1 else [run(aspect, axis, L) for L in boxes]
        raw, kinf = unbounded(K), unbounded([k / e for k, e in zip(K, shared)])
        ref = oberbeck(aspect)[0 if axis == "along" else 1]
        rows.append((aspect, axis, K, kinf, ref, raw))
        print("drag: aspect %g %-6s K(L=1) %.4f  K(L=1.5) %.4f  unbounded %.4f (%+.2f %%), with the sphere's error removed %.4f "
              "(%+.2f %%); Oberbeck %.4f" % (aspect, axis, K[0], K[1], raw, 100 * (raw / ref - 1), kinf, 100 * (kinf / ref - 1), ref),
              flush=True)
    fig, ax = plt.subplots(figsize=(6.5, 4))
    labels = ["%g %s" % (a, x) if a != 1 else "sphere" for a, x, *_ in rows]
    pos = range(len(rows))
    ax.bar([p - 0.27 for p in pos], [r[4] for r in rows], 0.27, label="Oberbeck (exact)", color="0.7")
    ax.bar(list(pos), [r[5] for r in rows], 0.27, label="vpsolve, box removed", color="C1")
    ax.bar([p + 0.27 for p in pos], [r[3] for r in rows], 0.27, label="... and the sphere's error", color="C0")
    for p, r in zip(pos, rows):
        ax.annotate("%+.1f %%" % (100 * (r[5] / r[4] - 1)), (p, r[5]), textcoords="offset points", xytext=(-10, 12), fontsize=6, color="C1")
        ax.annotate("%+.1f %%" % (100 * (r[3] / r[4] - 1)), (p + 0.27, r[3]), textcoords="offset points", xytext=(-8, 3), fontsize=6, color="C0")
    ax.set_xticks(list(pos))
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylim(0.8, 1.3)
    ax.set_xlabel("aspect c/a, axis relative to the flow")
    ax.set_ylabel("drag / (6 pi mu U R_v)")
    ax.set_title("Fixed spheroid, Stokes flow, d_v/dx = %d" % res, fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "spheroid_drag.png"), dpi=120)
    return rows


def axis_angle(row):
    """Angle (rad) of the body z axis in the flow-gradient (x-z) plane, from the flow direction x."""
    w, x, y, z = (float(row[k]) for k in ("qw", "qx", "qy", "qz"))
    return math.atan2(1 - 2 * (x * x + y * y), 2 * (x * z + w * y))


# Aspect 3 is a longer body: the case's box and walls 1.25 times wider, the same cells and shear rate.
JEFFERY_RUNS = ((2, []), (3, ["-grid_hi", "1.5,1.0,2.0", "-grid_n", "60,40,80", "-bc_zlo_velocity", "-1,0,0",
                              "-bc_zhi_velocity", "1,0,0", "-particle_position", "0.75,0.5,1.0", "-particle_aspect", "3",
                              "-time_final", "22"]))


def jeffery_turn(aspect, extra):
    """The axis angle turned (rad, unwrapped, positive in the sense of the shear) against gamma t."""
    out = os.path.join(scratch, "vp_val_shape_jeffery" + ("" if aspect == 2 else "_r%d" % aspect))
    case = os.path.join(root, "cases", "jeffery_orbit.opts")
    if not (reuse and os.path.exists(os.path.join(out, "particle_0.csv"))):
        subprocess.run(["mpirun", "-n", ranks, vpsolve, "-options_file", case, "-output_dir", out, "-output_overwrite",
                        "-monitor_every", "0", "-output_dt", "0"] + extra, check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(out, "particle_0.csv"))))
    t = [float(r["time"]) for r in rows]  # gamma = 1 in both boxes
    turned, last = [0.0], axis_angle(rows[0])
    for r in rows[1:]:
        a = axis_angle(r)
        d = (last - a + math.pi) % (2 * math.pi) - math.pi
        turned.append(turned[-1] + d)
        last = a
    return t, turned


def crossing(t, turned, level):
    """The time the turned angle first reaches level (linear between rows), or None."""
    for k in range(1, len(t)):
        if turned[k - 1] < level <= turned[k]:
            return t[k - 1] + (level - turned[k - 1]) / (turned[k] - turned[k - 1]) * (t[k] - t[k - 1])
    return None


def jeffery():
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for r_, extra in JEFFERY_RUNS:
        t, turned = jeffery_turn(r_, extra)
        T = 2 * math.pi * (r_ + 1 / r_)
        half, full = crossing(t, turned, math.pi), crossing(t, turned, 2 * math.pi)
        for name, tc, n in (("half", half, 0.5), ("full", full, 1.0)):
            if tc is not None:
                print("jeffery: aspect %d, %s turn at gamma t = %.3f: period %.3f vs Jeffery %.3f (%+.2f %%)" %
                      (r_, name, tc, tc / n, T, 100 * (tc / n / T - 1)), flush=True)
        exact = []
        for tt in t:  # Jeffery: tan(angle) = tan(2 pi t / T) / r, unwrapped
            ph = 2 * math.pi * tt / T
            k = math.floor(ph / math.pi + 0.5)
            exact.append(math.atan(math.tan(ph) / r_) + k * math.pi)
        line, = ax.plot(t, [math.degrees(a) for a in turned],
                        label="aspect %d: period %s" % (r_, "%.2f (Jeffery %.2f)" % (full, T) if full else "not reached"))
        ax.plot(t, [math.degrees(a) for a in exact], "--", color=line.get_color(), lw=0.9)
    ax.set_xlabel("gamma t")
    ax.set_ylabel("axis angle from the flow direction (deg)")
    ax.set_title("Prolate spheroids in shear, Re_p 0.01 (dashed: Jeffery 1922)", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "jeffery_orbit.png"), dpi=120)


def time_panels(fig, axes, ylabels, title, name):
    """Two panels against time, the legend in the first, saved into docs/validation/."""
    for ax, label in zip(axes, ylabels):
        ax.set_xlabel("t (s)")
        ax.set_ylabel(label)
    axes[0].legend(fontsize=7)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, name), dpi=120)


def bounce():
    case = os.path.join(root, "cases", "restitution.opts")
    shape = ["-grid_n", "60,60,70", "-particle_shape", "spheroid", "-particle_aspect", 2, "-particle_radius", 0.00119,
             "-particle_axis", "0.5,0,0.866", "-time_final", 0.04, "-output_dt", 0, "-monitor_every", 0]
    variants = (("dry", ["-fluid_off", "-contact_hydro_departure", 0, "-contact_hydro_history", 0, "-lub_model", "none"]),
                ("liquid, no lubrication", ["-lub_model", "none", "-contact_hydro_departure", 0, "-contact_hydro_history", 0]),
                ("liquid, LLCM", []))
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for name, extra in variants:
        out = os.path.join(scratch, "vp_val_shape_bounce_" + name.split(",")[-1].strip().replace(" ", "_"))
        if not (reuse and os.path.exists(os.path.join(out, "particle_0.csv"))):
            subprocess.run(["mpirun", "-n", ranks, vpsolve, "-options_file", case, "-output_dir", out, "-output_overwrite"] +
                           [str(o) for o in shape + extra], check=True, stdout=subprocess.DEVNULL)
        rows = list(csv.DictReader(open(os.path.join(out, "particle_0.csv"))))
        t = [float(r["time"]) for r in rows]
        vz = [float(r["vz"]) for r in rows]
        wy = [float(r["wy"]) for r in rows]
        k = min(range(len(rows)), key=lambda i: float(rows[i]["z"]))  # the deepest point
        vin, vout = min(vz[:k + 1]), max(vz[k:])
        print("bounce: %-24s approach %.3f m/s, rebound %.3f m/s, e = %.3f; spin 2 ms before the deepest point %.1f, at the end %.1f rad/s" %
              (name, vin, vout, vout / -vin, wy[max(k - 10, 0)], wy[-1]), flush=True)
        axes[0].plot(t, vz, label="%s: e %.2f" % (name, vout / -vin))
        axes[1].plot(t, wy, label=name)
    time_panels(fig, axes, ("v_z (m/s)", "w_y (rad/s)"), "Spheroid (aspect 2, tilted 30 deg) onto a wall: steel in oil, St about 150",
                "spheroid_bounce.png")


def hoelzer_sommerfeld_speed(aspect, broadside):
    """Terminal speed (m/s) in the settling case's liquid of the body of volume pi d_v^3 / 6 (d_v
    2.52 mm, density 2000 in 1000, mu 0.02) from the drag correlation of Hoelzer & Sommerfeld 2008
    (Powder Technol. 184, 361; about 10 % scatter): C_D = 8 / (Re sqrt(P)) + 16 / (Re sqrt(S))
    + 3 / (sqrt(Re) S^(3/4)) + 0.42 10^(0.4 (-log10 S)^0.2) / P, S the sphericity, P the crosswise
    sphericity (the equal-volume sphere's cross-section over the projected area); broadside: a
    prolate body's axis horizontal, an oblate one's vertical."""
    dv, rho, mu, g = 2 * 0.001 * 2 ** (1 / 3), 1000.0, 0.02, 9.81
    a = dv / 2 / aspect ** (1 / 3)
    c = aspect * a
    if aspect > 1:
        e = math.sqrt(1 - 1 / aspect ** 2)
        area = 2 * math.pi * a * a * (1 + aspect / e * math.asin(e))
    elif aspect < 1:
        e = math.sqrt(1 - aspect ** 2)
        area = 2 * math.pi * a * a * (1 + (1 - e * e) / e * math.atanh(e))
    else:
        area = math.pi * dv * dv
    S = math.pi * dv * dv / area
    P = (math.pi * dv * dv / 4) / (math.pi * a * (c if aspect > 1 else a) if broadside else math.pi * a * a)
    U = 0.05
    for _ in range(200):  # weight = drag
        Re = rho * U * dv / mu
        cd = 8 / (Re * math.sqrt(P)) + 16 / (Re * math.sqrt(S)) + 3 / (math.sqrt(Re) * S ** 0.75) + \
            0.42 * 10 ** (0.4 * (-math.log10(S)) ** 0.2) / P
        U = math.sqrt((2000 - rho) * g * (math.pi * dv ** 3 / 6) / (0.5 * rho * cd * math.pi * dv * dv / 4))
    return U


def settling():
    """cases/spheroid_settling.opts as shipped (prolate, aspect 2) and with an oblate body of the
    same volume (aspect 1/2, a = 1.587 mm, 4.8 cells thick), both released at 45 degrees, and the
    sphere of that volume."""
    bodies = (("prolate (aspect 2)", "settling", []),
              ("oblate (aspect 1/2)", "settling_oblate", ["-particle_aspect", "0.5", "-particle_radius", "0.001587"]),
              ("sphere", "settling_sphere", ["-particle_aspect", "1", "-particle_radius", "0.00126"]))
    dv = 2 * 0.001 * 2 ** (1 / 3)
    fig, ax = plt.subplots(figsize=(6, 3.8))
    ax2 = ax.twinx()
    speeds = {}
    for k, (name, tag, extra) in enumerate(bodies):
        out = os.path.join(scratch, "vp_val_shape_" + tag)
        if not (reuse and os.path.exists(os.path.join(out, "particle_0.csv"))):
            subprocess.run(["mpirun", "-n", ranks, vpsolve, "-options_file", os.path.join(root, "cases", "spheroid_settling.opts"),
                            "-output_dir", out, "-output_overwrite", "-monitor_every", "0", "-output_dt", "0"] + extra, check=True,
                           stdout=subprocess.DEVNULL)
        rows = list(csv.DictReader(open(os.path.join(out, "particle_0.csv"))))
        t = [float(r["time"]) for r in rows]
        tilt = []
        for r in rows:
            w, x, y, z = (float(r[c]) for c in ("qw", "qx", "qy", "qz"))
            tilt.append(math.degrees(math.acos(min(1.0, abs(1 - 2 * (x * x + y * y))))))
        speed = [-float(r["vz"]) for r in rows]
        top = max(speed)
        if name == "sphere":
            sphere_speed = top
            print("settling sphere: largest speed %.4f m/s (Re %.1f); Hoelzer-Sommerfeld %.4f m/s" %
                  (top, top * dv * 1000 / 0.02, hoelzer_sommerfeld_speed(1, False)), flush=True)
            ax2.plot(t, speed, "C%d--" % k)
            ax.plot([], [], "C%d--" % k, label="sphere: settling speed")
            continue
        broad = (lambda a: a > 80) if "prolate" in name else (lambda a: a < 10)
        kb = next((i for i, a in enumerate(tilt) if broad(a)), None)
        print("settling %s: largest speed %.4f m/s (Re %.1f on d_v), broadside on (axis %s) at t = %s s, axis %.1f degrees from the "
              "vertical at the largest speed; at the end z = %.2f mm, %.1f degrees" %
              (name, top, top * dv * 1000 / 0.02, "past 80 degrees" if "prolate" in name else "within 10 degrees of the vertical",
               "%.3f" % t[kb] if kb is not None else "never", tilt[speed.index(top)], 1000 * float(rows[-1]["z"]), tilt[-1]),
              flush=True)
        speeds[name.split()[0]] = top
        ax.plot(t, tilt, "C%d" % k, label="%s: axis from the vertical" % name)
        ax2.plot(t, speed, "C%d--" % k, label="%s: settling speed" % name)
    for name, aspect in (("prolate", 2), ("oblate", 0.5)):
        measured = speeds[name] / sphere_speed
        expected = hoelzer_sommerfeld_speed(aspect, True) / hoelzer_sommerfeld_speed(1, False)
        print("settling %s broadside on: speed / the sphere's %.3f, Hoelzer-Sommerfeld %.3f (%+.1f %%)" %
              (name, measured, expected, 100 * (measured / expected - 1)), flush=True)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("axis from the vertical (deg)")
    ax2.set_ylabel("settling speed (m/s), dashed")
    ax.set_title("Spheroids of equal volume settling at Re about 10, released at 45 deg", fontsize=10)
    ax.legend(loc="center right", fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "spheroid_settling.png"), dpi=120)


def pair():
    """Two bodies of equal volume (d_v 2.52 mm) released at rest one above the other, 3 d_v apart,
    the upper one 0.2 d_v aside; prolate ones lie broadside (axis along x, their steady attitude).
    The settling case's liquid and grid (d_v/dx 7.6), the box 120 mm tall, the LLCM on (its explicit squeeze
    at the saturation gap 4e-4 a is stable for DEM sub-steps below 3 us: 1000 per fluid step)."""
    dv = 2 * 0.001 * 2 ** (1 / 3)
    bodies = {"prolate spheroids": ("spheroid", 2, 0.001, (0.7071068, 0, 0.7071068, 0)),
              "spheres": ("sphere", 1, dv / 2, (1, 0, 0, 0))}
    fig, axes = plt.subplots(1, 2, figsize=(9.5, 3.8))
    for name, (shape, aspect, a, q) in bodies.items():
        out = os.path.join(scratch, "vp_val_shape_pair_" + shape)
        if not (reuse and os.path.exists(os.path.join(out, "particle_1.csv"))):
            os.makedirs(out, exist_ok=True)
            inp = os.path.join(out, "pair.csv")
            with open(inp, "w") as f:
                f.write("id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz,shape,aspect,qw,qx,qy,qz\n")
                for i, (x, z) in enumerate(((0.006, 0.105), (0.006 + 0.2 * dv, 0.105 + 3 * dv))):
                    f.write("%d,%g,0.006,%g,%g,2000,0,0,0,0,0,0,%s,%g,%g,%g,%g,%g\n" % ((i, x, z, a, shape, aspect) + q))
            # The settling case without its one particle.
            case = [w for line in open(os.path.join(root, "cases", "spheroid_settling.opts"))
                    if line.startswith("-") and not line.startswith("-particle_") for w in line.split()]
            subprocess.run(["mpirun", "-n", ranks, vpsolve] + case +
                           ["-particles_file", inp, "-grid_hi", "0.012,0.012,0.12", "-grid_n", "36,36,360", "-lub_model", "llcm", "-dem_substeps", "1000",
                            "-time_final", "1.5", "-output_dir", out, "-output_overwrite", "-monitor_every", "0", "-output_dt", "0"],
                           check=True, stdout=subprocess.DEVNULL)
        rows = [list(csv.DictReader(open(os.path.join(out, "particle_%d.csv" % i)))) for i in (0, 1)]
        n = min(len(rows[0]), len(rows[1]))
        t = [float(rows[0][k]["time"]) for k in range(n)]
        x = [[[float(rows[i][k][c]) for c in "xyz"] for k in range(n)] for i in (0, 1)]
        dist = [math.dist(x[0][k], x[1][k]) / dv for k in range(n)]
        # Until the leader nears the bottom (1.5 d_v above it): the wall's part left out.
        end = next((k for k in range(n) if x[0][k][2] < 1.5 * dv), n)
        close = sum(t[k + 1] - t[k] for k in range(end - 1) if dist[k] < 1.5)
        kiss = min(range(end), key=lambda k: dist[k])
        tilt = []
        for i in (0, 1):
            w, qx, qy, qz = (float(rows[i][kiss][c]) for c in ("qw", "qx", "qy", "qz"))
            tilt.append(math.degrees(math.acos(min(1.0, abs(1 - 2 * (qx * qx + qy * qy))))))
        passed = next((t[k] for k in range(end) if x[1][k][2] < x[0][k][2]), None)
        print("pair: %-18s closest %.3f d_v at t = %.3f s, %.3f s within 1.5 d_v (to t = %.3f s); the trailing body passes "
              "the leading one %s%s" % (name, dist[kiss], t[kiss], close, t[end - 1],
                                      "at t = %.3f s" % passed if passed is not None else "never",
                                      "; tilts at the closest %.0f / %.0f degrees" % tuple(tilt) if shape == "spheroid" else ""),
              flush=True)
        axes[0].plot(t[:end], dist[:end], label="%s: %.2f s within 1.5 d_v" % (name, close))
        axes[1].plot(t[:end], [(x[1][k][2] - x[0][k][2]) / dv for k in range(end)], label=name)
    axes[0].axhline(1.5, color="0.7", lw=0.8)
    time_panels(fig, axes, ("centre distance / d_v", "height of the trailing body above the leading one / d_v"),
                "Drafting, kissing and tumbling at Re about 10: two prolate spheroids (aspect 2) against two spheres",
                "spheroid_pair.png")



def free_fall(out, aspect, mu, height, final, cells=10):
    """An oblate spheroid of d_v = 4 mm (d_v/dx `cells`), density 1500 in 1000, released at rest 15 mm below
    the top of a box with periodic sides 6 d_v, its axis 5 degrees from the vertical in the x-z plane.
    Returns time, the axis' tilt in that plane (degrees, signed), the drift along x (in d_v), the fall
    speed and the horizontal speed."""
    if not (reuse and os.path.exists(os.path.join(out, "particle_0.csv"))):
        h = 0.004 / cells
        cmd = ["mpirun", "-n", ranks, vpsolve, "-grid_lo", "0,0,0", "-grid_hi", "0.024,0.024,%g" % height,
               "-grid_n", "%d,%d,%d" % (6 * cells, 6 * cells, round(height / h)), "-bc_xlo", "periodic", "-bc_xhi", "periodic",
               "-bc_ylo", "periodic", "-bc_yhi", "periodic", "-fluid_rho", "1000", "-fluid_mu", mu,
               "-gravity", "0,0,-9.81", "-particle_position", "0.012,0.012,%g" % (height - 0.015),
               "-particle_shape", "spheroid", "-particle_radius", "%.7g" % (0.002 / aspect ** (1 / 3)),
               "-particle_aspect", "%.7g" % aspect, "-particle_axis", "0.0872,0,0.9962", "-particle_density", "1500",
               "-contact_tc", "1e-3", "-dem_substeps", "20", "-time_cfl", "0.5", "-time_final", final,
               "-track_particles", "all", "-output_dir", out, "-output_overwrite", "-output_dt", "0",
               "-monitor_every", "0"]
        subprocess.run([str(x) for x in cmd], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(out, "particle_0.csv"))))
    t = [float(r["time"]) for r in rows]
    tilt = []
    for r in rows:
        w, qx, qy, qz = (float(r[c]) for c in ("qw", "qx", "qy", "qz"))
        ax, az = 2 * (qx * qz + w * qy), 1 - 2 * (qx * qx + qy * qy)
        tilt.append(math.degrees(math.atan2(ax if az > 0 else -ax, abs(az))))
    drift = [(float(r["x"]) - 0.012) / 0.004 for r in rows]
    speed = [-float(r["vz"]) for r in rows]
    side = [math.hypot(float(r["vx"]), float(r["vy"])) for r in rows]
    return t, tilt, drift, speed, side


def galileo_mu(ga):
    """The viscosity (Pa s) giving Ga = sqrt((rho_p / rho - 1) g d_v^3) / nu for the bodies of free_fall."""
    return 1000 * math.sqrt(0.5 * 9.81 * 0.004 ** 3) / ga


def zigzag():
    """Aspect 1/3 (a = 2.884 mm, c = 0.961 mm: 4.8 cells thick) at Ga 250 in a box 160 mm tall."""
    t, tilt, drift, speed, _ = free_fall(os.path.join(scratch, "vp_val_shape_zigzag"), 1 / 3, 0.00224, 0.16, 1.2)
    late = [k for k in range(len(t)) if t[k] > 0.5]
    crossings = [t[k] for k in late[1:] if tilt[k - 1] * tilt[k] < 0]
    swing = [max(tilt[k] for k in late), min(tilt[k] for k in late)]
    mean_speed = sum(speed[k] for k in late) / len(late)
    period = 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1) if len(crossings) > 1 else float("nan")
    print("zigzag: after 0.5 s the axis swings between %+.1f and %+.1f degrees, through the vertical at t = %s s (period %.2f s, "
          "Strouhal f d_v / U = %.3f at the mean speed %.3f m/s, Re %.0f); drift along x %.2f d_v at the end" %
          (swing[0], swing[1], ", ".join("%.3f" % c for c in crossings), period, 0.004 / (period * mean_speed), mean_speed,
           mean_speed * 0.004 / 2.24e-6, drift[-1]), flush=True)
    fig, axes = plt.subplots(1, 2, figsize=(9.5, 3.8))
    axes[0].plot(t, tilt, label="axis from the vertical, in the x-z plane (deg)")
    axes[0].axhline(0, color="0.7", lw=0.8)
    axes[1].plot(t, drift, label="x drift")
    time_panels(fig, axes, ("tilt (deg)", "horizontal drift along x / d_v"),
                "Oblate spheroid (aspect 1/3) at Ga 250: a growing zigzag (d_v/dx 10, coarse)", "spheroid_zigzag.png")


# Moriche, Uhlmann & Dusek ("On the clustering of low-aspect-ratio oblate spheroids settling in ambient
# fluid", J. Fluid Mech.): a single oblate spheroid of aspect 1/1.5, density ratio 1.5, falls on a
# steady vertical path at Ga 111 and a steady oblique one at Ga 152.
THRESHOLD = ((111, "steady vertical"), (152, "steady oblique"))


def threshold():
    """Aspect 2/3 (0.76 d_v thick: 7.6 cells at d_v/dx 10, the default; --res N) at Ga 111 and 152 in a box
    260 mm tall, 1 s."""
    cells = res if "--res" in sys.argv else 10
    fig, axes = plt.subplots(1, 2, figsize=(9.5, 3.8))
    for ga, regime in THRESHOLD:
        mu = galileo_mu(ga)
        t, tilt, drift, speed, side = free_fall(os.path.join(scratch, "vp_val_shape_threshold_ga%d_r%d" % (ga, cells)), 2 / 3,
                                                "%.6g" % mu, 0.26, 1.0, cells)
        path = [math.degrees(math.atan2(h, max(v, 1e-9))) for h, v in zip(side, speed)]  # from the vertical
        late = [k for k in range(len(t)) if t[k] > t[-1] - 0.3]
        u = sum(speed[k] for k in late) / len(late)
        angle = math.degrees(math.atan2(sum(side[k] for k in late) / len(late), u))
        print("threshold: Ga %d (%s in Moriche et al.): over the last 0.3 s fall speed %.4f m/s (Re %.0f), path %.2f degrees "
              "from the vertical (from %.2f to %.2f), axis tilt %+.2f to %+.2f degrees; drift along x %.2f d_v" %
              (ga, regime, u, u * 0.004 * 1000 / mu, angle, min(path[k] for k in late), max(path[k] for k in late),
               min(tilt[k] for k in late), max(tilt[k] for k in late), drift[-1]), flush=True)
        axes[0].plot(t, tilt, label="Ga %d (%s)" % (ga, regime))
        axes[1].plot(t, path)
    axes[0].axhline(0, color="0.7", lw=0.8)
    time_panels(fig, axes, ("axis tilt in the x-z plane (deg)", "path angle from the vertical (deg)"),
                "Oblate spheroid (aspect 2/3, density ratio 1.5) either side of the threshold (d_v/dx %d)" % cells,
                "spheroid_threshold.png")


for name, study in (("drag", drag), ("jeffery", jeffery), ("bounce", bounce), ("settling", settling), ("pair", pair),
                    ("zigzag", zigzag), ("threshold", threshold)):
    if what in (name, "all"):
        study()
