#!/usr/bin/env bash
# Under mpirun the rank count never changes a bit of a study (docs/mpi.md): the same COMMAND on 1,
# 2 and 3 ranks gives the serial run's JSON — except wall times, provenance and the echoed options.
# For converge: every level's norms, orders, statuses, self-convergence, the CVODE reference's error
# estimate and counts, the case's diagnostics. For a sweep of runs — precision (CVODE's Adams and
# BDF runs, whose sums span the ranks, and the fixed-step levels) or check --tolerances (CVODE or
# ARKODE's adaptive methods, whose error tests, Newton and GMRES iterations sum over every rank) —
# every error norm, step, RHS and iteration count, the fitted exponents, the reference's counts.
# Ranks own whole norm blocks of 4,096 members, so the sizes given give every one of 3 ranks
# members of its own.
# usage: same_bits.sh MPIEXEC DLPVERIFY COMMAND ARGS...
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)  # comparable_json.py
mpiexec=$1 dlpverify=$2 command=$3
shift 3
source "$(dirname "$0")/mpi_env.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$dlpverify" "$command" "$@" --json "$dir/serial.json" >/dev/null || { echo "FAIL: serial $command exited $?"; exit 1; }
for ranks in 1 2 3; do
  run_ranks "$ranks" "$dlpverify" "$command" "$@" --json "$dir/r$ranks.json" >"$dir/out$ranks" 2>"$dir/err$ranks" ||
    { echo "FAIL: $command on $ranks ranks exited $?"; cat "$dir/err$ranks"; exit 1; }
  # Only rank 0 prints: a levels table at most once.
  [ "$(grep -c '^level  ' "$dir/out$ranks")" -le 1 ] || { echo "FAIL: more than one rank printed"; exit 1; }
done
PYTHONPATH="$tests" /usr/bin/python3 - "$dir" <<'PY'
import json, sys
from comparable_json import comparable
folder = sys.argv[1]
def result(name):
    return comparable(f"{folder}/{name}.json")
serial = result("serial")
for ranks in (1, 2, 3):
    if result(f"r{ranks}") != serial:
        print(f"FAIL: {ranks} ranks differ from the serial run")
        sys.exit(1)
what = "levels" if "levels" in serial else "runs"
print(f"ok: {serial['particles']} particles, {len(serial[what])} {what}, the serial bits on 1, 2 and 3 ranks")
PY
