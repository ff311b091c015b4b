#!/usr/bin/env bash
# `cpack -G DEB` builds the Debian package of this build tree, into a temporary folder, and the
# package holds what a user needs, under /usr: the command, every public header of the source
# tree's include/dlpverify, the static libraries, the CMake package (config, version, targets)
# and the gzipped man page; its control fields name the package and the project's version, and
# Depends names SUNDIALS both as the -dev package the headers need and as the shared libraries
# dpkg-shlibdeps found the command links (libsundials-cvode*), beside libc6.
#
# usage: deb.sh BUILD_DIR SOURCE_DIR PROJECT_VERSION
set -euo pipefail
build=$1 source=$2 version=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpack -G DEB -B "$work" --config "$build/CPackConfig.cmake" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; echo "FAIL: cpack -G DEB exited non-zero"; exit 1; }
debs=("$work"/*.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || { cat "$work/cpack.log"; echo "FAIL: expected one .deb, got ${debs[*]}"; exit 1; }
deb=${debs[0]}
echo "package: $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB)"

contents=$(dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./||')
fail=0
has() {  # an extended regular expression one listed path must match whole
  grep -qE "^$1\$" <<<"$contents" || { echo "FAIL: no path matching $1"; fail=1; }
}
has 'usr/bin/dlpverify'
for header in "$source"/include/dlpverify/*.hpp; do
  has "usr/include/dlpverify/$(basename "$header" | sed 's/\./\\./g')"
done
for library in harness sundials dlp simd; do has "usr/lib/(x86_64-linux-gnu/)?libdlpverify_$library\\.a"; done
for file in dlpverifyConfig dlpverifyConfigVersion dlpverifyTargets; do
  has "usr/lib/(x86_64-linux-gnu/)?cmake/dlpverify/$file\\.cmake"
done
has 'usr/share/man/man1/dlpverify\.1\.gz'
# Nothing outside /usr (no build-tree or /usr/local paths).
outside=$(grep -vE '^(usr/.*|usr|)$' <<<"$contents" || true)
[ -z "$outside" ] || { echo "FAIL: paths outside usr/: $outside"; fail=1; }

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = dlpverify ] || { echo "FAIL: Package is '$(field Package)'"; fail=1; }
[ "$(field Version)" = "$version" ] || { echo "FAIL: Version is '$(field Version)', not $version"; fail=1; }
depends=$(field Depends)
echo "Depends: $depends"
for package in 'libsundials-dev' 'libsundials-cvode[0-9]+' 'libc6' 'libeigen3-dev' 'nlohmann-json3-dev' 'libgsl-dev'; do
  grep -qE "(^|, )$package( |,|\$)" <<<"$depends" || { echo "FAIL: Depends lacks $package"; fail=1; }
done

# The installed man page renders from the package.
dpkg-deb -x "$deb" "$work/root"
LC_ALL=C.UTF-8 MANWIDTH=100 man -l "$work/root/usr/share/man/man1/dlpverify.1.gz" | grep -F -- "--version" >/dev/null ||
  { echo "FAIL: the packaged man page does not render with --version"; fail=1; }
[ "$fail" -eq 0 ] || { dpkg-deb -c "$deb"; exit 1; }
echo "PASS"
