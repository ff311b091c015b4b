#!/usr/bin/env bash
# Under mpirun a sweep of runs gives the serial run's JSON on 1, 2 and 3 ranks (docs/mpi.md): a
# work-precision sweep (precision: CVODE's Adams and BDF runs, whose sums span the ranks, and the
# fixed-step levels) or a tolerance sweep (check --tolerances: CVODE or ARKODE's adaptive methods,
# explicit and implicit, whose error tests, Newton and GMRES iterations sum over every rank) —
# every error norm, step, RHS and iteration count, the fitted exponents, the reference's counts —
# except wall times, provenance and the echoed options.
# usage: same_bits_sweep.sh MPIEXEC DLPVERIFY COMMAND ARGS...
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
print(f"ok: {serial['particles']} particles, {len(serial['runs'])} runs, the serial bits on 1, 2 and 3 ranks")
PY
