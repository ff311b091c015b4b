#!/usr/bin/env bash
# Installs the dependencies (Debian packages) and builds dlpverify in build/ (Release).
# Under CI (CI=true) a warning in the project's own code fails the build (DLPVERIFY_WERROR);
# a user's build only prints it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDLPVERIFY_WERROR="$werror"
cmake --build build -j "$(nproc)"
