#!/usr/bin/env bash
# The run lifecycle as a user meets it (docs/robustness.md); one scenario per call:
#   check_lifecycle.sh <scenario> <vpsolve> <work dir>
# help | rerun | output_dir_file | restart_setup | signal | killed | wall_limit | disk_full | defaults
set -u
scenario=$1 vp=$2 work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
BOX="-grid_n 8,8,8 -monitor_every 0"
run() { mpirun -n "${NP:-1}" --oversubscribe "$vp" "$@"; }
fail() { echo "FAIL: $*"; exit 1; }
lines() { wc -l < "$1"; }

case $scenario in
help)  # prints the options, exits 0, touches nothing
  run $BOX -time_max_steps 3 -output_dir out >/dev/null 2>&1 || fail "first run"
  before=$(md5sum out/* | md5sum)
  for h in -help -h --help; do
    run $h -output_dir out -grid_n 4,4,4 >help.log 2>&1 || fail "$h exited non-zero"
    grep -q -- "-grid_n <32,32,32> (given: 4,4,4)" help.log || fail "$h does not list -grid_n with its default and given value"
    grep -q -- "-bc_xlo <wall>.*(wall, slip, periodic, velocity)" help.log || fail "$h does not list the choices"
    [ "$(md5sum out/* | md5sum)" = "$before" ] || fail "$h changed the output directory"
  done
  run -help -lub_activation -1 -grid_n 4.5,4,4 >help_bad.log 2>&1 || fail "-help with bad values exited non-zero" ;;
rerun)  # a used directory is refused and kept; -output_overwrite replaces it
  run $BOX -time_max_steps 3 -output_dir out >/dev/null 2>&1 || fail "first run"
  before=$(md5sum out/* | md5sum)
  run $BOX -time_max_steps 5 -output_dir out >rerun.log 2>&1 && fail "a rerun into a used directory ran"
  grep -q "option -output_dir: 'out' holds another run" rerun.log || fail "no message naming -output_dir"
  [ "$(md5sum out/* | md5sum)" = "$before" ] || fail "the refused rerun changed the earlier outputs"
  run $BOX -time_max_steps 5 -output_dir out -output_overwrite >/dev/null 2>&1 || fail "-output_overwrite did not run"
  [ "$(lines out/diagnostics.csv)" = 6 ] || fail "-output_overwrite: diagnostics.csv has $(lines out/diagnostics.csv) lines, not 6"
  [ -e out/fields_000003.h5 ] && fail "-output_overwrite left the old run's fields_000003.h5"
  true ;;
output_dir_file)
  echo keep > afile
  run $BOX -output_dir afile >err.log 2>&1 && fail "ran into a file"
  grep -q "option -output_dir: 'afile' exists and is not a directory" err.log || fail "no message"
  [ "$(cat afile)" = keep ] || fail "the file was changed" ;;
restart_setup)  # a restart with other physics is refused, or warned with -restart_allow_changes
  run $BOX -time_max_steps 4 -checkpoint_every 2 -output_dir out >/dev/null 2>&1 || fail "first run"
  run $BOX -time_max_steps 6 -restart out/checkpoint_000002.h5 -output_dir out -fluid_mu 1e-3 >same.log 2>&1 || fail "restart with the same -fluid_mu written 1e-3 refused: $(grep error same.log)"
  run $BOX -time_max_steps 6 -restart out/checkpoint_000002.h5 -output_dir out -fluid_mu 2e-3 >err.log 2>&1 && fail "restart with another -fluid_mu ran"
  grep -q "option -restart: the checkpoint was written with other set-up options: -fluid_mu 0.001 (now 0.002)" err.log || fail "no message naming -fluid_mu: $(cat err.log)"
  run $BOX -time_max_steps 6 -restart out/checkpoint_000002.h5 -output_dir out -fluid_mu 2e-3 -restart_allow_changes >ok.log 2>&1 || fail "-restart_allow_changes did not run"
  grep -q "warning: continuing with changed set-up options" ok.log || fail "no warning" ;;
signal)  # SIGTERM: a checkpoint at the next step boundary, exit 128 + 15, and the run continues from it.
  # Sent to vpsolve itself (a singleton MPI run): mpirun, when signalled, forwards the signal but
  # reports its own status and may drop the last lines of output.
  "$vp" -grid_n 16,16,16 -time_max_steps 100000 -time_final 1e9 -output_dir out >term.log 2>&1 &
  pid=$!
  for _ in $(seq 200); do [ -s out/diagnostics.csv ] && [ "$(lines out/diagnostics.csv)" -gt 20 ] && break; sleep 0.1; done
  kill -TERM $pid
  wait $pid; echo $? > status
  [ "$(cat status)" = 143 ] || fail "exit status $(cat status), not 143"
  grep -q "stopped at step .*: signal SIGTERM" term.log || fail "no stop reason"
  ls out | grep -q "checkpoint_0.*h5" || fail "no checkpoint"
  grep -q '"stop_reason": "signal SIGTERM"' out/run.json || fail "run.json lacks the stop reason"
  run -grid_n 16,16,16 -time_max_steps 100000 -time_final 1e9 -restart out/checkpoint_latest.h5 -output_dir out -time_wall_limit 1 >cont.log 2>&1 || fail "the run did not continue from the checkpoint" ;;
killed)  # killed outright (no end, no checkpoint): the tracked particle's rows of all but the last 10 s are on disk
  "$vp" -grid_n 32,32,32 -monitor_every 0 -fluid_mu 0.01 -gravity 0,0,-9.81 -particle_position 0.5,0.5,0.7 \
    -particle_radius 0.1 -particle_density 1500 -track_particles all -time_dt 1e-3 -time_final 1e9 -output_dir out >kill.log 2>&1 &
  pid=$!
  sleep 15
  steps=$(($(lines out/diagnostics.csv) - 1))
  kill -KILL $pid; wait $pid
  rows=$(($(lines out/particle_0.csv) - 1))
  [ "$steps" -gt 50 ] || fail "only $steps steps in 15 s"
  [ $((2 * rows)) -ge "$steps" ] || fail "particle_0.csv kept $rows rows of the $steps steps the run had made" ;;
wall_limit)  # -time_wall_limit: a checkpoint and exit 0
  run -grid_n 16,16,16 -time_max_steps 100000 -time_final 1e9 -time_wall_limit 2 -output_dir out >wl.log 2>&1 || fail "exit status $?"
  grep -q "reached -time_wall_limit" wl.log || fail "no stop reason"
  ls out | grep -q "checkpoint_0.*h5" || fail "no checkpoint"
  ls out | grep -q "fields_0.*h5" || fail "no final snapshot" ;;
disk_full)  # a full disk stops the run (status 3) with the earlier snapshots and their index intact
  mkdir small
  mount -t tmpfs -o size=3m tmpfs small 2>/dev/null || { echo "skipped: cannot mount a small file system here"; exit 77; }
  trap 'umount "$work/small"' EXIT
  run -grid_n 16,16,16 -time_max_steps 200 -time_final 1e9 -output_every 1 -output_dir small/out >full.log 2>&1; status=$?
  [ $status = 3 ] || fail "exit status $status, not 3: $(tail -3 full.log)"
  grep -q "the file system of -output_dir 'small/out' has .* MB free, the snapshot of step .* needs about" full.log || fail "no message"
  n=$(ls small/out | grep -c "^fields_.*h5$")
  [ "$n" -gt 3 ] || fail "only $n snapshots before the disk was full"
  [ "$(grep -c "<Grid Name=\"step" small/out/fields.xmf)" = "$n" ] || fail "fields.xmf does not list the $n snapshots on disk"
  /usr/bin/python3 -c "import h5py, sys; [h5py.File(f)['velocity'][...] for f in sys.argv[1:]]" small/out/fields_*.h5 || fail "a snapshot is unreadable" ;;
defaults)  # a lone sphere needs no contact options; LLCM without a roughness runs
  run $BOX -time_max_steps 5 -particle_position 0.5,0.5,0.5 -particle_radius 0.1 -particle_fixed -output_dir lone >lone.log 2>&1 || fail "lone sphere: $(tail -2 lone.log)"
  grep -q "no contact stiffness given: -contact_tc .* s, ten times the first fluid step" lone.log || fail "the chosen contact time is not in the log"
  [ -e lone/fields_000005.h5 ] || fail "no final snapshot after 5 steps"
  run $BOX -time_max_steps 5 -particle_position 0.5,0.5,0.5 -particle_radius 0.1 -lub_model llcm -output_dir llcm >llcm.log 2>&1 || fail "llcm without roughness: $(tail -2 llcm.log)" ;;
*) fail "unknown scenario $scenario" ;;
esac
echo "ok: $scenario"
