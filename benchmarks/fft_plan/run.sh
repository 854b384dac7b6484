#!/usr/bin/env bash
# The fft pressure solve against FFTW's own time for its plans, on the d/dx 8 collapse grid
# (512 x 32 x 160, walls in x and z, periodic y), 1 and 2 ranks alternating, twice.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
source "$root/scripts/mpienv"
echo "ranks,nx,ny,nz,solve_ms,transforms_ms,transposes_ms"
for rep in 1 2; do
  for np in 1 2; do mpirun -n "$np" "$root/build/benchmarks/bench_fft_plan" -nx 512 -ny 32 -nz 160 -solves 20 | tail -n 1; done
done
