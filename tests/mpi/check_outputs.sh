#!/usr/bin/env bash
# `check` under mpirun writes what the serial run writes (docs/mpi.md): the verdict and exit code,
# the JSON (but for wall times, provenance and the echoed options) and, byte for byte, the
# per-particle file (rank 0 gathers the finest state and the reference) and the error history
# (its norms reduced over every rank, the CVODE reference continued in blocks on each).
# 11,512 particles at R_out 14: 3 norm blocks, one per rank.
# usage: check_outputs.sh MPIEXEC DLPVERIFY
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)  # comparable_json.py
mpiexec=$1 dlpverify=$2
source "$(dirname "$0")/mpi_env.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
study=(check --case full --outer 14 --levels 3 --expect-order 2)
"$dlpverify" "${study[@]}" --json "$dir/s.json" --per-particle "$dir/s.csv" --history "$dir/s-history.csv" >/dev/null ||
  { echo "FAIL: the serial check exited $?"; exit 1; }
run_ranks 3 "$dlpverify" "${study[@]}" --json "$dir/r.json" --per-particle "$dir/r.csv" --history "$dir/r-history.csv" \
  >/dev/null 2>"$dir/err" || { echo "FAIL: check on 3 ranks exited $?"; cat "$dir/err"; exit 1; }
cmp "$dir/s.csv" "$dir/r.csv" || { echo "FAIL: the per-particle files differ"; exit 1; }
cmp "$dir/s-history.csv" "$dir/r-history.csv" || { echo "FAIL: the histories differ"; exit 1; }
PYTHONPATH="$tests" /usr/bin/python3 - "$dir/s.json" "$dir/r.json" <<'PY'
import json, sys
from comparable_json import comparable
def result(path):
    return comparable(path)
if result(sys.argv[1]) != result(sys.argv[2]):
    print("FAIL: check on 3 ranks gives another JSON than serially")
    sys.exit(1)
print("ok: check on 3 ranks: the serial verdict, JSON, per-particle file and history")
PY
