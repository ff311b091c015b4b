#!/usr/bin/env bash
# The installed package works for a project of its own: install this build into a fresh prefix,
# configure examples/own-integrator against it (find_package(dlpverify)), build it and run its
# tests — including the broken stepper, which must fail its check with an order miss — and the
# checks its CMakeLists.txt registers with dlpverify_add_check and dlpverify_add_suite (the suite's
# JUnit XML written). A project whose one check is inconclusive (RK4 checked as second order: exit
# 5) sees it reported skipped by CTest, not failed. Both projects enable C++ only (LANGUAGES CXX):
# the libraries with every dependency, and the command component alone with none. The fitted
# orders docs/verification.md quotes for the project's studies are the ones they print.
#
# usage: own_integrator.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$source/examples/own-integrator" -B "$work/example" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" "${launcher[@]}" >/dev/null
cmake --build "$work/example" -j 2 >/dev/null
ctest --test-dir "$work/example" --output-on-failure
# study: the fitted orders docs/verification.md ("The study and the verdict") quotes, in print order
quoted=(midpoint-on-drag:2.023,2.028 midpoint-on-oscillator:2.001,2.003 rk4-on-oscillator:4.024,4.006
        broken-stepper-misses-order:1.030,1.033 midpoint-on-pendulums-manufactured:1.987,1.989
        rk4-on-pendulums-manufactured:3.997,3.997 midpoint-on-pendulums-rk4-reference:1.992,1.996
        broken-stepper-misses-order-on-pendulums:1.024,1.040 late-stage-passes-on-oscillator:2.001,2.003
        late-stage-misses-order-on-pendulums:0.982,0.964)
for entry in "${quoted[@]}"; do
  study=${entry%%:*}
  printed=$("$work/example/verify_own_integrator" "$study" | sed -n 's/.*fitted order \([0-9.]*\) .*/\1/p' | paste -sd,)
  [ "$printed" = "${entry#*:}" ] || { echo "FAIL: $study prints fitted orders $printed, docs/verification.md ${entry#*:}"; exit 1; }
done
ctest --test-dir "$work/example" --output-on-failure -R kutta3 | tee "$work/checks.log"
grep -q "kutta3-on-drag .*Passed" "$work/checks.log"
grep -q "kutta3-suite .*Passed" "$work/checks.log"
grep -q '<testsuite name="kutta3-on-adiabat" tests="2" failures="0" errors="0" skipped="0"' "$work/example/kutta3-suite.xml"

mkdir "$work/skip"
cat >"$work/skip/rk4-as-second-order.toml" <<'TOML'
case = "drag"
outer = 4
integrator = "rk4"
expect-order = 2
TOML
cat >"$work/skip/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(skip LANGUAGES CXX)
find_package(dlpverify CONFIG REQUIRED COMPONENTS command)
enable_testing()
dlpverify_add_check(rk4-as-second-order CONFIG rk4-as-second-order.toml)
CMAKE
# A C++-only project that only registers study files: the command component finds none of the
# libraries' dependencies (each one's find_package is disabled here) and no C compiler.
cmake -S "$work/skip" -B "$work/skip/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_DISABLE_FIND_PACKAGE_OpenMP=ON -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON \
      -DCMAKE_DISABLE_FIND_PACKAGE_GSL=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON \
      -DCMAKE_DISABLE_FIND_PACKAGE_SUNDIALS=ON -DCMAKE_DISABLE_FIND_PACKAGE_QD=ON >/dev/null
ctest --test-dir "$work/skip/build" | tee "$work/skip.log"
grep -q "rk4-as-second-order .*Skipped" "$work/skip.log"
echo "ok: the package's project builds and passes; its dlpverify checks run under CTest, inconclusive as skipped"
