#!/usr/bin/env bash
# A solver failure in a block only rank 1 owns (docs/mpi.md): the serial run's one line and exit 3,
# nothing on standard output, no JSON. At R_out 11 and --max-steps 137, the CVODE reference's error
# estimate (rtol/10) fails in the block of members 5,120–6,143 alone (found by logging each failing
# block once: 5120 at 137 steps; 0 and 5120 at 134; none at 140); on 2 ranks those members are
# rank 1's (its norm block 4,096–8,191).
# And CVODE as the integrator, its sums spanning 3 ranks: at --max-steps 20 it gives up at the
# same step on every rank (it takes 82 steps over level 0 of drag at R_out 13), so the serial line.
# usage: solver_failure.sh MPIEXEC DLPVERIFY
set -u
mpiexec=$1 dlpverify=$2
source "$(dirname "$0")/mpi_env.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
study=(converge --case full --outer 11 --levels 2 --max-steps 137 --json "$dir/out.json")
"$dlpverify" "${study[@]}" >"$dir/out" 2>"$dir/serial"
code=$?
[ "$code" -eq 3 ] || { echo "FAIL: the serial run exited $code, expected 3"; exit 1; }
run_ranks 2 "$dlpverify" "${study[@]}" >"$dir/out" 2>"$dir/ranks"
code=$?
[ "$code" -eq 3 ] || { echo "FAIL: 2 ranks exited $code, expected 3"; cat "$dir/ranks"; exit 1; }
cmp -s "$dir/serial" "$dir/ranks" || { echo "FAIL: 2 ranks printed"; cat "$dir/ranks"; echo "not the serial"; cat "$dir/serial"; exit 1; }
[ ! -s "$dir/out" ] && [ ! -e "$dir/out.json" ] || { echo "FAIL: output from a failed study"; exit 1; }
echo "ok: $(cat "$dir/ranks") (exit 3 on 2 ranks, as serially)"
study=(converge --case drag --outer 13 --levels 2 --integrator cvode --max-steps 20 --json "$dir/out.json")
"$dlpverify" "${study[@]}" >"$dir/out" 2>"$dir/serial"
code=$?
[ "$code" -eq 3 ] || { echo "FAIL: the serial CVODE run exited $code, expected 3"; exit 1; }
run_ranks 3 "$dlpverify" "${study[@]}" >"$dir/out" 2>"$dir/ranks"
code=$?
[ "$code" -eq 3 ] || { echo "FAIL: CVODE on 3 ranks exited $code, expected 3"; cat "$dir/ranks"; exit 1; }
cmp -s "$dir/serial" "$dir/ranks" || { echo "FAIL: 3 ranks printed"; cat "$dir/ranks"; echo "not the serial"; cat "$dir/serial"; exit 1; }
[ ! -s "$dir/out" ] && [ ! -e "$dir/out.json" ] || { echo "FAIL: output from a failed CVODE study"; exit 1; }
echo "ok: $(cat "$dir/ranks") (exit 3 on 3 ranks, as serially)"
