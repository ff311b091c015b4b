#!/usr/bin/env bash
# `dlpverify compress` (docs/model.md §7.2) end to end. usage: compress.sh DLPVERIFY MODE
#   seed-table      --runs 20 reproduces the seed's table 1 within 1% at every ratio (exit 0)
#   one-axis-free   one-axis compression with few collisions: (r² + 2)/3 within 2%, says collisionless
#   one-axis-dense  one-axis compression with many collisions: r^(2/3) within 2%, says collision-dominated
#   outputs         --json rows carry the issue's fields, --plot draws, both whole
#   check-fails     a tolerance the finite spheres cannot meet: exit 1 and a MISS line
#   overlaps        the overlap check after every event, walls moving: exit 0
#   work-bound      a run past its bound on events in all (--max-events), or on events per
#                   simulated second (inelastic collapse at e = 0): exit 3, one line with the reason,
#                   nothing on stdout, nothing written
#   bench           --bench counts exactly the events asked for and names its rate events/s
#   bad-input       each bad value: exit 2, one stderr line naming the option, nothing written
# Every run has a tight work bound: about four times the events a run needs (measured, most per
# run: 2504 for the seed's gas, 57,092 and 174,343 for the one-axis gases) and ten times kinetic
# theory's rate (these runs need at most twice it), so a slip in the engine fails in seconds with
# its reason instead of running to ctest's time limit.
set -u
bin=$1 mode=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; [ -f "$out/stdout" ] && cat "$out/stdout"; [ -f "$out/stderr" ] && cat "$out/stderr"; exit 1; }
bound=(--max-events 10000 --max-event-rate 10)
run() { "$bin" compress "$@" >"$out/stdout" 2>"$out/stderr"; }
# A run that must be refused: exit CODE, one stderr line matching PATTERN (grep -E: a regular
# expression, -F: a fixed string), nothing on stdout, no file written.
refused() {
  local code=$1 grep_mode=$2 pattern=$3; shift 3
  "$bin" compress "$@" --json "$out/refused.json" >"$out/stdout" 2>"$out/stderr"
  local got=$?
  [ "$got" -eq "$code" ] || fail "$*: exit $got, expected $code"
  [ "$(wc -l <"$out/stderr")" -eq 1 ] || fail "$*: stderr is not one line"
  grep -q "$grep_mode" -- "$pattern" "$out/stderr" || fail "$*: stderr does not say '$pattern'"
  [ ! -s "$out/stdout" ] || fail "$*: output on stdout"
  [ ! -e "$out/refused.json" ] || fail "$*: a file was written"
}
# A run that must stop at its work bound: exit 3, one stderr line saying PATTERN, nothing else.
stopped() {
  refused 3 -E "$@"
  echo "ok: exit 3: $(cat "$out/stderr")"
}

case $mode in
seed-table)
  run --runs 20 --expect seed-table --tolerance 0.01 "${bound[@]}" || fail "exit $?"
  grep -q "^PASS" "$out/stdout" || fail "no PASS line" ;;
one-axis-free)
  run --axes 1 --spheres 300 --radius 0.002 --wall-speed 0.05 --rest-before 1 --rest-after 1 --ratios 2 --runs 8 \
      --expect law --tolerance 0.02 --max-events 200000 --max-event-rate 10 || fail "exit $?"
  grep -q "collisionless: (r2+2)/3" "$out/stdout" || fail "regime not named collisionless" ;;
one-axis-dense)
  run --axes 1 --spheres 200 --radius 0.05 --wall-speed 0.01 --rest-before 1 --rest-after 1 --ratios 2 --runs 4 \
      --expect law --tolerance 0.02 --max-events 600000 --max-event-rate 10 || fail "exit $?"
  grep -q "collision-dominated: r^(2/3)" "$out/stdout" || fail "regime not named collision-dominated" ;;
outputs)
  run --runs 3 --ratios 1.5,2 --json "$out/r.json" --plot "$out/r.png" "${bound[@]}" || fail "exit $?"
  [ -s "$out/r.png" ] || fail "no figure"
  python3 - "$out/r.json" <<'PY' || fail "JSON rows"
import json, sys
rows = json.load(open(sys.argv[1]))["rows"]
assert len(rows) == 2
for r in rows:
    for key in ("volume_ratio", "analytic", "simulated", "stderr", "pair_events", "wall_events"):
        assert key in r, key
