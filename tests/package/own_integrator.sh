#!/usr/bin/env bash
# The installed package works for a project of its own: install this build into a fresh prefix,
# configure examples/own-integrator against it (find_package(dlpverify)), build it and run its
# tests — including the broken stepper, which must fail its check with an order miss.
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
