#!/usr/bin/env bash
# Runs one libFuzzer target for a bounded time from its seed corpus; exits non-zero on a crash, a
# hang (an input taking over 10 s), a leak, running out of memory or any sanitizer report.
# New inputs go to a scratch folder, so the seed corpus in the repository is never written; a
# finding is kept in FINDINGS with the line that replays it.
#
# usage: run_fuzz.sh TARGET CORPUS SECONDS FINDINGS
set -u
target=$1 corpus=$2 seconds=$3 findings=$4
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$findings"

"$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
          -artifact_prefix="$findings/" "$scratch" "$corpus" >"$scratch/log" 2>&1
code=$?
grep -E "^(#[0-9]+ +(INITED|DONE)|stat::number_of_executed_units|stat::new_units_added)" "$scratch/log"
if [ "$code" -ne 0 ]; then
  echo "FAIL: $(basename "$target") exited $code; its report:"
  sed -n '/^==[0-9]*==\|^SUMMARY\|runtime error\|ERROR: libFuzzer/,$p' "$scratch/log" | head -80
  for f in "$findings"/*; do [ -e "$f" ] && echo "replay: $target $f"; done
  exit 1
fi
echo "ok: $(basename "$target") ran ${seconds} s without a finding"
