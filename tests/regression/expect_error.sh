#!/usr/bin/env bash
# usage: expect_error.sh <np> <regex> <outdir> <command...>
# Runs the command (under mpirun -n np; one rank without mpirun, as a singleton) with -output_dir
# <outdir>, after putting an earlier output in <outdir>. Passes when it exits non-zero, its output
# has exactly one line matching regex (on every rank count: one message, not one per rank), the
# earlier output is intact and nothing else was written (NEW_FILES_OK=1: a run-time failure writes
# its files and a snapshot).
# EXPECT_STATUS: the exit status required; EXPECT_SNAPSHOT=1: a snapshot after the initial one (of the
# step that failed a check) must have been written;
# EXPECT_SNAPSHOT=0: no snapshot after the initial one (of a step that could not be completed).
np=$1; regex=$2; dir=$3; shift 3
rm -rf "$dir"; mkdir -p "$dir"
echo "an earlier result that must survive" > "$dir/earlier_result.txt"
if [ "$np" = 1 ]; then out=$("$@" -output_dir "$dir" 2>&1); rc=$?
else out=$(mpirun -n "$np" --oversubscribe "$@" -output_dir "$dir" 2>&1); rc=$?; fi
if [ $rc -eq 0 ]; then echo "expected a non-zero exit, got 0; output:"; echo "$out"; exit 1; fi
count=$(grep -cE -- "$regex" <<<"$out")
if [ "$count" = 0 ]; then echo "exit $rc but no message matching '$regex'; output:"; echo "$out"; exit 1; fi
if [ "$count" != 1 ]; then echo "the message appears $count times (once expected, whatever the rank count); output:"; echo "$out"; exit 1; fi
if [ "$(cat "$dir/earlier_result.txt" 2>/dev/null)" != "an earlier result that must survive" ]; then echo "the earlier output was changed or removed"; exit 1; fi
if [ -n "${EXPECT_STATUS:-}" ] && [ $rc -ne "$EXPECT_STATUS" ]; then echo "exit status $rc, expected $EXPECT_STATUS"; exit 1; fi
later=$(ls "$dir" | grep -E '^(fields|particles)_[0-9]+\.h5$' | grep -vE '_000000\.h5$')
if [ "${EXPECT_SNAPSHOT:-}" = 1 ] && [ -z "$later" ]; then echo "no snapshot of the failed step written for inspection"; exit 1; fi
if [ "${EXPECT_SNAPSHOT:-}" = 0 ] && [ -n "$later" ]; then echo "a snapshot of the half-advanced step was written: $later"; exit 1; fi
if [ "${NEW_FILES_OK:-0}" != 1 ] && [ "$(ls "$dir" | wc -l)" != 1 ]; then echo "files written before the error: $(ls "$dir" | tr '\n' ' ')"; exit 1; fi
grep -E -- "$regex" <<<"$out" | head -n 1
