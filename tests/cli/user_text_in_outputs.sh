#!/usr/bin/env bash
# User text reaches the outputs intact and harmless. A file name need not be UTF-8 (Linux names
# are bytes): the study writes to it, and the JSON and the CSV header, which must be UTF-8,
# record it with U+FFFD (a finding of fuzz_options: such a name failed every output after the
# study, exit 3). A newline in an argument stays escaped on the CSV's "# command:" line, so every
# line above the column header still starts with '#'.
#
# usage: user_text_in_outputs.sh DLPVERIFY
set -eu
dlpverify=$1
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
name=$(printf 's\223.json')
"$dlpverify" converge --case drag --outer 3 --levels 2 --json "$d/$name" --csv "$d/s.csv" \
             --plot "$d/s.svg" --title "$(printf 'two\nlines')" >/dev/null
/usr/bin/python3 - "$d/$name" "$d/s.csv" <<'PY'
import json, sys
recorded = json.load(open(sys.argv[1], encoding="utf-8"))["options"]["json"]
assert recorded.endswith("/s\ufffd.json"), recorded
lines = open(sys.argv[2], encoding="utf-8").read().split("\n")
options = [l for l in lines if l.startswith("# options: ")][0]
assert json.loads(options[len("# options: "):])["json"] == recorded, options
header = next(i for i, l in enumerate(lines) if not l.startswith("#"))
assert lines[header].startswith("level,"), lines[: header + 1]
PY
echo "ok: written, recorded as …/s\ufffd.json, CSV comments intact"
