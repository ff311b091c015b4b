#!/usr/bin/env bash
# Installs what the study needs (scripts/install-deps.sh --study), builds the dlpverify command
# alone, and runs the main study: Kuhl & Grote's drag case (docs/model.md §4.3) integrated with the
# paper's RK2 on the paper's full sphere (R_out = 100, 4,187,856 particles), five levels of Δt.
# Writes results/drag-rk2.{txt,csv,json} and the error-against-dt figure results/drag-rk2.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --study
mkdir -p results
build/dlpverify converge --case drag --integrator rk2 \
  --table results/drag-rk2.txt --csv results/drag-rk2.csv --json results/drag-rk2.json \
  --plot results/drag-rk2.png
