#!/usr/bin/python3
"""Collision validation (docs/collisions.md), plots into docs/validation/:
  restitution: e(St) of a steel sphere (d = 3 mm, rho_p/rho 8.34) driven onto a wall, St 5-1000 by
               the viscosity, against e_dry exp(-35/St); the cases' set-up (limit, weighted projection),
               keep and the plain projection at 3 St
  glass_grid:  the light sphere (glass in water) at nominal St 1000 against the grid, d/dx 8 to 24, and the step
  timestep:    e at St 27, 130 and 450 against the fluid step (CFL 0.5 to 1/16), d/dx 8, the case's
               contact (stretched over 10 fluid steps); with --short also a real, short one (50 us)
  gondret:     Gondret's St 27 (d = 6 mm) and St 152 (d = 3 mm) set-ups: gap/d against t/t_ref with the
               measured trajectories (scripts/validation/data), released 3 d above the floor and from
               high enough to arrive at the terminal speed; the first apex against the measured one
  oblique:     dry (Foerster glass, DEM only) and wet (Joseph & Hunt steel and glass in glycerol-water)
               impacts, Psi_2 and Psi_out against Psi_in with the rigid-body lines
  calibration: fixed spheres in Stokes flow at fixed gaps (normal, two spheres at five positions of
               their gap on the grid, parallel, rotating):
               resolved force alone and with LLCM/BLCM against the exact values
  replacement: -lub_coupling add against replace at d/dx 12 (normal, the pair at three positions of its
               gap on the grid along an axis and along a diagonal, parallel, rotation) against the
               exact values; the patch's depth; the replacement's gap and blend at eps 0.2
  confinement: the normal mode's and the pair's resolved force in boxes of 4 (the study's) to 12 d
  sensitivity: e at St 27 and 152 against grid, activation, saturation, R0, t_c, sub-steps and the
               mask's stiffness (lambda x0.5, x2)
  pair:        two spheres colliding head-on: e with and without the departure, and against the mask's
               stiffness
  harada:      the e(St) set-up in the Harada point-particle model (build/harada: drag, lubrication,
               added mass with its wall images, a real contact), with and without the Basset history
               force, and with it left out from the contact to a gap of d/16 (the departure's window
               at d/dx 16): what the history of the boundary layer takes from a rebound, and where it
               takes it
  inertia:     e at St 20, 30, 60 and 100 (d/dx 12) with and without the liquid's O(Re) inertia in the
               gap (-lub_inertia)
usage: collisions.py [restitution|glass_grid|timestep|gondret|oblique|calibration|replacement|confinement|sensitivity|pair|harada|inertia|all] [--res N] [--cfl C] [--release H] [--width W] [--reuse] [--fine]
                     [--cases-only] [--roughness] [--no-departure] [--no-history] [--short]
  --res N: grid (d/dx) of the restitution and Gondret runs (default 16)
  --cfl C: the restitution runs' CFL at the release speed (default 0.5; 0.25 at St 1000 in any case)
  --release H: restitution's spheres released H d above the floor (default 3, at 0.585 m/s); above 3 at
               their terminal speed (a drag curve), arriving as settling spheres do (nominal St >= 20);
               glass at nominal St 500 (Re 1100) needs --cfl 0.25 (at 0.5 the health check stops it)
  --width W: the Gondret box's width in d (default 6)
  --cases-only: restitution with the cases' set-up only (not keep and the plain projection)
  --roughness: restitution with the cases' set-up and the same with Gondret's reported roughness (5e-5 d)
               (figure restitution_roughness.png)
  --no-departure: restitution with the cases' set-up (-contact_hydro_departure 1), the same without it
               (-contact_hydro_departure 0), and a glass sphere in water (St 100-1000) both ways; the other
               wet studies without it (their runs and figures named ..._nodeparture)
  --no-history: restitution with the cases' set-up (-contact_hydro_history 1: the Basset history force
               while the resolved force is excluded) and the same without it, steel and glass in water
  --short: timestep also with the short contact
  --reuse: read runs already in $VP_SCRATCH/vp_col_* (/tmp unless set) instead of running them again (a run's name comes from
           its options, not from the code: after a change of the model, remove the runs it touches)"""
import csv, math, os, subprocess, sys
from common import plt, root, ranks, vpsolve, harada as harada_bin, scratch, outdir, chosen_study

reuse = "--reuse" in sys.argv
res = int(sys.argv[sys.argv.index("--res") + 1]) if "--res" in sys.argv else 16
CFL = float(sys.argv[sys.argv.index("--cfl") + 1]) if "--cfl" in sys.argv else 0.5  # the restitution runs' largest CFL
E_DRY = 0.97
HYDRO = "limit"  # -contact_hydro of the cases and of the studies that do not compare it (the default)
STEEL, RHO_F, D3 = 7800.0, 935.0, 0.003
U_RELEASE = 0.585  # m/s: the e(St) study's release speed (Gondret's St 152 impact speed)
GAP_RELEASE = 3  # d above the floor: where the e(St) study releases at U_RELEASE (higher: settling spheres)
RELEASE = int(sys.argv[sys.argv.index("--release") + 1]) if "--release" in sys.argv else GAP_RELEASE  # restitution's release gap (d)
SETTLING = RELEASE > GAP_RELEASE


def study_mu(st, d=D3, rho_p=STEEL):
    """Viscosity (Pa s) that gives the nominal St to a sphere of diameter d, density rho_p at U_RELEASE."""
    return rho_p * U_RELEASE * d / (9 * st)


def run(out, *opts, case="restitution.opts", np=None):
    """Runs vpsolve (unless --reuse finds the run) and returns the tracked particle's rows."""
    done = os.path.join(out, "particle_0.csv")
    if not (reuse and os.path.exists(done)):
        subprocess.run(["rm", "-rf", out], check=True)
        cmd = ["mpirun", "-n", str(np or ranks), vpsolve]
        if case != "none":  # first: the options after it override the case's
            cmd += ["-options_file", os.path.join(root, "cases", case)]
        cmd += ["-output_dir", out, "-output_overwrite", "-monitor_every", "0", "-output_every", "0", "-output_dt", "0", "-track_particles", "all"]
        subprocess.run(cmd + [str(o) for o in opts], check=True, stdout=subprocess.DEVNULL, cwd=root)
    return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(done))]


def crossing(g, v, i, level):
    """The fraction of row i-1 -> i at which the gap series g passes `level`, and v interpolated there."""
    w = (g[i - 1] - level) / (g[i - 1] - g[i])
    return w, v[i - 1] + w * (v[i] - v[i - 1])


# Where the speeds are read, as the experiments read them (Joseph et al. 2001, Gondret et al. 2002): the
# approach speed before the wall's influence (a gap of 1 d; St from it), the rebound speed after the
# contact, where the gap passes 0.1 d on the way out (outside the film, which takes the speed the
# contact returns within micrometres). At 0.1 d on the way in the wall has already slowed the sphere
# by 10-20 %.
GAP_APPROACH, GAP_REBOUND = 1.0, 0.1


def impact(rows, a, axis="z", gap_in=GAP_APPROACH, gap_out=GAP_REBOUND):
    """Impact on the floor z = 0: the approach speed as the gap passes gap_in d on the way down, the
    rebound speed as it passes gap_out d on the way up after the first contact (0 when it never rises
    that far: no rebound). Returns (u_in, u_out, touched); u_in is None for a release below gap_in."""
    d = 2 * a
    g = [(r[axis] - a) / d for r in rows]
    v = [r["v" + axis] for r in rows]
    down = next((i for i in range(1, len(rows)) if g[i - 1] > gap_in >= g[i]), None)
    # The first contact: a row in contact or, for a contact shorter than a fluid step, the first row
    # moving away from the wall after the approach.
    first = None if down is None else next((i for i in range(down, len(rows)) if g[i] <= 2e-4 or v[i] >= 0), None)
    u_in = None if down is None else -crossing(g, v, down, gap_in)[1]
    if down is None or first is None:
        return u_in, 0.0, first is not None
    up = next((i for i in range(first + 1, len(rows)) if g[i - 1] < gap_out <= g[i]), None)
    return u_in, (crossing(g, v, up, gap_out)[1] if up is not None else 0.0), True


def departure(rows, a, mu, rho_p=STEEL):
    """The rebound's way out, from the end of the first fluid step that ends out of contact to the gap
    0.1 d: the sphere's speed at both, the resolved force's impulse over those steps (over the sphere's
    mass, m/s) and the loss that rigid-sphere lubrication theory gives over the same gaps (Brenner's
    resistance, quasi-steady)."""
    d = 2 * a
    g = [(r["z"] - a) / d for r in rows]
    c0 = next((i for i in range(1, len(rows)) if g[i] <= 0), None)
    c1 = None if c0 is None else next((i for i in range(c0, len(rows)) if g[i] > 0), None)
    up = None if c1 is None else next((i for i in range(c1 + 1, len(rows)) if g[i - 1] < 0.1 <= g[i]), None)
    if up is None:  # no contact, or no rebound to 0.1 d
        return None
    w, u_out = crossing(g, [r["vz"] for r in rows], up, 0.1)
    m = rho_p * 4 / 3 * math.pi * a ** 3
    impulse = sum(rows[i]["fz"] * (rows[i]["time"] - rows[i - 1]["time"]) for i in range(c1 + 1, up)) / m
    impulse += w * rows[up]["fz"] * (rows[up]["time"] - rows[up - 1]["time"]) / m
    theory = 6 * math.pi * mu * a * a / m * brenner_integral(2 * g[c1], 0.2)
    return g[c1], rows[c1]["vz"], u_out, impulse, theory


