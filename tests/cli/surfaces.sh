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
#   console-controls a suite's study file and a tableau file whose names hold ESC and BEL: the
#                   summary and the console header show them escaped (\x1b, \x07), no raw control byte;
#   html-ids        studies `a b.toml` and `a-b.toml` get two anchors, each summary link leads to
#                   its own study, and no id is given twice: not across the two inline figures,
#                   nor across one figure's panels (gnuplot numbers each anew), each reference
#                   resolving inside its own figure;
#   tableau-stages  a tableau file of 33 stages is refused with one line naming the file, b and
#                   the bound (exit 2, before any work); one of 32 is read and checked;
#   resume-messages `suite --resume` after a study file changed names that file; a damaged line of
#                   the journal is named by file and line in the tool's words (no library exception);
# Protections the code keeps, each with the test that goes red when its rule changes:
#   dangling-output a dangling link to an output not made yet (out.json, or ../out.json from a
#                   folder) is the same file as that output's own name: refused naming both;
#   resume-keeps-journal a study whose exec: program fails before its first level leaves no journal,
#                   after its first a journal of that level; resumed, the same study failing (exit 3)
#                   or stopped by SIGTERM (exit 143) before its next level keeps the journal it
#                   resumed byte for byte (this run did not create it), and a last --resume finishes;
#   suite-restart   `suite --restart` starts over a study whose own journal (beside its json, left
#                   by an earlier version of the study file, one level finished) is there: discarded,
#                   the study passes, exit 0, no journal left;
#   html-heading    a study file named a<b>.toml: every place of the suite's HTML shows the name
#                   as a&lt;b&gt; (its heading, summary row and link), and the page holds no <b>;
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

# mode_program: writes ./prog, an exec: program that copies the state (no motion, errors finite)
# or, as the file ./mode says: fails every time, fails from its second run on (after level 0), or
# sends SIGTERM to dlpverify while it runs, ignoring it itself. Its command line, and so a
# journal's header, stays the same whatever it does.
mode_program() {
  cat >prog <<EOF
n=\$((\$(cat "$work/count" 2>/dev/null || echo 0) + 1))
echo "\$n" >"$work/count"
case \$(cat "$work/mode") in
  fail) exit 7 ;;
  fail-second) [ "\$n" -lt 2 ] || exit 7 ;;
  stop) trap '' TERM; kill -TERM "\$PPID" ;;
esac
exec cp "\$1" "\$2"
EOF
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
n = 32
print("name = \"dirk32\"\norder = 1")
print("c =", [(i + 1) / n for i in range(n)])
print("b =", [1 / n] * n)
print("A =", [[1 / n if j <= i else 0.0 for j in range(n)] for i in range(n)])' >dirk32.toml
    refused 2 "--outer = 20: the study needs about 192 MB of memory (90 copies of the 33400 x 8 state" \
      limited 150000 converge --case drag --outer 20 --levels 2 --integrator tableau:dirk32.toml
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
  console-controls)
    # no_controls FILE: FILE holds no control byte but the line feed.
    no_controls() { python3 -c 'import re, sys; sys.exit(bool(re.search(rb"[\x00-\x09\x0b-\x1f\x7f]", open(sys.argv[1], "rb").read())))' "$1"; }
    # ESC ] 0 ; … BEL retitles a terminal, ESC [ 2 J clears it; the line feed would forge a row.
    evil=$'t\e]0;owned\a\e[2J\nPASSED'
    shown='t\x1b]0;owned\x07\x1b[2J\nPASSED'
    study_file "$evil.toml"
    "$dlpverify" suite "$evil.toml" >stdout 2>stderr || fail "suite of the study file $shown.toml: exit $?: $(cat stderr)"
    no_controls stdout || fail "the suite's summary holds a raw control byte: $(od -c stdout | head -5)"
    grep -qF "$shown  " stdout || fail "the summary does not show the name escaped: $(cat stdout)"
    cp "$src/examples/tableaux/rk4.toml" "$evil.toml"
    "$dlpverify" converge "${small[@]}" --integrator "tableau:$evil.toml" >stdout 2>stderr ||
      fail "converge with tableau:$shown.toml: exit $?: $(cat stderr)"
    no_controls stdout || fail "the console header holds a raw control byte: $(od -c stdout | head -5)"
    grep -qF "$shown" stdout || fail "the header does not show the name escaped: $(head -2 stdout)"
    echo "ok: ESC and BEL in a study file's and a tableau file's name reach the console escaped"
    ;;
  html-ids)
    study_file 'a b.toml'
    study_file 'a-b.toml'
    "$dlpverify" suite 'a b.toml' a-b.toml --html s.html >/dev/null 2>stderr
    code=$?
    [ "$code" -eq 0 ] || fail "suite: exit $code: $(cat stderr)"
    python3 - s.html <<'PY' || fail "the HTML's ids are not unique or a link leads elsewhere"
