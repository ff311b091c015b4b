#!/usr/bin/env bash
# --resume under mpirun (docs/mpi.md): a serial study stopped by SIGTERM is finished on 3 ranks,
# and a study on 2 ranks whose ranks get SIGTERM is stopped after the level under way and finished
# on 2 ranks; each JSON is the uninterrupted serial run's, bit for bit (but for wall times,
# provenance and the echoed options). Rank 0 reads the journal and sends its levels to the others;
# the last one is solved again on every rank and must give its journaled norms (the rule of a
# serial resume).
#
# When the signal lands decides nothing. Once the journal holds a level the study is stopped
# (SIGSTOP) and, standing still, signalled (SIGTERM) and let go on (SIGCONT): the levels journaled
# while it stood still are known, so is what must follow (signal_events.sh, stopped_study): any
# level may take the signal, the last one included, and the resumed JSON must be the serial one
# whichever it was. Every wait is for an event, bounded only by a deadline that catches a hang.
# usage: resume.sh MPIEXEC DLPVERIFY
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)  # comparable_json.py
mpiexec=$1 dlpverify=$2
source "$(dirname "$0")/mpi_env.sh"
source "$(dirname "$0")/../signal_events.sh"
dir=$(mktemp -d)
started=()
trap 'kill -KILL "${started[@]}" 2>/dev/null; rm -rf "$dir"' EXIT
cd "$dir" || exit 1
# 9,170 particles (3 norm blocks), a CVODE reference; at ratio 2 levels 1–6 take about 50 times
# level 0, so the study is still under way when its first journaled level is seen.
total=7
study=(--case full --outer 13 --levels "$total")
journal=out.json.journal.jsonl
fail() { echo "FAIL: $phase: $*"; head -5 stderr 2>/dev/null; exit 1; }

phase="uninterrupted serial run"
"$dlpverify" converge "${study[@]}" --json serial.json >/dev/null 2>&1 || fail "exited $?"

# signal_mid_way PID...: once the journal holds a level, SIGTERM to PID... (the study's processes)
# while they stand still; sets code (the exit code of $pid) and kept (the levels journaled then).
signal_mid_way() {
  await "$phase: a level journaled" has_a_level "$journal" "$pid"
  freeze "$@"
  kept=$(kept_levels "$journal" "$total")
  kill -TERM "$@" 2>/dev/null
  kill -CONT "$@" 2>/dev/null
  wait "$pid"
  code=$?
}

# resume_on RANKS NAME: the study finished from its journal on RANKS ranks, its JSON kept as NAME.
resume_on() {
  if [ "$outcome" = stopped ]; then
    run_ranks "$1" "$dlpverify" converge "${study[@]}" --json out.json --resume >stdout 2>stderr ||
      fail "--resume on $1 ranks exited $?"
    [ ! -e "$journal" ] || fail "the journal was not removed after the study finished"
  fi
  mv out.json "$2"
  echo "ok: $phase: SIGTERM with $kept of $total levels journaled, $outcome after $levels; then on $1 ranks"
}

phase="serial study stopped, resumed on 3 ranks"
"$dlpverify" converge "${study[@]}" --json out.json >stdout 2>stderr &
pid=$!
started+=("$pid")
signal_mid_way "$pid"
stopped_study "$code" "$kept" "$total" "$journal"
resume_on 3 resumed-serial.json

# The same on 2 ranks, SIGTERM sent to each rank's process (children of mpirun): every rank stops
# after the level under way (the stop is decided together), rank 0 prints the serial stop line,
# and mpirun exits with the ranks' code.
phase="2 ranks stopped, resumed on 2 ranks"
"$mpiexec" -q -np 2 --oversubscribe "$dlpverify" converge "${study[@]}" --json out.json >stdout 2>stderr &
pid=$!  # mpirun's own process (not a function's subshell), whose children are the ranks
started+=("$pid")
await "$phase: a level journaled" has_a_level "$journal" "$pid"
ranks=($(pgrep -P "$pid"))
started+=("${ranks[@]}")
[ "${#ranks[@]}" -eq 2 ] || fail "mpirun has ${#ranks[@]} children, expected 2 ranks"
signal_mid_way "${ranks[@]}"
stopped_study "$code" "$kept" "$total" "$journal"
resume_on 2 resumed-ranks.json

phase="the resumed JSON"
PYTHONPATH="$tests" /usr/bin/python3 - serial.json resumed-serial.json resumed-ranks.json <<'PY' || exit 1
import sys
from comparable_json import comparable
serial = comparable(sys.argv[1])
for path, what in ((sys.argv[2], "stopped serially, resumed on 3 ranks"), (sys.argv[3], "stopped and resumed on 2 ranks")):
    resumed = comparable(path)
    if resumed != serial:
        print(f"FAIL: the study {what} differs from the serial run in",
              ", ".join(k for k in sorted(set(serial) | set(resumed)) if serial.get(k) != resumed.get(k)))
        sys.exit(1)
print("ok: stopped serially and resumed on 3 ranks, stopped and resumed on 2 ranks: the serial JSON")
PY
