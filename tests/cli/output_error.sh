#!/usr/bin/env bash
# Exit code 4: an output into a folder that cannot be written is refused with one line naming
# the option and the path, before any work, and nothing is written anywhere — for every output
# option of every command. Root ignores permission bits, so as root the commands run as the
# unprivileged user nobody (setpriv).
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
fail() { echo "FAIL: $*"; cat "$dir/stderr"; exit 1; }
small=(--case drag --outer 4 --levels 2)
"$binary" converge "${small[@]}" --json "$dir/s.json" >/dev/null || fail "converge for plot's input"
chmod 644 "$dir/s.json"

# refused OPTION COMMAND...: exit 4, one line naming OPTION and the path, nothing written.
refused() {
  local option=$1 path=readonly/out.png
  shift
  (cd "$dir" && "${run[@]}" "$@" "$option" "$path" >"$dir/stdout" 2>"$dir/stderr")
  local code=$?
  [ "$code" -eq 4 ] || fail "$option: exit code $code, expected 4"
  [ "$(wc -l <"$dir/stderr")" -eq 1 ] || fail "$option: stderr is not one line"
  grep -qF -- "$option" "$dir/stderr" || fail "$option: stderr does not name it"
  grep -qF -- "$path" "$dir/stderr" || fail "$option: stderr does not name the path"
  [ ! -s "$dir/stdout" ] || fail "$option: partial output on stdout"
  [ -z "$(ls -A "$dir/readonly")" ] || fail "$option: something was written into the folder"
}
for option in --json --csv --table --plot --history --per-particle; do refused "$option" converge "${small[@]}"; done
for option in --json --csv --table --plot; do refused "$option" precision "${small[@]}" --rtol-max 1e-4 --rtol-min 1e-5; done
refused --json audit
refused -o plot s.json
echo "ok: exit 4 for every output option, one line naming the option and the path, nothing written"
