#!/usr/bin/env bash
# Under mpirun the rank count never changes a bit of a study (docs/mpi.md): the same converge on
# 1, 2 and 3 ranks gives the serial run's JSON — every level's norms, orders, statuses,
# self-convergence, the CVODE reference's error estimate and counts, the case's diagnostics — except
# wall times, provenance and the echoed options. Ranks own whole norm blocks of 4,096 members, so
# the sizes here give every one of 3 ranks members of its own.
# usage: same_bits.sh MPIEXEC DLPVERIFY ARGS...
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)  # comparable_json.py
mpiexec=$1 dlpverify=$2
shift 2
source "$(dirname "$0")/mpi_env.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$dlpverify" converge "$@" --json "$dir/serial.json" >/dev/null || { echo "FAIL: serial converge exited $?"; exit 1; }
for ranks in 1 2 3; do
  run_ranks "$ranks" "$dlpverify" converge "$@" --json "$dir/r$ranks.json" >"$dir/out$ranks" 2>"$dir/err$ranks" ||
    { echo "FAIL: converge on $ranks ranks exited $?"; cat "$dir/err$ranks"; exit 1; }
  # Only rank 0 prints: the table once.
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
print(f"ok: {serial['particles']} particles, {len(serial['levels'])} levels, the serial bits on 1, 2 and 3 ranks")
PY
