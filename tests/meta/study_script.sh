#!/usr/bin/env bash
# The README's first command installs and builds only what the study needs: scripts/study.sh asks
# build.sh for --study, which installs install-deps.sh's study packages (no test package, nothing
# from the npm registry) and builds the dlpverify target alone, with the tests and benchmarks off;
# scripts/test.sh's plain build.sh still installs everything (npm with nodejs) and builds every target.
#
# usage: study_script.sh SOURCE_DIR
set -euo pipefail
source=$1
fail() { echo "FAIL: $*"; exit 1; }
study=$(bash "$source/scripts/install-deps.sh" --study --list)
all=$(bash "$source/scripts/install-deps.sh" --list)
for p in libboost-test-dev libbenchmark-dev doxygen chromium nodejs npm clang ninja-build jq python3-h5py; do
  grep -qx "$p" <<<"$study" && fail "the study installs the test package $p"
  grep -qx "$p" <<<"$all" || fail "the tests' install lacks $p"
done
for p in cmake libsundials-dev libhdf5-dev gnuplot-nox libopenmpi-dev; do
  grep -qx "$p" <<<"$study" || fail "the study's install lacks $p"
done
set +e
bash "$source/scripts/install-deps.sh" --bogus >/dev/null 2>&1
rc=$?
set -e
[ "$rc" = 2 ] || fail "an unknown option of install-deps.sh exits $rc, not 2"

grep -qx 'bash scripts/build.sh --study' "$source/scripts/study.sh" || fail "study.sh does not build with --study"
grep -qx 'bash scripts/build.sh' "$source/scripts/test.sh" || fail "test.sh does not build everything"
study_build=$(DLPVERIFY_DRY_RUN=1 bash "$source/scripts/build.sh" --study)
all_build=$(DLPVERIFY_DRY_RUN=1 bash "$source/scripts/build.sh")
grep -qx 'bash scripts/install-deps.sh --study' <<<"$study_build" || fail "build.sh --study installs more than the study's packages"
grep -q -- '-DDLPVERIFY_BUILD_TESTS=OFF -DDLPVERIFY_BUILD_BENCH=OFF' <<<"$study_build" || fail "build.sh --study configures the tests"
grep -q -- '--target dlpverify$' <<<"$study_build" || fail "build.sh --study builds more than dlpverify"
grep -qx 'bash scripts/install-deps.sh' <<<"$all_build" || fail "build.sh does not install everything"
grep -q -- '-DDLPVERIFY_BUILD_TESTS=ON -DDLPVERIFY_BUILD_BENCH=ON' <<<"$all_build" || fail "build.sh leaves the tests off"
grep -q -- '--target' <<<"$all_build" && fail "build.sh builds one target only"
echo "ok: study.sh installs $(wc -l <<<"$study") packages and builds dlpverify; test.sh installs $(wc -l <<<"$all") and builds everything"
