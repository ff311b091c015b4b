#!/usr/bin/env bash
# The command built with the damped oscillators added as a problem family the way the step list
# says (CMakeLists.txt beside): `cases` lists the case, its closed form passes the audit, a check
# passes at RK4's order against the closed form and at RK2's against CVODE and fails at a wrong
# order, another family's option is refused for it, and under mpirun (when given) the study spans
# the ranks with the serial run's bits.
# Usage: new_problem.sh DLPVERIFY [MPIRUN]
set -u
bin=$1 mpirun=${2:-}
dir=$(mktemp -d) && trap 'rm -rf "$dir"' EXIT && cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
expect() {  # expect CODE ARGS…: the command exits CODE
  local code=$1; shift
  "$bin" "$@" > out.txt 2>&1; local got=$?
  [ "$got" = "$code" ] || { cat out.txt; fail "$* exited $got, not $code"; }
}

"$bin" cases > cases.txt || fail "cases exited $?"
grep -Eq '^damped-oscillators +exact' cases.txt || fail "cases does not list damped-oscillators with its closed form"
expect 0 audit
grep -q 'damped-oscillators' out.txt || fail "the audit does not list damped-oscillators"
case=(--case damped-oscillators)
expect 0 check "${case[@]}" --integrator rk4 --expect-order 4 --json serial.json
jq -e '[.fitted_order[].value | (. - 4) | fabs < 0.1] | all' serial.json > /dev/null ||
  fail "fitted orders $(jq -c '[.fitted_order[].value]' serial.json) are not 4 ± 0.1"
expect 0 check "${case[@]}" --integrator rk2 --expect-order 2 --reference cvode
expect 1 check "${case[@]}" --integrator rk2 --expect-order 3
expect 2 converge "${case[@]}" --outer 5
grep -q -- '--outer' out.txt || fail "the DLP cloud's --outer is not refused by name"
if [ -n "$mpirun" ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  "$mpirun" -np 2 --oversubscribe "$bin" check "${case[@]}" --integrator rk4 --expect-order 4 --json ranks.json \
    > out.txt 2>&1 || { cat out.txt; fail "check under mpirun -np 2 exited $?"; }
  errors='[.fitted_order, (.levels[] | del(.wall_s))]'
  diff <(jq -S "$errors" serial.json) <(jq -S "$errors" ranks.json) > /dev/null ||
    fail "2 ranks do not give the serial errors and orders"
fi
echo "damped-oscillators: listed, audited, order 4 (exact) and 2 (cvode), order 3 refused, --outer refused${mpirun:+, same bits on 2 ranks}"
