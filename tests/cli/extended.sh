#!/usr/bin/env bash
# --precision extended on the command line (docs/verification.md, "Extended precision"), one mode
# a test:
#   floor    RK4 on drag (--outer 2, 32 particles) from dt = 2.5e-4 over 12 levels: in extended
#            precision every level is ok, the finest position error is below 1e-20 (recorded
#            3.7e-21 … 5.9e-20 over the two finest) and the fitted order is 4 within 0.01; the same
#            levels in double against the same extended reference end at double's floor: the
#            finest level is round-off with an error above 1e-15 (recorded 3.3e-14). The JSON names
#            the precision and the extended reference;
#   tableau  the rk4 tableau file passes `check --expect-order 4 --precision extended` on drag
#            (its 1/6 and 1/3, printed to 16 digits, read back as fractions), and the slipped
#            midpoint tableau (c2 = 0.6) with --reference manufactured is refused: a manufactured
#            reference is computed in double;
#   refused  what extended precision cannot run is refused with exit 2, one line naming the option,
#            before any work: cvode and a diagonally implicit tableau (--precision), --levels auto
#            (--precision), --reference cvode (--reference), a case without an extended right-hand
#            side (cooling: --precision), an unknown arithmetic (--precision quad), and the option
#            in `dlpverify sharpness`.
# usage: extended.sh DLPVERIFY SOURCE_DIR MODE
set -u
dlpverify=$1 src=$2 mode=$3
tableaux=$src/examples/tableaux
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; echo "--- stdout:"; cat "$out/stdout" 2>/dev/null; echo "--- stderr:"; cat "$out/stderr" 2>/dev/null; exit 1; }
run() { "$dlpverify" "$@" >"$out/stdout" 2>"$out/stderr" </dev/null; }
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }

# refuse WHAT OPTION ARGS…: exit 2, one stderr line naming OPTION, nothing on stdout.
refuse() {
  local what=$1 option=$2
  shift 2
  run "$@"
  local code=$?
  [ "$code" -eq 2 ] || fail "$what: exit $code, not 2"
  [ "$(wc -l <"$out/stderr")" -eq 1 ] || fail "$what: not one line"
  grep -q -- "^dlpverify: $option" "$out/stderr" || fail "$what: the line does not name $option"
  [ ! -s "$out/stdout" ] || fail "$what: wrote to standard output"
}

case $mode in
  floor)
    common=(--case drag --outer 2 --integrator rk4 --dt 2.5e-4)
    run converge "${common[@]}" --levels 12 --precision extended --json "$out/e.json" || fail "extended study: exit $?"
    [ "$(jq -r .precision "$out/e.json")" = extended ] || fail "the JSON does not name the precision"
    [ "$(jq -r .reference "$out/e.json")" = extended ] || fail "the reference is not the extended one"
    [ "$(jq '[.levels[].status | select(. != "ok")] | length' "$out/e.json")" -eq 0 ] || fail "a level is not ok"
    finest=$(jq '.levels[-1].l2_position' "$out/e.json")
    below "$finest" 1e-20 || fail "finest position error $finest is not below 1e-20"
    order=$(jq '.fitted_order.position' "$out/e.json")
    below "$(awk -v o="$order" 'BEGIN { print (o > 4 ? o - 4 : 4 - o) }')" 0.01 || fail "fitted order $order is not 4 within 0.01"
    grep -q "precision extended" "$out/stdout" || fail "the table does not say extended"
    run converge "${common[@]}" --levels 9 --reference extended --json "$out/d.json" || fail "double study: exit $?"
    [ "$(jq -r '.levels[-1].status' "$out/d.json")" = round-off ] || fail "double's finest level is not round-off"
    below 1e-15 "$(jq '.levels[-1].l2_position' "$out/d.json")" || fail "double's finest error is not above 1e-15"
    [ "$(jq -r '.precision // "double"' "$out/d.json")" = double ] || fail "the double study names a precision"
    ;;
  tableau)
    run check --case drag --outer 2 --integrator "tableau:$tableaux/rk4.toml" --dt 2.5e-4 --levels 6 \
      --precision extended --expect-order 4 || fail "rk4.toml in extended: exit $?"
    refuse "manufactured" --reference check --case drag --outer 2 --integrator "tableau:$tableaux/midpoint-slipped-c2.toml" \
      --precision extended --reference manufactured --expect-order 2 --levels 3
    ;;
  refused)
    refuse "cvode" --precision converge --case drag --outer 2 --integrator cvode --precision extended --levels 3
    refuse "dirk" --precision converge --case drag --outer 2 --integrator "tableau:$tableaux/sdirk2-alexander.toml" \
      --precision extended --levels 3
    refuse "search" --precision converge --case drag --outer 2 --integrator rk4 --precision extended --levels auto
    refuse "cvode reference" --reference converge --case drag --outer 2 --integrator rk4 --precision extended \
      --reference cvode --levels 3
    refuse "cooling" --precision converge --case cooling --integrator rk4 --precision extended --levels 3
    refuse "quad" --precision converge --case drag --outer 2 --integrator rk4 --precision quad --levels 3
    refuse "sharpness" --precision sharpness --case drag --outer 2 --integrator rk4 --precision extended
    ;;
  *) echo "extended.sh: unknown mode $mode" >&2; exit 2 ;;
esac
