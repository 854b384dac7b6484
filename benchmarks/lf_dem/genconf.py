#!/usr/bin/python3
"""Random non-overlapping bidisperse (or monodisperse) configuration in LF_DEM's text format.

LF_DEM's own generator (`LF_DEM -g seed`) aborts at the commit built here ("Can't adapt dt!": its
first relaxation step has no velocity yet), so this does the same thing in numpy: random positions in
a cubic periodic box at the target volume fraction, then overlaps removed by gradient descent on a
harmonic overlap energy with radii inflated by 1 % (as LF_DEM's generator does), to min gap > 0.
usage: genconf.py N phi a2 vf_ratio_small seed out.dat   (a1 = 1; a2 = 1 for monodisperse)"""
import sys
import numpy as np

def generate(n, phi, a2, vf1, seed):
    rng = np.random.default_rng(seed)
    v1, v2 = 4 / 3 * np.pi, 4 / 3 * np.pi * a2**3
    if a2 == 1:
        n1, n2 = n, 0
    else:
        n1 = int(round(n * (vf1 / v1) / (vf1 / v1 + (1 - vf1) / v2)))
        n2 = n - n1
    vol_p = n1 * v1 + n2 * v2
    L = (vol_p / phi) ** (1 / 3)
    r = np.r_[np.ones(n1), np.full(n2, a2)]
    x = rng.random((n, 3)) * L
    rin = r * 1.01
    sumr = rin[:, None] + rin[None, :]
    np.fill_diagonal(sumr, 0)
    step = 0.2
    for it in range(20000):
        d = x[:, None, :] - x[None, :, :]
        d -= L * np.round(d / L)
        dist = np.sqrt((d**2).sum(-1))
        np.fill_diagonal(dist, np.inf)
        ov = sumr - dist
        ov[ov < 0] = 0
        if it % 50 == 0:
            true_gap = (dist - (r[:, None] + r[None, :])).min()
            if true_gap > 0 and ov.max() < 0.01 * 2:  # no true overlap; inflated overlap < 1 %
                break
        if not ov.any():
            break
        f = ((ov / dist)[:, :, None] * d).sum(1)
        x = (x + step * f) % L
    d = x[:, None, :] - x[None, :, :]
    d -= L * np.round(d / L)
    dist = np.sqrt((d**2).sum(-1))
    np.fill_diagonal(dist, np.inf)
    gap = (dist - (r[:, None] + r[None, :])).min()
    return x, r, L, n1, n2, vf1 * phi if n2 else phi, (1 - vf1) * phi if n2 else 0.0, gap, it

if __name__ == "__main__":
    n, phi, a2, vf1, seed, out = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]), sys.argv[6]
    x, r, L, n1, n2, phi1, phi2, gap, it = generate(n, phi, a2, vf1, seed)
    with open(out, "w") as f:
        f.write("# np1 np2 vf lx ly lz vf1 vf2 disp\n")
        f.write(f"# {n1} {n2} {phi} {L!r} {L!r} {L!r} {phi1} {phi2} 0\n")
        for p, a in zip(x, r):
            f.write(f"{p[0]!r} {p[1]!r} {p[2]!r} {a!r}\n")
    print(f"{out}: N {n1}+{n2}, L {L:.4f}, min gap {gap:.4f}, {it} iterations")
