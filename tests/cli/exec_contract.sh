#!/usr/bin/env bash
# The exec: integrator's contract beyond one exit code (docs/exchange.md).
#   timeout        a program that never ends is ended by --exec-timeout: exit 3, one line saying
#                  "timed out after T s" and quoting the program's last stderr line, nothing written
#   timeout-group  after --exec-timeout the program and the child it started are both ended
#   signal         SIGTERM to dlpverify (no journal: it would end at once) while the program runs reaches the program's group too:
#                  dlpverify ends by SIGTERM (143), the program and its child are gone, no files left
#   cleanup        the private folder of the exchange files is removed after a study, passed or failed
#   h5dump         `h5dump -H` of an exchange file (h5dump knows nothing of dlpverify) lists every
#                  attribute of the format, the parameters with their units and the fields
#   reference-at   --reference integrator:SPEC@DT splits at the last '@': a program whose file name
#                  holds an '@' is the reference, at DT, and measures the levels as the closed form does
# No outcome depends on how fast the machine is: the program in mode sleep says it is ready (its
# stderr line written, its child started) by creating $BAD_READY_FILE and then blocks forever, so
# only the timeout or the signal can end it. A timeout that fired before the program was ready
# (a machine too loaded to start Python within the limit) says nothing about the contract: the
# run is repeated with a limit four times longer; any other failure fails at once. Every wait for
# an event is a poll with a bound.
# usage: exec_contract.sh DLPVERIFY BAD_INTEGRATOR_PY MODE
set -u
dlpverify=$1 bad="/usr/bin/python3 $2" mode=$3
here=$(cd "$(dirname "$0")" && pwd)
d=$(mktemp -d)
# A child that outlived a broken timeout (still the program's `sleep`) is ended here, so a failing
# test leaves nothing running.
leftover() {
  local child
  child=$(cat "$d/child.pid" 2>/dev/null) || return 0
  grep -qa '^sleep' "/proc/$child/cmdline" 2>/dev/null && kill "$child"
  return 0
}
trap 'leftover; rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
small=(--outer 2 --levels 2)
# Whether process $1 has ended: gone, or a zombie waiting for init to reap it (polled for up to
# 20 s: a SIGKILLed process ends at once, so only a process that was never signalled waits it out).
ended() {
  local state deadline=$((SECONDS + 20))
  while [ $SECONDS -lt $deadline ]; do
    state=$(awk '{print $3}' "/proc/$1/stat" 2>/dev/null || echo gone)
    { [ "$state" = gone ] || [ "$state" = Z ]; } && return 0
    sleep 0.1
  done
  kill "$1" 2>/dev/null
  return 1
}
# The limits tried in turn until the program was ready before its timeout fired.
limits=(0.5 2 8 32 128)

case $mode in
timeout)
  # expect_exit.sh checks the exit code, the one line with the limit and the quote, and that
  # nothing was written. coreutils' timeout ends dlpverify only if its own timeout never fires.
  for limit in "${limits[@]}"; do
    rm -f "$d/ready"
    BAD_READY_FILE=$d/ready BAD_CHILD_PID_FILE=$d/child.pid bash "$here/expect_exit.sh" 3 "timed out after $limit s" "sleep is what I do" -- \
      timeout -k 10 600 "$dlpverify" check "${small[@]}" --expect-order 2 --exec-timeout "$limit" \
      --integrator "exec:$bad sleep {input} {output}" >"$d/log"
    code=$?
    [ "$code" -eq 0 ] && { cat "$d/log"; break; }
    [ -e "$d/ready" ] && { cat "$d/log"; fail "with --exec-timeout $limit"; }
    grep -q "timed out after $limit s" "$d/log" || { cat "$d/log"; fail "with --exec-timeout $limit: no timeout"; }
    echo "the program was not ready within --exec-timeout $limit s on this machine: again with a longer limit"
  done
  [ "$code" -eq 0 ] || fail "the program was never ready before its timeout (the last limit ${limits[-1]} s)"
  ;;
