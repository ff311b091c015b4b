#!/usr/bin/env bash
# Inputs are regular files of bounded size (docs/cli.md, "What a path may name"): a FIFO with no
# writer, a link to /dev/zero or a folder named as any input — a tableau, an analyze run, a
# variables file, a baseline, a figure's result, a resumed journal — is refused at once with
# exit 2 and one line naming the input and the path, and the node is left as it was. `timeout`
# only guards a hang: its expiry (exit 124) fails the test naming the command that blocked.
#
# usage: inputs.sh DLPVERIFY SOURCE_DIR
set -uo pipefail
dlpverify=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mkfifo fifo.toml fifo.h5 fifo.json
ln -s /dev/zero zero.toml
mkdir folder.toml
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# refused TEXT COMMAND...: exit 2 within the guard, one line on stderr holding TEXT, no stdout.
refused() {
  local text=$1
  shift
  timeout 60 "$dlpverify" "$@" >stdout 2>stderr
  local code=$?
  if [ "$code" -eq 124 ]; then fail "$*: blocked (no answer within 60 s)"; return; fi
  [ "$code" -eq 2 ] || { fail "$*: exit $code, expected 2: $(cat stderr)"; return; }
  [ "$(wc -l <stderr)" -eq 1 ] || fail "$*: stderr is not one line: $(cat stderr)"
  grep -qF -- "$text" stderr || fail "$*: stderr does not say '$text': $(cat stderr)"
  [ ! -s stdout ] || fail "$*: output on stdout"
  echo "ok: $(cat stderr)"
}

for input in fifo.toml zero.toml folder.toml; do
  what=$(case $input in fifo.*) echo "a FIFO" ;; zero.*) echo "a device" ;; *) echo "a folder" ;; esac)
  refused "tableau file = $input: is $what, not a regular file" tableau "$input"
  refused "tableau file = $input: is $what" converge --case drag --outer 4 --levels 2 --integrator "tableau:$input"
  refused "--variables = $input: is $what" analyze fifo.h5 fifo.h5 fifo.h5 --variables "$input"
done
refused "run = fifo.h5: is a FIFO, not a regular file" analyze fifo.h5 zero.toml folder.toml
refused "run = zero.toml: is a device" analyze zero.toml fifo.h5 folder.toml
refused "--baseline = fifo.json: is a FIFO" check --case drag --outer 4 --levels 2 --expect-order 2 --baseline fifo.json
refused "fifo.json: is a FIFO" plot fifo.json -o figure.png
refused "fifo.json: is a FIFO" compare fifo.json fifo.json

# A resumed journal that links to /dev/zero (read without end before) or is a FIFO.
ln -s /dev/zero out.json.journal.jsonl
refused "journal = out.json.journal.jsonl: is not a regular file" converge --case drag --outer 4 --levels 2 --json out.json --resume
rm out.json.journal.jsonl && mkfifo out.json.journal.jsonl
refused "journal = out.json.journal.jsonl: is not a regular file" converge --case drag --outer 4 --levels 2 --json out.json --resume

# The nodes are what they were, and nothing was written beside them.
[ -p fifo.toml ] && [ -p fifo.h5 ] && [ -p fifo.json ] && [ -p out.json.journal.jsonl ] || fail "a FIFO was replaced"
[ "$(readlink zero.toml)" = /dev/zero ] && [ -d folder.toml ] || fail "the link or the folder changed"
[ ! -e out.json ] && [ ! -e figure.png ] || fail "an output was written"

# A tableau file above its 1 MiB limit is refused before it is parsed.
{ cat "$source/examples/tableaux/rk4.toml"; head -c 1048576 /dev/zero | tr '\0' '#'; } >big.toml
refused "tableau file = big.toml: is 10" tableau big.toml

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "PASS: every input refused at once, every node as it was"
