#!/usr/bin/env bash
# Runs a dlpverify command with every output option pointed into a fresh folder and checks the
# exit code. For bad input (code 2), solver failures (3) and unwritable outputs (4) it also checks
# the contract: exactly one line on stderr, naming OPTION (and VALUE when given), and no file
# written; a finished study (0 done, 1 a check failed, 5 inconclusive) writes every output.
#
# usage: expect_exit.sh CODE OPTION VALUE -- dlpverify ARGS...   (OPTION/VALUE may be "")
set -uo pipefail
expected=$1 option=$2 value=$3
shift 3
[ "$1" = "--" ] && shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$@" --json "$out/study.json" --csv "$out/study.csv" --table "$out/study.txt" >"$out/.stdout" 2>"$out/.stderr"
code=$?
fail() { echo "FAIL: $*"; echo "--- stderr:"; cat "$out/.stderr"; echo "--- stdout (head):"; head -5 "$out/.stdout"; exit 1; }

[ "$code" -eq "$expected" ] || fail "exit code $code, expected $expected"
if [ "$expected" -ge 2 ] && [ "$expected" -le 4 ]; then
  lines=$(wc -l <"$out/.stderr")
  [ "$lines" -eq 1 ] || fail "stderr has $lines lines, expected exactly one"
  [ -z "$option" ] || grep -qF -- "$option" "$out/.stderr" || fail "stderr does not name $option"
  [ -z "$value" ] || grep -qF -- "$value" "$out/.stderr" || fail "stderr does not name the value $value"
  written=$(find "$out" -mindepth 1 ! -name '.stdout' ! -name '.stderr' | wc -l)
  [ "$written" -eq 0 ] || fail "$written file(s) written: $(ls -A "$out")"
  [ ! -s "$out/.stdout" ] || fail "partial output on stdout"
else
  for f in study.json study.csv study.txt; do [ -s "$out/$f" ] || fail "$f was not written"; done
  leftovers=$(find "$out" -name '.*.tmp.*' | wc -l)
  [ "$leftovers" -eq 0 ] || fail "temporary files left behind"
fi
echo "ok: exit $code$( [ -n "$option" ] && echo ", names $option")"
