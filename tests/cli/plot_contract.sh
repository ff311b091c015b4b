#!/usr/bin/env bash
# The figures' contract at the command line (issue 5). usage: plot_contract.sh DLPVERIFY CHECK
#   overlay   three studies' JSON redrawn as one figure by `dlpverify plot`, from the JSON alone
#   hostile   titles that try to run shell commands through gnuplot draw a figure and run nothing
#   refusals  a bad extension or inputs of mixed kinds: exit 2, one line, no figure
set -u
dlpverify=$1 check=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
is_png() {  # PNG signature and a non-trivial size
  [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$1 is not a PNG"
  [ "$(stat -c %s "$1")" -gt 20000 ] || fail "$1 is too small to be a figure"
}

case $check in
overlay)
  for integrator in euler rk2 rk4; do
    "$dlpverify" converge --case drag --integrator "$integrator" --outer 4 --json "$dir/$integrator.json" >/dev/null ||
      fail "converge $integrator"
  done
  "$dlpverify" plot "$dir/euler.json" "$dir/rk2.json" "$dir/rk4.json" -o "$dir/overlay.png" || fail "plot exited $?"
  is_png "$dir/overlay.png"
  "$dlpverify" plot "$dir/rk2.json" -o "$dir/rk2.svg" || fail "svg"
  grep -q '</svg>' "$dir/rk2.svg" || fail "the SVG is not whole"
  ;;
hostile)
  rm -f /tmp/pwned /tmp/pwned2 /tmp/pwned3
  i=0
  for title in 'x"; system("touch /tmp/pwned"); print "' '`touch /tmp/pwned2`' "x'; system('touch /tmp/pwned3'); print '"; do
    i=$((i + 1))
    "$dlpverify" converge --case drag --outer 4 --levels 3 --plot "$dir/h$i.png" --title "$title" >/dev/null ||
      fail "converge with a hostile title exited $?"
    is_png "$dir/h$i.png"
  done
  for f in /tmp/pwned /tmp/pwned2 /tmp/pwned3; do [ ! -e "$f" ] || fail "$f exists: a title ran a command"; done
  ;;
refusals)
  "$dlpverify" converge --case drag --outer 4 --levels 2 --json "$dir/s.json" --per-particle "$dir/p.csv" >/dev/null
  "$dlpverify" plot "$dir/s.json" -o "$dir/figure.jpg" 2>"$dir/err"
  [ $? -eq 2 ] || fail "a .jpg figure did not exit 2"
  [ "$(wc -l <"$dir/err")" -eq 1 ] && grep -q -- "-o" "$dir/err" || fail "the refusal does not name -o in one line"
  "$dlpverify" plot "$dir/s.json" "$dir/p.csv" -o "$dir/mixed.png" 2>"$dir/err"
  [ $? -eq 2 ] || fail "mixed kinds did not exit 2"
  ls "$dir" | grep -qE 'figure|mixed' && fail "a refused figure was written"
  "$dlpverify" converge --case drag --outer 4 --plot "$dir/x.gif" --json "$dir/t.json" >/dev/null 2>&1
  [ $? -eq 2 ] && [ ! -e "$dir/t.json" ] || fail "converge --plot x.gif must exit 2 before writing anything"
  ;;
*) fail "unknown check $check" ;;
esac
echo "ok: $check"
