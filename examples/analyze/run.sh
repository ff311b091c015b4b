#!/bin/sh
# The worked example of docs/analyze.md: particles.py run at five steps (as a batch system would
# run them, one job each), then dlpverify analyze on the files, with check's verdict.
#   examples/analyze/run.sh DLPVERIFY OUT_DIR [--euler]
# Exit: analyze's (0 the order 2 is met, 1 it is not, 2 runs that do not belong together).
set -e
dlpverify=$1 out=$2
shift 2
here=$(dirname "$0")
mkdir -p "$out"
for steps in 25 50 100 200 400; do
  /usr/bin/python3 "$here/particles.py" --steps $steps --out "$out/run-$steps.h5" "$@"
done
set +e
"$dlpverify" analyze "$out"/run-25.h5 "$out"/run-50.h5 "$out"/run-100.h5 "$out"/run-200.h5 "$out"/run-400.h5 \
    --variables "$here/variables.toml" --order 2 --expect-order 2 --label particles.py \
    --json "$out/analyze.json" --plot "$out/analyze.png" --junit "$out/analyze.xml"
