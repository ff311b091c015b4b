#!/usr/bin/env bash
# The progress line (io/progress.hpp) of long work, per MODE:
#   study      converge on the `full` case: the CVODE reference's blocks, then the levels
#   precision  the runs of a work-precision sweep
#   compress   the runs of a compression ensemble
# Under a pseudo-terminal (util-linux `script`) stderr shows "WHAT k/n, … elapsed, about … left",
# rewritten with carriage returns and blanked at the end; with stderr a pipe, and with --quiet on
# the terminal, stderr has none of it. In a CI's log (stderr a file, CI=true) each work's first
# finished item is one whole line, "WHAT k/n finished, … elapsed", no carriage return, and with
# --quiet there too nothing; standard output and the JSON carry none of it either, and are the same
# (timings aside) in all five runs.
#
# usage: progress.sh DLPVERIFY MODE
set -euo pipefail
bin=$1
mode=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL ($mode): $*"; for f in "$work"/*.out "$work"/*.err "$work"/*.tty; do [ -f "$f" ] && { echo "--- $f"; cat -A "$f" | sed -n 1,40p; }; done; exit 1; }
command -v script >/dev/null || fail "util-linux script is missing"
# One thread: only OpenMP's thread 0 writes the line, and on two threads a short ensemble's runs may
# all go to the other thread; the line under test is the same.
export OMP_NUM_THREADS=1

# The expected progress texts, counted from the options alone.
case $mode in
  study)
    # --outer 4: the lattice points of the sphere of radius 4 spacings, counted below from the JSON's
    # particle count; the reference solves them in blocks of 1024.
    args=(converge --case full --integrator rk2 --outer 4 --levels 3)
    expect=("level 1/3" "level 2/3") ;;
  precision)
    # rtol 1e-4 … 1e-8 at one per decade: 5 tolerances × (Adams, BDF) + 3 fixed-step levels = 13 runs.
    args=(precision --case drag --outer 3 --per-decade 1 --rtol-max 1e-4 --rtol-min 1e-8 --levels 3)
    expect=("run 1/13" "run 2/13") ;;
  compress)
    # 2 volume ratios × 3 runs = 6 runs.
    args=(compress --runs 3 --ratios 1.5,2)
    expect=("compression run 1/6") ;;
  *) echo "unknown mode $mode" >&2; exit 2 ;;
esac

# $1: name; the rest: extra options. Under `script`, stderr is the terminal (its copy: NAME.tty)
# and stdout a file. Every run writes the same JSON path (the options it records name it), then
# the file moves to NAME.json.
json=$work/result.json
on_terminal() {
  local name=$1; shift
  local line
  line=$(printf '%q ' "$bin" "${args[@]}" --json "$json" "$@")
  script -qec "$line >$(printf '%q' "$work/$name.out")" /dev/null >"$work/$name.tty" </dev/null \
    || fail "$name: exit $?"
  mv "$json" "$work/$name.json"
}
on_terminal tty
on_terminal quiet --quiet
"$bin" "${args[@]}" --json "$json" >"$work/pipe.out" 2>"$work/pipe.err" </dev/null || fail "pipe: exit $?"
mv "$json" "$work/pipe.json"
CI=true "$bin" "${args[@]}" --json "$json" >"$work/ci.out" 2>"$work/ci.err" </dev/null || fail "ci: exit $?"
mv "$json" "$work/ci.json"
CI=true "$bin" "${args[@]}" --json "$json" --quiet >"$work/ciquiet.out" 2>"$work/ciquiet.err" </dev/null || fail "ci quiet: exit $?"
mv "$json" "$work/ciquiet.json"

if [ "$mode" = study ]; then
  particles=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["particles"])' "$work/tty.json")
  blocks=$(( (particles + 1023) / 1024 ))
  expect+=("reference block 1/$blocks")
fi

for text in "${expect[@]}"; do
  grep -qF "dlpverify: $text, " "$work/tty.tty" || fail "the terminal shows no '$text'"
done
first=${expect[0]%/*}/  # "level 1/" of "level 1/3": the first item of the first work
[ "$mode" = study ] && first="reference block 1/"
grep -qE "^dlpverify: ${first}[0-9]+ finished, [0-9].* elapsed" "$work/ci.err" || fail "the CI log shows no '${first}… finished' line"

grep -q "elapsed, about [0-9].* left" "$work/tty.tty" || fail "the terminal shows no estimate of the time left"

/usr/bin/python3 - "$work" <<'PY' || fail "the progress line"
import json, re, sys
work = sys.argv[1]
tty = open(f"{work}/tty.tty", encoding="utf-8", errors="replace", newline="").read()
# Every rewrite starts with a carriage return and none ends its line: the last one shown is blanked
# by a carriage return, as many spaces as it had characters, and a carriage return.
shown = re.findall(r"\r(dlpverify: [^\r\n]*?) *(?=\r)", tty)
assert shown, "no line rewritten in place"
assert not re.search(r"dlpverify: [^\r\n]* left *\r?\n", tty), "a progress line ended with a newline"
last = tty.rfind("\rdlpverify: ")
width = len(re.match(r"\r(dlpverify: [^\r\n]*)", tty[last:]).group(1).rstrip())
assert re.search(r"\r {%d,}\r" % width, tty[last:]), "the last progress line was not blanked"

progress = re.compile(r"elapsed|left|\r")
for name in ("quiet.tty", "pipe.err", "ciquiet.err", "tty.out", "quiet.out", "pipe.out", "ci.out", "ciquiet.out",
             "tty.json", "quiet.json", "pipe.json", "ci.json", "ciquiet.json"):
    text = open(f"{work}/{name}", encoding="utf-8", errors="replace", newline="").read()
    assert not progress.search(text), f"{name} holds progress text: {progress.search(text).group(0)!r}"

# Standard output and the JSON: the same in the three runs once timings and the command line go.
def timeless(value):
    if isinstance(value, dict):
        return {k: timeless(v) for k, v in value.items()
                if k != "provenance" and "wall" not in k and "seconds" not in k and not k.endswith("_s")}
    if isinstance(value, list):
        return [timeless(v) for v in value]
    return value
def table(name):
    # precision's rows: "METHOD  rtol|dt VALUE  STEPS  RHS-EVALS  WALL-S | …": the wall seconds masked.
    return [re.sub(r"(\s\d+\s+\d+\s+)[-+.e0-9]+( \|)", r"\1T\2", l) for l in open(f"{work}/{name}").read().splitlines()]
# The CI log: whole lines only, each a finished item.
log = open(f"{work}/ci.err", encoding="utf-8", errors="replace", newline="").read()
assert "\r" not in log, "the CI log holds a carriage return"
for line in log.splitlines():
    assert re.fullmatch(r"dlpverify: .* \d+/\d+ finished, .* elapsed(, about .* left)?", line), f"CI log line {line!r}"

jsons = [timeless(json.load(open(f"{work}/{n}.json"))) for n in ("tty", "quiet", "pipe", "ci", "ciquiet")]
assert all(j == jsons[0] for j in jsons), "the JSON differs with the progress line on"
tables = [table(f"{n}.out") for n in ("tty", "quiet", "pipe", "ci", "ciquiet")]
assert all(t == tables[0] for t in tables), "standard output differs with the progress line on"
PY
echo "ok ($mode)"
