#!/usr/bin/python3
"""Stacked bars of the fluid step benchmark: seconds per step by stage."""
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(7, 4.5))
labels = ["%s^3, %s rank%s" % (r["n"], r["ranks"], "" if r["ranks"] == "1" else "s") for r in rows]
bottom = [0.0] * len(rows)
for stage in ("advection", "diffusion", "pressure"):
    v = [float(r[stage + "_s"]) for r in rows]
    ax.bar(labels, v, bottom=bottom, label=stage)
    bottom = [b + x for b, x in zip(bottom, v)]
other = [float(r["step_s"]) - b for r, b in zip(rows, bottom)]
ax.bar(labels, other, bottom=bottom, label="other")
for i, r in enumerate(rows):
    ax.text(i, float(r["step_s"]), "%.2f s" % float(r["step_s"]), ha="center", va="bottom", fontsize=8)
ax.set_yscale("log")
ax.set_ylabel("seconds per step")
ax.set_title("Fluid step by stage (3-D lid-driven cavity, Re 400)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
