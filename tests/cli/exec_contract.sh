#!/usr/bin/env bash
# The exec: integrator's contract beyond one exit code (docs/exchange.md).
#   timeout-group  after --exec-timeout the program and the child it started are both ended
#   signal         SIGTERM to dlpverify (no journal: it would end at once) while the program runs reaches the program's group too:
#                  dlpverify ends by SIGTERM (143), the program and its child are gone, no files left
#   cleanup        the private folder of the exchange files is removed after a study, passed or failed
#   h5dump         `h5dump -H` of an exchange file (h5dump knows nothing of dlpverify) lists every
#                  attribute of the format, the parameters with their units and the fields
# usage: exec_contract.sh DLPVERIFY BAD_INTEGRATOR_PY MODE
set -u
dlpverify=$1 bad="/usr/bin/python3 $2" mode=$3
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
small=(--outer 2 --levels 2)
# Whether process $1 has ended: gone, or a zombie waiting for init to reap it (within 5 s).
ended() {
  local state
  for _ in $(seq 25); do
    state=$(awk '{print $3}' "/proc/$1/stat" 2>/dev/null || echo gone)
    { [ "$state" = gone ] || [ "$state" = Z ]; } && return 0
    sleep 0.2
  done
  kill "$1" 2>/dev/null
  return 1
}

case $mode in
timeout-group)
  BAD_CHILD_PID_FILE=$d/child.pid "$dlpverify" converge "${small[@]}" --exec-timeout 1 \
    --integrator "exec:$bad sleep {input} {output}" >/dev/null 2>"$d/err"
  code=$?
  [ "$code" -eq 3 ] || fail "exit $code, expected 3: $(cat "$d/err")"
  [ -s "$d/child.pid" ] || fail "the program never started its child"
  ended "$(cat "$d/child.pid")" || fail "the program's child still runs"
  ;;
signal)
  mkdir "$d/tmp"
  TMPDIR=$d/tmp BAD_CHILD_PID_FILE=$d/child.pid "$dlpverify" converge "${small[@]}" --csv "$d/s.csv" \
    --integrator "exec:$bad sleep {input} {output}" >/dev/null 2>"$d/err" &
  study=$!
  for _ in $(seq 100); do [ -s "$d/child.pid" ] && break; sleep 0.1; done
  [ -s "$d/child.pid" ] || { kill -KILL $study; fail "the program never started its child"; }
  kill -TERM $study
  wait $study
  code=$?
  [ "$code" -eq 143 ] || fail "exit $code, expected 143 (SIGTERM): $(cat "$d/err")"
  ended "$(cat "$d/child.pid")" || fail "the program's child still runs"
  left=$(ls -A "$d/tmp")
  [ -z "$left" ] || fail "left in TMPDIR: $left"
  [ ! -e "$d/s.csv" ] || fail "a result was written"
  ;;
cleanup)
  mkdir "$d/tmp"
  TMPDIR=$d/tmp "$dlpverify" converge "${small[@]}" --integrator "exec:$bad copy {input} {output}" >/dev/null 2>&1 ||
    fail "the copying program's study failed"
  TMPDIR=$d/tmp "$dlpverify" converge "${small[@]}" --integrator "exec:$bad exit {input} {output}" >/dev/null 2>&1
  [ $? -eq 3 ] || fail "the failing program's study did not exit 3"
  left=$(ls -A "$d/tmp")
  [ -z "$left" ] || fail "left in TMPDIR: $left"
  ;;
h5dump)
  "$dlpverify" converge --case full "${small[@]}" --exec-shell \
    --integrator "exec:cp {input} '$d/input.h5' && cp {input} {output}" >/dev/null 2>"$d/err" ||
    fail "study failed: $(cat "$d/err")"
  h5dump -H "$d/input.h5" >"$d/header" || fail "h5dump -H failed"
  for a in dlpverify_exchange_version problem case t0 dt steps t_end members threads fields field_units \
           diameter diameter_unit rho_particle rho_particle_unit cs_particle t_particle rho_gas mu_gas cp_gas \
           prandtl t_gas cd gravity gravity_unit burn_rate burn_rate_unit expansion_speed \
           drag heat burning terms unit; do
    grep -q "ATTRIBUTE \"$a\"" "$d/header" || fail "h5dump -H shows no attribute $a"
  done
  for f in x y z vx vy vz T m; do grep -q "DATASET \"$f\"" "$d/header" || fail "no dataset /fields/$f"; done
  grep -q 'H5T_IEEE_F64LE' "$d/header" || fail "the fields are not float64"
  # Values, read by h5dump alone: the case, and the last (finest) of full's two levels: 40 steps of 2.5e-4 s.
  h5dump -a /case "$d/input.h5" | grep -q '"full"' || fail "attribute case is not full"
  h5dump -a /steps "$d/input.h5" | grep -q '(0): 40$' || fail "attribute steps is not 40"
  h5dump -a /parameters/gravity_unit "$d/input.h5" | grep -q '"m/s^2"' || fail "gravity's unit is not m/s^2"
  h5dump -a /terms/drag "$d/input.h5" | grep -q '"reynolds"' || fail "full's drag is not the C_D(Re) law"
  ;;
*) fail "unknown mode $mode" ;;
esac
echo "ok: $mode"
