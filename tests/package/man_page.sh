#!/usr/bin/env bash
# The man page generated at build time renders with man: `man -l` exits 0 and the page names the
# command, its version (help2man's footer, from --version), the top-level options and options of
# the subcommands (converge's --integrator and --dt), check's and analyze's exit codes with 5 (the
# help's one string, in the page's source as help2man wrote it: the rendering may hyphenate), and
# the installed .gz is the same page.
#
# usage: man_page.sh BUILD_DIR PROJECT_VERSION
set -euo pipefail
build=$1 version=$2
page=$build/dlpverify.1
[ -f "$page" ] || { echo "FAIL: $page was not generated"; exit 1; }
[ -f "$page.gz" ] || { echo "FAIL: $page.gz was not generated"; exit 1; }
export LC_ALL=C.UTF-8 MANWIDTH=100
if command -v man >/dev/null; then
  text=$(man -l "$page") || { echo "FAIL: man -l $page exited $?"; exit 1; }
else
  text=$(groff -man -Tutf8 "$page") || { echo "FAIL: groff -man exited $?"; exit 1; }
fi
fail=0
expect() {  # a fixed string the rendered page must hold
  grep -qF -- "$1" <<<"$text" || { echo "FAIL: the page lacks '$1'"; fail=1; }
}
expect "DLPVERIFY(1)"
expect "dlpverify $version"
expect "--version"
expect "--help"
expect "converge"
expect "--integrator"   # a subcommand's option: the page lists every subcommand's options
expect "--dt"
codes="exit 0 pass, 1 fail, 5 inconclusive"
[ "$(grep -cF -- "$codes" "$page")" -eq 2 ] || { echo "FAIL: the page's check and analyze lack '$codes'"; fail=1; }
[ "$fail" -eq 0 ] || { printf '%s\n' "$text" | sed -n 1,40p; exit 1; }
# The compressed copy (the one installed) is the same page.
cmp <(gzip -dc "$page.gz") "$page" || { echo "FAIL: dlpverify.1.gz is not dlpverify.1"; exit 1; }
echo "PASS: $(printf '%s\n' "$text" | wc -l) lines"