import re, sys
page = open(sys.argv[1], encoding="utf-8").read()
ids = re.findall(r'\bid=["\']([^"\']*)["\']', page)
dup = sorted({i for i in ids if ids.count(i) > 1})
assert not dup, f"ids given twice: {dup[:5]}"
sections = dict(re.findall(r'<section class="study" id="([^"]+)">\n<h2>([^<]*):', page))
assert sorted(sections.values()) == ["a b", "a-b"], sections
links = re.findall(r'<tr class="[^"]*"><td><a href="#([^"]+)">([^<]*)</a>', page)
assert sorted(n for _, n in links) == ["a b", "a-b"], links
for target, name in links:
    assert sections.get(target) == name, f"the summary's link to {name} leads to {target}: {sections.get(target)}"
figures = re.findall(r"<svg.*?</svg>", page, re.S)
assert len(figures) == 2, f"{len(figures)} figures"
own = [set(re.findall(r'\bid=["\']([^"\']*)["\']', f)) for f in figures]
assert own[0] and own[1] and not own[0] & own[1], f"the figures share ids: {sorted(own[0] & own[1])[:5]}"
for f, mine in zip(figures, own):
    refs = re.findall(r'href=["\']#([^"\']*)["\']', f) + re.findall(r"url\(#([^)]*)\)", f)
    assert refs, "a figure without references"
    stray = sorted(set(refs) - mine)
    assert not stray, f"references outside their figure: {stray[:5]}"
