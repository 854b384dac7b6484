#!/usr/bin/python3
"""Performance model of a coupled step (docs/scaling.md): computation per stage from the one-rank
stage times of results.csv (run.sh), communication counted per stage from the algorithms, with
network constants assumed for an InfiniBand cluster. Projects the step time and the parallel
efficiency for a large case and names the stage whose communication grows fastest.
usage: model.py RESULTS_CSV OUT_MD OUT_PNG [cells_per_axis particles ranks...]"""
import csv, math, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

res, out_md, out_png = sys.argv[1:4]
n_axis = int(sys.argv[4]) if len(sys.argv) > 4 else 1024
particles = float(sys.argv[5]) if len(sys.argv) > 5 else 1e6
ranks = [int(r) for r in sys.argv[6:]] or [64, 128, 256, 512, 1024, 2048, 4096]
rows = list(csv.DictReader(open(res)))
one = {r["case"]: r for r in rows if r["ranks"] == "1"}
two = {r["case"]: r for r in rows if r["ranks"] == "2"}

# Measured case sizes (run.sh).
N1, P1, SUB1 = 128**3, 1000, 10          # coupled benchmark
PDEM = 2000                              # dry collapse, one sub-step per step
# Computation constants, seconds per unit of work, from one rank.
c = one["coupled"]
k_adv = float(c["advection_s"]) / N1
k_diff = float(c["diffusion_s"]) / N1
k_pres = float(c["pressure_s"]) / N1
# The penalization has a per-cell part (the mask reset and the theta field over the whole box) and a
# per-sphere part (the mask over each sphere's box, clipped to the subdomain, so a sphere cut by a
# boundary costs no more in total); measured split at 128^3, 1 / 100 / 1000 spheres
# (benchmarks/RESULTS.md, coupled step): 0.019 / 0.027 / 0.074 s, i.e. 26 % per cell at 1000.
PEN_CELL_SHARE = 0.019 / 0.074
k_pen_cell = PEN_CELL_SHARE * float(c["penalization_s"]) / N1
k_pen = (1 - PEN_CELL_SHARE) * float(c["penalization_s"]) / P1
k_hyd = float(c["hydroforce_s"]) / P1     # per sphere, clipped to the subdomain like the mask
k_dem = float(one["dem"]["dem_s"]) / PDEM  # per particle and sub-step with contacts
# Memory-bandwidth sharing between the cores of a node: measured from 1 -> 2 ranks on this machine
# (the part of the 2-rank loss that the communication counts below do not explain is of this kind).
share = float(one["coupled"]["s_per_step"]) / (2 * float(two["coupled"]["s_per_step"])) if "coupled" in two else 1.0

# Network constants (assumed, typical InfiniBand HDR cluster, per message between nodes).
ALPHA = 2e-6        # latency of a point-to-point message [s]
BETA = 5e9          # bandwidth per rank [B/s] (a 25 GB/s link shared by about 5 ranks per link)
ALPHA_RED = 3e-6    # allreduce latency per tree level [s]

# Algorithm counts per fluid step (measured on the cases: docs/scaling.md).
SWEEPS = 1 + 12 + 3      # face-halo exchanges: advection, viscous CG iterations, projection
CG_RED = 2 * 12 + 2 * 7  # reductions: viscous CG and pressure CG (dot products, norms)
V_CYCLES = 7             # BoomerAMG V-cycles per solve
SUBSTEPS = 150           # DEM sub-steps per fluid step (the dam-break setting)
DEM_RED = 1              # reductions per sub-step (the neighbour-list rebuild test)
GHOST_BYTES = 13 * 8     # position, velocity, spin, orientation of a ghost per sub-step
D_CELLS = 8              # sphere diameter in cells
HALO_D = 1.2             # particle halo in diameters


def step_time(p):
    n = n_axis**3 / p
    l = n ** (1 / 3)                         # subdomain edge [cells] (cubic subdomains)
    pp = particles / p
    lg = math.log2(max(p, 2))
    t = {}
    # Fluid computation.
    t["advection"] = k_adv * n / share
    t["diffusion"] = k_diff * n / share
    halo = lambda dof: 6 * ALPHA + 6 * l * l * dof * 8 / BETA
    t["fluid halos"] = SWEEPS * halo(3)
    t["fluid reductions"] = CG_RED * ALPHA_RED * lg
    # Pressure (BoomerAMG): fine-grid work, then every level's halo; coarse levels are latency
    # bound (tens of neighbours once the coarse grids thin out).
    levels = max(1, round(math.log(n_axis**3 / 64, 8)))  # coarsening by about 8 per level to 64 unknowns
    t["pressure"] = k_pres * n / share
    t["pressure halos"] = V_CYCLES * sum(4 * (6 + min(20, lv * 4)) * ALPHA + 6 * (l / 2**lv) ** 2 * 8 / BETA
                                         for lv in range(levels))
    # Particles.
    ghost = ((l + 2 * HALO_D * D_CELLS) ** 3 - l**3) / l**3  # ghost-to-owned ratio
    t["penalization"] = k_pen_cell * n + k_pen * pp
    t["hydro force"] = k_hyd * pp
    t["DEM"] = k_dem * pp * (1 + ghost) * SUBSTEPS  # pairs with ghosts computed on both sides: an upper bound
    neighbours = 26
    t["DEM ghosts"] = SUBSTEPS * (neighbours * ALPHA + pp * ghost * GHOST_BYTES / BETA)
    t["DEM reductions"] = SUBSTEPS * DEM_RED * ALPHA_RED * lg
    return t


