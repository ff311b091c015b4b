#!/usr/bin/env bash
# One run's outputs are committed together (io/atomic_file.hpp): under a file-size limit (ulimit
# -f, which needs no root and fails a write as a full disk does) that every output but the largest
# fits, the run exits 4 with one line naming the largest, prints no table on standard output, and
# leaves every old file as it was, with no temporary beside them; a study's kept journal then lets
# --resume finish the run.
#
# usage: output_set.sh DLPVERIFY MODE   (MODE: converge precision stagger compress plot audit)
set -euo pipefail
bin=$1
mode=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The command of MODE writing its outputs into folder $1, and the output that must be the largest.
outputs_of() {
  local d=$1
  case $mode in
    converge)
      victim=pp.csv
      cmd=(converge --case burn --outer 10 --levels 2 --json "$d/keep.json" --csv "$d/keep.csv" --table "$d/keep.txt"
           --history "$d/history.csv" --history-outputs 5 --plot "$d/figure.svg" --per-particle "$d/pp.csv") ;;
    precision)
      victim=figure.png
      cmd=(precision --case drag --outer 3 --per-decade 1 --json "$d/keep.json" --csv "$d/keep.csv" --table "$d/keep.txt"
           --plot "$d/figure.png") ;;
    stagger)
      victim=keep.json
      cmd=(stagger --case stagger-2x2 --dt 0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9 --json "$d/keep.json" --csv "$d/keep.csv" --table "$d/keep.txt") ;;
    compress)
      victim=figure.png
      cmd=(compress --runs 1 --json "$d/keep.json" --plot "$d/figure.png") ;;
    plot)
      victim=figure.png
      cmd=(plot "$work/study.json" -o "$d/figure.png") ;;
    audit)
      victim=keep.json
      cmd=(audit --json "$d/keep.json") ;;
    *) echo "unknown mode $mode" >&2; exit 2 ;;
  esac
}

if [ "$mode" = plot ]; then  # the figure's input
  "$bin" converge --case drag --outer 3 --levels 2 --json "$work/study.json" > /dev/null
fi

# A run without a limit: every output's size.
mkdir "$work/free"
outputs_of "$work/free"
"$bin" "${cmd[@]}" > /dev/null
victim_size=$(stat -c %s "$work/free/$victim")
others=0
for f in "$work/free"/*; do
  [ "$(basename "$f")" = "$victim" ] && continue
  size=$(stat -c %s "$f")
  [ "$size" -gt "$others" ] && others=$size
done
# ulimit -f counts 1024-byte blocks: the least limit above the largest other output.
limit=$(( others / 1024 + 1 ))
if [ $(( limit * 1024 )) -ge "$victim_size" ]; then
  echo "FAIL: $victim ($victim_size bytes) is not clearly the largest output (next: $others bytes)" >&2
  exit 1
fi

# The same run over old files, under the limit.
mkdir "$work/run"
names=$(ls "$work/free")
for f in $names; do echo "old $f" > "$work/run/$f"; done
snapshot() { (cd "$work/run" && for f in $names; do echo "== $f"; cat "$f"; done); }
before=$(snapshot)
outputs_of "$work/run"
set +e
(ulimit -f "$limit"; exec "$bin" "${cmd[@]}") > "$work/stdout" 2> "$work/stderr"
code=$?
set -e
fail() { echo "FAIL ($mode, limit $limit KiB): $*" >&2; cat "$work/stderr" >&2; exit 1; }
[ "$code" -eq 4 ] || fail "exit $code, expected 4"
[ "$(wc -l < "$work/stderr")" -eq 1 ] || fail "expected one line on stderr"
grep -q "$victim" "$work/stderr" || fail "the error line does not name $victim"
# compress prints its table row by row as the runs finish; the others print after their outputs.
[ "$mode" = compress ] || [ ! -s "$work/stdout" ] || fail "standard output is not empty"
[ "$before" = "$(snapshot)" ] || fail "an old output changed"
# Nothing else beside them but a study's journal, kept so that --resume can finish the run.
left=$(cd "$work/run" && ls -A | grep -v '^keep\.json\.journal\.jsonl$' | sort)
[ "$left" = "$(echo "$names" | sort)" ] || fail "files left beside the outputs: $(ls -A "$work/run")"
if [ -e "$work/run/keep.json.journal.jsonl" ]; then
  "$bin" "${cmd[@]}" --resume > /dev/null 2>&1 || fail "--resume after the failed commit exited $?"
  [ ! -e "$work/run/keep.json.journal.jsonl" ] || fail "--resume left its journal"
  grep -q '^old ' "$work/run/$victim" && fail "--resume did not write $victim"
fi
echo "ok: $mode, limit $limit KiB; $victim ($victim_size bytes) failed, $(echo "$names" | wc -l) old outputs untouched"
