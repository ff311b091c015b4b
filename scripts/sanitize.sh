#!/usr/bin/env bash
# The sanitizer builds of CMakePresets.json, each in its own tree with Debian's clang, and their
# tests (scripts/test.sh runs this after the normal build's tests):
#   asan     ASan + UBSan (-fno-sanitize-recover=all): every test, and the fuzz tests (label
#            fuzz: each libFuzzer target on a fixed number of inputs from its seed corpus, with
#            a fixed libFuzzer -seed, so every run tries the same inputs)
#   tsan     TSan: the tests labelled `threaded`, on 4 OpenMP threads (LLVM's runtime, whose
#            Archer tool tells TSan about OpenMP's barriers; libgomp's would be false races)
#   planted  the asan tree with two bugs planted (tests/planted): the fuzzer and ASan must report
#            them; switching the tree recompiles two files
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
if command -v ccache >/dev/null; then
  export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
fi
jobs=$(nproc)
for preset in asan tsan planted; do
  echo "== sanitize: $preset"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  ctest --preset "$preset" -j "$jobs"
done
