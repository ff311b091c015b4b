#!/usr/bin/env bash
# Runs a command, then checks its exit code and that its standard output holds TEXT (fixed text,
# grep -F). The output is read whole before it is searched, so the command's own status is kept
# (a crash after the matching line fails) and no reader stops early.
#
# usage: expect_output.sh CODE TEXT -- COMMAND ARGS...
set -euo pipefail
expected=$1 text=$2
shift 2
[ "$1" = "--" ] && shift
errors=$(mktemp)
trap 'rm -f "$errors"' EXIT
code=0
out=$("$@" 2>"$errors") || code=$?
err=$(cat "$errors")
fail() { echo "FAIL: $*"; echo "--- stdout:"; printf '%s\n' "$out" | sed -n 1,60p; echo "--- stderr:"; printf '%s\n' "$err"; exit 1; }
[ "$code" -eq "$expected" ] || fail "exit code $code, expected $expected"
grep -qF -- "$text" <<<"$out" || fail "standard output does not hold: $text"
echo "ok: exit $code, output holds: $text"
