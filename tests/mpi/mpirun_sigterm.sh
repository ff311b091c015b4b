#!/usr/bin/env bash
# SIGTERM to mpirun itself (docs/mpi.md, "Stopping and resuming"). OpenMPI 4.1's mpirun answers it
# by sending the ranks SIGCONT at once, SIGTERM T seconds later and SIGKILL T seconds after that,
# T = its MCA parameter odls_base_sigkill_timeout (1 by default; set here through the environment,
# OMPI_MCA_odls_base_sigkill_timeout). With T longer than the level under way when the ranks' SIGTERM
# arrives, every rank stops after that level: rank 0 prints the serial stop line, the journal holds
# every finished level, mpirun exits with 1 (its own forced exit), and the study resumed on 3 ranks
# gives the serial JSON, bit for bit (but for wall times, provenance and the echoed options).
#
# No race with the machine's speed: T is 40 % of this machine's serial study, measured just before,
# and the levels are nearly equal (ratio 9/8: 4,096 … 6,561 steps, each 16–25 % of the study). Two
# ranks take at least half the serial time, so the ranks' SIGTERM (T after mpirun's, itself sent as
# the journal opens) comes before the study ends, and the level under way when it comes is shorter
# than T unless two ranks run 1.6 times slower than one (a failure then names T).
# usage: mpirun_sigterm.sh MPIEXEC DLPVERIFY
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)  # comparable_json.py
mpiexec=$1 dlpverify=$2
source "$(dirname "$0")/mpi_env.sh"
dir=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null; rm -rf "$dir"' EXIT
pid=
cd "$dir" || exit 1
# 150,554 particles (37 norm blocks), closed-form reference, about 8 s of Heun steps on one idle
# core; dt = t_end/4096, an exact binary fraction.
study=(--case drag --outer 33 --integrator heun --levels 5 --ratio 1.125 --dt 2.44140625e-06 --threads 1)
journal=out.json.journal.jsonl
fail() { echo "FAIL: $*"; head -5 stderr 2>/dev/null; exit 1; }

"$dlpverify" converge "${study[@]}" --json serial.json >/dev/null 2>&1 || fail "the serial run exited $?"
T=$(/usr/bin/python3 -c 'import json, sys
print(max(1, round(0.4 * sum(l["wall_s"] for l in json.load(open(sys.argv[1]))["levels"]))))' serial.json)

OMPI_MCA_odls_base_sigkill_timeout=$T "$mpiexec" -q -np 2 --oversubscribe "$dlpverify" converge "${study[@]}" \
  --json out.json >stdout 2>stderr &
pid=$!  # mpirun's own process
deadline=$((SECONDS + 300))
until [ -f "$journal" ] && [ "$(wc -l <"$journal")" -ge 1 ]; do  # its header: the levels begin
  kill -0 "$pid" 2>/dev/null || fail "the study on 2 ranks ended before its journal began"
  [ $SECONDS -lt $deadline ] || fail "no journal within 300 s"
  sleep 0.01
done
kill -TERM "$pid"
wait "$pid"
code=$?
pid=
[ "$code" -eq 1 ] || fail "mpirun stopped by SIGTERM: exit $code, expected 1"
[ -f "$journal" ] || fail "the study ended before the ranks' SIGTERM (T = $T s after mpirun's): the journal is gone"
levels=$(($(wc -l <"$journal") - 1))
[ "$levels" -ge 1 ] || fail "no level journaled (T = $T s)"
[ "$(wc -l <stderr)" -eq 1 ] && grep -q "SIGTERM: stopped after $levels of 5 levels; $journal keeps the first.*--resume" stderr ||
  fail "no single stop line for the $levels journaled levels (T = $T s): killed before the level under way ended?"

run_ranks 3 "$dlpverify" converge "${study[@]}" --json out.json --resume >stdout 2>stderr || fail "--resume on 3 ranks exited $?"
[ ! -e "$journal" ] || fail "the journal was not removed after the study finished"
PYTHONPATH="$tests" /usr/bin/python3 - serial.json out.json "$levels" "$T" <<'PY'
import json, sys
from comparable_json import comparable
def result(path):
    return comparable(path)
if result(sys.argv[2]) != result(sys.argv[1]):
    print("FAIL: stopped through mpirun on 2 ranks and resumed on 3, the study differs from the serial run")
    sys.exit(1)
print(f"ok: SIGTERM to mpirun (T = {sys.argv[4]} s) stopped 2 ranks after {sys.argv[3]} of 5 levels; "
      "resumed on 3 ranks: the serial JSON")
PY
