#!/usr/bin/python3
"""Coupling benchmark: share of each stage in a fluid step (stacked %), seconds per step on top."""
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
stages = ["advection", "diffusion", "pressure", "penalization", "hydroforce", "dem", "exchange"]
fig, ax = plt.subplots(figsize=(8, 4.5))
labels = ["%s part., %s rank%s" % (r["particles"], r["ranks"], "" if r["ranks"] == "1" else "s") for r in rows]
total = [float(r["step_s"]) for r in rows]
bottom = [0.0] * len(rows)
for st in stages:
    share = [100 * float(r[st + "_s"]) / t for r, t in zip(rows, total)]
    ax.bar(labels, share, bottom=bottom, label=st)
    bottom = [b + s for b, s in zip(bottom, share)]
for i, t in enumerate(total):
    ax.text(i, 101, "%.3g s" % t, ha="center", va="bottom", fontsize=8)
ax.set_ylim(0, 112)
ax.set_ylabel("share of the fluid step (%)")
ax.set_title("Coupled step by stage, 128^3, spheres with d/dx = 8")
ax.tick_params(axis="x", labelsize=7)
ax.legend(fontsize=7, loc="lower right")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