PY
    echo "ok: two anchors for a b and a-b, and two figures with ids of their own"
    ;;
  tableau-stages)
    explicit() {  # explicit N: forward Euler in N stages (all nodes 0, weights 1/N), order 1
      python3 -c '
import sys
n = int(sys.argv[1])
print(f"name = \"euler{n}\"\norder = 1")
print("c =", [0.0] * n)
print("b =", [1 / n] * n)
print("A =", [[0.0] * n for _ in range(n)])' "$1" >"euler$1.toml"
    }
    explicit 33
    explicit 32
    refused 2 "tableau euler33.toml: b = 33 stages: at most 32 stages" tableau euler33.toml
    refused 2 "tableau euler33.toml: b = 33 stages: at most 32 stages" converge "${small[@]}" --integrator tableau:euler33.toml --json r.json
    refused 2 "tableau euler33.toml: b = 33 stages: at most 32 stages" sharpness --integrator tableau:euler33.toml
    timeout 60 "$dlpverify" tableau euler32.toml >stdout 2>stderr || fail "a tableau of 32 stages: exit $?: $(cat stderr)"
    grep -q "stages.*32\|32 stages" stdout || fail "the report of 32 stages does not say so: $(head -5 stdout)"
    echo "ok: 33 stages refused, 32 read"
    ;;
  resume-messages)
    . "$src/tests/signal_events.sh"
    # a journaled, b under way when SIGINT comes (finished: a suite stops between studies), c left.
    study_file a.toml
    cp "$src/tests/cli/suite/full-slow.toml" b.toml
    study_file c.toml
    journal=s.json.journal.jsonl
    set -m  # its own process group, so SIGINT is not ignored as in a background job
    "$dlpverify" suite a.toml b.toml c.toml --jobs 1 --json s.json >stdout 2>stderr &
    pid=$!
    set +m
    await "a study in $journal" has_a_level "$journal" "$pid"
    freeze "$pid"
    kept=$(kept_levels "$journal" 3)
    kill -INT "$pid" 2>/dev/null
    kill -CONT "$pid" 2>/dev/null
    wait "$pid"
    code=$?
    if [ "$kept" -eq 3 ]; then echo "note: every study was journaled before the suite stood still"; exit 0; fi
    [ "$code" -eq 130 ] || fail "SIGINT: exit $code, expected 130"
    # resumed CODE TEXT: suite --resume exits CODE saying TEXT in the tool's words; no output, no file changed.
    resumed() {
      local before
      before=$(snapshot)
      timeout 60 "$dlpverify" suite a.toml b.toml c.toml --jobs 1 --json s.json --resume >stdout 2>stderr
      local got=$?
      [ "$got" -eq "$1" ] || { fail "--resume: exit $got, expected $1: $(cat stderr)"; return; }
      grep -qF -- "$2" stderr || fail "--resume: stderr does not say '$2': $(cat stderr)"
      ! grep -q "json.exception\|\[json\|fnv1a64" stderr || fail "--resume: a library's words or hashes: $(cat stderr)"
      [ ! -s stdout ] || fail "--resume: output on stdout"
      [ "$before" = "$(snapshot)" ] || fail "--resume: the files changed"
      echo "ok: $(tail -1 stderr)"
    }
    cp a.toml a.kept
    echo "# edited" >>a.toml
    resumed 2 "--resume = $journal: study file a.toml changed since the journal was written: its content hash differs"
    cp a.kept a.toml
    cp "$journal" journal.kept
    line=$(($(wc -l <"$journal") + 1))
    echo '{"index": "first", "study": {}}' >>"$journal"
    resumed 2 "--resume = $journal: line $line is not a study of this suite (a value is a string where a number belongs)"
    cp journal.kept "$journal"
    echo '{"study": {}}' >>"$journal"
    resumed 2 "--resume = $journal: line $line is not a study of this suite (it has no \"index\")"
    ;;
  dangling-output)
    # No target exists yet: what a write through each link would make is that output itself.
    ln -s a.json a.csv
    mkdir sub
    ln -s ../b.json sub/b.csv
    ln -s c.json c.txt
    refused 2 "--csv = a.csv: is the same file as --json a.json (a run writes each file once)" \
      converge "${small[@]}" --json a.json --csv a.csv
    refused 2 "--csv = sub/b.csv: is the same file as --json b.json (a run writes each file once)" \
      converge "${small[@]}" --json b.json --csv sub/b.csv
    refused 2 "--table = c.txt: is the same file as --json c.json (a run writes each file once)" \
      check "${small[@]}" --expect-order 2 --json c.json --table c.txt
    ;;
  resume-keeps-journal)
    mode_program
    study=(converge --case drag --outer 2 --levels 3 --integrator "exec:bash $work/prog {input} {output}" --json r.json)
    journal=r.json.journal.jsonl
    # ran CODE TEXT ARGS...: the study with ARGS exits CODE, its stderr's last line holding TEXT.
    ran() {
      timeout 120 "$dlpverify" "${study[@]}" "${@:3}" >stdout 2>stderr
      local got=$?
      [ "$got" -eq "$1" ] || fail "${*:3}: exit $got, expected $1: $(cat stderr)"
      [[ $(tail -n 1 stderr) == *"$2"* ]] || fail "${*:3}: stderr does not end with '$2': $(cat stderr)"
    }
    echo fail >mode
    ran 3 "exited with status 7"
    [ ! -e "$journal" ] || fail "a study that finished no level left its journal"
    echo fail-second >mode
    rm count
    ran 3 "exited with status 7"
    [ "$(wc -l <"$journal")" -eq 2 ] || fail "the journal does not hold its header and level 0: $(ls)"
    cp "$journal" journal.kept
    echo fail >mode
    ran 3 "exited with status 7" --resume
    grep -qF "resuming from $journal (1 finished, taken as they are)" stderr || fail "--resume did not resume: $(cat stderr)"
    cmp -s "$journal" journal.kept || fail "a resumed study that failed before its next level lost its journal: $(ls)"
    echo stop >mode
    ran 143 "SIGTERM: stopped after 1 of 3 levels; $journal keeps the first: continue with --resume" --resume
    cmp -s "$journal" journal.kept || fail "a resumed study stopped before its next level lost its journal: $(ls)"
    echo run >mode
    ran 0 "" --resume  # progress lines may follow, as fast as the machine is
    grep -qF "resuming from $journal (1 finished, taken as they are)" stderr || fail "the last --resume did not resume: $(cat stderr)"
    [ ! -e "$journal" ] && [ -s r.json ] || fail "the finished study left its journal or wrote no r.json: $(ls)"
    echo "ok: the journal a study resumed is kept when it fails or stops before its next level"
    ;;
  suite-restart)
    mode_program
    echo fail-second >mode
    "$dlpverify" check --case drag --outer 2 --levels 3 --expect-order 2 --integrator "exec:bash $work/prog {input} {output}" \
      --json a.json >/dev/null 2>stderr
    code=$?
    [ "$code" -eq 3 ] && [ "$(wc -l <a.json.journal.jsonl)" -eq 2 ] || fail "no journal of one level: exit $code: $(cat stderr)"
    study_file a.toml json=a.json
    timeout 120 "$dlpverify" suite a.toml --json s.json --restart >stdout 2>stderr
    code=$?
    [ "$code" -eq 0 ] || fail "suite --restart: exit $code, expected 0: $(cat stderr)"
    for s in "--restart: a.json.journal.jsonl (1 finished) discarded" "dlpverify suite: [1/1] a: pass"; do
      grep -qF -- "$s" stderr || fail "suite --restart: stderr does not say '$s': $(cat stderr)"
    done
    [ ! -e a.json.journal.jsonl ] && [ ! -e s.json.journal.jsonl ] || fail "a journal left: $(ls)"
    grep -qF '"integrator": "rk2"' a.json || fail "a.json is not the restarted study's result"
    echo "ok: suite --restart started over the study with a journal of its own"
    ;;
  html-heading)
    study_file 'a<b>.toml'
    study_file c.toml
    "$dlpverify" suite 'a<b>.toml' c.toml --html s.html >/dev/null 2>stderr || fail "suite: exit $?: $(cat stderr)"
    for s in '<h2>a&lt;b&gt;: <span class="tag">pass</span></h2>' '">a&lt;b&gt;</a></td><td class="tag">pass</td>'; do
      grep -qF -- "$s" s.html || fail "the HTML does not hold '$s'"
    done
    ! grep -qF '<b>' s.html || fail "a study's name reached the HTML as markup: $(grep -F '<b>' s.html)"
    echo "ok: the name a<b> is text in the HTML's heading and summary"
    ;;
  *) echo "unknown mode $mode"; exit 2 ;;
esac
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all passed"
