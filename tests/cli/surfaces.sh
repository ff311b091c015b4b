#!/usr/bin/env bash
# Issue 51: nothing lost on the new surfaces, one mode a test. Every refusal is exit 2 (4 for an
# unwritable output) with one stderr line holding the words the test names, before any work:
# nothing on stdout and every file that was there byte for byte as it was.
#   journal-output  an output named as --json's journal (FILE.journal.jsonl) in converge, check,
#                   precision and suite (a study's output on another study's journal, and on the
#                   suite's own) is refused naming that output and the journal;
#   journal-link    a journal whose place is a link (to a user's file, to another study's journal,
#                   dangling) or a folder is refused with and without --restart, never written through;
#   memory-stages   a 50-stage diagonally implicit tableau under ulimit -v 150000 is refused with
#                   26 + 2 × 50 copies (it crashed with SIGSEGV: 26 were counted), and CVODE and
#                   Crouzeix's SDIRK 4 at R_out 20 under ulimit -v 100000 are refused, not crashed;
#   tolerance-junit check --tolerances' --junit naming a missing folder, a FIFO, a folder or a link
#                   loop is refused before the sweep (it was exit 4 after it, "no longer a regular file");
#   suite-stdout    a study file's json = "-" or csv = "/dev/stdout" is refused as that study's error
#                   (exit 2), and `suite --junit -` still prints XML alone (it printed the study's
#                   JSON into it);
#   svg-cdata       an SVG whose title holds "]]>" (--title, and a tableau file's name as the
#                   default title) parses as XML, the title drawn;
# usage: surfaces.sh DLPVERIFY SOURCE_DIR MODE
set -uo pipefail
dlpverify=$1 src=$2 mode=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
small=(--case drag --outer 4 --levels 2)

# snapshot: every file's path, type and bytes, to compare after a refusal.
snapshot() { find . -mindepth 1 \( -name stdout -o -name stderr \) -prune -o -printf '%p %y %l\n' | sort; find . -type f ! -name stdout ! -name stderr -exec sha256sum {} + | sort; }

# refused CODE TEXT COMMAND...: exit CODE, one stderr line holding TEXT, no stdout, nothing changed.
refused() {
  local code=$1 text=$2
  shift 2
  local before
  before=$(snapshot)
  if [ "$1" = limited ]; then  # limited KB COMMAND...: under ulimit -v KB
    bash -c 'ulimit -v "$0" && exec timeout 120 "$@"' "$2" "$dlpverify" "${@:3}" >stdout 2>stderr
  else
    timeout 120 "$dlpverify" "$@" >stdout 2>stderr
  fi
  local got=$?
  [ "$got" -eq "$code" ] || { fail "$*: exit $got, expected $code: $(cat stderr)"; return; }
  [ "$(wc -l <stderr)" -eq 1 ] || fail "$*: stderr is not one line: $(cat stderr)"
  grep -qF -- "$text" stderr || fail "$*: stderr does not say '$text': $(cat stderr)"
  [ ! -s stdout ] || fail "$*: output on stdout"
  [ "$before" = "$(snapshot)" ] || fail "$*: the files changed: $(diff <(echo "$before") <(snapshot))"
  echo "ok: $(cat stderr)"
}

study_file() {  # study_file NAME KEY=VALUE...: a small passing drag study file
  local name=$1
  shift
  { printf 'case = "drag"\nouter = 4\nlevels = 2\nintegrator = "rk2"\nexpect-order = 2\n'
    for kv in "$@"; do printf '%s = "%s"\n' "${kv%%=*}" "${kv#*=}"; done; } >"$name"
}

case $mode in
  journal-output)
    journal="is the same file as the journal beside --json"
    refused 2 "--csv = c.json.journal.jsonl: $journal" converge "${small[@]}" --json c.json --csv c.json.journal.jsonl
    refused 2 "--table = ./c.json.journal.jsonl: $journal" check "${small[@]}" --expect-order 2 --json c.json --table ./c.json.journal.jsonl
    refused 2 "--csv = c.json.journal.jsonl: $journal" precision --case drag --outer 4 --levels 2 --integrator rk2 \
      --rtol-max 1e-4 --rtol-min 1e-5 --json c.json --csv c.json.journal.jsonl
    # In a suite: a study's output on an earlier study's journal, and on the suite's own.
    study_file a.toml json=a.json
    study_file b.toml csv=a.json.journal.jsonl
    study_file c.toml csv=s.json.journal.jsonl
    "$dlpverify" suite a.toml b.toml c.toml --json s.json --jobs 2 >stdout 2>stderr
    code=$?
    [ "$code" -eq 2 ] || fail "suite: exit $code, expected 2: $(cat stderr)"
    line=$(grep -F "b: ERROR (exit 2)" stderr)
    [[ $line == *"--csv = a.json.journal.jsonl: is the same file as the journal beside --json of a.toml"* ]] ||
      fail "suite: b's csv on a's journal not refused: $(cat stderr)"
    line=$(grep -F "c: ERROR (exit 2)" stderr)
    [[ $line == *"--csv = s.json.journal.jsonl: is the same file as the journal beside --json s.json"* ]] ||
      fail "suite: c's csv on the suite's journal not refused: $(cat stderr)"
    [ ! -e a.json.journal.jsonl ] && [ ! -e s.json.journal.jsonl ] && [ -s a.json ] && [ -s s.json ] ||
      fail "suite: a journal left or an output lost: $(ls)"
    ;;
  journal-link)
    mkdir other
    echo "a user's file" >other/keep
    ln -s other/keep r.json.journal.jsonl
    refused 2 "--json = r.json: its journal's place r.json.journal.jsonl is a symbolic link" converge "${small[@]}" --json r.json
    refused 2 "--json = r.json: its journal's place r.json.journal.jsonl is a symbolic link" converge "${small[@]}" --json r.json --restart
    ln -s other/none d.json.journal.jsonl
    refused 2 "--json = d.json: its journal's place d.json.journal.jsonl is a symbolic link" check "${small[@]}" --expect-order 2 --json d.json
    mkdir f.json.journal.jsonl
    refused 2 "--json = f.json: its journal's place f.json.journal.jsonl is a directory" converge "${small[@]}" --json f.json --restart
    # Another stopped study's journal, reached by a link: kept whole under --restart.
    "$dlpverify" converge "${small[@]}" --json o.json >/dev/null 2>&1 || fail "the other study did not run"
    printf '{"dlpverify_journal": 1}\n{"level": 0}\n' >other/o.journal.jsonl
    ln -s other/o.journal.jsonl s.json.journal.jsonl
    refused 2 "is a symbolic link" converge "${small[@]}" --json s.json --restart
    ;;
  memory-stages)
    python3 -c '