def approach_rate(rows, a, rho_p, rho_f, gap=GAP_APPROACH):
    """The approach speed's rate of change where the gap passes `gap` d, over the buoyant gravity
    g' = g (1 - rho_f / rho_p): 0 for a sphere arriving at its terminal speed, negative while the
    liquid still slows it (released too fast or too low)."""
    g = [(x["z"] - a) / (2 * a) for x in rows]
    i = next(i for i in range(1, len(rows)) if g[i - 1] > gap >= g[i])
    j = max(0, i - 5)
    return -(rows[i]["vz"] - rows[j]["vz"]) / (rows[i]["time"] - rows[j]["time"]) / (9.81 * (1 - rho_f / rho_p))


def brenner_integral(lo, hi, resistance=None, n=2000):
    """The integral of a squeeze resistance F / (6 pi mu a V) (Brenner's, a sphere at a wall, unless
    given) over the gap eps = h/a from lo to hi: a rigid sphere's velocity loss over those gaps is
    6 pi mu a^2 / m times it. Midpoint rule in ln(eps): the integral of lambda d eps is that of
    lambda eps d ln(eps)."""
    resistance = resistance or brenner
    eps = [lo * (hi / lo) ** ((k + 0.5) / n) for k in range(n)]
    return sum(resistance(e) * e for e in eps) * math.log(hi / lo) / n


SHORT = ["-contact_tc_steps", 0, "-contact_tc", 5e-5]  # a real impact's duration, resolved by the sub-steps


def terminal_speed(rho_p, rho_f, mu, d, g=9.81):
    """A sphere's settling speed from the standard drag curve (Schiller-Naumann with a Newton-regime
    term; Clift, Grace & Weber): where a sphere released from high enough arrives."""
    u = 0.1
    for _ in range(200):  # fixed point: converges in a few tens of iterations for Re 0.1-1e4
        re = rho_f * u * d / mu
        cd = 24 / re * (1 + 0.15 * re ** 0.687) + 0.42 / (1 + 42500 / re ** 1.16)
        u = math.sqrt(4 / 3 * g * d * (rho_p / rho_f - 1) / cd)
    return u


def restitution_run(st, hydro, r=None, extra=(), d=D3, label=None, cfl=0.5, rho_p=STEEL, rho_f=RHO_F, release=GAP_RELEASE):
    """Sphere of diameter d (steel in the cases' liquid unless rho_p, rho_f say otherwise) at nominal St
    (viscosity from St with u = 0.585 m/s) in a 6d x 6d x (release + 4)d box, released `release` d above
    the floor at 0.585 m/s (3 d) or, released higher, at its terminal speed (terminal_speed), so that it
    arrives as a settling sphere does. Returns (St at impact, e, u_in, the tracked rows)."""
    r = r or res
    a = d / 2
    mu = study_mu(st, d, rho_p)
    settling = release > GAP_RELEASE
    u = terminal_speed(rho_p, rho_f, mu, d) if settling else U_RELEASE
    h = d / r
    n = 6 * r
    dt = cfl * h / u  # CFL at the release speed
    others = [str(o) for o in extra if o not in PLAIN]  # the run's options beyond the plain projection
    tag = ("_plain" if PLAIN[0] in extra else "") + "".join(others).replace("-", "_")
    tag += "" if (rho_p, rho_f) == (STEEL, RHO_F) else "_rp%g_rf%g" % (rho_p, rho_f)
    tag += "" if cfl == default_cfl(st) else "_cfl%g" % cfl
    tag += "_h%g" % release if settling else ""
    out = os.path.join(scratch, "vp_col_%s" % (label or "e_st%g_%s%s_r%d_d%g" % (st, hydro, tag, r, d)))
    rows = run(out, "-grid_n", "%d,%d,%d" % (n, n, (release + 4) * r), "-grid_hi", "%g,%g,%g" % (6 * d, 6 * d, (release + 4) * d),
               "-particle_position", "%g,%g,%g" % (3 * d, 3 * d, (release + 0.5) * d), "-particle_radius", a, "-particle_velocity", "0,0,%g" % -u,
               "-fluid_mu", mu, "-time_dt", dt, "-time_final", ((20 if st <= 20 else 12) + release - GAP_RELEASE) * d / u + 20 * dt, "-dem_substeps", 200,
               "-particle_density", rho_p, "-fluid_rho", rho_f,
               "-contact_hydro", hydro, "-health_overlap_max", 0.3, "-health_cfl_max", 1.5, *extra)
    u_in, u_out, touched = impact(rows, a)
    if u_in is None or not touched:
        return None
    return rho_p * u_in * d / (9 * mu), u_out / u_in, u_in, rows


ST_LIST = [5, 20, 30, 40, 70, 100, 152, 300, 500, 1000]


def default_cfl(st):
    """CFL of the e(St) runs at the release speed: 0.5, and 0.25 at St 1000 (impact Re about 1040), where the
    liquid squeezed out at the impact, advected by the central scheme, passes the health check's CFL
    1.5 at 0.5; the rebound converges in the step (d/dx 12: 0.890 / 0.889 at CFL 0.25 / 0.125)."""
    return 0.25 if st >= 1000 else 0.5


def study_cfl(st):
    """The restitution runs' CFL: the default, or --cfl where that is smaller."""
    return min(CFL, default_cfl(st))

PLAIN = ["-penalization_projection", "plain"]  # the cases use weighted
# The cases replace the excluded resolved force by the Basset history force (-contact_hydro_history 1)
# while a sphere departs; --no-history measures e(St) without it.
NO_HISTORY = ["-contact_hydro_history", 0]
# The cases leave a wall after an impact with the departure (docs/collisions.md, "The departure after an
# impact"); --no-departure measures the studies without it (restitution: both ways), and so without
# the history force, which acts while a sphere departs.
NO_DEPARTURE = ["-contact_hydro_departure", 0] + NO_HISTORY
WITHOUT = NO_DEPARTURE if "--no-departure" in sys.argv else []
SUFFIX = "_nodeparture" if WITHOUT else ""
# The published recipes (docs/collisions.md, "Choice of the model"): Costa et al. 2015, the resolved force
# excluded only beyond the buoyant-weight overlap, the film saturated at 1e-3 a above the contact gap
# and acting down to contact, the contact over 8 fluid steps; Rettinger & Rude 2022, the resolved force
# kept through a shallow contact (the cases' 2 fluid steps: about 0.02 d).
COSTA = NO_DEPARTURE + ["-lub_saturation", 1e-3, "-contact_tc_steps", 8]
RETTINGER = NO_DEPARTURE
# The seed's local replacement (-lub_coupling replace, docs/lubrication.md), with the cases' set-up
# and with the resolved force kept through the contact.
REPLACE = ["-lub_coupling", "replace"]
MODEL_ST = [20, 40, 100, 300, 1000]
GLASS, WATER = 2500.0, 1000.0  # a light sphere: glass in water
GLASS_ST = [100, 300, 500, 1000]
# Gondret et al.'s spheres: a roughness of 1e-4 a reported (as cited by Biegert et al. 2017); the
# cases keep the seed's 2e-4 d (docs/collisions.md).
ROUGH_GONDRET = ["-contact_roughness", 5e-5]


def restitution_axes(ax):
    """The experiments' curve, its pass band and rigid-sphere lubrication theory on e/e_dry-St axes."""
    s = [10 ** (k / 50) for k in range(0, 151)]
    ax.semilogx(s, [math.exp(-35 / x) for x in s], "k-", label="exp(-35/St) (Legendre et al.)")
    ax.fill_between(s, [max(0, math.exp(-35 / x) - 0.1) for x in s], [math.exp(-35 / x) + 0.1 for x in s],
                    color="0.85", label="pass band +-0.1 (St 20-1000)")
    # Rigid-sphere lubrication theory inside 0.1 d: the same velocity loss u_in L / St on the way in and
    # out, L the integral of Brenner's resistance from 0.1 d to the roughness (2e-4 d).
    L = brenner_integral(4e-4, 0.2)
    ax.semilogx(s, [max(0.0, 1 - (1 + 1 / E_DRY) * L / x) for x in s], "k--", lw=1,
                label="lubrication theory inside 0.1 d, rigid sphere (L = %.2f)" % L)


