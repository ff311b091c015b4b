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
# The implicit schemes take norms over every member inside their steps (CVODE's and ARKODE's sums
# span the ranks, docs/mpi.md), and so does an integrator reference of CVODE.
expect 2 "^dlpverify: --integrator = implicit-fp: steps the whole population at once" converge --case drag --outer 3 --integrator implicit-fp
expect 2 "^dlpverify: --reference = integrator:cvode: steps the whole population at once" converge --case drag --outer 3 --reference integrator:cvode@1e-4
expect 2 "^dlpverify: --reference = manufactured: its manufactured solution is built from the whole population" converge --case drag --outer 3 --reference manufactured
# The memory estimate is each rank's (docs/mpi.md): 4 copies of its half (5 with --per-particle,
# state_copies in src/case_study/setup.cpp), and on rank 0 the 2 whole states it gathers for --per-particle only (R_out 2000: 33.5 G particles, 2.14 TB a whole state,
# as tests/cli/limits.sh).
expect 2 "^dlpverify: --outer = 2000: the study needs about .* (on rank 0: 4 copies of its .* members' state) but" converge --case drag --outer 2000
expect 2 "^dlpverify: --outer = 2000: the study needs about .* (on rank 0: 5 copies of its .* members' state and 2 of the whole, 2.14 TB) but" converge --case drag --outer 2000 --per-particle "$dir/errors.csv"
expect 2 "^dlpverify: command = audit: runs on one process" audit
expect 2 "^dlpverify: command = analyze: runs on one process" analyze a.h5 b.h5
# A tolerance sweep of a program of yours gives it the whole population.
expect 2 "^dlpverify: --integrator = exec:prog {rtol}: steps the whole population at once" check --case drag --outer 3 --integrator "exec:prog {rtol}" --tolerances 1e-4:1e-6
# A diagonally implicit tableau's Newton iteration spans the population: one rank only.
sdirk="$(cd "$(dirname "$0")/../.." && pwd)/examples/tableaux/sdirk2-alexander.toml"
expect 2 "^dlpverify: --integrator = tableau:$sdirk: a diagonally implicit tableau steps the whole population on one rank" converge --case drag --outer 3 --integrator "tableau:$sdirk"
[ "$fail" -eq 0 ] && echo "ok: refused on 2 ranks with one line and exit 2"
exit "$fail"
