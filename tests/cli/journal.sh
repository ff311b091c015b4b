#!/usr/bin/env bash
# Interrupted studies (docs/cli.md, "The journal and --resume"): a study stopped by a signal after its first
# journaled level keeps its journal, and --resume finishes it with the JSON of an uninterrupted
# run; a resume that differs from the journal in an option, the command or the build is refused.
#
# usage: journal.sh DLPVERIFY resume|refusals|precision|restart|abandon [SOURCE_DIR]
#   resume    SIGTERM after level 0 is journaled → exit 143; a torn line appended to the journal
#             (a write cut short) is left out; --resume → exit 0 and the same JSON as a run never
#             stopped, but for the fields listed in same_json below; the journal is then removed.
#   precision the same for a work-precision sweep, stopped after its first run.
#   refusals  SIGINT → exit 130; without --resume, with --outer changed, as `check`, with another
#             build's commit in the journal, and --resume without --json: each exit 2 with one
#             line naming what differs, the journal unchanged; then --resume still finishes.
#   restart   SIGINT → exit 130; --restart with --resume, and --restart onto a file that is not a
#             journal, are refused (exit 2, the files unchanged); --restart discards the journal and
#             runs the whole study (exit 0, every level measured anew). A level search killed by
#             SIGKILL leaves a journal with no level: --resume is refused saying to run it again
#             without, and a plain run then starts it over (exit 0). --tolerances keeps no journal:
#             --resume and --restart are refused naming it.
#   abandon   SIGTERM inside a level that would run for many minutes, stepped by each kind of
#             integrator the tool owns (a built-in Runge–Kutta method on its fused path and on
#             Problem::rhs, a tableau file, CVODE, a diagonally implicit tableau through ARKStep,
#             double-double): the level is abandoned, so the study ends long before it (exit 143,
#             the one stop line, the journal keeping level 0, no JSON).
set -u
binary=$1 mode=$2 source_dir=${3:-}
source "$(dirname "$0")/../signal_events.sh"
dir=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null; kill -CONT "$pid" 2>/dev/null; rm -rf "$dir"' EXIT
pid=
cd "$dir" || exit 1
# A CVODE reference (recomputed when resumed) and four variables; level 0 takes ~0.07 s and
# levels 1–5 about 1.8 s: at ratio 2, 62 times level 0 (2 + 4 + … + 32), on any machine.
command=converge units=levels total=6
study=(--case full --outer 10 --levels 6 --json out.json)
if [ "$mode" = precision ]; then  # 19 runs: the first ~0.06 s, the other 18 about 1.1 s
  command=precision units=runs total=19
  study=(--case drag --outer 10 --rtol-min 1e-9 --levels 5 --json out.json)
fi
journal=out.json.journal.jsonl
fail() { echo "FAIL: $*"; for f in stderr stdout; do [ -f "$f" ] && { echo "--- $f:"; head -5 "$f"; }; done; exit 1; }

# Starts the study in the background, waits until the journal holds a finished level (the header
# and level 0: two lines), stops the study there (SIGSTOP), sends the signal and lets it go on
# (SIGCONT). The signal then lands while the study stands still with a known number of levels
# journaled, so what must follow is decided by that number, not by the machine's speed
# (tests/signal_events.sh, stopped_study): with levels still to run, the study stops after the
# level under way. Only if every level was journaled before it stood still (what is left takes
# 62 times level 0, so practically never) may it also finish; the resume checks then have
# nothing to resume and the test says so.
stop_mid_way() {
  local signal=$1 expected=$2
  set -m  # the study gets its own process group, so SIGINT is not ignored as in a background job
  "$binary" "$command" "${study[@]}" >stdout 2>stderr &
  pid=$!
  set +m
  await "a level in $journal" has_a_level "$journal" "$pid"
  freeze "$pid"
  local kept
  kept=$(kept_levels "$journal" "$total")
  kill -"$signal" "$pid" 2>/dev/null
  kill -CONT "$pid" 2>/dev/null
  wait "$pid"
  local code=$?
  pid=
  if [ "$kept" -eq "$total" ] && [ "$code" -eq 0 ]; then
    echo "note: every $units was journaled before the study stood still; it finished (nothing to resume)"
    exit 0
  fi
  [ "$code" -eq "$expected" ] || fail "SIG$signal with $kept of $total $units journaled: exit $code, expected $expected"
  [ "$(wc -l <stderr)" -eq 1 ] || fail "stderr is not one line"
  grep -q "SIG$signal: stopped after .* of $total $units; $journal keeps the first.*--resume" stderr || fail "no stop line"
  [ ! -e out.json ] || fail "final results written by a stopped study"
  local lines
  lines=$(wc -l <"$journal")
  [ "$lines" -ge $((kept + 1)) ] && [ "$lines" -le $((total + 1)) ] ||
    fail "the journal has $lines lines, expected $((kept + 1))–$((total + 1)) (header, $units)"
  [ -z "$(tail -c 1 "$journal")" ] || fail "the journal does not end with a whole line"
  echo "ok: SIG$signal with $kept of $total $units journaled → exit $code, journal keeps $((lines - 1))"
}

