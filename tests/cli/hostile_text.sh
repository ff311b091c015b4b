#!/usr/bin/env bash
# User text echoed in an error line is made printable (issue 9): a study file of arbitrary bytes,
# option values and paths carrying terminal escapes, and overlong values each give exit 2 and one
# stderr line of well-formed UTF-8 with no control character (C0, DEL, C1) but its final newline,
# the escapes shown as \xNN and a long value cut with "…".
# usage: hostile_text.sh DLPVERIFY
set -u
dlpverify=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; echo "--- stderr:"; cat -v "$dir/err"; exit 1; }

# check_line WHAT EXPECTED_FRAGMENT COMMAND...
check_line() {
  local what=$1 fragment=$2
  shift 2
  "$@" >"$dir/out" 2>"$dir/err"
  local code=$?
  [ "$code" -eq 2 ] || fail "$what: exit $code, expected 2"
  /usr/bin/python3 - "$dir/err" <<'PY' || fail "$what: the error line is not printable"
import sys, unicodedata
data = open(sys.argv[1], "rb").read()
assert data.endswith(b"\n") and data.count(b"\n") == 1, "not exactly one line"
text = data[:-1].decode("utf-8")  # strict: raises on a byte that is not UTF-8
bad = [hex(ord(c)) for c in text if unicodedata.category(c) == "Cc"]
assert not bad, "control characters " + " ".join(bad)
assert len(text) <= 420, "the line is %d characters long" % len(text)
PY
  [ -z "$fragment" ] || grep -qF -- "$fragment" "$dir/err" || fail "$what: the line does not show $fragment"
}

# A study file of every byte value 0–255, in order, then the escapes as a key of their own.
{
  for i in $(seq 0 255); do printf "\\x$(printf %02x "$i")"; done
  printf '\n\x1b[2J\x1b]0;pwned\x07\x9b31m\xc2\x9b = 1\n'
} >"$dir/bytes.toml"
check_line "a study file of every byte" "--config" "$dlpverify" converge --config "$dir/bytes.toml"
# A key of raw control bytes is not TOML (refused at its line and column); a quoted key may hold
# them as TOML escapes, and the unknown key is shown with them escaped.
printf 'a\x1b[2J\x1b]0;pwned\x07\xff = 1\n' >"$dir/key.toml"
check_line "a study-file key of raw escapes" 'not TOML at line 1, column' "$dlpverify" converge --config "$dir/key.toml"
printf '"a\\u001b[2J\\u001b]0;pwned\\u0007" = 1\n' >"$dir/quoted-key.toml"
check_line "a study-file key of escapes" '\x1b[2J\x1b]0;pwned\x07' "$dlpverify" converge --config "$dir/quoted-key.toml"
printf 'case = "\\u001b[31mred\\u001b[0m"\n' >"$dir/value.toml"  # TOML's escapes: raw ones are not TOML
check_line "a study-file value of escapes" '\x1b[31mred\x1b[0m' "$dlpverify" converge --config "$dir/value.toml"

check_line "an option value of escapes" '--case = \x1b[2J\x07' "$dlpverify" converge --case "$(printf '\x1b[2J\x07')"
check_line "a number that is an escape" '\x1b[31m' "$dlpverify" converge --dt "$(printf '\x1b[31m')"
long=$(printf 'x%.0s' $(seq 1 500))
check_line "a 500-character value" "--case = $(printf 'x%.0s' $(seq 1 79))…:" "$dlpverify" converge --case "$long"
grep -qF "$(printf 'x%.0s' $(seq 1 80))" "$dir/err" && fail "a 500-character value is shown past 79 characters"

mkdir "$dir/$(printf 'd\x1b[2J')"
check_line "a path of escapes" 'd\x1b[2J' "$dlpverify" converge --outer 4 --json "$dir/$(printf 'd\x1b[2J')"
check_line "a plot input of escapes" 'no\x1b]0;x\x07such.json' "$dlpverify" plot "$dir/$(printf 'no\x1b]0;x\x07such.json')" -o "$dir/f.png"
check_line "an unknown option of escapes" '\x1b[2J' "$dlpverify" converge "$(printf -- '--\x1b[2J')"
echo "ok: every echo of user text is one printable line"
