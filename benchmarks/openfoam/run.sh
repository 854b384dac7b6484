#!/usr/bin/env bash
# vpsolve against OpenFOAM icoFoam (Debian's openfoam, installed here if missing) on the 64^3
# lid-driven cavity of cavity64/ (Re 100, 50 steps of dt 5e-4, no output; the OpenFOAM case is
# the tutorial set-up scaled to 64^3: PISO with 2 correctors, GAMG pressure). Whole-process wall
# time, the codes run alternately (vpsolve default, vpsolve fft, icoFoam) REPS times on 1 and 2
# ranks; writes results.csv (one row per run) and prints medians and ratios.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
REPS=${REPS:-3}
command -v icoFoam >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends openfoam >/dev/null
export WM_PROJECT_DIR=/usr/share/openfoam
source "$root/scripts/mpienv"
"$root/scripts/build" >/dev/null
work=$(mktemp -d /tmp/vp_bench_of.XXXX)
cp -r "$here/cavity64" "$work/of"
(cd "$work/of" && blockMesh >log.blockMesh 2>&1 && decomposePar >log.decomposePar 2>&1)
cavity="-grid_n 64,64,64 -grid_lo 0,0,0 -grid_hi 0.1,0.1,0.1 -bc_xlo wall -bc_xhi wall -bc_ylo wall -bc_yhi velocity
 -bc_yhi_velocity 1,0,0 -bc_zlo wall -bc_zhi wall -fluid_rho 1 -fluid_mu 1e-3 -time_dt 5e-4 -time_max_steps 50 -output_every 0"
out="$here/results.csv"
echo "code,ranks,rep,wall_s,kinetic_energy" > "$out"
timed() { local s e; s=$(date +%s.%N); "$@" >/dev/null 2>&1; e=$(date +%s.%N); echo "$e - $s" | bc -l; }
ke() { tail -n 1 "$1/diagnostics.csv" | cut -d, -f7; }
for np in 1 2; do
  for rep in $(seq "$REPS"); do
    # shellcheck disable=SC2086
    t=$(timed mpirun -n "$np" "$root/build/vpsolve" $cavity -output_dir "$work/vp_amg"); echo "vpsolve_boomeramg,$np,$rep,$t,$(ke "$work/vp_amg")" >> "$out"
    # shellcheck disable=SC2086
    t=$(timed mpirun -n "$np" "$root/build/vpsolve" $cavity -pressure_pc_type fft -output_dir "$work/vp_fft"); echo "vpsolve_fft,$np,$rep,$t,$(ke "$work/vp_fft")" >> "$out"
    rm -rf "$work/vp_amg" "$work/vp_fft"
    if [ "$np" -eq 1 ]; then t=$(cd "$work/of" && timed icoFoam)
    else t=$(cd "$work/of" && timed mpirun -n 2 icoFoam -parallel); fi
    echo "icoFoam,$np,$rep,$t," >> "$out"
    tail -n 3 "$out"
  done
done
/usr/bin/python3 - "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for np in ("1", "2"):
    med = {c: statistics.median(float(r["wall_s"]) for r in rows if r["code"] == c and r["ranks"] == np)
           for c in ("vpsolve_boomeramg", "vpsolve_fft", "icoFoam")}
    print("%s rank(s): icoFoam %.2f s, vpsolve BoomerAMG %.2f s (%.1fx), vpsolve fft %.2f s (%.1fx)" % (
        np, med["icoFoam"], med["vpsolve_boomeramg"], med["icoFoam"] / med["vpsolve_boomeramg"],
        med["vpsolve_fft"], med["icoFoam"] / med["vpsolve_fft"]))
PY
rm -rf "$work"
