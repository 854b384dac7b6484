#!/usr/bin/python3
"""Bar chart of the Poisson benchmark: seconds per solve for each solver, grid and rank count."""
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
solvers = list(dict.fromkeys(r["solver"] for r in rows))
groups = list(dict.fromkeys((r["n"], r["ranks"]) for r in rows))
fig, ax = plt.subplots(figsize=(9, 4.5))
w = 0.8 / len(solvers)
for k, s in enumerate(solvers):
    t = [next((float(r["solve_s"]) for r in rows if r["solver"] == s and (r["n"], r["ranks"]) == g), 0) for g in groups]
    its = [next((r["iterations"] for r in rows if r["solver"] == s and (r["n"], r["ranks"]) == g), "") for g in groups]
    bars = ax.bar([i + k * w for i in range(len(groups))], t, w, label=s)
    for b, it in zip(bars, its):
        ax.text(b.get_x() + b.get_width() / 2, b.get_height(), "%s it" % it, ha="center", va="bottom", fontsize=7)
ax.set_xticks([i + 0.4 - w / 2 for i in range(len(groups))])
ax.set_xticklabels(["%s^3, %s rank%s" % (n, p, "" if p == "1" else "s") for n, p in groups])
ax.set_yscale("log")
ax.set_ylabel("seconds per solve (rtol 1e-10, zero initial guess)")
ax.set_title("Pressure Poisson, closed box (singular Neumann)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