def restitution():
    fig, ax = plt.subplots(figsize=(10, 4.4))
    restitution_axes(ax)
    failures = []
    steel = (STEEL, RHO_F)
    sets = ((HYDRO, [], "s", ST_LIST, steel), ("keep", NO_DEPARTURE, "o", [40, 152, 500], steel),  # (the departure needs limit)
            (HYDRO, PLAIN, "^", [40, 152, 500], steel))
    if "--cases-only" in sys.argv:  # the cases' set-up alone
        sets = sets[:1]
    if SETTLING:  # settling spheres: the cases' set-up, steel and glass in water
        sets = (sets[0], (HYDRO, [], ">", GLASS_ST, (GLASS, WATER)))
    if "--roughness" in sys.argv:  # the cases' set-up and the same with Gondret's reported roughness
        sets = (sets[0], (HYDRO, ROUGH_GONDRET, "D", ST_LIST, steel))
    if WITHOUT:  # the cases' set-up with and without the departure, steel and glass in water
        sets = (sets[0], (HYDRO, WITHOUT, "v", ST_LIST, steel), (HYDRO, [], ">", GLASS_ST, (GLASS, WATER)),
                (HYDRO, WITHOUT, "<", GLASS_ST, (GLASS, WATER)))
    if "--models" in sys.argv:  # the cases' set-up (steel, glass) against the published recipes and the replacement
        sets = (sets[0], (HYDRO, [], ">", GLASS_ST, (GLASS, WATER)), (HYDRO, COSTA, "D", MODEL_ST, steel),
                ("keep", RETTINGER, "o", MODEL_ST, steel), (HYDRO, REPLACE, "v", ST_LIST, steel),
                (HYDRO, REPLACE, "P", GLASS_ST, (GLASS, WATER)), ("keep", RETTINGER + REPLACE, "<", ST_LIST[1:], steel))
    if "--no-history" in sys.argv:  # the cases' set-up with and without the history force, steel and glass in water
        sets = (sets[0], (HYDRO, NO_HISTORY, "D", ST_LIST, steel), (HYDRO, [], ">", GLASS_ST, (GLASS, WATER)),
                (HYDRO, NO_HISTORY, "<", GLASS_ST, (GLASS, WATER)))
    for hydro, extra, mark, st_list, (rho_p, rho_f) in sets:
        cases = ", departure 1 cell, history force"  # what the cases add to -contact_hydro limit
        name = hydro + (cases + ", plain projection" if extra == PLAIN else cases + ", roughness 5e-5 d" if extra == ROUGH_GONDRET else
                        ", no history force" if extra == NO_HISTORY else
                        ", Costa et al. 2015's recipe" if extra == COSTA else
                        cases + ", local replacement" if extra == REPLACE else
                        ", local replacement" if extra == RETTINGER + REPLACE else
                        ", no departure" if extra == NO_DEPARTURE and hydro == HYDRO else
                        cases if hydro == HYDRO else "") + (", glass in water" if rho_p == GLASS else "")
        pts = []
        for st in st_list:
            if SETTLING and st < 20:  # settling at St below 10: no rebound, as released at 3 d
                continue
            label = "e_st%g_rough_r%d" % (st, res) if extra == ROUGH_GONDRET else None
            r = restitution_run(st, hydro, extra=extra, label=label, cfl=study_cfl(st), rho_p=rho_p, rho_f=rho_f, release=RELEASE)
            if r is None:
                print("restitution: St %g %s: no contact within the run (a creeping approach: no rebound)" % (st, name), flush=True)
                continue
            sti, e, u_in, _ = r
            pts.append((sti, e / E_DRY))
            ok = "" if not 20 <= sti <= 1000 else (" ok" if abs(e / E_DRY - math.exp(-35 / sti)) <= 0.1 else " OUT")
            print("restitution: -contact_hydro %-24s nominal St %4g: u(1 d) %.4f m/s (its rate of change %+.2f g'), St %.1f, e %.3f, "
                  "e/e_dry %.3f, exp(-35/St) %.3f%s" % (name, st, u_in, approach_rate(r[3], D3 / 2, rho_p, rho_f), sti, e, e / E_DRY,
                                                        math.exp(-35 / sti), ok), flush=True)
            out = departure(r[3], D3 / 2, study_mu(st, D3, rho_p), rho_p) if hydro == HYDRO and extra in ([], NO_DEPARTURE, NO_HISTORY) else None
            if out:
                print("restitution: departure at nominal St %4g: %.3f m/s at gap %.3f d (the first step out of contact), "
                      "%.3f at 0.1 d: loss %.3f (lubrication theory %.3f); resolved force's impulse %+.3f m/s" %
                      (st, out[1], out[0], out[2], out[1] - out[2], out[4], out[3]), flush=True)
            if hydro == HYDRO and not extra and rho_p == STEEL and abs(e / E_DRY - math.exp(-35 / sti)) > 0.1 and 20 <= sti <= 1000:
                failures.append(st)
        ax.semilogx([p[0] for p in pts], [p[1] for p in pts], mark, mfc="none", label="vpsolve, -contact_hydro %s" % name)
    ax.set_xlabel("St = rho_p u_in d / (9 mu)  (u_in at gap 1 d)")
    ax.set_ylabel("e / e_dry")
    ax.set_title("Restitution on a wall (steel in the cases' liquid%s), d/dx = %d%s" %
                 (", glass in water" if WITHOUT or "--no-history" in sys.argv or "--models" in sys.argv or SETTLING else "", res,
                  (", CFL %g" % CFL if CFL < 0.5 else "") + (", released %d d above at the terminal speed" % RELEASE if SETTLING else "")), fontsize=9)
    print("restitution: -contact_hydro %s: %s" % (HYDRO, "all in the band (St 20-1000)" if not failures else
                                                 "outside the band at nominal St %s" % failures), flush=True)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.set_ylim(-0.05, 1.1)
    fig.tight_layout()
    name = ("restitution_departure.png" if WITHOUT else "restitution_history.png" if "--no-history" in sys.argv else
            "restitution_roughness.png" if "--roughness" in sys.argv else "restitution_models.png" if "--models" in sys.argv else
            "restitution_stokes.png")
    if CFL < 0.5:
        name = name.replace(".png", "_cfl%g.png" % CFL)
    if SETTLING:
        name = name.replace(".png", "_h%d.png" % RELEASE)
    fig.savefig(os.path.join(outdir, name), dpi=120)


def glass_grid():
    """The light sphere (glass in water) at nominal St 1000 (impact St 526 at d/dx 8 to 641 at 24), the cases'
    set-up at the study's CFL 0.25, against the grid, d/dx 8 to 24, and against the fluid step (CFL 0.125
    and 1/16 at d/dx 8, 0.125 at d/dx 20): where its rebound settles against the pass band."""
    grids = (8, 12, 16, 20, 24)
    runs = [(r, study_cfl(1000)) for r in grids] + [(8, 0.125), (8, 0.0625), (20, 0.125)]
    pts = {}
    for r, cfl in runs:
        label = None if cfl == study_cfl(1000) else "glass_dt_r%d_cfl%g" % (r, cfl)
        out = restitution_run(1000, HYDRO, r=r, cfl=cfl, rho_p=GLASS, rho_f=WATER, label=label)
        if out is None:
            print("glass_grid: d/dx %2d, CFL %g: no contact within the run" % (r, cfl), flush=True)
            continue
        sti, e = out[0], out[1] / E_DRY
        pts.setdefault(cfl, []).append((r, e - math.exp(-35 / sti)))
        print("glass_grid: d/dx %2d, CFL %6g: impact St %.1f, e/e_dry %.4f, exp(-35/St) %.4f, difference %+.4f" %
              (r, cfl, sti, e, math.exp(-35 / sti), pts[cfl][-1][1]), flush=True)
    fig, ax = plt.subplots(figsize=(6, 3.8))
    ax.axhspan(-0.1, 0.1, color="0.85", label="pass band +-0.1")
    for (cfl, p), mark in zip(sorted(pts.items(), reverse=True), ("o-", "s", "^")):
        ax.plot([x[0] for x in p], [x[1] for x in p], mark, mfc="none", label="vpsolve, the cases' set-up, CFL %g" % cfl)
    ax.set_xlabel("d/dx")
    ax.set_ylabel("e/e_dry - exp(-35/St)")
    ax.set_xticks(grids)
    ax.set_ylim(-0.18, -0.08)  # the band's lower edge is the question
    ax.set_title("Glass in water (rho_p/rho 2.5), nominal St 1000, against grid and step", fontsize=9)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "restitution_glass_grid.png"), dpi=120)


def harada_run(st, history, window=0.0):
    """The e(St) study's sphere and release (3 d above the floor at U_RELEASE, gravity) in the Harada
    point-particle model, the wall y = 0, with a real contact (10 us, dry restitution E_DRY) and the
    cases' roughness. Returns (St at impact, e) as the resolved study measures them, or None."""
    a, d = D3 / 2, D3
    mu = study_mu(st)
    out = os.path.join(scratch, "vp_col_harada_st%g_history%d" % (st, history) + ("_window%g" % window if window else ""))
    tc = 1e-5
    if not (reuse and os.path.exists(os.path.join(out, "particle_0.csv"))):
        subprocess.run([str(o) for o in [harada_bin, "-output_dir", out, "-fluid_rho", RHO_F,
                        "-fluid_mu", mu, "-particle_density", STEEL, "-particle_radius", a,
                        "-particle_position", "0,%r,0" % (a + 3 * d), "-particle_velocity", "0,%r,0" % -U_RELEASE,
                        "-gravity", "0,-9.81,0", "-contact_restitution", E_DRY, "-contact_roughness", 2e-4,
                        "-contact_tc", tc, "-time_dt", tc / 40, "-time_final", 0.06, "-output_every", 1,
                        "-harada_history", int(history), "-harada_history_window", window]], check=True,
                       stdout=subprocess.DEVNULL)
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(os.path.join(out, "particle_0.csv")))]
    u_in, u_out, touched = impact(rows, a, axis="y")
    if u_in is None or not touched:
        return None
    return STEEL * u_in * d / (9 * mu), u_out / u_in


