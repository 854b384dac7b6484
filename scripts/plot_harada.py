#!/usr/bin/env python3
"""Plot Harada point-particle runs: approach velocity u(t) and wall approach (gap vs time).

usage: scripts/plot_harada.py [-o out.png] [--terminal U] label=path/particle_0.csv ...
Each CSV is written by build/harada (columns time, y, vy, gap, ...). Needs numpy and matplotlib.
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in ("time", "vy", "gap")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="label=csv")
    ap.add_argument("-o", "--output", default="docs/validation/harada_falling_sphere.png")
    ap.add_argument("--terminal", type=float, default=0.1462, help="terminal velocity line (m/s)")
    ap.add_argument("--diameter", type=float, default=0.0254, help="sphere diameter (m) for gap/d")
    ap.add_argument("--roughness", type=float, default=2e-4, help="roughness gap / d, drawn as a line")
    args = ap.parse_args()

    fig, (ax_u, ax_h) = plt.subplots(1, 2, figsize=(11, 4.2))
    for run in args.runs:
        label, path = run.split("=", 1)
        d = read(path)
        ax_u.plot(d["time"], -d["vy"], label=label)
        ax_h.semilogy(d["time"], d["gap"] / args.diameter, label=label)
    ax_u.axhline(args.terminal, color="k", ls="--", lw=0.8, label=f"Schiller-Naumann terminal {args.terminal} m/s")
    ax_u.set_xlabel("t (s)")
    ax_u.set_ylabel("approach velocity -v_y (m/s)")
    ax_u.set_title("Velocity")
    ax_u.grid(alpha=0.3)
    ax_u.legend(fontsize=8)
    ax_h.axhline(args.roughness, color="k", ls=":", lw=0.8, label="roughness gap (contact)")
    ax_h.set_xlabel("t (s)")
    ax_h.set_ylabel("gap h / d")
    ax_h.set_title("Wall approach")
    ax_h.grid(alpha=0.3, which="both")
    ax_h.legend(fontsize=8)
    fig.suptitle("Seed falling sphere, Harada point-particle model (St 3.3)")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
