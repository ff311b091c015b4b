#!/usr/bin/env bash
# A solver failure on ranks other than rank 0 (docs/mpi.md): the serial run's one line and exit 3,
# nothing on standard output, no JSON.
#
# The step limits come from the same study run once with CVODE's default limit: its JSON gives the
# steps CVODE took, and half of them is a limit that must fail, since the solve that took S steps
# in one CVode call cannot reach its end in S/2 (CVODE's steps do not depend on the machine or the
# rank count: docs/mpi.md). --threads 1, so the first failure in block order is the one reported,
# serially and on every rank alike.
#
# The CVODE reference failing in rank 1's members alone: at R_out 9 the cloud is 3,070 particles,
# one norm block of 4,096, which on 2 ranks is rank 1's (blocks ⌊B r / R⌋ … ⌊B (r + 1) / R⌋ − 1
# with B = 1): rank 0 holds no member, never fails, and prints rank 1's line. The limit is half the
# most steps a reference block took (`reference_statistics.solve.steps_max`).
# And CVODE as the integrator, its sums spanning 3 ranks (drag at R_out 13, 9,170 particles): at
# half the steps it took over level 0 (`levels[0].solver_statistics.steps`) it gives up at the same
# step on every rank, so the serial line.
# usage: solver_failure.sh MPIEXEC DLPVERIFY
set -u
mpiexec=$1 dlpverify=$2
source "$(dirname "$0")/mpi_env.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# half_the_steps STUDY_JSON PYTHON_EXPRESSION: half the step count the expression reads from j.
half_the_steps() {
  /usr/bin/python3 -c 'import json, sys
j = json.load(open(sys.argv[1]))
print(int(eval(sys.argv[2])) // 2)' "$1" "$2"
}

# fails_alike RANKS ARGS...: the study exits 3 serially and on RANKS ranks with the same one line,
# and writes nothing.
fails_alike() {
  local ranks=$1 code
  shift
  "$dlpverify" "$@" --json "$dir/out.json" >"$dir/out" 2>"$dir/serial"
  code=$?
  [ "$code" -eq 3 ] || fail "the serial run exited $code, expected 3"
  [ "$(wc -l <"$dir/serial")" -eq 1 ] && grep -q "CV_TOO_MUCH_WORK" "$dir/serial" ||
    { cat "$dir/serial"; fail "the serial run did not print one CV_TOO_MUCH_WORK line"; }
  [ ! -s "$dir/out" ] && [ ! -e "$dir/out.json" ] || fail "output from a failed serial study"
  run_ranks "$ranks" "$dlpverify" "$@" --json "$dir/out.json" >"$dir/out" 2>"$dir/ranks"
  code=$?
  [ "$code" -eq 3 ] || { cat "$dir/ranks"; fail "$ranks ranks exited $code, expected 3"; }
  cmp -s "$dir/serial" "$dir/ranks" || { cat "$dir/ranks"; echo "not the serial"; cat "$dir/serial"; fail "$ranks ranks printed another line"; }
  [ ! -s "$dir/out" ] && [ ! -e "$dir/out.json" ] || fail "output from a failed study on $ranks ranks"
  echo "ok: $(cat "$dir/ranks") (exit 3 on $ranks ranks, as serially)"
}

study=(converge --case full --outer 9 --levels 2 --threads 1)
"$dlpverify" "${study[@]}" --json "$dir/whole.json" >/dev/null 2>&1 || fail "the study with CVODE's default step limit exited $?"
particles=$(/usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["particles"])' "$dir/whole.json")
[ "$particles" -le 4096 ] || fail "$particles particles: more than one norm block, so rank 0 holds some"
limit=$(half_the_steps "$dir/whole.json" 'j["reference_statistics"]["solve"]["steps_max"]')
echo "reference: $particles particles, --max-steps $limit (half the most steps of a block)"
fails_alike 2 "${study[@]}" --max-steps "$limit"

study=(converge --case drag --outer 13 --levels 2 --integrator cvode --threads 1)
"$dlpverify" "${study[@]}" --json "$dir/whole.json" >/dev/null 2>&1 || fail "the CVODE study with its default step limit exited $?"
limit=$(half_the_steps "$dir/whole.json" 'j["levels"][0]["solver_statistics"]["steps"]')
echo "integrator: --max-steps $limit (half of level 0's steps)"
fails_alike 3 "${study[@]}" --max-steps "$limit"
