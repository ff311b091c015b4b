#!/usr/bin/env bash
# --resume under mpirun (docs/mpi.md): a serial study stopped by SIGTERM after its first journaled
# level is finished on 3 ranks, and a study on 2 ranks whose ranks get SIGTERM is stopped after the
# level under way and finished on 2 ranks; each JSON is the uninterrupted serial run's, bit for bit
# (but for wall times, provenance and the echoed options). Rank 0 reads the journal and sends its
# levels to the others; the last one is solved again on every rank and must give its journaled
# norms (the rule of a serial resume).
# usage: resume.sh MPIEXEC DLPVERIFY
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)  # comparable_json.py
mpiexec=$1 dlpverify=$2
source "$(dirname "$0")/mpi_env.sh"
dir=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null; rm -rf "$dir"' EXIT
pid=
cd "$dir" || exit 1
# 9,170 particles (3 norm blocks), a CVODE reference; levels 1–4 take 30 times level 0.
study=(--case full --outer 13 --levels 5)
journal=out.json.journal.jsonl
fail() { echo "FAIL: $*"; cat stderr 2>/dev/null | head -5; exit 1; }

"$dlpverify" converge "${study[@]}" --json serial.json >/dev/null 2>&1 || fail "the serial run exited $?"

# The serial study, stopped once its journal holds level 0 (polled, not timed: see tests/cli/journal.sh).
"$dlpverify" converge "${study[@]}" --json out.json >stdout 2>stderr &
pid=$!
deadline=$((SECONDS + 240))
until [ -f "$journal" ] && [ "$(wc -l <"$journal")" -ge 2 ]; do
  kill -0 "$pid" 2>/dev/null || fail "the study ended before its first level was journaled"
  [ $SECONDS -lt $deadline ] || fail "no level journaled within 240 s"
  sleep 0.01
done
kill -TERM "$pid"
wait "$pid"
code=$?
pid=
[ "$code" -eq 143 ] || fail "stopped by SIGTERM: exit $code, expected 143"

run_ranks 3 "$dlpverify" converge "${study[@]}" --json out.json --resume >stdout 2>stderr || fail "--resume on 3 ranks exited $?"
[ ! -e "$journal" ] || fail "the journal was not removed after the study finished"
mv out.json resumed-serial.json

# The same on 2 ranks, SIGTERM sent to each rank's process (children of mpirun): every rank stops
# after the level under way (the stop is decided together), rank 0 prints the serial stop line.
"$mpiexec" -q -np 2 --oversubscribe "$dlpverify" converge "${study[@]}" --json out.json >stdout 2>stderr &
pid=$!  # mpirun's own process (not a function's subshell), whose children are the ranks
until [ -f "$journal" ] && [ "$(wc -l <"$journal")" -ge 2 ]; do
  kill -0 "$pid" 2>/dev/null || fail "the study on 2 ranks ended before its first level was journaled"
  [ $SECONDS -lt $deadline ] || fail "no level journaled within 240 s"
  sleep 0.01
done
kill -TERM $(pgrep -P "$pid")
wait "$pid"
code=$?
pid=
[ "$code" -eq 143 ] || fail "2 ranks stopped by SIGTERM: exit $code, expected 143"
[ "$(wc -l <stderr)" -eq 1 ] && grep -q "SIGTERM: stopped after .* of 5 levels; $journal keeps the first.*--resume" stderr ||
  fail "no single stop line"
run_ranks 2 "$dlpverify" converge "${study[@]}" --json out.json --resume >stdout 2>stderr || fail "--resume on 2 ranks exited $?"
mv out.json resumed-ranks.json
PYTHONPATH="$tests" /usr/bin/python3 - serial.json resumed-serial.json resumed-ranks.json <<'PY'
import json, sys
from comparable_json import comparable
def result(path):
    return comparable(path)
serial = result(sys.argv[1])
for path, what in ((sys.argv[2], "stopped serially, resumed on 3 ranks"), (sys.argv[3], "stopped and resumed on 2 ranks")):
    if result(path) != serial:
        print(f"FAIL: the study {what} differs from the serial run")
        sys.exit(1)
print("ok: stopped serially and resumed on 3 ranks, stopped and resumed on 2 ranks: the serial JSON")
PY