assert abs(rows[1]["analytic"] - 2 ** (2 / 3)) < 1e-12
PY
  run --runs 2 --ratios 2 --json - "${bound[@]}" || fail "--json -: exit $?"
  python3 -c 'import json, sys; json.load(sys.stdin)["rows"][0]["simulated"]' <"$out/stdout" || fail "--json -: stdout is not the JSON alone"
  run --sweep 1.6,0.8,0.4 --runs 8 --ratios 2 --json "$out/s.json" --plot "$out/s.svg" "${bound[@]}" || fail "sweep: exit $?"
  [ -s "$out/s.svg" ] || fail "no sweep figure"
  python3 - "$out/s.json" <<'PY' || fail "sweep JSON"
import json, sys
sweep = json.load(open(sys.argv[1]))["sweep"]
assert len(sweep) == 1 and len(sweep[0]["points"]) == 3
assert sweep[0]["slope"] is None or sweep[0]["slope"] > 0
PY
  [ "$(find "$out" -name '.*.tmp.*' | wc -l)" -eq 0 ] || fail "temporary files left" ;;
check-fails)
  run --runs 5 --expect adiabat --tolerance 0.001 "${bound[@]}"
  code=$?
  [ "$code" -eq 1 ] || fail "exit $code, expected 1"
  grep -q "^MISS" "$out/stdout" || fail "no MISS line" ;;
overlaps)
  run --check-overlaps --ratios 3.64 --runs 2 "${bound[@]}" || fail "exit $?" ;;
work-bound)
  # The seed's gas at V1/V2 = 2 needs about 1600 events a run.
  stopped "^dlpverify: V1/V2 2, run 0: hard spheres at t = .* after 501 events: past the bound of 500 events" \
    --runs 2 --ratios 2 --max-events 500
  # Perfectly inelastic spheres (e = 0), dense: they cluster and collide ever faster, without
  # time passing. The rate bound stops them, long before the bound on events in all would.
  stopped "past the work bound of 100 x the kinetic-theory rate [0-9.e+]+ events/s" \
    --restitution 0 --spheres 300 --radius 0.3 --lattice --runs 1 --ratios 1.5 --max-events 1000000 ;;
bench)
  run --bench --bench-events 2000 --json "$out/bench.json" || fail "exit $?"
  grep -q "^2000 events (" "$out/stdout" || fail "not 2000 events"
  grep -q "^events/s: [0-9]* (wall clock)" "$out/stdout" || fail "no events/s line"
  [ "$(jq .bench.events "$out/bench.json")" = 2000 ] || fail "--json events not 2000" ;;
bad-input)
  check_bad() {  # an option's bad value: exit 2, one line naming the option
    local option=$1; shift
    refused 2 -F "$option" "$@"
  }
  check_bad --radius --radius -1
  check_bad --radius --radius 5
  check_bad --runs --runs 0
  check_bad --axes --axes 2
  check_bad --ratios --ratios 0.5
  check_bad --ratios --ratios 1e6
  check_bad --wall-speed --wall-speed 0
  check_bad --restitution --restitution 1.5
  check_bad --expect --expect nonsense
  check_bad --size-sweep --size-sweep 100,200
  check_bad --sweep --sweep 0.1
  check_bad --spheres --spheres 0
  check_bad --mass --mass 0
  check_bad --velocity-max --velocity-max -9
  check_bad --edge --edge nan
  check_bad --rest-before --rest-before -1
  check_bad --rest-after --rest-after inf
  check_bad --tangential-restitution --tangential-restitution 2
  check_bad --friction --friction -0.1
  check_bad --packing-fraction --packing-fraction 0.6
  check_bad --tolerance --tolerance 0
  check_bad --max-events --max-events -1
  check_bad --max-event-rate --max-event-rate -2
  check_bad --max-event-rate --max-event-rate inf
  check_bad --bench-events --bench --bench-events 0
  check_bad --runs --runs abc
  check_bad --sweep --sweep 0.2,-0.1
  check_bad --size-sweep --packing-fraction 0.1 --size-sweep 108,1
  check_bad --radius --spheres 1500 --radius 0.3 --ratios 1.1
  check_bad --ratios --spheres 2000 --radius 0.3 ;;
*) fail "unknown mode $mode" ;;
esac
echo "ok: $mode"
