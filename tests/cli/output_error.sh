#!/usr/bin/env bash
# Exit code 4: an output into a folder that cannot be written is refused with one line naming
# the option and the path, before any work, and nothing is written anywhere. Root ignores
# permission bits, so as root the command runs as the unprivileged user nobody (setpriv).
#
# usage: output_error.sh DLPVERIFY
set -u
binary=$1
dir=$(mktemp -d)
trap 'chmod -R u+w "$dir"; rm -rf "$dir"' EXIT
chmod 755 "$dir"
mkdir "$dir/readonly"
chmod 555 "$dir/readonly"
run=("$binary")
if [ "$(id -u)" -eq 0 ]; then run=(setpriv --reuid=65534 --regid=65534 --clear-groups "$binary"); fi
(cd "$dir" && "${run[@]}" converge --case drag --outer 4 --levels 2 --json readonly/study.json \
   >"$dir/stdout" 2>"$dir/stderr")
code=$?
fail() { echo "FAIL: $*"; cat "$dir/stderr"; exit 1; }
[ "$code" -eq 4 ] || fail "exit code $code, expected 4"
[ "$(wc -l <"$dir/stderr")" -eq 1 ] || fail "stderr is not one line"
grep -qF -- "--json" "$dir/stderr" || fail "stderr does not name --json"
grep -qF -- "readonly/study.json" "$dir/stderr" || fail "stderr does not name the path"
[ ! -s "$dir/stdout" ] || fail "partial output on stdout"
[ -z "$(ls -A "$dir/readonly")" ] || fail "something was written into the folder"
echo "ok: exit 4, one line naming --json and the path, nothing written"
