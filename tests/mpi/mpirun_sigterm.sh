#!/usr/bin/env bash
# SIGTERM to mpirun itself (docs/mpi.md, "Stopping and resuming"). OpenMPI 4.1's mpirun answers it
# by sending the ranks SIGCONT at once, SIGTERM T seconds later and SIGKILL T seconds after that,
# T = its MCA parameter odls_base_sigkill_timeout (set here through the environment). Every rank
# stops after the level under way: rank 0 prints the serial stop line, the journal holds every
# finished level, mpirun exits with 1 (its own forced exit), and the study resumed on 3 ranks gives
# the serial JSON, bit for bit (but for wall times, provenance and the echoed options).
#
# The test decides when the ranks run, not the machine's speed (signal_events.sh): once the journal
# holds a level the ranks are stopped (SIGSTOP) and mpirun gets SIGTERM; mpirun's SIGCONT lets them
# go on, so they are stopped again as soon as it is seen, and stand still until mpirun's SIGTERM is
# pending in both; then they go on (SIGCONT), and SIGTERM stops them after the level under way.
# So mpirun's SIGTERM always comes while the study is under way, and any level may take it, the
# last included (if every level was journaled before the ranks stood still, they may also finish:
# then mpirun still exits 1, with the JSON written). What is left to T: the level under way must
# end before mpirun's SIGKILL, T seconds after its SIGTERM less up to 0.5 s per SIGCHLD that cuts
# mpirun's sleep short (sleep(3) rounds the time left; the two SIGCONTs and the two exits here).
# T = 10 s is a parameter, not a measurement: the longest level here takes about 0.25 s on one idle
# core, and each rank does half of it.
# usage: mpirun_sigterm.sh MPIEXEC DLPVERIFY
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
T=10
fail() { echo "FAIL: $*"; head -5 stderr 2>/dev/null; exit 1; }

"$dlpverify" converge "${study[@]}" --json serial.json >/dev/null 2>&1 || fail "the serial run exited $?"

OMPI_MCA_odls_base_sigkill_timeout=$T "$mpiexec" -q -np 2 --oversubscribe "$dlpverify" converge "${study[@]}" \
  --json out.json >stdout 2>stderr &
pid=$!  # mpirun's own process, whose children are the ranks
started+=("$pid")
await "a level journaled on 2 ranks" has_a_level "$journal" "$pid"
ranks=($(pgrep -P "$pid"))
started+=("${ranks[@]}")
[ "${#ranks[@]}" -eq 2 ] || fail "mpirun has ${#ranks[@]} children, expected 2 ranks"
freeze "${ranks[@]}"
kill -TERM "$pid"
await "mpirun's SIGCONT to the ranks" none_stopped "${ranks[@]}"
freeze "${ranks[@]}"
kept=$(kept_levels "$journal" "$total")
await "mpirun's SIGTERM to the ranks, T = $T s after its own" sigterm_pending "${ranks[@]}"
kill -CONT "${ranks[@]}" 2>/dev/null
wait "$pid"
code=$?
stopped_study "$code" "$kept" "$total" "$journal" 1 1

if [ "$outcome" = stopped ]; then
  run_ranks 3 "$dlpverify" converge "${study[@]}" --json out.json --resume >stdout 2>stderr || fail "--resume on 3 ranks exited $?"
  [ ! -e "$journal" ] || fail "the journal was not removed after the study finished"
fi
PYTHONPATH="$tests" /usr/bin/python3 - serial.json out.json <<'PY' || exit 1
import sys
from comparable_json import comparable
if comparable(sys.argv[2]) != comparable(sys.argv[1]):
    print("FAIL: stopped through mpirun on 2 ranks and resumed on 3, the study differs from the serial run")
    sys.exit(1)
PY
echo "ok: SIGTERM to mpirun (T = $T s) with $kept of $total levels journaled: the ranks $outcome after $levels," \
  "mpirun exit $code; resumed on 3 ranks: the serial JSON"
