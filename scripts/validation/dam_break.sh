#!/usr/bin/env bash
# The full immersed dam breaks (docs/dam_break.md): the loose and the dense column at N cells per
# diameter (default 8) until they come to rest (the 99th-percentile front slower than 0.1 d/s over
# 0.5 s: -collapse_rest_speed) or time T (default 30 s; at d/dx 6 the dense column rested at 14.9 s),
# then scripts/plot_dam_break into docs/validation; with NP=1 the two columns run side by side.
# `grid` instead of N: the grid check, the loose column at d/dx 8 and 12 to rest, figures
# docs/validation/dam_break_grid_8_12_*.png and the runouts compared. Checkpoints every 250 steps;
# run again, the script continues each column from its latest checkpoint (a run cut short by a job's
# time limit loses at most 250 steps) and skips a column that came to rest (marked DIR/at_rest); the
# console goes to DIR.log as well; delete output/validate_dam_break_* to start afresh.
# S (a whole number, default 1): the height study, columns S times as long and as high (about 15 S
# diameters high, S^2 times the spheres) in a tank S times as long and high, the slab as before;
# the columns are prepared first when missing (scripts/prepare_columns --scale S, into output/).
# SPREAD=R (environment): slightly polydisperse columns instead (radii uniform in a (1 - R) ..
# a (1 + R); scripts/prepare_columns --spread R, prepared when missing), outputs suffixed _spreadR.
# PROJECTION=weighted (environment): the weighted projection (no liquid through the spheres;
# docs/coupling.md) with BoomerAMG, outputs suffixed _weighted (about ten times the step's cost).
# usage (through scripts/validate): scripts/validate dam_break [N|grid [T [S]]]
# Cost on 2 cores (measured): d/dx 6 about 0.3 s per step of 1e-3 s (5 minutes per simulated
# second), d/dx 8 about 0.84 s (14 minutes), d/dx 12 about 1.6 s (27 minutes), per column; with
# NP=1 (side by side, a core each) S 2 at d/dx 4 about 0.56 s per step.
set -euo pipefail
case ${1:-8} in
  -h|--help) sed -n "2,21s/^# \{0,1\}//p" "$0"; exit 0 ;;
  grid|[1-9]|[1-9][0-9]) ;;
  *) echo "dam_break: N must be whole cells per diameter (1-99) or 'grid', not '$1'" >&2; exit 2 ;;
esac
t=${2:-30}
scale=${3:-1}
[[ $scale =~ ^[1-9]$ ]] || { echo "dam_break: S must be a whole number 1-9, not '$scale'" >&2; exit 2; }
spread=${SPREAD:-0}
awk -v r="$spread" 'BEGIN { exit !(r + 0 == r && r >= 0 && r <= 0.5) }' ||
  { echo "dam_break: SPREAD must be a number in [0, 0.5], not '$spread'" >&2; exit 2; }
# The name suffixes of the height, polydispersity and projection studies (empty for the shipped set-up).
tall_tag=$([ "$scale" = 1 ] || echo "_x$scale")
spread_tag=$([ "$spread" = 0 ] || echo "_spread$spread")
projection=${PROJECTION:-plain}
case $projection in
  plain) proj_tag="" proj_opts=() ;;
  weighted) proj_tag=_weighted proj_opts=(-penalization_projection weighted -pressure_pc_type hypre) ;;
  *) echo "dam_break: PROJECTION must be plain or weighted, not '$projection'" >&2; exit 2 ;;
esac
cd "$VP_ROOT"
mkdir -p output
labels=()
bind=()  # mpirun's process binding: Open MPI's default unless the columns run side by side

