#!/usr/bin/env bash
# usage: expect_error.sh <np> <regex> <outdir> <command...>
# Runs the command (under mpirun -n np) with -output_dir <outdir>, after putting an earlier output
# in <outdir>. Passes when it exits non-zero, its output matches regex, the earlier output is intact
# and nothing else was written (NEW_FILES_OK=1: a run-time failure writes its files and a snapshot).
# EXPECT_STATUS: the exit status required; EXPECT_SNAPSHOT=1: a snapshot must have been written.
np=$1; regex=$2; dir=$3; shift 3
rm -rf "$dir"; mkdir -p "$dir"
echo "an earlier result that must survive" > "$dir/earlier_result.txt"
out=$(mpirun -n "$np" --oversubscribe "$@" -output_dir "$dir" 2>&1); rc=$?
if [ $rc -eq 0 ]; then echo "expected a non-zero exit, got 0; output:"; echo "$out"; exit 1; fi
if ! grep -qE -- "$regex" <<<"$out"; then echo "exit $rc but no message matching '$regex'; output:"; echo "$out"; exit 1; fi
if [ "$(cat "$dir/earlier_result.txt" 2>/dev/null)" != "an earlier result that must survive" ]; then echo "the earlier output was changed or removed"; exit 1; fi
if [ -n "${EXPECT_STATUS:-}" ] && [ $rc -ne "$EXPECT_STATUS" ]; then echo "exit status $rc, expected $EXPECT_STATUS"; exit 1; fi
if [ "${EXPECT_SNAPSHOT:-0}" = 1 ] && ! ls "$dir" | grep -qE '^(fields|particles)_[0-9]+\.h5$'; then echo "no snapshot written for inspection"; exit 1; fi
if [ "${NEW_FILES_OK:-0}" != 1 ] && [ "$(ls "$dir" | wc -l)" != 1 ]; then echo "files written before the error: $(ls "$dir" | tr '\n' ' ')"; exit 1; fi
grep -E -- "$regex" <<<"$out" | head -n 1
