#!/usr/bin/env bash
# `dlpverify suite` and --junit (docs/cli.md, "dlpverify suite"), one mode a test:
#   verification  every study file of verification/ in one command: exit 0, one summary row per
#                 variable, "N studies: … 0 fail, 0 inconclusive; 0 studies ended without a
#                 verdict"; with Euler checked as second order added (tests/cli/suite/), exit 1;
#   junit         a passing, a failing and an inconclusive study: exit 1 (a failure outranks
#                 inconclusive); the JUnit XML validates against Jenkins' JUnit schema
#                 (junit-4.xsd, fetched by scripts/install-deps.sh) and counts 6 cases, 2 failures
#                 and 2 skipped; the failure's message is the verdict's line, its text the level
#                 table; a skip carries its finding as its message too; each suite's properties
#                 carry every variable's fitted order, interval, band and error constant; --summary
#                 lists the failure, then the inconclusive study, then the pass; `check --junit`
#                 writes the same suite for one study, and for a sweep of --tolerances (its
#                 variables' proportionality verdicts); a check whose program fails (exit 3) writes
#                 its --junit as one error case and its --summary as an ERROR row, and no --json;
#   errors        a study file of an unknown case among them: exit 2, the others still run and are
#                 summarised, and the JUnit XML holds it as an error naming --case; of two studies
#                 writing one file, or one writing over a study file, the later is an error (exit 2)
#                 naming the other, and the first runs;
#   analyze       analyze --junit (examples/analyze, forward Euler's runs checked at order 2): exit 1,
#                 the JUnit XML validates and names the failure of the runs' position;
#   parallel      eight study files with --jobs 2 --threads 4 (studies side by side, their OpenMP
#                 teams at once; the TSan build runs this mode): the same summary, one stderr line per
#                 study, and every study's JSON result equal to one run in turn, timings aside;
#   resume        a suite with --json stopped by SIGINT once its journal holds a finished study:
#                 exit 130, the study under way (with a journal of its own) stopped after its level
#                 or finished and journaled, no output; a plain run is refused, as is --resume with
#                 a study file changed; --resume runs only the studies left, the stopped one from
#                 its own journal, and prints the summary of a suite never stopped (exit 1: one
#                 study fails);
#   refused       the suite's own bad input — a study file that does not exist, --junit on a
#                 study file, --jobs -1, --resume without --json — and --html with --tolerances are
#                 one stderr line, exit 2, no output; so are --summary on the path of --junit and
#                 in a folder that does not exist, of suite and of check.
# usage: suite.sh DLPVERIFY SOURCE_DIR MODE
set -u
dlpverify=$1 src=$2 mode=$3
schema=$src/.deps/junit/jenkins-junit.xsd
here=$src/tests/cli/suite
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; echo "--- stdout:"; head -40 "$out/stdout" 2>/dev/null; echo "--- stderr:"; head -20 "$out/stderr" 2>/dev/null; exit 1; }
run() { "$dlpverify" "$@" >"$out/stdout" 2>"$out/stderr"; }
# junit-4.xsd, but for one change: <skipped> takes a message attribute as <failure> does (as in the
# xunit plugin's junit-10.xsd and Surefire's schema; Jenkins' JUnit plugin reads it).
skipped='<xs:element name="skipped" type="xs:string"/>'
with_message='<xs:element name="skipped"><xs:complexType mixed="true"><xs:attribute name="message" type="xs:string" use="optional"/></xs:complexType></xs:element>'
valid() {
  [ -f "$schema" ] || fail "no JUnit schema at $schema: run scripts/install-deps.sh"
  if [ ! -f "$out/junit.xsd" ]; then
    grep -qF "$skipped" "$schema" || fail "$schema has no $skipped to give a message"
    sed "s|$skipped|$with_message|" "$schema" >"$out/junit.xsd"
  fi
  xmllint --noout --schema "$out/junit.xsd" "$1" 2>"$out/xmllint" || { cat "$out/xmllint"; fail "$1 does not validate"; }
}
has() { grep -qF -- "$2" "$1" || fail "$1 does not hold: $2"; }

