#!/usr/bin/env bash
# scripts/column_phi on a cubic lattice of spacing d (18 x 4 x 14 spheres): phi = pi/6 = 0.524.
set -eu
out=$1
/usr/bin/python3 - "$out" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("id,x,y,z,radius,density,vx,vy,vz,wx,wy,wz\n")
    n = 0
    for i in range(18):
        for j in range(4):
            for k in range(14):
                f.write(f"{n},{(i + 0.5) * 1e-3},{(j + 0.5) * 1e-3},{(k + 0.5) * 1e-3},0.0005,2500,0,0,0,0,0,0\n")
                n += 1
PY
"$(dirname "$0")/../../scripts/column_phi" "$out" --x0 0 --x1 0.018 --width 0.004 | tee /dev/stderr | grep -q "phi = 0.524 "