def fft_transposes(p):
    """The FFT pressure solve's communication (the alternative to BoomerAMG, not in the step sum):
    two slab transposes per solve, each an all-to-all of the rank's whole field; one slab per rank,
    so p <= n_axis."""
    if p > n_axis:
        return float("nan")
    n = n_axis**3 / p
    return 2 * ((p - 1) * ALPHA + 8 * n / BETA)


table = {p: step_time(p) for p in ranks}
base = ranks[0]
tot = {p: sum(table[p].values()) for p in ranks}
eff = {p: tot[base] * base / (p * tot[p]) for p in ranks}
comm = ["fluid halos", "fluid reductions", "pressure halos", "DEM ghosts", "DEM reductions"]
with open(out_md, "w") as f:
    f.write(f"Projection: {n_axis}^3 cells, {particles:.0f} spheres (d/dx {D_CELLS}), {SUBSTEPS} DEM sub-steps per fluid "
            f"step; computation from one rank of this machine (bandwidth-sharing factor {share:.2f} from two ranks), "
            f"alpha {ALPHA * 1e6:.0f} us, beta {BETA / 1e9:.0f} GB/s per rank, allreduce {ALPHA_RED * 1e6:.0f} us per tree level.\n\n")
    stages = list(table[base].keys())
    f.write("| ranks | " + " | ".join(stages) + " | step (s) | efficiency vs %d | (fft transposes) |\n" % base)
    f.write("|---" * (len(stages) + 4) + "|\n")
    for p in ranks:
        fft = fft_transposes(p)
        f.write(f"| {p} | " + " | ".join(f"{1e3 * table[p][s]:.3g}" for s in stages) +
                f" | {tot[p]:.3g} | {100 * eff[p]:.0f} % | {'-' if fft != fft else f'{1e3 * fft:.3g}'} |\n")
    f.write("\n(stage columns in ms per fluid step; the last column is the communication of the FFT pressure "
            "solve, the alternative to BoomerAMG's halos, possible up to one slab per rank)\n")
    last = ranks[-1]
    # Where the efficiency goes: each stage's time beyond perfect scaling from the base.
    excess = {st: table[last][st] - table[base][st] * base / last for st in stages}
    lost = tot[last] - tot[base] * base / last
    f.write(f"\nAt {last} ranks the step is {1e3 * lost:.3g} ms above perfect scaling from {base}; by stage: " +
            ", ".join(f"{st} {1e3 * v:.3g} ms ({100 * v / lost:.0f} %)"
                      for v, st in sorted(((v, st) for st, v in excess.items()), reverse=True) if v > 0.01 * lost) + ".\n")
print(open(out_md).read())

fig, ax = plt.subplots(1, 2, figsize=(11, 4))
stages = list(table[base].keys())
bottom = [0.0] * len(ranks)
for s in stages:
    v = [100 * table[p][s] / tot[p] for p in ranks]
    ax[0].bar([str(p) for p in ranks], v, bottom=bottom, label=s, hatch="//" if s in comm else None)
    bottom = [b + x for b, x in zip(bottom, v)]
for i, p in enumerate(ranks):
    ax[0].text(i, 101, f"{tot[p]:.3g} s", ha="center", fontsize=7)
ax[0].set_ylim(0, 112)
ax[0].set_ylabel("share of the fluid step (%; hatched: communication)")
ax[0].set_xlabel("ranks")
ax[0].legend(fontsize=6, ncol=2)
ax[0].set_title(f"model: {n_axis}^3 cells, {particles:.0e} spheres")
ax[1].plot(ranks, [100 * eff[p] for p in ranks], "o-")
ax[1].set_xscale("log", base=2)
ax[1].set_xticks(ranks)
ax[1].set_xticklabels([str(p) for p in ranks])
ax[1].set_ylim(0, 105)
ax[1].set_xlabel("ranks")
ax[1].set_ylabel(f"parallel efficiency vs {base} ranks (%)")
ax[1].set_title("projected strong scaling")
fig.tight_layout()
fig.savefig(out_png, dpi=120)