n = 50
print("name = \"dirk50\"\norder = 1")
print("c =", [(i + 1) / n for i in range(n)])
print("b =", [1 / n] * n)
print("A =", [[1 / n if j <= i else 0.0 for j in range(n)] for i in range(n)])' >dirk50.toml
    refused 2 "--outer = 20: the study needs about 269 MB of memory (126 copies of the 33400 x 8 state" \
      limited 150000 converge --case drag --outer 20 --levels 2 --integrator tableau:dirk50.toml
    refused 2 "--outer = 20: the study needs about 55.6 MB of memory (26 copies" limited 100000 converge --case drag --outer 20 --levels 2 --integrator cvode
    refused 2 "--outer = 20: the study needs about 68.4 MB of memory (32 copies" \
      limited 100000 converge --case drag --outer 20 --levels 2 --integrator "tableau:$src/examples/tableaux/sdirk4-crouzeix.toml"
    ;;
  tolerance-junit)
    mkfifo fifo.xml
    mkdir folder.xml
    ln -s loop.xml loop.xml
    sweep=(check --case drag --outer 4 --integrator cvode --tolerances 1e-4:1e-6)
    refused 2 "--junit = none/x.xml: its folder none does not exist" "${sweep[@]}" --junit none/x.xml
    refused 2 "--junit = fifo.xml: is a FIFO" "${sweep[@]}" --junit fifo.xml
    refused 2 "--junit = folder.xml: is a directory" "${sweep[@]}" --junit folder.xml
    refused 2 "--junit = loop.xml: is a loop of symbolic links" "${sweep[@]}" --junit loop.xml
    ;;
  suite-stdout)
    study_file a.toml json=-
    study_file b.toml csv=/dev/stdout
    study_file c.toml
    "$dlpverify" suite a.toml b.toml c.toml --junit - >stdout 2>stderr
    code=$?
    [ "$code" -eq 2 ] || fail "suite: exit $code, expected 2"
    for s in "a: ERROR (exit 2)" "--json = -: a study of a suite writes no output to standard output" \
             "b: ERROR (exit 2)" "--csv = /dev/stdout: a study of a suite writes no output to standard output" "c: pass"; do
      grep -qF -- "$s" stderr || fail "suite: stderr does not say '$s': $(cat stderr)"
    done
    python3 -c 'import sys, xml.etree.ElementTree as t; r = t.parse(sys.argv[1]).getroot(); assert r.get("errors") == "2", r.get("errors")' stdout ||
      fail "suite --junit -: standard output is not the JUnit XML alone: $(head -c 300 stdout)"
    ;;
  svg-cdata)
    cp "$src/examples/tableaux/rk4.toml" 'x]]>y.toml'
    "$dlpverify" converge "${small[@]}" --integrator 'tableau:x]]>y.toml' --json r.json --plot default.svg >/dev/null 2>stderr ||
      fail "converge with the tableau x]]>y.toml: $(cat stderr)"
    "$dlpverify" plot r.json -o titled.svg --title 'a]]>b' >/dev/null 2>stderr || fail "plot --title: $(cat stderr)"
    for svg in default.svg titled.svg; do
      python3 -c '
import sys, xml.etree.ElementTree as t
texts = "".join(e.text or "" for e in t.parse(sys.argv[1]).iter("{http://www.w3.org/2000/svg}text")).replace("\u2060", "")
assert sys.argv[2] in texts, texts[:300]' "$svg" "$( [ $svg = titled.svg ] && echo 'a]]>b' || echo 'x]]>y')" ||
        fail "$svg is not XML with its title"
    done
    ;;
  *) echo "unknown mode $mode"; exit 2 ;;
esac
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all passed"
