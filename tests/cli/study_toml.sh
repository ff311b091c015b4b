#!/usr/bin/env bash
# Study files are TOML; empty values are refused. Each case: exit 2, exactly one line on stderr
# naming the option (and for a study file, the file and its line), nothing written, nothing on
# stdout (docs/cli.md, "Study files" and "Empty values").
#
# usage: study_toml.sh CASE DLPVERIFY
#   unquoted      case = drag                      not TOML, line 2, column 8
#   unterminated  case = "drag                     not TOML, line 2
#   empty-title   title = "" then csv = "x.csv"    an empty string (no CSV written)
#   empty-dt      dt = ""                          a string for a number
#   quiet-yes     quiet = "yes"                    a string for a flag
#   quiet-one     quiet = 1                        an integer for a flag
#   dt-string     dt = "0.001"                     a string for a number
#   empty-json, empty-config, empty-dt-typed, empty-threads, empty-baseline, empty-bench-outer,
#   empty-equals  an empty value on the command line (--dt= as one word, too)
#   runs          the hostile file's well-written twin runs: quiet = true, title "-x=y" kept
set -uo pipefail
case_name=$1 dlpverify=$2
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
mkdir "$d/out"

fail() { echo "FAIL ($case_name): $*"; echo "--- stderr:"; cat "$d/err"; exit 1; }

# refused EXPECTED ARGS...: exit 2, one line holding EXPECTED, no file in out/, nothing on stdout.
refused() {
  local expected=$1
  shift
  (cd "$d/out" && "$dlpverify" "$@" >"$d/stdout" 2>"$d/err")
  local code=$?
  [ "$code" -eq 2 ] || fail "exit $code, expected 2"
  [ "$(wc -l <"$d/err")" -eq 1 ] || fail "stderr is not one line"
  local err
  err=$(cat "$d/err")
  [[ "$err" == *"$expected"* ]] || fail "stderr does not say: $expected"
  [ -z "$(ls -A "$d/out")" ] || fail "written: $(ls -A "$d/out")"
  [ ! -s "$d/stdout" ] || fail "output on stdout"
  echo "ok: $err"
}

study() { printf 'outer = 4\nlevels = 2\n%s\n' "$1" >"$d/s.toml"; }
small=(--outer 4 --levels 2)

case $case_name in
  unquoted) study 'case = drag'
    refused "--config = $d/s.toml: not TOML at line 3, column 8" converge --config "$d/s.toml" --json study.json ;;
  unterminated) study 'case = "drag'
    refused "--config = $d/s.toml: not TOML at line 3" converge --config "$d/s.toml" --json study.json ;;
  empty-title) study "$(printf 'title = ""\ncsv = "x.csv"')"
    refused 'line 3: title = "" is empty' converge --config "$d/s.toml" ;;
  empty-dt) study 'dt = ""'
    refused 'line 3: dt = "" is a string; --dt takes a number' converge --config "$d/s.toml" --json study.json ;;
  quiet-yes) study 'quiet = "yes"'
    refused 'quiet = "yes" is a string; --quiet takes true or false' converge --config "$d/s.toml" --json study.json ;;
  quiet-one) study 'quiet = 1'
    refused 'quiet = 1 is an integer; --quiet takes true or false' converge --config "$d/s.toml" --json study.json ;;
  dt-string) study 'dt = "0.001"'
    refused 'dt = "0.001" is a string; --dt takes a number' converge --config "$d/s.toml" --json study.json ;;
  empty-json) refused "--json = '': is empty" converge "${small[@]}" --json '' --csv study.csv ;;
  empty-config) refused "--config = '': is empty" converge "${small[@]}" --config '' --json study.json ;;
  empty-dt-typed) refused "--dt = '': is empty" converge "${small[@]}" --dt '' --json study.json ;;
  empty-threads) refused "--threads = '': is empty" converge "${small[@]}" --threads '' --json study.json ;;
  empty-baseline) refused "--baseline = '': is empty" check "${small[@]}" --expect-order 2 --baseline '' --json study.json ;;
  empty-bench-outer) refused "--outer = '': is empty" bench --outer '' --seconds 0.01 --json bench.json ;;
  empty-equals) refused "--dt = '': is empty" converge "${small[@]}" --dt= 0.001 --json study.json ;;
  runs) study "$(printf 'quiet = true\ntitle = "-x=y"\nplot = "study.svg"\ncase = "drag"')"
    (cd "$d/out" && "$dlpverify" converge --config "$d/s.toml" --json study.json >"$d/stdout" 2>"$d/err") || fail "exit $?"
    title=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["options"]["title"])' "$d/out/study.json")
    [ "$title" = "-x=y" ] || fail "title recorded as '$title', not -x=y"
    echo "ok: ran, title -x=y" ;;
  *) echo "unknown case $case_name"; exit 2 ;;
esac
