#!/usr/bin/env bash
# Regenerates the seed corpora under tests/fuzz/corpus/ from real inputs: the documented command
# lines (NUL-separated words), the study files of verification/ and tests/cli/, and results that
# the given dlpverify writes (small clouds, so each file stays a few KB). Run it when an option,
# a study key or a result format changes, and commit what it wrote.
#
# usage: tests/fuzz/make_corpus.sh build/dlpverify
set -euo pipefail
dlpverify=$(realpath "$1")
cd "$(dirname "$0")"
corpus=$PWD/corpus
rm -rf "$corpus"
mkdir -p "$corpus"/{fuzz_options,fuzz_study_file,fuzz_result_json,fuzz_result_csv,fuzz_runs}

# Command lines: each as the words after `dlpverify`, NUL-separated.
n=0
while IFS= read -r line; do
  [ -z "$line" ] && continue
  n=$((n + 1))
  read -r -a words <<<"$line"
  printf '%s\0' "${words[@]}" | head -c -1 >"$corpus/fuzz_options/$(printf '%02d' $n)"
done <<'LINES'
cases
audit --json audit.json
--version
converge --help
converge --case drag --integrator rk4 --outer 10 --json out.json
check --case drag --integrator rk2 --expect-order 2
check --config verification/drag-rk2.toml --levels 2
check --case full --outer 10 --expect-order 2 --order-tolerance 0.2
precision --case drag --outer 10 --json wp.json --csv wp.csv --table wp.txt --plot wp.png --title work
precision --rtol-max 1e-4 --rtol-min 1e-8 --per-decade 2 --integrator rk4 --levels 3 --dt 0.001
converge --case full --outer 10 --per-particle p.csv --history h.csv --history-outputs 7 --plot-relative --plot e.svg
converge --integrator arkode-erk:ARKODE_VERNER_8_5_6 --case drag --outer 6 --levels 4 --dt 0.001 --ratio 2
converge --integrator cvode --rtol 1e-8 --atol 1e-10 --method bdf --linear-solver spgmr --max-steps 500 --vector openmp
converge --shape shell --outer 20 --inner 15 --spacing 2e-4 --us 50 --diameter 1e-4 --rho-p 2700 --cs 900 --t-particle 1500
converge --rho-gas 1.2 --mu-gas 1.8e-5 --cp-gas 1005 --prandtl 0.72 --t-gas 300 --cd 0.48 --g 9.81 --cb 10 --case drag-law
check --case burn --t-end=0.02 --dt=0.001 --levels=3 --expect-order=2 --threads 2 --reference cvode --reference-rtol 1e-10
converge --outer 4 --dt -0.001
converge --outer 4 --dt nan --t-end inf --ratio 1.5 --levels 1
converge --outer 4 --inner 7 --case vortex --integrator rk45 --shape cube
converge --config missing.toml --frobnicate 3
plot a.json b.json c.json -o fig.png --title T --relative
plot p.csv h.csv -o where.pdf --labels a,b
LINES

cp ../../verification/*.toml ../cli/*.toml "$corpus/fuzz_study_file/"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { "$dlpverify" "$@" >/dev/null; }
run converge --case drag --outer 3 --levels 3 --json "$work/drag.json" --per-particle "$work/drag-particles.csv" --history "$work/drag-history.csv" --history-outputs 12
run check --case burn --outer 3 --levels 3 --expect-order 2 --json "$work/burn-check.json" --per-particle "$work/burn-particles.csv" --history "$work/burn-history.csv" --history-outputs 7
run converge --case drag-law --outer 2 --levels 2 --integrator heun --json "$work/drag-law-cvode.json"
run converge --case drag-gravity-vertical --outer 2 --levels 3 --integrator cvode --json "$work/vertical-cvode.json"
run converge --case similarity --outer 3 --levels 3 --json "$work/similarity-round-off.json"
run precision --case drag --outer 2 --rtol-max 1e-4 --rtol-min 1e-6 --levels 2 --json "$work/precision.json"
cp "$work"/*.json "$corpus/fuzz_result_json/"
cp "$work"/*.csv "$corpus/fuzz_result_csv/"
# The runs analyze reads (fuzz_runs.cpp): CSV runs of steps 10 and 20 (and 40), NUL-separated,
# with ids in another order, a units line, and a --variable after the last NUL.
runs() { local name=$1; shift; printf '%s\0' "$@" | head -c -1 >"$corpus/fuzz_runs/$name"; }
runs by-id $'id,x,vx\n0,1.0,2.0\n1,1.5,2.5\n2,3.25,-1\n' $'id,x,vx\n2,3.2,-1.01\n0,1.01,2.0\n1,1.49,2.5\n'
runs by-position $'x,y\n1,2\n3,4\n' $'x,y\n1.1,2\n3,4.1\n' $'x,y\n1.05,2\n3,4.05\n'
runs units $'# units: m,m/s\nx,vx\n1,2\n' $'# units: m,m/s\nx,vx\n1.1,2\n' 'position=x'
runs variable $'id,x,y,vx,vy\n0,1,2,3,4\n1,5,6,7,8\n' $'id,x,y,vx,vy\n0,1.1,2,3,4\n1,5,6.1,7,8\n' 'speed=vx,vy'
for d in "$corpus"/*; do echo "$(basename "$d"): $(ls "$d" | wc -l) files, $(du -sh "$d" | cut -f1)"; done
