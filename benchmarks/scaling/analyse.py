#!/usr/bin/python3
"""Strong-scaling tables and plot from the runs of run.sh (RUNS/<case>_np<N>.log and their output
directories); writes results.csv, scaling.md and scaling.png into OUT.
usage: analyse.py RUNS OUT CORES RANKS..."""
import csv, re, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

runs, here, cores, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3]), [int(r) for r in sys.argv[4:]]
STAGES = ["Advection", "Diffusion", "Pressure", "Penalization", "HydroForce", "DEM", "Exchange", "IO", "Health"]


def parse(path):
    text = open(path).read()
    r = {"stages": {}, "petsc": {}}
    for m in re.finditer(r"^vpsolve:\s+(\w+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$", text, re.M):
        r["stages"][m.group(1)] = float(m.group(2))  # slowest rank's seconds
    m = re.search(r"vpsolve: stopped at step (\d+)", text)
    r["steps"] = int(m.group(1))
    m = re.search(r"loop time ([\d.]+) s", text)
    r["loop"] = float(m.group(1)) if m else None
    m = re.search(r"particle exchange between ranks: (\d+) messages, ([\d.e+-]+) MB", text)
    r["pmsg"], r["pmb"] = (int(m.group(1)), float(m.group(2))) if m else (0, 0.0)
    last = list(csv.DictReader(open(path[:-4] + "/diagnostics.csv")))[-1]  # 10 significant digits
    r["ke_fluid"], r["ke_particles"] = float(last["kinetic_energy"]), float(last["particle_kinetic_energy"])
    m = re.search(r"MPI Msg Count:\s+\S+\s+\S+\s+\S+\s+(\S+)", text)
    r["petsc_msgs"] = float(m.group(1)) if m else 0.0
    m = re.search(r"MPI Reductions:\s+(\S+)", text)
    r["petsc_reductions"] = float(m.group(1)) if m else 0.0
    return r


rows = []
for case in ("coupled", "dem"):
    base = None
    for np in ranks:
        r = parse(f"{runs}/{case}_np{np}.log")
        t = r["loop"] / r["steps"]  # the stepping loop: set-up and the final snapshot excluded
        if base is None:
            base = (np, t, r)
        speedup = base[1] / t
        ke = "ke_fluid" if case == "coupled" else "ke_particles"
        dke = abs(r[ke] - base[2][ke]) / abs(base[2][ke])
        rows.append({"case": case, "ranks": np, "oversubscribed": int(np > cores), "s_per_step": t,
                     "speedup": speedup, "efficiency": speedup * base[0] / np, "ke_rel_diff": dke,
                     "petsc_msgs_per_step": r["petsc_msgs"] / r["steps"],
                     "petsc_reductions_per_step": r["petsc_reductions"] / r["steps"],
                     "particle_msgs_per_step": r["pmsg"] / r["steps"], "particle_kb_per_step": 1e3 * r["pmb"] / r["steps"],
                     **{s.lower() + "_s": r["stages"].get(s, 0.0) / r["steps"] for s in STAGES}})
with open(f"{here}/results.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    w.writeheader()
    w.writerows(rows)

with open(f"{here}/scaling.md", "w") as f:
    for case, title in (("coupled", "Coupled step, 128^3, 1,000 spheres"), ("dem", "Dry DEM collapse, 2,000 spheres")):
        f.write(f"\n{title} ({cores} cores; rows marked * oversubscribed: timings not speed-ups)\n\n")
        f.write("| ranks | s/step | speed-up | efficiency | KE vs 1 rank | PETSc msgs/step (all ranks) | reductions/step (per rank) | particle msgs/step (all ranks) | particle kB/step (all ranks) | slowest stages (ms/step) |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|\n")
        for r in (r for r in rows if r["case"] == case):
            top = sorted(((r[s.lower() + "_s"], s) for s in STAGES if s != "IO"), reverse=True)[:3]  # IO: the final snapshot
            stages = ", ".join(f"{s} {1e3 * v:.3g}" for v, s in top if v > 0)
            f.write(f"| {r['ranks']}{'*' if r['oversubscribed'] else ''} | {r['s_per_step']:.4g} | {r['speedup']:.2f} | "
                    f"{100 * r['efficiency']:.0f} % | {r['ke_rel_diff']:.1e} | {r['petsc_msgs_per_step']:.0f} | "
                    f"{r['petsc_reductions_per_step']:.0f} | {r['particle_msgs_per_step']:.1f} | {r['particle_kb_per_step']:.1f} | {stages} |\n")

fig, axes = plt.subplots(1, 2, figsize=(10, 4))
for case, ax in zip(("coupled", "dem"), axes):
    rs = [r for r in rows if r["case"] == case]
    ok = [r for r in rs if not r["oversubscribed"]]
    ax.plot([r["ranks"] for r in ok], [100 * r["efficiency"] for r in ok], "o-", label="measured")
    over = [r for r in rs if r["oversubscribed"]]
    if over:
        ax.plot([r["ranks"] for r in over], [100 * r["efficiency"] for r in over], "x", color="grey",
                label=f"oversubscribed (> {cores} cores)")
    ax.axhline(100, color="k", lw=0.5)
    ax.set_xscale("log", base=2)
    ax.set_xticks(ranks)
    ax.set_xticklabels([str(r) for r in ranks])
    ax.set_ylim(0, 110)
    ax.set_xlabel("ranks")
    ax.set_ylabel("parallel efficiency (%)")
    ax.set_title({"coupled": "coupled step, 128^3, 1,000 spheres", "dem": "dry DEM collapse, 2,000 spheres"}[case])
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{here}/scaling.png", dpi=120)
print(open(f"{here}/scaling.md").read())