timeout-group)
  for limit in "${limits[@]}"; do
    rm -f "$d/ready" "$d/child.pid"
    BAD_READY_FILE=$d/ready BAD_CHILD_PID_FILE=$d/child.pid timeout -k 10 600 "$dlpverify" converge "${small[@]}" \
      --exec-timeout "$limit" --integrator "exec:$bad sleep {input} {output}" >/dev/null 2>"$d/err"
    code=$?
    [ -e "$d/ready" ] && break
    grep -q "timed out after $limit s" "$d/err" || fail "exit $code with --exec-timeout $limit: $(cat "$d/err")"
    [ -s "$d/child.pid" ] && ended "$(cat "$d/child.pid")"  # started, but not yet ready: ended too
    echo "the program was not ready within --exec-timeout $limit s on this machine: again with a longer limit"
  done
  [ -e "$d/ready" ] || fail "the program was never ready before its timeout (the last limit ${limits[-1]} s)"
  [ "$code" -eq 3 ] || fail "exit $code, expected 3: $(cat "$d/err")"
  grep -q "timed out after $limit s" "$d/err" || fail "no 'timed out after $limit s': $(cat "$d/err")"
  ended "$(cat "$d/child.pid")" || fail "the program's child still runs"
  ;;
signal)
  mkdir "$d/tmp"
  TMPDIR=$d/tmp BAD_READY_FILE=$d/ready BAD_CHILD_PID_FILE=$d/child.pid "$dlpverify" converge "${small[@]}" \
    --csv "$d/s.csv" --integrator "exec:$bad sleep {input} {output}" >/dev/null 2>"$d/err" &
  study=$!
  deadline=$((SECONDS + 120))
  while [ ! -e "$d/ready" ] && [ $SECONDS -lt $deadline ] && kill -0 $study 2>/dev/null; do sleep 0.05; done
  [ -e "$d/ready" ] || { kill -KILL $study; fail "the program was not ready within 120 s: $(cat "$d/err")"; }
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
  # attribute PATH PATTERN MESSAGE: h5dump's output read whole, so its own failure fails the check.
  attribute() { local out; out=$(h5dump -a "$1" "$d/input.h5") || fail "h5dump -a $1 failed"; grep -q -- "$2" <<<"$out" || fail "$3"; }
  attribute /case '"full"' "attribute case is not full"
  attribute /steps '(0): 40$' "attribute steps is not 40"
  attribute /parameters/gravity_unit '"m/s^2"' "gravity's unit is not m/s^2"
  attribute /terms/drag '"reynolds"' "full's drag is not the C_D(Re) law"
  ;;
reference-at)
  # SPEC = exec:/usr/bin/python3 …/mid@v2.py {input} {output}, DT = 1e-5 s (1000 steps of drag's
  # 0.01 s); the JSON records both as given. Its levels' errors are the closed form's to within
  # the reference's own error: |‖y − r‖ − ‖y − x‖| ≤ ‖r − x‖ ≈ its estimate (Richardson's, ×2 for
  # the estimate's own error).
  cp "$here/../../examples/external/python/midpoint.py" "$d/mid@v2.py"
  spec="exec:/usr/bin/python3 $d/mid@v2.py {input} {output}"
  "$dlpverify" converge --case drag "${small[@]}" --exec-order 2 --reference "integrator:$spec@1e-5" \
    --json "$d/at.json" >/dev/null 2>"$d/err" || fail "exit $?: $(cat "$d/err")"
  "$dlpverify" converge --case drag "${small[@]}" --json "$d/exact.json" >/dev/null 2>"$d/err" ||
    fail "exit $? against the closed form: $(cat "$d/err")"
  [ "$(jq -r .reference "$d/at.json")" = integrator ] || fail "reference $(jq -r .reference "$d/at.json")"
  [ "$(jq -r .reference_statistics.integrator "$d/at.json")" = "$spec" ] ||
    fail "reference integrator $(jq .reference_statistics.integrator "$d/at.json"), expected \"$spec\""
  jq -e '.reference_statistics.dt == 1e-5 and .reference_statistics.steps == 1000' "$d/at.json" >/dev/null ||
    fail "reference step $(jq -c '.reference_statistics | {dt, steps}' "$d/at.json"), expected 1e-5 s, 1000 steps"
  for v in position velocity; do
    jq -e --arg v "$v" --slurpfile x "$d/exact.json" '
      .reference_error[$v] as $r | [.levels, $x[0].levels] | transpose |
      all(.[]; ((.[0]["l2_" + $v] - .[1]["l2_" + $v]) | fabs) <= 2 * $r) and $r > 0' "$d/at.json" >/dev/null ||
      fail "$v: the levels' errors differ from the closed form's by more than twice the reference's error"
  done
  ;;
*) fail "unknown mode $mode" ;;
esac
echo "ok: $mode"
