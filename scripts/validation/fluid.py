#!/usr/bin/python3
"""Fluid validation: Taylor-Green convergence (N = 16..128) and the channel's Poiseuille profile.
Runs vpsolve, reads its HDF5 output, writes docs/validation/{taylor_green_convergence,channel_profile}.png."""
import math, os, subprocess
import h5py
import numpy as np
from common import plt, root, ranks as np_ranks, vpsolve, outdir, help_requested

help_requested(__doc__)


def run(case, out, *opts):
    cmd = ["mpirun", "-n", np_ranks, vpsolve, "-options_file", os.path.join(root, "cases", case),
           "-output_dir", out, "-output_overwrite", "-monitor_every", "0"] + list(opts)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def last_fields(out):
    files = sorted(f for f in os.listdir(out) if f.startswith("fields_") and f.endswith(".h5"))
    return h5py.File(os.path.join(out, files[-1]), "r")


def taylor_green():
    ns, errs = [16, 32, 64, 128], []
    nu, T = 0.01, 2.0
    for n in ns:
        out = "/tmp/vp_validate_tg_%d" % n
        L = 2 * math.pi
        run("taylor_green.opts", out, "-grid_n", "%d,%d,2" % (n, n), "-grid_hi", "%r,%r,%r" % (L, L, 2 * L / n),
            "-output_dt", "0", "-output_every", "100000", "-time_final", str(T))
        with last_fields(out) as f:
            u = f["velocity"][...]
            t = f.attrs["time"][0]
            h = f.attrs["spacing"]
        x = (np.arange(n) + 0.5) * h[0]
        X, Y = np.meshgrid(x, x, indexing="xy")
        decay = math.exp(-2 * nu * t)
        ue, ve = np.cos(X) * np.sin(Y) * decay, -np.sin(X) * np.cos(Y) * decay
        errs.append(max(abs(u[0, :, :, 0] - ue).max(), abs(u[0, :, :, 1] - ve).max()))
    orders = [math.log2(errs[i] / errs[i + 1]) for i in range(len(errs) - 1)]
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.loglog(ns, errs, "o-", label="vpsolve (cell-centred output)")
    ax.loglog(ns, [errs[0] * (ns[0] / n) ** 2 for n in ns], "k--", label="second order")
    for n, e, o in zip(ns[1:], errs[1:], orders):
        ax.annotate("%.2f" % o, (n, e), textcoords="offset points", xytext=(5, 5), fontsize=8)
    ax.set_xticks(ns)
    ax.set_xticklabels([str(n) for n in ns])
    ax.minorticks_off()
    ax.set_xlabel("N (cells per 2 pi)")
    ax.set_ylabel("max |u - u_exact| at t = %g" % T)
    ax.set_title("Taylor-Green vortex, CFL 0.5, nu = 0.01")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "taylor_green_convergence.png"), dpi=120)
    print("taylor-green: errors", ["%.3e" % e for e in errs], "orders", ["%.2f" % o for o in orders])


def channel():
    out = "/tmp/vp_validate_channel"
    run("channel.opts", out)
    with last_fields(out) as f:
        u = f["velocity"][...]
        h = f.attrs["spacing"]
        t = f.attrs["time"][0]
    ny = u.shape[1]
    y = (np.arange(ny) + 0.5) * h[1]
    profile = u[:, :, :, 0].mean(axis=(0, 2))
    exact = 0.01 / (2 * 0.01) * y * (1 - y)
    fine = np.linspace(0, 1, 200)
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(0.5 * fine * (1 - fine), fine, "k-", label="exact f/(2 nu) y (1 - y)")
    ax.plot(profile, y, "o", ms=4, label="vpsolve, t = %g s" % t)
    ax.set_xlabel("u (m/s)")
    ax.set_ylabel("y (m)")
    ax.set_title("Plane Poiseuille flow (cases/channel.opts)\nmax relative deviation %.1e" % (abs(profile - exact).max() / exact.max()))
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "channel_profile.png"), dpi=120)
    print("channel: max relative deviation %.2e" % (abs(profile - exact).max() / exact.max()))


taylor_green()
channel()
