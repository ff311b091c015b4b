#!/usr/bin/env bash
# The figures' contract at the command line (issue 5). usage: plot_contract.sh DLPVERIFY CHECK
#   overlay   three studies' JSON redrawn as one figure by `dlpverify plot`, from the JSON alone
#   hostile   titles that try to run shell commands through gnuplot draw a figure and run nothing
#   refusals  a bad extension or inputs of mixed kinds: exit 2, one line, no figure
#   own-variables  a problem's own variables and a dimensionless step, as the files declare them,
#             draw with their names and units and "Δt" without "[s]"; a study's JSON names its
#             units, and one written before units were recorded draws with "Δt [s]"
set -uo pipefail
dlpverify=$1 check=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
is_png() {  # PNG signature and a non-trivial size
  [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$1 is not a PNG"
  [ "$(stat -c %s "$1")" -gt 20000 ] || fail "$1 is too small to be a figure"
}

case $check in
overlay)
  for integrator in euler rk2 rk4; do
    "$dlpverify" converge --case drag --integrator "$integrator" --outer 4 --json "$dir/$integrator.json" >/dev/null ||
      fail "converge $integrator"
  done
  "$dlpverify" plot "$dir/euler.json" "$dir/rk2.json" "$dir/rk4.json" -o "$dir/overlay.png" || fail "plot exited $?"
  is_png "$dir/overlay.png"
  "$dlpverify" plot "$dir/rk2.json" -o "$dir/rk2.svg" || fail "svg"
  grep -q '</svg>' "$dir/rk2.svg" || fail "the SVG is not whole"
  ;;
hostile)
  rm -f /tmp/pwned /tmp/pwned2 /tmp/pwned3
  i=0
  for title in 'x"; system("touch /tmp/pwned"); print "' '`touch /tmp/pwned2`' "x'; system('touch /tmp/pwned3'); print '"; do
    i=$((i + 1))
    "$dlpverify" converge --case drag --outer 4 --levels 3 --plot "$dir/h$i.png" --title "$title" >/dev/null ||
      fail "converge with a hostile title exited $?"
    is_png "$dir/h$i.png"
  done
  for f in /tmp/pwned /tmp/pwned2 /tmp/pwned3; do [ ! -e "$f" ] || fail "$f exists: a title ran a command"; done
  ;;
refusals)
  "$dlpverify" converge --case drag --outer 4 --levels 2 --json "$dir/s.json" --per-particle "$dir/p.csv" >/dev/null
  "$dlpverify" plot "$dir/s.json" -o "$dir/figure.jpg" 2>"$dir/err"
  [ $? -eq 2 ] || fail "a .jpg figure did not exit 2"
  [ "$(wc -l <"$dir/err")" -eq 1 ] && grep -q -- "-o" "$dir/err" || fail "the refusal does not name -o in one line"
  "$dlpverify" plot "$dir/s.json" "$dir/p.csv" -o "$dir/mixed.png" 2>"$dir/err"
  [ $? -eq 2 ] || fail "mixed kinds did not exit 2"
  ls "$dir" | grep -E 'figure|mixed' >/dev/null && fail "a refused figure was written"
  "$dlpverify" converge --case drag --outer 4 --plot "$dir/x.gif" --json "$dir/t.json" >/dev/null 2>&1
  [ $? -eq 2 ] && [ ! -e "$dir/t.json" ] || fail "converge --plot x.gif must exit 2 before writing anything"
  ;;
own-variables)
  # A history and a convergence result of a pendulum of its own, dimensionless time.
  printf '# units: 1,J,rad,J,rad\nt,l2_energy,l2_angle,ref_l2_energy,ref_l2_angle\n0.5,1e-6,2e-7,1,2\n1,3e-6,5e-7,1,2\n' \
    >"$dir/history.csv"
  "$dlpverify" plot "$dir/history.csv" -o "$dir/history.svg" || fail "plot of a history of its own variables exited $?"
  for text in '<text>energy [J]</text>' '<text>angle [rad]</text>' '<text>L2 error [J, rad]</text>' '<text>t</text>'; do
    grep -qF "$text" "$dir/history.svg" || fail "the history figure does not show $text"
  done
  grep -qF '[s]' "$dir/history.svg" && fail "a dimensionless history's figure shows [s]"
  level() { echo "{\"level\": $1, \"dt\": $2, \"l2_energy\": $3, \"l2_angle\": $4}"; }
  fit='{"value": 2.0, "ci95": [1.9, 2.1], "levels_used": [0, 1, 2], "exact_to_round_off": false}'
  cat >"$dir/study.json" <<JSON
{"case": "pendulum", "integrator": "rk2", "integrator_order": 2, "particles": 1, "time_unit": "1",
 "variables": ["energy", "angle"], "units": {"energy": "J", "angle": "rad"},
 "levels": [$(level 0 0.1 1e-2 4e-3), $(level 1 0.05 2.5e-3 1e-3), $(level 2 0.025 6.25e-4 2.5e-4)],
 "fitted_order": {"energy": $fit, "angle": $fit}}
JSON
  "$dlpverify" plot "$dir/study.json" -o "$dir/study.svg" || fail "plot of a study of its own variables exited $?"
  for text in '<text>energy [J]: p = 2.00 [1.90, 2.10]</text>' '<text>angle [rad]: p = 2.00 [1.90, 2.10]</text>' \
    '<text>L2 error [J, rad]</text>' '<text>Δt</text>'; do
    grep -qF "$text" "$dir/study.svg" || fail "the study figure does not show $text"
  done
  grep -qF '[s]' "$dir/study.svg" && fail "a dimensionless study's figure shows [s]"
  # The cloud's study names its units; without them (a result of an earlier version) it draws the same.
  "$dlpverify" converge --case drag --outer 4 --levels 3 --json "$dir/drag.json" >/dev/null || fail "converge"
  /usr/bin/python3 - "$dir/drag.json" "$dir/old.json" <<'PY' || fail "drag.json does not name its units"
import json, sys
study = json.load(open(sys.argv[1]))
if (study.get("time_unit"), study.get("variables"), study.get("units")) != (
        "s", ["position", "velocity"], {"position": "m", "velocity": "m/s"}):
    sys.exit(f"time_unit {study.get('time_unit')}, variables {study.get('variables')}, units {study.get('units')}")
for key in ("time_unit", "variables", "units"):
    del study[key]
json.dump(study, open(sys.argv[2], "w"))
PY
  "$dlpverify" plot "$dir/old.json" -o "$dir/old.svg" || fail "plot of a result without units exited $?"
  for text in '<text>Δt [s]</text>' '<text>L2 error [m, m/s]</text>'; do
    grep -qF "$text" "$dir/old.svg" || fail "the figure of a result without units does not show $text"
  done
  ;;
*) fail "unknown check $check" ;;
esac
echo "ok: $check"