def harada():
    fig, ax = plt.subplots(figsize=(8, 4))
    restitution_axes(ax)
    window = D3 / 16  # the departure's window at d/dx 16: one cell
    for history, win, mark in ((True, 0.0, "o"), (True, window, "s"), (False, 0.0, "x")):
        name = "off" if not history else "on, left out from the contact to d/16" if win else "on"
        pts = []
        for st in ST_LIST:
            r = harada_run(st, history, win)
            if r is None:
                print("harada: St %g: no contact (a creeping approach)" % st, flush=True)
                continue
            sti, e = r
            pts.append((sti, e / E_DRY))
            print("harada: history %-39s nominal St %4g: St %.1f, e/e_dry %.3f, exp(-35/St) %.3f, difference %+.3f" %
                  (name, st, sti, e / E_DRY, math.exp(-35 / sti), e / E_DRY - math.exp(-35 / sti)), flush=True)
        ax.semilogx([p[0] for p in pts], [p[1] for p in pts], mark, mfc="none", label="Harada model, Basset history %s" % name)
    ax.set_xlabel("St = rho_p u_in d / (9 mu)  (u_in at gap 1 d)")
    ax.set_ylabel("e / e_dry")
    ax.set_title("The e(St) set-up in the Harada point-particle model (steel, d = 3 mm)", fontsize=9)
    ax.legend(fontsize=7, loc="lower right")
    ax.set_ylim(-0.05, 1.1)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "restitution_harada.png"), dpi=120)


def timestep():
    """e at nominal St 40, 152 and 500 (impact St about 27, 130 and 450), d/dx 8, against the fluid
    step: the case's contact, stretched over 10 fluid steps (its duration shrinks with the step); with
    --short also a real, short contact (50 us, resolved by the sub-steps, shorter than any fluid step)."""
    cfls = (0.5, 0.25, 0.125, 0.0625)
    contacts = (("stretched", [], "o-"),) + ((("short", SHORT, "s--"),) if "--short" in sys.argv else ())
    fig, ax = plt.subplots(figsize=(8.5, 4.2))
    for k, st in enumerate((40, 152, 500)):
        for name, opts, mark in contacts:
            pts = []
            for cfl in cfls:
                out = restitution_run(st, HYDRO, r=8, cfl=cfl, extra=opts + WITHOUT, label="dt_%s_st%d_cfl%g%s" % (name, st, cfl, SUFFIX))
                print("timestep: %-9s contact, nominal St %3d, CFL %6g: impact St %.1f, e/e_dry %.3f (exp(-35/St) %.3f)" %
                      (name, st, cfl, out[0], out[1] / E_DRY, math.exp(-35 / out[0])) if out else
                      "timestep: %s contact, St %d, CFL %g: no contact" % (name, st, cfl), flush=True)
                if out:
                    pts.append((cfl, out[1] / E_DRY, out[0]))
            ax.semilogx([p[0] for p in pts], [p[1] for p in pts], mark, color="C%d" % k, mfc="none",
                        label="St %.0f, %s contact" % (pts[-1][2], name))
        curve = math.exp(-35 / pts[-1][2])
        ax.axhspan(curve - 0.1, curve + 0.1, color="C%d" % k, alpha=0.12)
    ax.set_xlabel("CFL of the fluid step at the release speed (u dt / h)")
    ax.set_ylabel("e / e_dry")
    ax.set_title("Rebound against the fluid step, d/dx 8 (bands: exp(-35/St) +- 0.1)", fontsize=9)
    ax.invert_xaxis()
    ax.set_ylim(0, 1)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "restitution_timestep%s.png" % SUFFIX), dpi=120)


# --- Gondret's set-ups: trajectories ------------------------------------------------------------------
GONDRET = {  # St: (d, rho_p/rho, nu, u_in, final time after the first contact (s): the experiment's rebounds,
    #      a release gap (in d) from which the sphere regains most of its terminal speed by 1 d); steel rho_p 7800
    27: (0.006, 8.083, 1.036e-4, 0.518, 0.06, 15),
    152: (0.003, 8.342, 1.070e-5, 0.585, 0.18, 15),
}
APEX_BAND = 0.25  # the first apex within 25 % of the experiment's
# Released 3 d above the floor at u_in, the sphere meets liquid at rest: the added mass and the history
# force take about 13 % (St 27) and 11 % (St 152) of its speed by a gap of 1 d, whatever the box's width
# (6 or 12 d: 0.4 % apart). Released higher it regains most of its terminal speed, as the experiments'
# spheres arrive.
width = int(sys.argv[sys.argv.index("--width") + 1]) if "--width" in sys.argv else 6


def gondret_run(st, hydro, r=None, extra=(), release=3):
    r = r or res
    d, ratio, nu, u, after, _ = GONDRET[st]
    rho = STEEL / ratio
    h = d / r
    dt = 0.5 * h / u
    tall = max(10, release + 5)
    out = os.path.join(scratch, "vp_col_gondret_st%d_%s_r%d" % (st, hydro, r) + ("_w%d" % width if width != 6 else "") +
                       ("_h%d" % release if release != 3 else "") + "".join(str(x) for x in extra).replace("-", "_"))
    rows = run(out, "-grid_n", "%d,%d,%d" % (width * r, width * r, tall * r), "-grid_hi", "%g,%g,%g" % (width * d, width * d, tall * d),
               "-particle_position", "%g,%g,%g" % (width / 2 * d, width / 2 * d, (release + 0.5) * d), "-particle_radius", d / 2,
               "-particle_velocity", "0,0,%g" % -u, "-fluid_rho", rho, "-fluid_mu", rho * nu, "-time_dt", dt,
               "-time_final", release * d / u + after, "-dem_substeps", 200, "-contact_hydro", hydro, *extra)
    return d, rows


def gondret_measured(st):
    """The experiment's trajectory (time from the first contact, gap), scripts/validation/data."""
    f = os.path.join(root, "scripts", "validation", "data", "gondret2002_st%d.csv" % st)
    rows = list(csv.DictReader(line for line in open(f) if not line.startswith("#")))
    return [float(x["time"]) for x in rows], [float(x["gap"]) for x in rows]


def measured_rebound(t, g, d):
    """The rebound speed of a measured trajectory (s, m) where the gap passes GAP_REBOUND d on the way out:
    the slope of the segment that crosses it (the points lie about 2 ms apart)."""
    k = next(i for i in range(1, len(t)) if t[i - 1] >= 0 and g[i - 1] < GAP_REBOUND * d <= g[i])
    return (g[k] - g[k - 1]) / (t[k] - t[k - 1])


def rebound_apexes(t, g, lowest=0.01):
    """(t, g) of each rebound's highest point: the local maxima of the gap after the first contact (t > 0)
    higher than `lowest` (a resting sphere's film and the measured points' scatter lie below it)."""
    return [(t[i], g[i]) for i in range(1, len(g) - 1) if t[i] > 0 and g[i] > lowest and g[i - 1] < g[i] >= g[i + 1]]


def gondret(hydro=HYDRO):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for ax, st in zip(axes, (27, 152)):
        d = GONDRET[st][0]
        tref = math.sqrt(d / 9.81)
        te, ge = gondret_measured(st)
        u_exp = measured_rebound(te, ge, d)
        print("gondret: St %d measured: rebound speed at %g d %.3f m/s, e %.2f over u_in %.3f, e/e_dry %.2f (exp(-35/St) %.3f)" %
              (st, GAP_REBOUND, u_exp, u_exp / GONDRET[st][3], GONDRET[st][3], u_exp / GONDRET[st][3] / E_DRY, math.exp(-35 / st)))
        te, ge = [x / tref for x in te], [x / d for x in ge]
        exp = rebound_apexes(te, ge)
        ax.plot(te, ge, "o", mfc="none", color="k", ms=4, label="Gondret et al. 2002 (measured)")
        for release in (3, GONDRET[st][5]):
            d, rows = gondret_run(st, hydro, extra=WITHOUT, release=release)
            u_in, u_out, _ = impact(rows, d / 2)
            first = next(i for i, x in enumerate(rows) if (x["z"] - d / 2) / d <= 2e-4)
            t0 = rows[first]["time"]
            ts = [(x["time"] - t0) / tref for x in rows]
            gs = [(x["z"] - d / 2) / d for x in rows]
            ax.plot(ts, gs, "-", label="vpsolve d/dx %d, released %d d above at u_in" % (res, release))
            sim = rebound_apexes(ts, gs)
            st_in = GONDRET[st][1] * u_in * d / (9 * GONDRET[st][2])  # St of u(1 d): (rho_p/rho) u d / (9 nu)
            ok = sim and exp and abs(sim[0][1] / exp[0][1] - 1) <= APEX_BAND
            print("gondret: St %d (-contact_hydro %s, d/dx %d, box %d d wide, released %d d above): u(1 d) %.4f m/s (experiment's u_in %.3f), e %.3f, "
                  "e/e_dry %.3f (exp(-35/St) %.3f at the approach St %.1f); apexes gap/d at t/t_ref: %s; measured %s; "
                  "first apex %s: %s" %
                  (st, hydro, res, width, release, u_in, GONDRET[st][3], u_out / u_in, u_out / u_in / E_DRY, math.exp(-35 / st_in), st_in,
                   ", ".join("%.3f at %.2f" % (g, t) for t, g in sim[:3]) or "none",
                   ", ".join("%.3f at %.2f" % (g, t) for t, g in exp[:3]),
                   "%+.0f %%" % (100 * (sim[0][1] / exp[0][1] - 1)) if sim else "none",
                   "ok (within %d %%)" % (100 * APEX_BAND) if ok else "SHORT"), flush=True)
        ax.axhline(0, color="k", lw=0.5)
        ax.set_title("Gondret St %d: d = %g mm, t_ref = sqrt(d/g) = %.4f s" % (st, d * 1e3, tref), fontsize=9)
        ax.set_xlabel("(t - t_contact) / t_ref")
        ax.set_ylabel("gap / d")
        ax.set_xlim(left=-1.2)
        ax.set_ylim(-0.05, 1.5 * exp[0][1])
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "gondret_trajectories%s.png" % SUFFIX), dpi=120)