# column KIND N: the KIND (loose, dense) column at N cells per diameter, to rest or t = T.
column() {
  local kind=$1 n=$2 case_file=cases/dam_break.opts
  [ "$kind" = dense ] && case_file=cases/dam_break_dense.opts
  local grid="$((64 * n * scale)),$((4 * n)),$((20 * n * scale))" out=output/validate_dam_break_${kind}_d$n
  local tall=() file=""
  if [ "$scale" != 1 ]; then
    out=${out}_x$scale
    file=output/column_${kind}_x$scale.csv
    local at=(0.0095 0.062 0.019 0.064 0.020)  # the probes' x, x, z and the tank's length and height (m)
    for i in "${!at[@]}"; do at[$i]=$(awk -v v="${at[$i]}" -v s="$scale" 'BEGIN { print v * s }'); done
    tall=(-grid_hi "${at[3]},0.004,${at[4]}" -probe "${at[0]},0.002,0.00025,${at[1]},0.002,${at[2]}")
  fi
  if [ "$spread" != 0 ]; then
    file=output/column_${kind}${tall_tag}${spread_tag}.csv
    out=${out}_spread$spread
  fi
  out=$out$proj_tag
  if [ -n "$file" ]; then
    [ -e "$file" ] || scripts/prepare_columns $([ "$scale" = 1 ] || echo "--scale $scale") \
      $([ "$spread" = 0 ] || echo "--spread $spread") "$kind"
    tall+=(-particles_file "$file")
  fi
  labels+=("$(basename "$out" | sed 's/^validate_dam_break_//')=$out")
  # A column at rest is done: a restart would begin a new rest window and run on for 0.5 s.
  if [ -e "$out/at_rest" ]; then echo "dam break $kind, d/dx $n: at rest ($(cat "$out/at_rest")); delete $out to run it again"; return; fi
  local start=(-output_overwrite)
  if [ -e "$out/checkpoint_latest.h5" ]; then start=(-restart "$out/checkpoint_latest.h5"); fi
  echo "dam break $kind, d/dx $n ($grid cells), to rest or t = $t s -> $out (${start[*]})"
  mpirun "${bind[@]}" -n "$NP" build/vpsolve -options_file "$case_file" -grid_n "$grid" "${tall[@]}" "${proj_opts[@]}" -time_final "$t" -output_dir "$out" \
    "${start[@]}" -monitor_every 200 -output_dt 0.1 -checkpoint_every 250 \
    -collapse_rest_speed 1e-4 -collapse_rest_window 0.5 | tee -a "$out.log"
  local stopped
  if stopped=$(grep "stopped at step" "$out.log" | tail -1) && [[ $stopped == *"came to rest"* ]]; then echo "${stopped#vpsolve: }" > "$out/at_rest"; fi
}

if [ "${1:-8}" = grid ]; then
  column loose 8
  column loose 12
  scripts/plot_dam_break --out docs/validation --name dam_break_grid_8_12 "${labels[@]}"
else
  n=${1:-8}
  # One rank each: the two columns side by side (each column's console in its log only), unbound:
  # Open MPI binds a lone rank to the first core, so two runs would share it.
  if [ "$NP" = 1 ]; then
    bind=(--bind-to none)
    column loose "$n" >/dev/null & loose=$!
    column dense "$n" >/dev/null & dense=$!
    wait "$loose"; wait "$dense"  # a column that fails stops the script
    tag=$tall_tag$spread_tag$proj_tag
    labels=("loose_d$n$tag=output/validate_dam_break_loose_d$n$tag" "dense_d$n$tag=output/validate_dam_break_dense_d$n$tag")
  else
    column loose "$n"
    column dense "$n"
  fi
  if [ "$spread" != 0 ] || [ -n "$proj_tag" ]; then  # beside the shipped set-up's columns of the same grid and height, when run
    for kind in dense loose; do
      dir=output/validate_dam_break_${kind}_d$n$tall_tag
      [ -d "$dir" ] && labels=("${kind}_d$n$tall_tag=$dir" "${labels[@]}")
    done
  fi
  scripts/plot_dam_break --out docs/validation --name "dam_break_d$n$tall_tag$spread_tag$proj_tag" "${labels[@]}"
fi
