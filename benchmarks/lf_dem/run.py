#!/usr/bin/python3
"""LF_DEM peer runs at vpsolve's shear-cell conditions (README.md in this directory).

  Set A (shear): rate-controlled simple shear, phi 0.2 0.3 0.4 0.45 0.5 with Coulomb friction 0.5 and
      phi 0.2 0.3 0.4 0.5 frictionless -> results_shear.csv
  Set B (thickening): stress-controlled, critical load model (friction 0.5 above F_CL), phi 0.52 0.54
      0.56, sigma/sigma* = 0.1 0.3 1 3 10 30 100 (sigma* = F_CL/(6 pi a^2)) -> results_thickening.csv,
      thickening.png
Bidisperse a : 1.4 a at equal volume fractions, N = 500, cubic Lees-Edwards box, one run at a time
(LF_DEM is single-threaded). eta_r, N1, N2: means over the second half of the strain.
usage: run.py [--lfdem BIN] [--work DIR] [--strain-a S] [--strain-b S] [--sets A,B] [--runs-a 0.2:0.5,...]
              [--phis-b 0.54,...] [--stresses-b 0.1,...] [--mu-b 0.5] [--np N] [--plot-only]
Runs already done (data file present in the work dir) are read again, not rerun."""
import argparse, csv, os, resource, subprocess, sys, time
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
ap = argparse.ArgumentParser()
ap.add_argument("--lfdem", default="/work/lfdem/build/LF_DEM")
ap.add_argument("--work", default="/work/lfdem/runs")
ap.add_argument("--strain-a", type=float, default=20.0)
ap.add_argument("--strain-b", type=float, default=20.0)
ap.add_argument("--sets", default="A,B")
ap.add_argument("--runs-a", default="0.2:0.5,0.3:0.5,0.4:0.5,0.45:0.5,0.5:0.5,0.2:0,0.3:0,0.4:0,0.5:0",
                help="phi:friction pairs of set A")
ap.add_argument("--phis-b", default="0.52,0.54,0.56")
ap.add_argument("--stresses-b", default="0.1,0.3,1,3,10,30,100")
ap.add_argument("--mu-b", type=float, default=0.5)
ap.add_argument("--np", type=int, default=500)
ap.add_argument("--out", default=here)
ap.add_argument("--plot-only", action="store_true")
args = ap.parse_args()
os.makedirs(args.work, exist_ok=True)
sys.path.insert(0, here)
import genconf

A2, VF_SMALL, SEED = 1.4, 0.5, 1

# Common physics (README: parameter mapping).
COMMON = """lubrication_model = tangential;
lub_reduce_parameter = 0.02;
lub_max_gap = 0.5;
integration_method = 0;
disp_max = 5e-3;
out_data_particle = false;
out_data_interaction = false;
time_interval_output_config = 1000h;
"""

def conf_file(phi):
    path = os.path.join(args.work, f"conf_N{args.np}_phi{phi}.dat")
    if not os.path.exists(path):
        x, r, L, n1, n2, p1, p2, gap, it = genconf.generate(args.np, phi, A2, VF_SMALL, SEED)
        with open(path, "w") as f:
            f.write("# np1 np2 vf lx ly lz vf1 vf2 disp\n")
            f.write(f"# {n1} {n2} {phi} {L!r} {L!r} {L!r} {p1} {p2} 0\n")
            for p, a in zip(x, r):
                f.write(f"{p[0]!r} {p[1]!r} {p[2]!r} {a!r}\n")
        print(f"configuration {path}: {n1}+{n2} particles, box {L:.3f}, min gap {gap:.4f}", flush=True)
    return path

def read_data(path):
    cols, rows = {}, []
    for line in open(path):
        if line.startswith("#"):
            h = line[1:].strip()
            if ":" in h and h.split(":")[0].isdigit():
                k, name = h.split(":", 1)
                cols[name.strip()] = int(k) - 1
        elif line.strip():
            rows.append([float(v) for v in line.split()])
    return cols, np.array(rows)

def second_half(cols, d, strain_end):
    s = d[:, cols["cumulated shear strain"]]
    m = s >= 0.5 * strain_end
    mean = lambda name: float(np.mean(d[m, cols[name]]))
    return dict(eta_r=mean("viscosity"), n1=mean("N1 viscosity"), n2=mean("N2 viscosity"),
                rate=mean("shear rate"), min_gap=float(np.min(d[m, cols["min gap"]])),
                strain_end=float(s[-1]), contacts=mean("contact number"),
                frictional=mean("frictional contact number"))

def run(name, phi, params, control):
    """control: ('-r', '1h') or ('-s', 'Xcl'). Returns (data path, wall s, cpu s)."""
    d = os.path.join(args.work, name)
    os.makedirs(d, exist_ok=True)
    pfile = os.path.join(d, "p.txt")
    with open(pfile, "w") as f:
        f.write(COMMON + params)
    done = [f for f in os.listdir(d) if f.startswith("data_")]
    timing = os.path.join(d, "timing.txt")
    if done and os.path.exists(timing):
        wall, cpu = map(float, open(timing).read().split())
        return os.path.join(d, done[0]), wall, cpu
    if args.plot_only:
        return None, 0, 0
    conf = conf_file(phi)
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    with open(os.path.join(d, "log.txt"), "w") as log:
        subprocess.run([args.lfdem, control[0], control[1], conf, pfile], cwd=d, stdout=log,
                       stderr=subprocess.STDOUT, check=True)
    wall = time.time() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    open(timing, "w").write(f"{wall} {cpu}\n")
    done = [f for f in os.listdir(d) if f.startswith("data_")]
    return os.path.join(d, done[0]), wall, cpu