# --- Oblique impacts ------------------------------------------------------------------------------------
PSI_IN = [0.1, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0]
# In the liquid the sphere spins up and slows on its way to the wall: the measured Psi_in is about
# half the released ratio, so the wet sets are released up to 6 (Psi_in about 3). At 8 (2.4 m/s
# along the wall, impact Reynolds number 760) the central advection's face speeds reach CFL 1.6 and
# the run stops (-health_cfl_max 1.5).
PSI_IN_WET = PSI_IN + [6.0]


def psi(rows, a):
    """Psi_in, Psi_out, Psi_2 and the normal restitution from a trajectory (floor z = 0, no spin in)."""
    d = 2 * a
    g = [(x["z"] - a) / d for x in rows]
    first = next(i for i in range(len(g)) if g[i] <= 2e-4)
    last = next((i for i in range(first, len(g)) if g[i] > 2e-4), len(g) - 1)
    vc = lambda x: x["vx"] - a * x["wy"]  # contact point's tangential velocity
    i_in = max(0, first - 1)
    # Leaving: the largest upward speed after the contact (the liquid slows it afterwards).
    i_out = max(range(last, min(len(rows), last + 5)), key=lambda i: rows[i]["vz"])
    vn_in, vn_out = -rows[i_in]["vz"], rows[i_out]["vz"]
    return vc(rows[i_in]) / vn_in, vc(rows[i_out]) / vn_out, vc(rows[i_out]) / vn_in, vn_out / vn_in


def oblique_dry():
    """Foerster et al.: glass a = 1.59 mm in air, e 0.83, friction 0.11; DEM only."""
    a, vn = 1.59e-3, 0.5
    out = []
    for pin in PSI_IN:
        o = os.path.join(scratch, "vp_col_dry_psi%g" % pin)
        rows = run(o, "-fluid_off", "-grid_n", "4,4,4", "-grid_lo", "0,0,0", "-grid_hi", "0.2,0.02,0.02",
                   "-particle_position", "0.01,0.01,%g" % (a * 1.02), "-particle_velocity", "%g,0,%g" % (pin * vn, -vn),
                   "-particle_radius", a, "-particle_density", 2500, "-contact_restitution", 0.83,
                   "-contact_friction", 0.11, "-contact_restitution_t", 0.1, "-contact_tc", 1e-5, "-time_dt", 1e-5,
                   "-dem_substeps", 100, "-time_final", 2e-4, np=1, case="none")
        out.append(psi(rows, a))
    return out


def oblique_wet(material):
    """Joseph & Hunt: d = 12.7 mm, steel and glass in 78 % glycerol-water (the less viscous mixtures put
    the impact Reynolds number near 1000, a cell Reynolds number the central advection cannot run)."""
    d = 0.0127
    rho_p, rho, mu, mu_c = {"steel": (7780, 1203, 0.048, 0.02), "glass": (2540, 1203, 0.048, 0.15)}[material]
    vn = 0.3
    out = []
    r = min(res, 12)
    for pin in PSI_IN_WET:
        o = os.path.join(scratch, "vp_col_wet_%s_psi%g_r%d%s" % (material, pin, r, SUFFIX))
        rows = run(o, "-grid_n", "%d,%d,%d" % (6 * r, 6 * r, 4 * r), "-grid_hi", "%g,%g,%g" % (6 * d, 6 * d, 4 * d),
                   "-particle_position", "%g,%g,%g" % (3 * d, 3 * d, 1.5 * d), "-particle_velocity", "%g,0,%g" % (pin * vn, -vn),
                   "-particle_density", rho_p, "-fluid_rho", rho, "-fluid_mu", mu, "-contact_friction", mu_c,
                   "-time_dt", 0.5 * d / r / (vn * math.hypot(1, pin)), "-time_final", 1.6 * d / vn, "-dem_substeps", 200,
                   "-health_overlap_max", 0.3, "-health_cfl_max", 1.5, *WITHOUT, case="oblique_collision.opts")  # the stretched contact's overlap; CFL 1.12 at impact (weighted, steel, Psi_in 0.1)
        out.append(psi(rows, d / 2))
    return out, mu_c, rho_p * vn * d / (9 * mu), r


def oblique():
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    dry = oblique_dry()
    sets = [("dry glass (Foerster), DEM", dry, 0.11)]
    for m in ("steel", "glass"):
        pts, mu_c, st, r = oblique_wet(m)
        sets.append(("wet %s, St %.0f, d/dx %d" % (m, st, r), pts, mu_c))
    for ax, (title, pts, mu_c) in zip(axes, sets):
        e = sorted(p[3] for p in pts)[len(pts) // 2]  # the median normal restitution of the set
        xs = [0, max(p[0] for p in pts)]
        ax.plot(xs, [x - 3.5 * mu_c * (1 + e) for x in xs], "k-", label="Psi_in - (7/2) mu (1 + e), median e = %.2f" % e)
        # The rigid-body relation holds impact by impact, with that impact's own normal restitution
        # (in a liquid it changes with the incidence): the pass measure; the median line is drawn.
        own = [p[0] - 3.5 * mu_c * (1 + p[3]) for p in pts]
        ax.plot([p[0] for p in pts], own, "k+", label="the same with each impact's e")
        ax.plot([p[0] for p in pts], [p[2] for p in pts], "o", mfc="none", label="Psi_2 (vpsolve)")
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "x", label="Psi_out (vpsolve)")
        crit = 3.5 * mu_c * (1 + e)
        sliding = [(p, l) for p, l in zip(pts, own) if p[0] > 1.2 * 3.5 * mu_c * (1 + p[3])]
        worst = max((abs(p[2] - l) for p, l in sliding), default=float("nan"))
        worst_median = max((abs(p[2] - (p[0] - crit)) for p in pts if p[0] > 1.2 * crit), default=float("nan"))
        print("oblique: %s: friction %.2f, median e %.3f; sliding branch: largest |Psi_2 - line| %.3f with each "
              "impact's e (%.3f with the median e); sticking Psi_2/Psi_in at the smallest Psi_in: %.3f" %
              (title, mu_c, e, worst, worst_median, pts[0][2] / pts[0][0]), flush=True)
        for p in pts:
            print("oblique:   Psi_in %.3f  Psi_out %.3f  Psi_2 %.3f  e_n %.3f" % p, flush=True)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("Psi_in")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "oblique_impacts%s.png" % SUFFIX), dpi=120)


# --- Sensitivity at St 27 and 152 ------------------------------------------------------------------------
def sensitivity():
    """e of the 3 mm steel sphere at nominal St 152 (impact St about 130; with --fine also nominal
    St 40, impact about 27, and d/dx 16) at d/dx 12, one parameter changed at a time."""
    fine = [("d/dx 16", [], 16)] if "--fine" in sys.argv else []
    variants = [("reference", [], 12), ("d/dx 8", [], 8)] + fine + [
                ("activation 1 cell", ["-lub_activation_cells", 1], 12),
                ("activation 1.5 cells", ["-lub_activation_cells", 1.5], 12),
                ("activation 2 cells", ["-lub_activation_cells", 2], 12),
                ("saturation x3", ["-lub_saturation", 3 * 4e-4], 12), ("R0 2", ["-lub_llcm_r0", 2], 12),
                ("t_c 8 steps", ["-contact_tc_steps", 8], 12), ("t_c 20 steps", ["-contact_tc_steps", 20], 12),
                ("sub-steps 400", ["-dem_substeps", 400], 12)]
    for st in (152, 40) if "--fine" in sys.argv else (152,):
        # The mask's stiffness halved and doubled: lambda fixed at a multiple of its default at the
        # release (max(400 nu/h^2, 40 u/h) at d/dx 12, the floor of a CFL-0.5 motion).
        h = D3 / 12
        lam = max(400 * study_mu(st) / RHO_F / h ** 2, 40 * U_RELEASE / h)
        stiff = [("lambda x%g" % f, ["-penalization_lambda", f * lam], 12) for f in (0.5, 2)]
        base = None
        for name, opts, r in variants + stiff:
            label = None if name in ("reference", "d/dx 8", "d/dx 16") else \
                "sens_st%d_%s%s" % (st, name.replace(" ", "_").replace("/", ""), SUFFIX)
            out = restitution_run(st, HYDRO, r=r, extra=opts + WITHOUT, label=label)
            if out is None:
                print("sensitivity: nominal St %d, %s: no impact" % (st, name), flush=True)
                continue
            sti, e = out[0], out[1]
            base = base if base is not None else e
            print("sensitivity: nominal St %3d, %-18s impact St %6.1f  e %.3f (%+.1f %% vs d/dx 12 reference)" %
                  (st, name, sti, e, 100 * (e / base - 1) if base else 0), flush=True)


# --- Two spheres colliding ----------------------------------------------------------------------------
def case_options(case, drop):
    """The options of cases/<case> without those that start with one of the prefixes in drop."""
    out = []
    for line in open(os.path.join(root, "cases", case)):
        tok = line.split("#")[0].split()
        if tok and not tok[0].startswith(drop):
            out += tok
    return out


