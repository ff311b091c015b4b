#!/usr/bin/env bash
# Count limits and the memory estimate (issue 9). usage: limits.sh DLPVERIFY CHECK
#   threads  --threads above 4 × the cores is refused (it crashed libgomp: exit 139), at the bound
#            it runs; OMP_NUM_THREADS above it is refused too
#   memory   a study that does not fit is refused before any allocation, the line giving the
#            estimate (copies × N × F columns × 8 bytes, N from docs/model.md §2) and what is
#            available; a small study under the same limit runs
set -u
dlpverify=$1 check=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; echo "--- stderr:"; cat "$dir/err"; exit 1; }
small=(--case drag --outer 4 --levels 2)

# refused FRAGMENT... -- COMMAND...: exit 2, one stderr line holding every fragment, nothing on stdout.
refused() {
  local fragments=()
  while [ "$1" != "--" ]; do fragments+=("$1"); shift; done
  shift
  "$@" >"$dir/out" 2>"$dir/err"
  local code=$?
  [ "$code" -eq 2 ] || fail "$*: exit $code, expected 2"
  [ "$(wc -l <"$dir/err")" -eq 1 ] || fail "$*: stderr is not one line"
  for f in "${fragments[@]}"; do grep -qF -- "$f" "$dir/err" || fail "$*: stderr does not say $f"; done
  [ ! -s "$dir/out" ] || fail "$*: output on stdout, so the study ran"
}

case $check in
threads)
  cores=$(nproc)
  refused --threads 100000 "at most 4 x the $cores cores = $((4 * cores))" -- "$dlpverify" converge "${small[@]}" --threads 100000
  refused --threads "$((4 * cores + 1))" -- "$dlpverify" precision "${small[@]}" --threads "$((4 * cores + 1))"
  "$dlpverify" converge "${small[@]}" --threads "$((4 * cores))" >/dev/null 2>"$dir/err" || fail "--threads $((4 * cores)) exited $?"
  refused --threads OMP_NUM_THREADS 100000 -- env OMP_NUM_THREADS=100000 "$dlpverify" converge "${small[@]}"
  echo "ok: --threads bounded by 4 x $cores cores, OMP_NUM_THREADS too"
  ;;
memory)
  # R_out 2000: 33,510,290,992 particles, 4 copies of 2.14 TB — more than any CI machine has.
  refused --outer 2000 "needs about 8.58 TB" "2.14 TB each" "available (" -- "$dlpverify" converge --outer 2000
  # Under ulimit -v 900 MB: the seed sphere (4,187,856 particles, 268 MB a copy) needs 4 copies with
  # RK2 (measured peak 827 MB), 5 with --per-particle, 26 with CVODE integrating the whole cloud;
  # R_out 4 fits.
  limited() { (ulimit -v 900000 && "$@"); }
  refused --outer "needs about 1.07 GB" "4 copies" "268 MB each" "available (" -- limited "$dlpverify" converge --outer 100
  refused "needs about 1.34 GB" "5 copies" -- limited "$dlpverify" converge --outer 100 --per-particle "$dir/p.csv"
  refused "needs about 6.97 GB" "26 copies" -- limited "$dlpverify" converge --outer 100 --integrator cvode
  refused "needs about 6.97 GB" -- limited "$dlpverify" precision --outer 100
  # A tableau file steps as it is written: an explicit one each member alone (4 copies), a
  # diagonally implicit one the whole cloud in ARKStep's vectors (26, as CVODE, and 2 a stage:
  # Alexander's 2 stages, 30).
  tableaux=$(cd "$(dirname "$0")/../../examples/tableaux" && pwd)
  refused "needs about 1.07 GB" "4 copies" -- limited "$dlpverify" converge --outer 100 --integrator "tableau:$tableaux/rk4.toml"
  refused "needs about 8.04 GB" "30 copies" -- \
    limited "$dlpverify" converge --outer 100 --integrator "tableau:$tableaux/sdirk2-alexander.toml"
  # Gas parcels: 10^7 (the bound) × T and P, 160 MB a copy, 4 copies; under 500 MB refused before
  # any parcel exists.
  refused --parcels 10000000 "needs about 640 MB" "160 MB each" -- \
    bash -c 'ulimit -v 500000 && exec "$@"' _ "$dlpverify" converge --case adiabat-vdw --parcels 10000000
  limited "$dlpverify" converge "${small[@]}" >/dev/null 2>"$dir/err" || fail "R_out 4 under ulimit -v 1 GB exited $?"
  [ -z "$(ls -A "$dir" | grep -v -e '^out$' -e '^err$')" ] || fail "a refused study wrote a file"
  echo "ok: studies that do not fit are refused with the estimate and the available memory"
  ;;
*) fail "unknown check $check" ;;
esac
