#!/usr/bin/env bash
# The thread count never changes a bit of a result (issue 9, item 8): the same study on 1, 2 and
# 3 threads gives the same JSON — every level's norms, orders, statuses, self-convergence and the
# CVODE reference's error estimate — except wall times, provenance and the echoed options.
# usage: threads_same_bits.sh DLPVERIFY ARGS...
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)  # comparable_json.py
dlpverify=$1
shift
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for threads in 1 2 3; do
  "$dlpverify" converge "$@" --threads "$threads" --json "$dir/t$threads.json" >/dev/null ||
    { echo "FAIL: converge on $threads threads exited $?"; exit 1; }
done
PYTHONPATH="$tests" /usr/bin/python3 - "$dir" <<'PY'
import json, sys
from comparable_json import comparable
folder = sys.argv[1]
def result(threads):
    return comparable(f"{folder}/t{threads}.json")
one = result(1)
for threads in (2, 3):
    if result(threads) != one:
        print(f"FAIL: {threads} threads differ from 1 thread")
        sys.exit(1)
print(f"ok: {one['particles']} particles, {len(one['levels'])} levels, the same bits on 1, 2 and 3 threads")
PY