def pair_run(st, label, extra=(), r=12):
    """Two steel spheres of the e(St) study (the restitution case's liquid and contact) collide head-on
    along x, one released at 0.585 m/s a diameter from the other at rest, no gravity, in a 10 d x 6 d x
    6 d box. Returns (St of the relative speed at gap 0.1 d, e of the relative motion) or None."""
    d, a, u = D3, D3 / 2, U_RELEASE
    h = d / r
    out = os.path.join(scratch, "vp_col_pair_%s" % label)
    spheres = out + ".csv"
    with open(spheres, "w") as f:
        f.write("id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz\n0,%r,%r,%r,%r,%r,%r,0,0,0,0,0\n1,%r,%r,%r,%r,%r,0,0,0,0,0,0\n" %
                (3 * d, 3 * d, 3 * d, a, STEEL, u, 5 * d, 3 * d, 3 * d, a, STEEL))
    physics = case_options("restitution.opts", ("-particle_", "-grid_", "-gravity", "-fluid_mu", "-time_", "-output_",
                                                "-monitor_", "-track_", "-dem_substeps", "-health_"))
    first = run(out, *physics, "-grid_n", "%d,%d,%d" % (10 * r, 6 * r, 6 * r), "-grid_hi", "%g,%g,%g" % (10 * d, 6 * d, 6 * d),
                "-gravity", "0,0,0", "-fluid_mu", study_mu(st), "-particles_file", spheres, "-time_dt", 0.5 * h / u,
                "-time_final", 8 * d / u, "-dem_substeps", 200, "-health_overlap_max", 0.3, "-health_cfl_max", 1.5,
                *extra, case="none")
    second = [{k: float(v) for k, v in x.items()} for x in csv.DictReader(open(os.path.join(out, "particle_1.csv")))]
    # The relative motion as a sphere over a floor: gap x1 - x0 - d, its rate vx1 - vx0.
    rel = [{"z": a + q["x"] - p["x"] - d, "vz": q["vx"] - p["vx"]} for p, q in zip(first, second)]
    u_in, u_out, touched = impact(rel, a, gap_in=0.1)  # released at a gap of 1 d: both speeds at 0.1 d
    if u_in is None or not touched:
        return None
    return STEEL * u_in * d / (9 * study_mu(st)), u_out / u_in


def pair_lubrication_theory(st):
    """e/e_dry of two equal rigid spheres slowed by lubrication alone on the way in and out between the
    gap 0.1 d and the roughness gap, at St of the relative speed: the relative motion (mass m/2) loses
    u (2 L) / St each way, L the integral of the squeeze resistance F / (6 pi mu a V) over eps = h/a.
    The resistance: its leading terms 1/(4 eps) + (9/40) ln(1/eps) plus 0.69, the constant the exact
    values (Brenner; TWO) give at eps 0.01-0.2 (within 0.03)."""
    L = brenner_integral(4e-4, 0.2, lambda e: 1 / (4 * e) + 0.225 * math.log(1 / e) + 0.69)
    return max(0.0, 1 - (1 + 1 / E_DRY) * 2 * L / st)


def pair():
    """e of two colliding spheres with and without the departure, and with the mask's stiffness halved
    and doubled (lambda as in sensitivity()), d/dx 12, against rigid-sphere lubrication theory."""
    h = D3 / 12
    for st in (40, 152):
        lam = max(400 * study_mu(st) / RHO_F / h ** 2, 40 * U_RELEASE / h)
        base = {}
        for dep in (1, 0):
            for f in ((1, 0.5, 2) if st == 40 else (1,)):
                extra = (["-contact_hydro_departure", 1] if dep else NO_DEPARTURE) + ([] if f == 1 else ["-penalization_lambda", f * lam])
                out = pair_run(st, "st%d_dep%d_lam%g" % (st, dep, f), extra)
                if out is None:
                    print("pair: nominal St %d, departure %d, lambda x%g: no rebound" % (st, dep, f), flush=True)
                    continue
                base.setdefault(dep, out[1])
                print("pair: nominal St %3d, departure %d, lambda x%-3g: St %.1f (relative speed at 0.1 d), e %.3f, "
                      "e/e_dry %.3f (%+.1f %% vs lambda x1; lubrication theory %.3f)" %
                      (st, dep, f, out[0], out[1], out[1] / E_DRY, 100 * (out[1] / base[dep] - 1),
                       pair_lubrication_theory(out[0])), flush=True)


# --- Calibration: fixed spheres with a prescribed motion in Stokes flow ------------------------------
A, MU, U = 0.5, 1.0, 0.01          # radius, viscosity, speed (Re = 0.01); d = 1
GAPS = [0.01, 0.05, 0.1, 0.2, 0.5, 1.0]
# The normal mode has Brenner's series at any gap: two more where the resolved force falls away.
NORMAL_GAPS = [0.01, 0.02, 0.03, 0.05, 0.1, 0.2, 0.5, 1.0]
# The tangential modes: two below 0.01, where their correction (from its own activation gap) acts.
SHEAR_GAPS = [0.002, 0.005] + GAPS
# The resolved runs use the cases' fluid set-up: the weighted projection with PFMG (docs/coupling.md).
CASE_FLUID = ["-penalization_projection", "weighted", "-pressure_pc_type", "pfmg"]
TWO = {1.0: 1.01933, 0.5: 1.38621, 0.2: 2.31277, 0.1: 3.70665, 0.05: 6.35564, 0.01: 26.71115}
FXT = {0.01: 3.42253, 0.05: 2.59896, 0.1: 2.26430, 0.2: 1.95271, 0.5: 1.59571, 1.0: 1.38275}
TYR = {0.01: 2.24080, 0.05: 1.66746, 0.1: 1.45485, 0.2: 1.27664, 0.5: 1.11050, 1.0: 1.04178}


def brenner(eps):
    """Brenner (1961): F / (6 pi mu a U) of a sphere moving normal to a plane wall, gap eps a."""
    al = math.acosh(1 + eps)
    tot, n = 0.0, 1
    while n < 2000:
        num = 2 * math.sinh((2 * n + 1) * al) + (2 * n + 1) * math.sinh(2 * al)
        den = 4 * math.sinh((n + 0.5) * al) ** 2 - (2 * n + 1) ** 2 * math.sinh(al) ** 2
        term = n * (n + 1) / ((2 * n - 1) * (2 * n + 3)) * (num / den - 1)
        tot += term
        if abs(term) < 1e-14 * abs(tot):
            break
        n += 1
    return 4 / 3 * math.sinh(al) * tot


# Below eps 0.01 the tangential modes' asymptotic forms (Goldman, Cox & Brenner 1967; within 0.2 and
# 0.8 % of the tables at 0.01): F / (6 pi mu a U) = (8/15) ln(1/eps) + 0.9588 (translation),
# T / (8 pi mu a^3 Omega) = (2/5) ln(1/eps) + 0.3817 (rotation).
MODES = {  # exact value, normalisation, and how each is read from particle_0.csv
    "normal": (lambda e: brenner(e), "F / (6 pi mu a U), normal to a wall"),
    "pair": (lambda e: TWO[e], "F / (6 pi mu a V), two spheres approaching"),
    "parallel": (lambda e: FXT.get(e, 8 / 15 * math.log(1 / e) + 0.9588), "F / (6 pi mu a U), parallel to a wall"),
    "rotation": (lambda e: TYR.get(e, 0.4 * math.log(1 / e) + 0.3817), "T / (8 pi mu a^3 Omega), rotating at a wall"),
}


RELAX = 3 * A * A / MU    # viscous relaxation time of a run: 3 a^2 / nu (rho = 1)
SHRINK = 1.05             # normal and pair runs close the gap from SHRINK eps to eps over RELAX


def calib_geometry(mode, eps, box=4):
    """Options of the sphere(s) of infinite mass moving with a prescribed velocity (box `box` d, d = 1):
    towards the floor or towards each other, closing the gap from SHRINK eps to eps over RELAX; along
    the floor at gap eps; spinning in place at gap eps. Stokes flow is linear: forces scale with U."""
    bc = ["-bc_xlo", "periodic", "-bc_xhi", "periodic", "-bc_ylo", "periodic", "-bc_yhi", "periodic"]
    closing = (SHRINK - 1) * eps * A / RELAX  # speed that closes the gap by (SHRINK - 1) eps a
    if mode == "pair":
        return bc + ["-bc_zlo", "periodic", "-bc_zhi", "periodic"], None, closing
    if mode == "normal":
        return bc, ["-particle_position", "%r,%r,%r" % (box / 2, box / 2, A * (1 + SHRINK * eps)), "-particle_fixed",
                    "-particle_velocity", "0,0,%r" % -closing], closing
    one = ["-particle_position", "2,2,%r" % (A * (1 + eps)), "-particle_fixed"]
    if mode == "parallel":
        return bc, one + ["-particle_velocity", "%r,0,0" % U], U
    return bc, one + ["-particle_angular_velocity", "0,%r,0" % (U / A)], U


def pair_file(out, eps, v, shift=0.0, diagonal=False):
    """Two spheres of infinite mass approaching each other along x (or the x-y diagonal), each at v/2,
    gap SHRINK eps a, the gap centred `shift` (a length) beyond the face plane x = 2 (and y = 2)."""
    os.makedirs(out, exist_ok=True)
    f = os.path.join(out, "pair.csv")
    gap = SHRINK * eps * A
    e = (math.sqrt(0.5), math.sqrt(0.5)) if diagonal else (1.0, 0.0)
    c = (2 + shift, 2 + (shift if diagonal else 0))
    with open(f, "w") as o:
        o.write("id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz\n")
        for k, side in enumerate((-1, 1)):
            o.write("%d,%r,%r,2,%r,1,%r,%r,0,0,0,0\n" % (k, c[0] + side * (A + gap / 2) * e[0], c[1] + side * (A + gap / 2) * e[1],
                                                     A, -side * v / 2 * e[0], -side * v / 2 * e[1]))
    return f