# has_its_first_line JOURNAL PID: the journal holds its whole first line; fails if PID ended first.
has_its_first_line() {
  [ -f "$1" ] && [ "$(wc -l <"$1")" -ge 1 ] && return 0
  ended "$2" && fail "the study ended before its journal was written"
  return 1
}

# Runs a refused resume: exit 2, one line matching PATTERN, the journal byte for byte unchanged.
refused() {
  local pattern=$1
  shift
  cp "$journal" before.jsonl
  "$binary" "$@" >stdout 2>stderr
  local code=$?
  [ "$code" -eq 2 ] || fail "$*: exit $code, expected 2"
  [ "$(wc -l <stderr)" -eq 1 ] || fail "$*: stderr is not one line"
  grep -q -- "$pattern" stderr || fail "$*: stderr does not say '$pattern'"
  [ ! -s stdout ] || fail "$*: output on stdout"
  cmp -s "$journal" before.jsonl || fail "$*: the journal changed"
  echo "ok: refused, exit 2: $(cut -c 1-150 stderr)"
}

resume() {
  "$binary" "$command" "${study[@]}" --resume "$@" >stdout 2>stderr
  local code=$?
  [ "$code" -eq 0 ] || fail "--resume: exit $code"
  [ -s out.json ] || fail "--resume wrote no JSON"
  [ ! -e "$journal" ] || fail "the journal was not removed after the study finished"
  echo "ok: resumed, exit 0: $(tr '\n' ' ' <stderr)"
}

# Fields that legitimately differ between a resumed and an uninterrupted run: each level's (or
# run's) wall time (a resumed one's is its first run's), the recomputed reference's wall times,
# the date and the command line (--resume). Every other number must be equal, bit for bit.
same_json() {
  /usr/bin/python3 - "$1" "$2" <<'PY' || fail "the resumed JSON differs from the uninterrupted one"
import json, sys
def comparable(path):
    j = json.load(open(path))
    for level in j.get("levels", []) + j.get("runs", []):
        del level["wall_s"]
    for key in ("wall_s", "error_estimate_wall_s"):
        j["reference_statistics"].pop(key, None)
    for key in ("date", "command_line"):
        del j["provenance"][key]
    return j
a, b = comparable(sys.argv[1]), comparable(sys.argv[2])
if a != b:
    for key in sorted(set(a) | set(b)):
        if a.get(key) != b.get(key):
            print("differs:", key)
    sys.exit(1)
print("ok: the same JSON,", len(a.get("levels", a.get("runs"))), "levels or runs")
PY
}

