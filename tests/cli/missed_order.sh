#!/usr/bin/env bash
# A check that misses its order says why, where the study shows it (docs/verification.md, "Why an
# order was missed"): exit 1 (or $EXPECT_EXIT: 5 when the verdict is inconclusive), the reason in the table (`why: VARIABLE: REASON`) and in the JSON's
# missed_order.reasons.
#
# usage: missed_order.sh DLPVERIFY VARIABLE REASON CHECK-ARGS...
set -u
dlpverify=$1 variable=$2 reason=$3
shift 3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$dlpverify" check "$@" --json "$out/study.json" >"$out/table.txt" 2>"$out/stderr.txt"
code=$?
fail() { echo "FAIL: $*"; cat "$out/table.txt" "$out/stderr.txt"; exit 1; }
expected=${EXPECT_EXIT:-1}
[ "$code" -eq "$expected" ] || fail "exit $code, expected $expected"
grep -q "why: $variable: $reason" "$out/table.txt" || fail "the table does not say 'why: $variable: $reason'"
python3 - "$out/study.json" "$variable" "$reason" <<'PY' || fail "the JSON does not hold the reason"
import json, sys
missed = json.load(open(sys.argv[1]))["missed_order"]
reasons = [r["reason"] for r in missed["reasons"][sys.argv[2]]]
assert sys.argv[3] in reasons, reasons
PY