def calib_value(mode, row, speed, resolved=True, diagonal=False):
    """Normalised resistance from a particle_0.csv row: the resolved force (fx..) or the correction (fcx..)."""
    f = "f" if resolved else "fc"
    t = "th" if resolved else "t"
    if mode == "normal":
        return row[f + "z"] / (6 * math.pi * MU * A * speed)
    if mode == "pair" and diagonal:
        return -(row[f + "x"] + row[f + "y"]) * math.sqrt(0.5) / (6 * math.pi * MU * A * speed)
    if mode in ("pair", "parallel"):
        return -row[f + "x"] / (6 * math.pi * MU * A * speed)
    return -row[t + "y"] / (8 * math.pi * MU * A ** 3 * (speed / A))


def calib_run(mode, eps, r, lub="none", cells=1.5, r0=1.0, shear=None, align=0.0, box=4, patch=None, blend=None,
              diagonal=False):
    """Resolved run (lub none: the fluid, at nu dt / h^2 = 0.5 for RELAX; the value at its end, gap eps)
    or the DEM-only correction (lub blcm/llcm) at gap eps, at d/dx r, activated at `cells` (the
    tangential terms at `shear` cells; None: the solver's default, 0.06 or `cells` if smaller).
    lub "replace": the resolved run with -lub_coupling replace from `cells` (patches of depth `patch`
    radii, faded out over `blend` cells beyond; None: the defaults), the resolved force plus the
    LLCM's together.
    `align`: the pair's gap centre, in cells beyond a face plane (0: on it; 0.5: on a cell centre);
    `diagonal`: the pair along the x-y diagonal (its gap centre `align` cells beyond both face planes).
    `box`: the cubic box's side in d (the resolved runs; 4 elsewhere)."""
    n = box * r
    bc, one, speed = calib_geometry(mode, eps, box)
    tag = "%s_eps%g_r%d" % (mode, eps, r) + ("" if lub == "none" else "_%s_c%g_R%g" % (lub, cells, r0))
    tag += ("" if shear is None else "_s%g" % shear) + ("" if align == 0 else "_a%g" % align) + ("" if box == 4 else "_box%g" % box)
    tag += ("" if patch is None else "_p%g" % patch) + ("" if blend is None else "_b%g" % blend) + ("_diag" if diagonal else "")
    out = os.path.join(scratch, "vp_col_cal_" + tag)
    common = ["-grid_n", "%d,%d,%d" % (n, n, n), "-grid_lo", "0,0,0", "-grid_hi", "%g,%g,%g" % (box, box, box), "-fluid_rho", 1,
              "-fluid_mu", MU, "-particle_radius", A, "-particle_density", 1, "-contact_tc", 1,
              "-contact_roughness", 1e-4] + bc
    if lub in ("none", "replace"):
        dt = 0.5 / r ** 2 / MU
        part = ["-particles_file", pair_file(out + "_in", eps, speed, align / r, diagonal), "-particles_fixed"] if one is None else one
        film = ["-lub_model", "none"] if lub == "none" else \
            ["-lub_model", "llcm", "-lub_coupling", "replace", "-lub_activation_cells", cells] + \
            ([] if patch is None else ["-lub_patch_gap", patch]) + ([] if blend is None else ["-lub_patch_blend", blend])
        rows = run(out, *common, *part, *CASE_FLUID, "-time_dt", dt, "-time_final", RELAX, *film, case="none")
        total = calib_value(mode, rows[-1], speed, diagonal=diagonal)
        return total if lub == "none" else total + calib_value(mode, rows[-1], speed, resolved=False, diagonal=diagonal)
    # The correction at the final gap: the same spheres placed there (DEM only, one evaluation).
    part = one
    if one is None:
        part = ["-particles_file", pair_file(out + "_in", eps / SHRINK, speed), "-particles_fixed"]
    elif mode == "normal":
        part = ["-particle_position", "2,2,%r" % (A * (1 + eps)), "-particle_fixed", "-particle_velocity", "0,0,%r" % -speed]
    rows = run(out, *common, *part, "-fluid_off", "-time_dt", 1e-9, "-time_max_steps", 1, "-lub_model", lub,
               "-lub_activation_cells", cells, "-lub_llcm_r0", r0,
               *([] if shear is None else ["-lub_shear_activation_cells", shear]), np=1, case="none")
    return calib_value(mode, rows[0], speed, resolved=False)


# A pair's squeeze through a gap narrower than a cell depends on where the gap lies on the grid
# (docs/collisions.md): read at gap centres from a face plane (0) to a cell centre (0.5 cells), which
# by symmetry covers every position; the mean over them is what the pairs of a moving packing meet.
ALIGNMENTS = [0.0, 0.125, 0.25, 0.375, 0.5]


def pair_resolved(eps, r):
    """The pair's resolved resistance at each gap position and its mean over a cell (trapezoid rule)."""
    v = [calib_run("pair", eps, r, align=s) for s in ALIGNMENTS]
    return v, (sum(v) - (v[0] + v[-1]) / 2) / (len(v) - 1)


ACTIVATIONS = [0.1, 0.15, 0.2, 0.3, 0.5, 0.75, 1.0, 1.5]  # cells, for the scan (squeeze)
SHEAR_ACTIVATIONS = [0.04, 0.06, 0.08, 0.1, 0.12, 0.18]  # cells, for the scan of the tangential modes
DEFAULT_CELLS = 0.18  # kDefaultActivationCells (include/vp/interactions/LubricationModel.hpp)
TANGENTIAL = ("parallel", "rotation")


def calibration():
    fine = "--fine" in sys.argv
    res_list = {m: [8, 12] + ([16, 24] if fine and m == "normal" else [16] if fine else []) for m in MODES}
    gaps = {m: NORMAL_GAPS if m == "normal" else SHEAR_GAPS if m in TANGENTIAL else GAPS for m in MODES}
    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    by_gap = {}  # (d/dx, eps): the pair's error (%) at each gap position
    for ax, (mode, (exact, title)) in zip(axes.flat, MODES.items()):
        G = gaps[mode]
        ex = [exact(e) for e in G]
        ax.loglog(G, ex, "k-", lw=2, label="exact")
        for k, r in enumerate(res_list[mode]):
            c = "C%d" % k
            if mode == "pair":
                by_position = [pair_resolved(e, r) for e in G]
                resolved = [mean for _, mean in by_position]
                ax.fill_between(G, [min(v) for v, _ in by_position], [max(v) for v, _ in by_position], color=c,
                                alpha=0.15, label="resolved, range over the gap's position, d/dx %d" % r)
                for e, x, (v, mean) in zip(G, ex, by_position):
                    by_gap[(r, e)] = [100 * (y / x - 1) for y in v]
                    print("calibration: pair     d/dx %2d eps %5g  exact %8.4f  resolved at gap centres %s cells from a"
                          " face plane: %s %%; mean %+.1f %%" % (r, e, x, "/".join("%g" % a for a in ALIGNMENTS),
                          " / ".join("%+.1f" % (100 * (y / x - 1)) for y in v), 100 * (mean / x - 1)), flush=True)
            else:
                resolved = [calib_run(mode, e, r) for e in G]
            ax.loglog(G, resolved, "o--", color=c, mfc="none",
                      label="resolved%s, d/dx %d" % (", mean over positions" if mode == "pair" else "", r))
            # The defaults (squeeze 0.18, tangential 0.06 cells) and the sharp-interface codes' 1.5 cells.
            for cells, mark in ((DEFAULT_CELLS, "s-"), (1.5, "^:")):
                shear = cells if cells > DEFAULT_CELLS else None
                total = [x + calib_run(mode, e, r, "llcm", cells, shear=shear) for e, x in zip(G, resolved)]
                what = "%g cells" % cells if mode not in TANGENTIAL else \
                    "%g cells" % (shear or 0.06) if cells > DEFAULT_CELLS else "0.06 cells (tangential default)"
                ax.loglog(G, total, mark, color=c, ms=4, label="+ LLCM from %s, d/dx %d" % (what, r))
            for e, x, y in zip(G, ex, resolved):
                llcm = calib_run(mode, e, r, "llcm", DEFAULT_CELLS)
                blcm = calib_run(mode, e, r, "blcm", DEFAULT_CELLS)
                print("calibration: %-8s d/dx %2d eps %5g  exact %8.4f  resolved %8.4f (%+6.1f %%)  + LLCM %8.4f (%+6.1f %%)"
                      "  + BLCM %8.4f (%+6.1f %%)  [activation %g cells = eps %.3f]" %
                      (mode, r, e, x, y, 100 * (y / x - 1), y + llcm, 100 * ((y + llcm) / x - 1), y + blcm,
                       100 * ((y + blcm) / x - 1), DEFAULT_CELLS, DEFAULT_CELLS / r / A), flush=True)
            # Activation scan: error of resolved + LLCM for each activation gap (the tangential
            # modes: the gap of their own terms), over the gaps up to 0.5.
            for cells in SHEAR_ACTIVATIONS if mode in TANGENTIAL else ACTIVATIONS:
                squeeze, shear = (max(cells, DEFAULT_CELLS), cells) if mode in TANGENTIAL else (cells, None)
                errs = ["%+4.0f" % (100 * ((y + calib_run(mode, e, r, "llcm", squeeze, shear=shear)) / x - 1))
                        for e, x, y in zip(G, ex, resolved) if e <= 0.5]
                print("calibration scan: %-8s d/dx %2d activation %4g cells: error %% at eps %s..0.5: %s" %
                      (mode, r, cells, G[0], " ".join(errs)), flush=True)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("gap eps = h / a")
        ax.legend(fontsize=6)
    fig.suptitle("Resolved force and resolved + LLCM vs exact Stokes resistances (box 4 d)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "lubrication_calibration.png"), dpi=120)
    pair_position_figure(by_gap)


def confinement():
    """The resolved force in cubic boxes of 4 (the study's) to 12 d: what the box adds. Normal to a wall
    (walls at z = 0 and the box's side), and the pair (periodic in all three: its images), the pair's
    gap centred on a face plane."""
    for mode, exact, r, boxes, gaps in (("normal", brenner, 8, [4, 6, 8, 12], [0.2, 0.5, 1.0]),
                                        ("normal", brenner, 12, [4, 8], [0.05, 0.1, 0.2, 0.5, 1.0]),
                                        ("pair", TWO.get, 12, [4, 6, 8], [0.2, 0.5, 1.0])):
        for box in boxes:
            errs = ["%+.1f" % (100 * (calib_run(mode, e, r, box=box) / exact(e) - 1)) for e in gaps]
            print("confinement: %-6s d/dx %2d box %2d d: error %% at eps %s: %s" %
                  (mode, r, box, "/".join("%g" % e for e in gaps), " / ".join(errs)), flush=True)


def pair_position_figure(by_gap):
    """The pair's resolved force against where its gap lies on the grid, one line per gap and grid."""
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for (r, e), err in sorted(by_gap.items()):
        ax.plot(ALIGNMENTS, err, "o-" if r == 8 else "s--", color="C%d" % GAPS.index(e),
                label="eps %g, d/dx %d (gap %.2g cells)" % (e, r, e * A * r))
    ax.axhline(0, color="k", lw=1)
    ax.set_xlabel("gap centre: cells from a face plane (0.5 = a cell centre)")
    ax.set_ylabel("resolved force against exact (%)")
    ax.set_title("Two spheres approaching in Stokes flow: the gap's position on the grid", fontsize=10)
    ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "lubrication_pair_position.png"), dpi=120)