case $mode in
  resume | precision)
    "$binary" "$command" "${study[@]}" >stdout 2>stderr || fail "the uninterrupted study failed"
    [ ! -e "$journal" ] || fail "a finished study left its journal"
    mv out.json whole.json
    stop_mid_way TERM 143
    printf '{"dt":"0x1.0624dd2f1a9fcp-1' >>"$journal"  # a last write cut short
    resume
    grep -q "last line was cut short" stderr || fail "the torn last line was not reported"
    same_json whole.json out.json
    ;;
  refusals)
    stop_mid_way INT 130
    refused "journal of an unfinished study.*--resume, or start over with --restart" converge "${study[@]}"
    refused "option --outer is 11 here, 10 in the journal" converge "${study[@]}" --outer 11 --resume
    refused 'journal of a "converge" study, this is "check"' check "${study[@]}" --expect-order 2 --resume
    cp "$journal" saved.jsonl
    sed -i '1s/"git_commit":"[^"]*"/"git_commit":"another"/' "$journal"
    refused 'the build differs: its git_commit is .* here, "another" in the journal' converge "${study[@]}" --resume
    cp saved.jsonl "$journal"
    refused "--resume needs --json" converge --case full --outer 10 --levels 6 --resume
    resume
    ;;
  restart)
    stop_mid_way INT 130
    refused "--resume excludes --restart" converge "${study[@]}" --resume --restart
    refused "tolerances keeps no journal" check --case drag --integrator rk4 --tolerances 1e-3:1e-5 \
      --json out.json --restart
    echo 'my notes' >notes.json.journal.jsonl
    echo '{"my": "notes"}' >data.json.journal.jsonl
    refused "notes.json.journal.jsonl: line 1 is not a JSON object: not a journal" converge --case drag \
      --levels 3 --json notes.json --restart
    refused "data.json.journal.jsonl beside it is not a dlpverify journal" converge --case drag --levels 3 \
      --json data.json --restart
    [ "$(cat notes.json.journal.jsonl data.json.journal.jsonl)" = 'my notes
{"my": "notes"}' ] || fail "a file that is not a journal was changed"
    "$binary" "$command" "${study[@]}" --restart >stdout 2>stderr || fail "--restart: exit $?"
    grep -q -- "--restart: $journal (.* finished) discarded" stderr || fail "--restart did not say what it discarded"
    [ ! -e "$journal" ] || fail "the journal was not removed after the restarted study finished"
    /usr/bin/python3 -c 'import json,sys; n=len(json.load(open("out.json"))["levels"]); sys.exit(n != 6)' ||
      fail "the restarted study does not hold its 6 levels"
    echo "ok: --restart discarded the journal and ran all 6 levels"

    # A search journals no level: killed at any instant, its journal holds only its first line.
    search=(--case full --outer 10 --levels auto --budget 1e7 --json auto.json)
    set -m
    "$binary" converge "${search[@]}" >stdout 2>stderr &
    pid=$!
    set +m
    await "the search's journal" has_its_first_line auto.json.journal.jsonl "$pid"
    freeze "$pid"
    kill -KILL "$pid"
    wait "$pid"
    pid=
    [ "$(journaled auto.json.journal.jsonl)" -eq 0 ] || fail "the search journaled a level"
    journal=auto.json.journal.jsonl refused "records no levels to continue.*run it again without --resume" \
      converge "${search[@]}" --resume
    "$binary" converge --case drag --outer 3 --levels auto --order-ci 0.5 --budget 1e7 --json auto.json >stdout 2>stderr ||
      fail "a plain run after a killed search: exit $?"
    [ -s auto.json ] && [ ! -e auto.json.journal.jsonl ] || fail "the search did not start over and finish"
    echo "ok: a killed search's journal held no level and was started over"
    ;;
  abandon)
    # Level 1 is 10^7 times level 0: 2·10^8 steps of 32 particles, about 18 minutes for the
    # fastest of these integrators on a 2-core AMD EPYC (the fused RK4 path: 0.11 s for 20,000
    # steps; CVODE 6 times, double-double 130 times as long). The study must end within 60 s of
    # the signal: a fixed bound, 18 times shorter than the level it abandons there.
    for chosen in "drag rk4" "full rk4" "drag tableau:$source_dir/examples/tableaux/rk4.toml" "drag cvode" \
      "drag tableau:$source_dir/examples/tableaux/sdirk2-alexander.toml" "drag rk4 --precision extended"; do
      read -r case_name integrator extra <<<"$chosen"
      integrator="$case_name ${integrator##*/} $extra"
      # shellcheck disable=SC2206
      study=(--case "$case_name" --outer 4 --levels 2 --ratio 1e7 --json out.json --integrator ${chosen#* })
      rm -f out.json "$journal"
      set -m
      "$binary" converge "${study[@]}" >stdout 2>stderr &
      pid=$!
      set +m
      await "level 0 of $integrator in $journal" has_a_level "$journal" "$pid"
      freeze "$pid"
      kill -TERM "$pid"
      kill -CONT "$pid"
      deadline=$((SECONDS + 60))
      until ended "$pid"; do
        [ "$SECONDS" -lt "$deadline" ] || fail "$integrator: the level under way was not abandoned within 60 s of SIGTERM"
        sleep 0.01
      done
      wait "$pid"
      code=$?
      pid=
      [ "$code" -eq 143 ] || fail "$integrator: exit $code, expected 143"
      [ "$(wc -l <stderr)" -eq 1 ] || fail "$integrator: stderr is not one line"
      grep -q "^dlpverify: SIGTERM: stopped after 1 of 2 levels; $journal keeps the first: continue with --resume$" stderr ||
        fail "$integrator: no stop line"
      [ "$(journaled "$journal")" -eq 1 ] || fail "$integrator: the journal does not keep level 0 alone"
      [ ! -e out.json ] || fail "$integrator: final results written by a stopped study"
      echo "ok: $integrator: SIGTERM inside level 1 → exit 143 in $((SECONDS - deadline + 60)) s, level 0 kept"
    done
    ;;
  *) fail "unknown mode $mode" ;;
esac
