#!/usr/bin/env bash
# The command built with Ralston's method added as the step list says (CMakeLists.txt beside):
# it lists the method, a check at order 2 passes on the DLP cloud (against the closed form and a
# manufactured solution) and on the gas adiabat, a check at order 3 fails, and under mpirun (when
# given) the study spans the ranks with the serial run's bits.
# Usage: new_method.sh DLPVERIFY [MPIRUN]
set -u
bin=$1 mpirun=${2:-}
dir=$(mktemp -d) && trap 'rm -rf "$dir"' EXIT && cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }

"$bin" cases > cases.txt || fail "cases exited $?"
grep -Eq '^ralston +2 +Ralston' cases.txt || fail "cases does not list ralston at order 2"
expect() {  # expect CODE ARGS…: the command exits CODE
  local code=$1; shift
  "$bin" "$@" > out.txt 2>&1; local got=$?
  [ "$got" = "$code" ] || { cat out.txt; fail "$* exited $got, not $code"; }
}
small=(--case drag --outer 4 --integrator ralston)
expect 0 check "${small[@]}" --expect-order 2 --json serial.json
jq -e '[.fitted_order[].value | (. - 2) | fabs < 0.1] | all' serial.json > /dev/null ||
  fail "fitted orders $(jq -c '[.fitted_order[].value]' serial.json) are not 2 ± 0.1"
expect 1 check "${small[@]}" --expect-order 3
expect 0 check "${small[@]}" --expect-order 2 --reference manufactured
expect 0 check --case adiabat-ideal --integrator ralston --expect-order 2
if [ -n "$mpirun" ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  "$mpirun" -np 2 --oversubscribe "$bin" check "${small[@]}" --expect-order 2 --json ranks.json > out.txt 2>&1 ||
    { cat out.txt; fail "check under mpirun -np 2 exited $?"; }
  errors='[.fitted_order, (.levels[] | del(.wall_s))]'
  diff <(jq -S "$errors" serial.json) <(jq -S "$errors" ranks.json) > /dev/null ||
    fail "2 ranks do not give the serial errors and orders"
fi
echo "ralston: listed, order 2 on drag (exact and manufactured) and adiabat-ideal, order 3 refused${mpirun:+, same bits on 2 ranks}"
