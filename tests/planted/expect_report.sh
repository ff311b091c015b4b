#!/usr/bin/env bash
# Runs COMMAND, which must fail and print every PATTERN (a sanitizer's report of a planted bug);
# passes then, and fails if the command succeeds or its report misses one of them.
#
# usage: expect_report.sh PATTERN... -- COMMAND ARGS...
set -u
patterns=()
while [ "$1" != "--" ]; do patterns+=("$1"); shift; done
shift
log=$(mktemp)
trap 'rm -f "$log"' EXIT
start=$SECONDS
"$@" >"$log" 2>&1
code=$?
elapsed=$((SECONDS - start))
if [ "$code" -eq 0 ]; then
  echo "FAIL: the planted bug went unnoticed: '$*' passed in ${elapsed} s"
  tail -20 "$log"
  exit 1
fi
for p in "${patterns[@]}"; do
  grep -qF -- "$p" "$log" || { echo "FAIL: exit $code, but the report does not say '$p'"; tail -60 "$log"; exit 1; }
done
grep -m1 "ERROR: AddressSanitizer" "$log"
grep -m1 "^SUMMARY" "$log"
echo "ok: the planted bug was reported after ${elapsed} s (exit $code)"
