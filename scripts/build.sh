#!/usr/bin/env bash
# Installs the dependencies (Debian packages) and builds dlpverify in build/ (Release).
#   build.sh          every package, every target: the command, the tests, the examples, the benchmarks;
#   build.sh --study  the study's packages only, and only the dlpverify target (scripts/study.sh).
# The test and benchmark options are passed either way, so that one tree serves both in any order.
# Under CI (CI=true) a warning in the project's own code fails the build (DLPVERIFY_WERROR);
# a user's build only prints it. DLPVERIFY_DRY_RUN=1 prints the commands instead of running them.
set -euo pipefail
cd "$(dirname "$0")/.."
run=()
[ "${DLPVERIFY_DRY_RUN:-}" = 1 ] && run=(echo)
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
case "${1:-}" in
  --study) deps=(--study) tests=OFF target=(--target dlpverify) ;;
  "") deps=() tests=ON target=() ;;
  *) echo "build.sh: unknown option '$1' (--study)" >&2; exit 2 ;;
esac
"${run[@]}" bash scripts/install-deps.sh "${deps[@]}"
"${run[@]}" cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDLPVERIFY_WERROR="$werror" \
  -DDLPVERIFY_BUILD_TESTS="$tests" -DDLPVERIFY_BUILD_BENCH="$tests"
"${run[@]}" cmake --build build -j "$(nproc)" "${target[@]}"
