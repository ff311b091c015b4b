#!/usr/bin/env bash
# Runs one libFuzzer target on RUNS inputs from its seed corpus, with libFuzzer's random seed
# fixed to SEED; exits non-zero on a crash, a hang (an input taking over 10 s), a leak, running out
# of memory or any sanitizer report. The same RUNS and SEED try the same inputs in the same order,
# whatever the machine's speed (only the time taken changes) and wherever the build lives: one
# process; the corpus never re-read (-reload=0); no mutation from the operands of the code's
# comparisons (-use_cmp=0: some are addresses, which move with the paths in argv and the heap's
# layout; at these run counts coverage is the same without them, measured on all four targets);
# address randomisation off where allowed (setarch -R: some coverage depends on addresses too).
# Checked: two runs, and runs with other findings paths, add the same inputs. New inputs go to a
# scratch folder, so the seed corpus in the repository is never written; a finding is kept in
# FINDINGS with the line that replays it.
#
# usage: run_fuzz.sh TARGET CORPUS RUNS SEED FINDINGS
set -uo pipefail
target=$1 corpus=$2 runs=$3 seed=$4 findings=$5
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$findings"

# Without address randomisation where the system allows it (a container may refuse the personality).
fixed=(setarch "$(uname -m)" -R)
"${fixed[@]}" true 2>/dev/null || { fixed=(); echo "note: address randomisation stays on: runs may differ"; }

"${fixed[@]}" "$target" -runs="$runs" -seed="$seed" -reload=0 -use_cmp=0 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
          -artifact_prefix="$findings/" "$scratch" "$corpus" >"$scratch/log" 2>&1
code=$?
grep -aE "^(#[0-9]+[[:space:]]+(INITED|DONE)|stat::number_of_executed_units|stat::new_units_added)" "$scratch/log"
if [ "$code" -ne 0 ]; then
  echo "FAIL: $(basename "$target") exited $code; its report:"
  sed -n '/^==[0-9]*==\|^SUMMARY\|runtime error\|ERROR: libFuzzer/,$p' "$scratch/log" | sed -n 1,80p
  for f in "$findings"/*; do [ -e "$f" ] && echo "replay: $target $f"; done
  exit 1
fi
echo "ok: $(basename "$target") tried ${runs} inputs (seed ${seed}) without a finding"
