"""Stacked bars of the immersed collapse's time per step by stage (collapse.csv of collapse.sh):
one pair of bars (before, after) per resolution and rank count."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
stages = ["advection", "diffusion", "pressure", "penalization", "hydroforce", "dem", "io"]
keys = sorted({(int(r["d_dx"]), int(r["ranks"])) for r in rows})
builds = [b for b in ("before", "after") if any(r["build"] == b for r in rows)]
fig, ax = plt.subplots(figsize=(9, 4.5))
width = 0.8 / len(builds)
colours = plt.cm.tab10.colors
for bi, b in enumerate(builds):
    for ki, key in enumerate(keys):
        r = next((r for r in rows if r["build"] == b and (int(r["d_dx"]), int(r["ranks"])) == key), None)
        if r is None:
            continue
        bottom = 0.0
        for si, s in enumerate(stages):
            v = float(r[s + "_s"])
            ax.bar(ki + (bi - (len(builds) - 1) / 2) * width, v, width * 0.95, bottom=bottom, color=colours[si],
                   label=s if (bi == 0 and ki == 0) else None, hatch="//" if b == "before" else None, edgecolor="white")
            bottom += v
        ax.text(ki + (bi - (len(builds) - 1) / 2) * width, bottom, "%.2f" % float(r["step_s"]), ha="center", va="bottom", fontsize=7)
ax.set_xticks(range(len(keys)))
ax.set_xticklabels(["d/dx %d\n%d rank%s" % (d, n, "s" if n > 1 else "") for d, n in keys])
ax.set_ylabel("s per fluid step (slowest rank)")
ax.set_title("Immersed collapse (loose column, 1197 spheres): " + (" vs ".join(builds) if len(builds) > 1 else builds[0]) +
             (" (hatched: before)" if len(builds) > 1 else ""))
ax.legend(fontsize=8, ncol=2)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
