#!/usr/bin/env bash
# `dlpverify suite` and --junit (docs/cli.md, "dlpverify suite"), one mode a test:
#   verification  every study file of verification/ in one command: exit 0, one summary row per
#                 variable, "N studies: … 0 fail, 0 inconclusive; 0 studies ended without a
#                 verdict"; with Euler checked as second order added (tests/cli/suite/), exit 1;
#   junit         a passing, a failing and an inconclusive study: exit 1 (a failure outranks
#                 inconclusive); the JUnit XML validates against Jenkins' JUnit schema
#                 (junit-4.xsd, fetched by scripts/install-deps.sh) and counts 6 cases, 2 failures
#                 and 2 skipped; the failure's message is the verdict's line, its text the level
#                 table; `check --junit` writes the same suite for one study, and for a sweep of
#                 --tolerances (its variables' proportionality verdicts);
#   errors        a study file of an unknown case among them: exit 2, the others still run and are
#                 summarised, and the JUnit XML holds it as an error naming --case;
#   analyze       analyze --junit (examples/analyze, forward Euler's runs checked at order 2): exit 1,
#                 the JUnit XML validates and names the failure of the runs' position;
#   refused       the suite's own bad input — a study file that does not exist, --junit on a
#                 study file — and --html with --tolerances are one stderr line, exit 2, no output.
# usage: suite.sh DLPVERIFY SOURCE_DIR MODE
set -u
dlpverify=$1 src=$2 mode=$3
schema=$src/.deps/junit/jenkins-junit.xsd
here=$src/tests/cli/suite
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; echo "--- stdout:"; head -40 "$out/stdout" 2>/dev/null; echo "--- stderr:"; head -20 "$out/stderr" 2>/dev/null; exit 1; }
run() { "$dlpverify" "$@" >"$out/stdout" 2>"$out/stderr"; }
valid() {
  [ -f "$schema" ] || fail "no JUnit schema at $schema: run scripts/install-deps.sh"
  xmllint --noout --schema "$schema" "$1" 2>"$out/xmllint" || { cat "$out/xmllint"; fail "$1 does not validate"; }
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
      --junit "$out/suite.xml"
    code=$?
    [ "$code" -eq 1 ] || fail "exit $code, expected 1"
    valid "$out/suite.xml"
    has "$out/suite.xml" '<testsuites name="dlpverify" tests="6" failures="2" errors="0"'
    has "$out/suite.xml" '<testsuite name="drag-rk4-expects-2" tests="2" failures="0" errors="0" skipped="2"'
    has "$out/suite.xml" '<testcase name="position" classname="drag-euler-expects-2"'
    has "$out/suite.xml" '<failure message="position: FAIL, fitted order 1.000 outside 2.000 +/- 0.100 (over 5 levels)">'
    has "$out/suite.xml" '    4  3.125e-05     320 | 3.007e-03       1.00 | 7.802e-01       1.00 | ok'
    has "$out/suite.xml" '<skipped>velocity: INCONCLUSIVE, fitted order 3.997 above 2.000 +/- 0.100'
    run check --config "$here/drag-euler-expects-2.toml" --junit "$out/check.xml"
    code=$?
    [ "$code" -eq 1 ] || fail "check --junit: exit $code, expected 1"
    valid "$out/check.xml"
    has "$out/check.xml" '<testsuite name="drag-euler-expects-2" tests="2" failures="2" errors="0" skipped="0"'
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
    echo "ok: a bad study file is an error; the others run"
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
    refused "--html" check --case cooling --integrator cvode --tolerances 1e-4:1e-6 --html "$out/j.xml"
    echo "ok: the suite's own bad input is one line, exit 2, nothing written"
    ;;
  *) fail "unknown mode $mode" ;;
esac
