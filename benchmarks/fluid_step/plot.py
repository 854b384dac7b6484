#!/usr/bin/python3
"""Fluid step benchmark: share of each stage in a step (stacked, %), total seconds per step on top."""
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(7, 4.5))
labels = ["%s^3, %s rank%s" % (r["n"], r["ranks"], "" if r["ranks"] == "1" else "s") for r in rows]
total = [float(r["step_s"]) for r in rows]
bottom = [0.0] * len(rows)
for stage in ("advection", "diffusion", "pressure"):
    share = [100 * float(r[stage + "_s"]) / t for r, t in zip(rows, total)]
    ax.bar(labels, share, bottom=bottom, label=stage)
    bottom = [b + s for b, s in zip(bottom, share)]
ax.bar(labels, [100 - b for b in bottom], bottom=bottom, label="other")
for i, t in enumerate(total):
    ax.text(i, 101, "%.3g s/step" % t, ha="center", va="bottom", fontsize=9)
ax.set_ylim(0, 112)
ax.set_ylabel("share of the step (%)")
ax.set_title("Fluid step by stage (3-D lid-driven cavity, Re 400)")
ax.legend(fontsize=8, loc="lower right")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