case $mode in
  verification)
    studies=("$src"/verification/*.toml)
    run suite "${studies[@]}"
    code=$?
    [ "$code" -eq 0 ] || fail "exit $code, expected 0"
    has "$out/stdout" "${#studies[@]} studies: "
    has "$out/stdout" " pass, 0 fail, 0 inconclusive; 0 studies ended without a verdict"
    [ "$(grep -c "^drag-rk2 .* pass " "$out/stdout")" -eq 2 ] || fail "drag-rk2's two variables are not both listed as pass"
    [ "$(grep -c "^dlpverify suite: \[" "$out/stderr")" -eq "${#studies[@]}" ] || fail "not one stderr line per study"
    run suite "${studies[@]}" "$here/drag-euler-expects-2.toml"
    code=$?
    [ "$code" -eq 1 ] || fail "with a failing study: exit $code, expected 1"
    has "$out/stdout" "drag-euler-expects-2"
    has "$out/stdout" " pass, 2 fail, 0 inconclusive"
    echo "ok: ${#studies[@]} study files in one suite, exit 0; one made to fail, exit 1"
    ;;
  junit)
    run suite "$src/verification/drag-rk2.toml" "$here/drag-euler-expects-2.toml" "$here/drag-rk4-expects-2.toml" \
      --junit "$out/suite.xml" --summary "$out/suite.md"
    code=$?
    [ "$code" -eq 1 ] || fail "exit $code, expected 1"
    [ "$(tail -n 1 "$out/stdout")" = "failed: drag-euler-expects-2; inconclusive: drag-rk4-expects-2" ] ||
      fail "the summary's last line does not name the failed and inconclusive studies"
    run suite "$src/verification/drag-rk2.toml" "$here/drag-euler-expects-2.toml" "$here/drag-rk4-expects-2.toml" \
      --html "$out/suite.html"
    has "$out/suite.html" '<p class="names">failed: <a href="#study-drag-euler-expects-2">drag-euler-expects-2</a></p>'
    has "$out/suite.html" '<p class="names">inconclusive: <a href="#study-drag-rk4-expects-2">drag-rk4-expects-2</a></p>'
    grep -A1 "<th>study</th>" "$out/suite.html" >"$out/first-row"
    has "$out/first-row" 'drag-euler-expects-2'
    has "$out/suite.html" '<details><summary>figure, levels, reference, provenance</summary>'
    valid "$out/suite.xml"
    has "$out/suite.xml" '<testsuites name="dlpverify" tests="6" failures="2" errors="0"'
    has "$out/suite.xml" '<testsuite name="drag-rk4-expects-2" tests="2" failures="0" errors="0" skipped="2"'
    has "$out/suite.xml" '<testcase name="position" classname="drag-euler-expects-2"'
    has "$out/suite.xml" '<failure message="position: FAIL, fitted order 1.000 outside 2.000 +/- 0.100 (over 5 levels)">'
    has "$out/suite.xml" '    4  3.125e-05     320 | 3.007e-03       1.00 | 7.802e-01       1.00 | ok'
    has "$out/suite.xml" '<skipped message="velocity: INCONCLUSIVE, fitted order 3.997 above 2.000 +/- 0.100'
    has "$out/suite.xml" '>velocity: INCONCLUSIVE, fitted order 3.997 above 2.000 +/- 0.100'
    # The numbers a trend plugin reads, per variable, on the suite (the schema has none on a case).
    has "$out/suite.xml" '<property name="position.order" value="0.999'
    has "$out/suite.xml" '<property name="velocity.order_low" value="3.9'
    has "$out/suite.xml" '<property name="velocity.order_high" value="4.0'
    has "$out/suite.xml" '<property name="position.expected_order" value="2"/>'
    has "$out/suite.xml" '<property name="position.order_tolerance" value="0.1"/>'
    has "$out/suite.xml" '<property name="position.error_constant" value="'
    # A constant at P for drag-rk2's two variables only: Euler's and RK4's are fitted at the orders
    # their errors show (1 and 4), no point of a trend at 2.
    [ "$(grep -c '<property name="[a-z]*.error_constant" ' "$out/suite.xml")" -eq 2 ] || fail "error constants other than drag-rk2's"
    [ "$(grep -c '<property name="position.order" ' "$out/suite.xml")" -eq 3 ] || fail "not one position.order per study"
    # The Markdown summary: the failure first, the inconclusive study next, the pass last.
    [ "$(head -n 1 "$out/suite.md")" = "### dlpverify suite: FAIL" ] || fail "the summary's heading is not the verdict"
    [ "$(grep '^| ' "$out/suite.md" | sed 1d | cut -d'|' -f2,3 | tr -d ' ')" = "$(printf 'FAIL|drag-euler-expects-2\nINCONCLUSIVE|drag-rk4-expects-2\npass|drag-rk2')" ] ||
      fail "the summary's rows are not failure, inconclusive, pass: $(cat "$out/suite.md")"
    run check --config "$here/drag-euler-expects-2.toml" --junit "$out/check.xml" --summary "$out/check.md"
    code=$?
    [ "$code" -eq 1 ] || fail "check --junit: exit $code, expected 1"
    valid "$out/check.xml"
    has "$out/check.xml" '<testsuite name="drag-euler-expects-2" tests="2" failures="2" errors="0" skipped="0"'
    has "$out/check.md" '| FAIL | position | 2 | 1.000 \[0.999, 1.000\] | fitted order 1.000 outside'
    # A check whose program fails (exit 3) still writes its JUnit report and summary, nothing else.
    crash="exec:/usr/bin/python3 $src/tests/cli/bad_integrator.py exit {input} {output}"
    run check --case drag --outer 4 --expect-order 2 --integrator "$crash" --junit "$out/crash.xml" --summary "$out/crash.md" \
      --json "$out/crash.json"
    code=$?
    [ "$code" -eq 3 ] || fail "check of a failing program: exit $code, expected 3"
    [ "$(wc -l <"$out/stderr")" -eq 1 ] || fail "exit 3: stderr is not one line"
    valid "$out/crash.xml"
    has "$out/crash.xml" '<testsuites name="dlpverify" tests="1" failures="0" errors="1"'
    has "$out/crash.xml" '<testcase name="study" classname="drag exec:'
    has "$out/crash.xml" 'exited with status 7'
    has "$out/crash.xml" 'exit code 3</error>'
    has "$out/crash.md" '| ERROR (exit 3) | - | - | - | '
    [ ! -e "$out/crash.json" ] || fail "exit 3 wrote --json"
    run check --case cooling --integrator cvode --tolerances 1e-4:1e-8 --junit "$out/sweep.xml"
    code=$?
    [ "$code" -eq 0 ] || fail "check --tolerances --junit: exit $code, expected 0"
    valid "$out/sweep.xml"
    has "$out/sweep.xml" '<testcase name="temperature" classname="cooling cvode"'
    echo "ok: JUnit XML of a suite and of a check validates; failure and skipped as expected"
    ;;
  errors)
    run suite "$here/unknown-case.toml" "$src/verification/drag-rk2.toml" --junit "$out/suite.xml"
    code=$?
    [ "$code" -eq 2 ] || fail "exit $code, expected 2"
    valid "$out/suite.xml"
    has "$out/stdout" "unknown-case  "
    has "$out/stdout" "ERROR (exit 2)"
    [ "$(grep -c "^drag-rk2 .* pass " "$out/stdout")" -eq 2 ] || fail "the study after the bad one did not run"
    has "$out/suite.xml" '<testsuites name="dlpverify" tests="3" failures="0" errors="1"'
    has "$out/suite.xml" '<error message="--case = nope: unknown case'
    # A study file given twice (or two of one name) keeps two names: GitLab keeps one case per name.
    run suite "$src/verification/drag-rk2.toml" "$src/verification/drag-rk2.toml" --junit "$out/twice.xml"
    has "$out/twice.xml" '<testsuite name="drag-rk2 (2)"'
    has "$out/twice.xml" 'classname="drag-rk2 (2)"'
    # Two studies writing one file: the second is bad input before any study runs, the first runs.
    mkdir "$out/shared" && cd "$out/shared" || fail "no $out/shared"
    for name in first second; do
      { cat "$src/verification/drag-rk2.toml"; echo 'json = "result.json"'; } >"$name.toml"
    done
    { cat "$src/verification/drag-rk2.toml"; echo 'csv = "first.toml"'; } >third.toml
    run suite first.toml second.toml third.toml
    code=$?
    [ "$code" -eq 2 ] || fail "two studies writing one file: exit $code, expected 2"
    has "$out/stdout" "second  "
    # One --json, so one journal beside it: the first of the second study's paths to collide.
    has "$out/stdout" "is the same file as the journal beside --json of first.toml result.json.journal.jsonl"
    has "$out/stdout" "is the input study file first.toml"
    [ "$(grep -c "^first .* pass " "$out/stdout")" -eq 2 ] && [ -s result.json ] || fail "the first study did not run"
    cmp -s first.toml second.toml && [ "$(grep -c json first.toml)" -eq 1 ] || fail "a study file was written over"
    echo "ok: a bad study file is an error; the others run; a second writer of one file is refused"
    ;;
  analyze)
    sh "$src/examples/analyze/run.sh" "$dlpverify" "$out/runs" --euler >"$out/stdout" 2>"$out/stderr"
    code=$?
    [ "$code" -eq 1 ] || fail "analyze of Euler's runs: exit $code, expected 1"
    valid "$out/runs/analyze.xml"
    has "$out/runs/analyze.xml" '<testsuite name="particles.py" tests="'
    has "$out/runs/analyze.xml" '<failure message="position: FAIL, fitted order 1.0'
    echo "ok: analyze --junit validates and names the failure"
    ;;
  refused)
    refused() {
      local name=$1
      shift
      run "$@"
      local code=$?
      [ "$code" -eq 2 ] || fail "$*: exit $code, expected 2"
      [ "$(wc -l <"$out/stderr")" -eq 1 ] || fail "$*: stderr is not one line"
      has "$out/stderr" "$name"
      [ ! -s "$out/stdout" ] || fail "$*: output on stdout"
      [ ! -e "$out/j.xml" ] || fail "$*: --junit written"
    }
    refused "$out/missing.toml" suite "$src/verification/drag-rk2.toml" "$out/missing.toml" --junit "$out/j.xml"
    cp "$src/verification/drag-rk2.toml" "$out/study.toml"
    refused "--junit" suite "$out/study.toml" --junit "$out/study.toml"
    cmp -s "$src/verification/drag-rk2.toml" "$out/study.toml" || fail "the study file was changed"
    refused "--jobs" suite "$src/verification/drag-rk2.toml" --jobs -1 --junit "$out/j.xml"
    refused "--resume" suite "$src/verification/drag-rk2.toml" --resume --junit "$out/j.xml"
    refused "--html" check --case cooling --integrator cvode --tolerances 1e-4:1e-6 --html "$out/j.xml"
    refused "--summary = $out/j.xml: is also given for another output" suite "$src/verification/drag-rk2.toml" \
      --junit "$out/j.xml" --summary "$out/j.xml"
    refused "--summary = $out/j.xml: is also given for another output" check --config "$src/verification/drag-rk2.toml" \
      --junit "$out/j.xml" --summary "$out/j.xml"
    refused "--summary = $out/none/s.md: its folder" suite "$src/verification/drag-rk2.toml" --summary "$out/none/s.md"
    refused "--summary = $out/none/s.md: its folder" check --config "$src/verification/drag-rk2.toml" --summary "$out/none/s.md" \
      --junit "$out/j.xml"
    echo "ok: the suite's own bad input is one line, exit 2, nothing written"
    ;;
  parallel)
    studies=()
    for name in drag-rk2 drag-rk4 cooling-rk2 adiabat-vdw-cvode-reference full-rk2 stagger-2x2-jacobi gravity-heun burn-rk2; do
      studies+=("$src/verification/$name.toml")
    done
    run suite "${studies[@]}" --json "$out/in-turn.json"
    code=$?
    [ "$code" -eq 0 ] || fail "in turn: exit $code, expected 0"
    cp "$out/stdout" "$out/in-turn.txt"
    run suite --jobs 2 --threads 4 "${studies[@]}" --json "$out/side-by-side.json"
    code=$?
    [ "$code" -eq 0 ] || fail "--jobs 2: exit $code, expected 0"
    cmp -s "$out/in-turn.txt" "$out/stdout" || fail "--jobs 2 printed another summary"
    [ "$(grep -c "^dlpverify suite: \[" "$out/stderr")" -eq "${#studies[@]}" ] || fail "not one stderr line per study"
    python3 - "$out/in-turn.json" "$out/side-by-side.json" <<'PY' || fail "the studies' results differ"
import json, sys
def bare(x):  # a result without what a run's timing and provenance change
    if isinstance(x, dict):
        return {k: bare(v) for k, v in x.items()
                if k not in ("provenance", "seconds", "console", "table") and "wall" not in k}
    return [bare(v) for v in x] if isinstance(x, list) else x
one, other = (json.load(open(f)) for f in sys.argv[1:])
for a, b in zip(one["studies"], other["studies"]):
    if bare(a) != bare(b):
        sys.exit(a["name"] + " differs")
sys.exit(0 if len(one["studies"]) == len(other["studies"]) == 8 else "not 8 studies")
PY
    echo "ok: eight studies, two at once on two threads each: the same summary and results as in turn"
    ;;
  resume)
    . "$src/tests/signal_events.sh"
    cd "$out" || fail "no $out"
    cp "$src/verification/drag-rk2.toml" "$here/drag-euler-expects-2.toml" .
    slow() { cat "$here/full-slow.toml"; echo 'json = "full-slow.json"'; }  # a journal of its own
    slow >full-slow.toml
    studies=(drag-rk2.toml full-slow.toml drag-euler-expects-2.toml)
    journal=suite.json.journal.jsonl
    run suite "${studies[@]}"
    [ $? -eq 1 ] || fail "never stopped: exit $?, expected 1"
    cp stdout whole.txt
    set -m  # its own process group, so SIGINT is not ignored as in a background job
    "$dlpverify" suite "${studies[@]}" --json suite.json >stdout 2>stderr &
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
    [ "$code" -eq 130 ] || fail "SIGINT with $kept of 3 studies journaled: exit $code, expected 130"
    now=$(journaled "$journal")
    [ "$now" -ge "$kept" ] && [ "$now" -le $((kept + 1)) ] && [ "$now" -lt 3 ] ||
      fail "$now studies journaled after SIGINT with $kept journaled"
    has stderr "SIGINT: stopped after $now of 3 studies; $journal keeps the first"
    [ ! -e suite.json ] && [ ! -s stdout ] || fail "a stopped suite wrote its outputs"
    run suite "${studies[@]}" --json suite.json
    [ $? -eq 2 ] || fail "a plain run beside the journal: exit $?, expected 2"
    has stderr "continue that study with --resume"
    echo "# edited" >>full-slow.toml
    run suite "${studies[@]}" --json suite.json --resume
    [ $? -eq 2 ] || fail "--resume with a study file changed: exit $?, expected 2"
    has stderr "--resume = $journal: study file full-slow.toml changed since the journal was written: its content hash differs"
    slow >full-slow.toml
    run suite "${studies[@]}" --json suite.json --resume
    code=$?
    [ "$code" -eq 1 ] || fail "--resume: exit $code, expected 1"
    cmp -s whole.txt stdout || fail "--resume printed another summary than a suite never stopped"
    has stderr "resuming from $journal ($now finished"
    [ "$(grep -c "^dlpverify suite: \[" stderr)" -eq $((3 - now)) ] || fail "--resume ran more than the $((3 - now)) studies left"
    [ -s suite.json ] && [ -s full-slow.json ] && [ ! -e "$journal" ] && [ ! -e full-slow.json.journal.jsonl ] ||
      fail "--resume left no result, or a journal"
    echo "ok: a suite stopped after $now of 3 studies resumed with the rest, to the summary of one never stopped"
    ;;
  *) fail "unknown mode $mode" ;;
esac