def append(csvname, header, row):
    path = os.path.join(args.out, csvname)
    new = not os.path.exists(path)
    with open(path, "a", newline="") as f:
        w = csv.writer(f)
        if new:  # rows are appended run by run; delete the csv files to rebuild them from the run dirs
            w.writerow(header)
        w.writerow(row)

HEAD_A = ["phi", "friction", "eta_r", "n1", "n2", "strain_end", "seconds_per_strain",
          "cpu_seconds_per_strain", "min_gap", "contacts_per_particle"]
HEAD_B = ["phi", "sigma_over_sigma_star", "eta_r", "friction", "strain_end", "seconds_per_strain",
          "cpu_seconds_per_strain", "n1", "n2", "min_gap", "contacts_per_particle", "frictional_per_particle"]

def set_a():
    S = args.strain_a
    runs = [tuple(float(v) for v in r.split(":")) for r in args.runs_a.split(",")]
    for phi, mu in runs:
        fr = f"friction_model = 1;\nmu_static = {mu};\n" if mu > 0 else "friction_model = 0;\n"
        params = fr + f"""kn = 10000h;
kt = 5000h;
contact_relaxation_time = 1e-3h;
contact_relaxation_time_tan = 0h;
time_end = {S}h;
time_interval_output_data = 0.02h;
"""
        path, wall, cpu = run(f"A_phi{phi}_mu{mu}_S{S:g}", phi, params, ("-r", "1h"))
        if path is None:
            continue
        cols, d = read_data(path)
        m = second_half(cols, d, S)
        print(f"A phi {phi} mu {mu}: eta_r {m['eta_r']:.2f} N1 {m['n1']:.2f} N2 {m['n2']:.2f} "
              f"min gap {m['min_gap']:.4f}  {wall / m['strain_end']:.0f} s/strain", flush=True)
        append("results_shear.csv", HEAD_A, [phi, mu, f"{m['eta_r']:.4g}", f"{m['n1']:.4g}", f"{m['n2']:.4g}",
               f"{m['strain_end']:.3g}", f"{wall / m['strain_end']:.1f}", f"{cpu / m['strain_end']:.1f}",
               f"{m['min_gap']:.4f}", f"{m['contacts']:.3f}"])

def set_b():
    S = args.strain_b
    mu = args.mu_b
    for phi in [float(p) for p in args.phis_b.split(",")]:
        for X in [float(x) for x in args.stresses_b.split(",")]:
            # Stress in units of sigma* = F_CL/(6 pi a^2): LF_DEM's "-s Xcl" (internal target X/(6 pi) F_CL/a^2).
            # Stiffness proportional to the stress ("s" unit) so the overlaps stay ~1 % of a at every stress.
            params = f"""critical_load = 1cl;
friction_model = 2;
mu_static = {mu};
kn = 10000s;
kt = 0.5kn;
contact_relaxation_time = 10kn;
contact_relaxation_time_tan = 0kn;
time_end = {S}h;
time_interval_output_data = 0.02h;
"""
            path, wall, cpu = run(f"B_phi{phi}_s{X:g}_mu{mu}_S{S:g}", phi, params, ("-s", f"{X:g}cl"))
            if path is None:
                continue
            cols, d = read_data(path)
            m = second_half(cols, d, S)
            print(f"B phi {phi} sigma/sigma* {X:g}: eta_r {m['eta_r']:.2f} (rate*eta_r {m['rate'] * m['eta_r']:.3g}) "
                  f"min gap {m['min_gap']:.4f} Z {m['contacts']:.2f} Zf {m['frictional']:.2f}  "
                  f"{wall / m['strain_end']:.0f} s/strain", flush=True)
            append("results_thickening.csv", HEAD_B, [phi, X, f"{m['eta_r']:.4g}", mu, f"{m['strain_end']:.3g}",
                   f"{wall / m['strain_end']:.1f}", f"{cpu / m['strain_end']:.1f}", f"{m['n1']:.4g}", f"{m['n2']:.4g}",
                   f"{m['min_gap']:.4f}", f"{m['contacts']:.3f}", f"{m['frictional']:.3f}"])

def plot():
    path = os.path.join(args.out, "results_thickening.csv")
    if not os.path.exists(path):
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = list(csv.DictReader(open(path)))
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    for phi in sorted({r["phi"] for r in rows}):
        for mu in sorted({r["friction"] for r in rows if r["phi"] == phi}):
            rr = sorted((float(r["sigma_over_sigma_star"]), float(r["eta_r"])) for r in rows
                        if r["phi"] == phi and r["friction"] == mu)
            x, y = zip(*rr)
            ax.loglog(x, y, "o-", label=f"phi {phi}, mu {mu}")
    ax.set_xlabel("sigma / sigma*   (sigma* = F_CL / (6 pi a^2))")
    ax.set_ylabel("eta_r")
    ax.set_title("LF_DEM, critical load model, N = 500 bidisperse")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "thickening.png"), dpi=110)

if __name__ == "__main__":
    sets = args.sets.split(",")
    if "A" in sets:
        set_a()
    if "B" in sets:
        set_b()
    plot()
