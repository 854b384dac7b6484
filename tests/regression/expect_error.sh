#!/bin/sh
# usage: expect_error.sh <regex> <command> [args...]
# Passes when the command exits non-zero and its output matches the (extended) regex.
pattern=$1; shift
out=$("$@" 2>&1); rc=$?
printf '%s\n' "$out"
if [ "$rc" -eq 0 ]; then echo "expected a non-zero exit, got 0"; exit 1; fi
printf '%s\n' "$out" | grep -Eq -e "$pattern" || { echo "expected output matching: $pattern"; exit 1; }
