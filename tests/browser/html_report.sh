#!/usr/bin/env bash
# The HTML report (check --html, suite --html) in a real browser: the command writes it, then
# html_report.cjs loads it in headless Chromium and checks it (see there). Modes:
#   check  the main study as a check, from its study file (verification/drag-rk2.toml: drag, RK2,
#          R_out 10): one figure, pass;
#   suite  drag-rk2, a failing, an inconclusive and a broken study file: three figures (the broken
#          study has none), ERROR (exit 2) — the suite's exit code — first.
# The screenshot is kept in ARTEFACTS as html-report-MODE.png.
# usage: html_report.sh DLPVERIFY SOURCE_DIR ARTEFACTS MODE
set -u
dlpverify=$1 src=$2 artefacts=$3 mode=$4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mkdir -p "$artefacts"
[ -d "$src/.deps/node/node_modules/puppeteer-core" ] || { echo "FAIL: no puppeteer-core in $src/.deps/node: run scripts/install-deps.sh"; exit 1; }
case $mode in
  check)
    "$dlpverify" check --config "$src/verification/drag-rk2.toml" --html "$out/report.html" >/dev/null
    code=$? figures=1 verdict="pass"
    [ "$code" -eq 0 ] || { echo "FAIL: check exit $code"; exit 1; }
    ;;
  suite)
    "$dlpverify" suite "$src/verification/drag-rk2.toml" "$src"/tests/cli/suite/{drag-euler-expects-2,drag-rk4-expects-2,unknown-case}.toml --html "$out/report.html" >/dev/null 2>&1
    code=$? figures=3 verdict="ERROR (exit 2)"
    [ "$code" -eq 2 ] || { echo "FAIL: suite exit $code"; exit 1; }
    ;;
  *) echo "FAIL: unknown mode $mode"; exit 1 ;;
esac
node "$src/tests/browser/html_report.cjs" "$src/.deps" "$out/report.html" "$artefacts/html-report-$mode.png" "$figures" "$verdict"
