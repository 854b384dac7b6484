#!/usr/bin/env bash
# usage: expect_error.sh <np> <regex> <command...>
# Passes when the command (run under mpirun -n np) exits non-zero AND its output matches regex.
np=$1; regex=$2; shift 2
out=$(mpirun -n "$np" --oversubscribe "$@" 2>&1); rc=$?
if [ $rc -eq 0 ]; then echo "expected a non-zero exit, got 0; output:"; echo "$out"; exit 1; fi
if ! grep -qE -- "$regex" <<<"$out"; then echo "exit $rc but no message matching '$regex'; output:"; echo "$out"; exit 1; fi
grep -E -- "$regex" <<<"$out" | head -n 1
