#!/usr/bin/env bash
# Under mpirun, bad input and what does not yet run on several ranks end like a serial error: one
# line on standard error (from rank 0 alone), nothing on standard output, exit 2 on every rank.
# usage: refusals.sh MPIEXEC DLPVERIFY
set -u
mpiexec=$1 dlpverify=$2
source "$(dirname "$0")/mpi_env.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
# expect CODE PATTERN ARGS...: on 2 ranks, exit CODE and exactly one line of stderr matching PATTERN.
expect() {
  local code=$1 pattern=$2
  shift 2
  run_ranks 2 "$dlpverify" "$@" >"$dir/out" 2>"$dir/err"
  local got=$?
  local lines
  lines=$(grep -c . "$dir/err")
  if [ "$got" -ne "$code" ] || [ "$lines" -ne 1 ] || ! grep -q -- "$pattern" "$dir/err" || [ -s "$dir/out" ]; then
    echo "FAIL: $* exited $got (expected $code), stderr:"
    cat "$dir/err"
    fail=1
  fi
}
# The same line as serially: a bad value found on every rank.
serial=$("$dlpverify" converge --case drag --outer 3 --dt -1 2>&1 >/dev/null)
expect 2 "^$serial\$" converge --case drag --outer 3 --dt -1
# Whole-population SUNDIALS integrators take norms over every member inside their steps.
expect 2 "^dlpverify: --integrator = cvode: steps the whole population at once" converge --case drag --outer 3 --integrator cvode
expect 2 "^dlpverify: --reference = manufactured: its manufactured solution is built from the whole population" converge --case drag --outer 3 --reference manufactured
expect 2 "^dlpverify: command = precision: runs on one process" precision --case drag --outer 3
[ "$fail" -eq 0 ] && echo "ok: refused on 2 ranks with one line and exit 2"
exit "$fail"