# --- The local replacement (-lub_coupling replace) ---------------------------------------------------
REPLACEMENT_CELLS = 1.0  # kDefaultReplacementCells (include/vp/interactions/LubricationModel.hpp)
BLEND_CELLS = 3.0        # kDefaultPatchBlendCells (same file)
PATCH_GAP = 0.2          # kDefaultPatchGap (same file)


def spread(err):
    return "%s (mean %+.1f, range %.1f)" % (" / ".join("%+.1f" % y for y in err), sum(err) / len(err), max(err) - min(err))


def replacement():
    """-lub_coupling add (the resolved force plus the unresolved part, the default) against replace
    (the gap patches' normal force replaced by the LLCM's open-edge squeeze below REPLACEMENT_CELLS,
    faded out over BLEND_CELLS beyond), d/dx 12: each mode's error against its exact resistance; the
    pair at three positions of its gap on the grid (a face plane, a quarter cell, a cell centre), along
    x and along the x-y diagonal, its mean and range. The pair at eps 0.5 in a 6 d box (the 4 d box's
    images add 5 points there: confinement)."""
    r = 12
    gaps = {"normal": [0.01, 0.02, 0.05, 0.1, 0.2, 0.5], "pair": [0.01, 0.05, 0.1, 0.2, 0.5],
            "parallel": [0.01, 0.05, 0.1], "rotation": [0.01, 0.05, 0.1]}
    diagonal_gaps = [0.05, 0.1, 0.2]
    aligns = [0.0, 0.25, 0.5]

    def errors(mode, e, coupling, diagonal=False):
        al = aligns if mode == "pair" else [0.0]
        box = 6 if mode == "pair" and e >= 0.5 else 4
        if coupling == "add":
            corr = calib_run(mode, e, r, "llcm", DEFAULT_CELLS)
            v = [calib_run(mode, e, r, align=a, diagonal=diagonal, box=box) + corr for a in al]
        else:
            v = [calib_run(mode, e, r, "replace", REPLACEMENT_CELLS, align=a, diagonal=diagonal, box=box) for a in al]
        return [100 * (y / MODES[mode][0](e) - 1) for y in v]

    fig, axes = plt.subplots(1, 4, figsize=(16, 4.2))
    for ax, (mode, (exact, title)) in zip(axes, MODES.items()):
        series = [("add", False, "s--"), ("replace", False, "o-")]
        if mode == "pair":
            series += [("add", True, "v:"), ("replace", True, "D-")]
        for k, (coupling, diagonal, style) in enumerate(series):
            means, lows, highs, used = [], [], [], diagonal_gaps if diagonal else gaps[mode]
            for e in used:
                err = errors(mode, e, coupling, diagonal)
                means.append(sum(err) / len(err))
                lows.append(min(err))
                highs.append(max(err))
                print("replacement: %-8s%s d/dx %d eps %5g  %-7s error %% %s" %
                      (mode, " (diagonal)" if diagonal else "", r, e, coupling, spread(err) if len(err) > 1 else "%+.1f" % err[0]),
                      flush=True)
            g = [e * (1 + 0.04 * k) for e in used]
            ax.errorbar(g, means, yerr=[[m - lo for m, lo in zip(means, lows)], [hi - m for m, hi in zip(means, highs)]],
                        fmt=style, capsize=3, label=coupling + (", diagonal" if diagonal else "") +
                        (" (mean, range over positions)" if mode == "pair" else ""))
        ax.axhline(0, color="k", lw=0.8)
        for band in (5, 15) if mode in ("normal", "pair") else (15,):
            ax.axhspan(-band, band, color="g", alpha=0.06)
        ax.set_xscale("log")
        ax.set_xlabel("gap eps = h / a")
        ax.set_ylabel("error against exact (%)")
        ax.set_title(title, fontsize=9)
        ax.legend(fontsize=7)
    fig.suptitle("-lub_coupling add and replace (h_act %g cell, blend %g cell) against exact Stokes resistances, d/dx %d"
                 % (REPLACEMENT_CELLS, BLEND_CELLS, r), fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "lubrication_replacement.png"), dpi=120)
    # The patch's depth (-lub_patch_gap) over the replaced gaps: the wall, and the pair at the three
    # positions along x and along the diagonal; their mean.
    for patch in (0.15, PATCH_GAP, 0.25, 0.4):
        depth = None if patch == PATCH_GAP else patch  # the default's runs are the table's
        for e in (0.01, 0.05, 0.1, 0.2):
            wall = 100 * (calib_run("normal", e, r, "replace", REPLACEMENT_CELLS, patch=depth) / brenner(e) - 1)
            pairs = [100 * (calib_run("pair", e, r, "replace", REPLACEMENT_CELLS, align=al, patch=depth, diagonal=dg) / TWO[e] - 1)
                     for dg in ((False, True) if e in diagonal_gaps else (False,)) for al in aligns]
            print("replacement: patch depth %g a at eps %g, d/dx %d: normal %+.1f %%, pair %s %%" %
                  (patch, e, r, wall, spread(pairs)), flush=True)
    # The replacement's gap and blend at eps 0.2 (1.2 cells) and 0.5 (3 cells), where the resolved
    # squeeze's own error is positive and the replaced one's negative: a sharp switch at 1 cell (not
    # replaced) or at 2 (replaced), and a weight falling from 1 at 1 cell over 1 or 3 (the default) cells.
    for cells, blend in ((1.0, 0), (1.0, 1), (1.0, 3), (2.0, 0)):
        tag = "from %g cells, blend %g, d/dx %d" % (cells, blend, r)
        for e, box in ((0.2, 4), (0.5, 6)):
            if e == 0.5 and cells > 1:
                continue  # not replaced at 3 cells: the sharp switch at 1 cell's
            b = None if blend == BLEND_CELLS else blend
            wall = 100 * (calib_run("normal", e, r, "replace", cells, blend=b) / brenner(e) - 1)
            pair = [100 * (calib_run("pair", e, r, "replace", cells, align=al, blend=b, box=box) / TWO[e] - 1) for al in aligns]
            print("replacement: %s at eps %g: normal %+.1f %%, pair %s %%%s" %
                  (tag, e, wall, spread(pair), " (6 d box)" if box == 6 else ""), flush=True)


# --- The liquid's inertia in the gap ----------------------------------------------------------------
def inertia():
    print("nominal St  impact St  impact Re  e/e_dry  e/e_dry with -lub_inertia  change")
    for st in (20, 30, 60, 100):
        plain = restitution_run(st, HYDRO, r=12)
        inert = restitution_run(st, HYDRO, r=12, extra=["-lub_inertia"])
        if plain is None or inert is None:
            print(f"{st:10d}  no rebound read")
            continue
        re_a = RHO_F * plain[2] * D3 / 2 / study_mu(st)
        print(f"{st:10d}  {plain[0]:9.1f}  {re_a:9.1f}  {plain[1] / E_DRY:7.3f}  {inert[1] / E_DRY:24.3f}  "
              f"{(inert[1] - plain[1]) / E_DRY:+6.3f}", flush=True)


STUDIES = ("restitution", "glass_grid", "timestep", "gondret", "oblique", "calibration", "replacement", "confinement", "sensitivity",
           "pair", "harada", "inertia")

if __name__ == "__main__":
    what = chosen_study(__doc__, STUDIES, valued=("--res", "--width"))
    for name in STUDIES:
        if what in (name, "all"):
            globals()[name]()
