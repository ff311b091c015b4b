#!/usr/bin/env bash
# `dlpverify --version` names this build: exits 0 and prints exactly
#   dlpverify <project version> (commit <12 hex digits>, SUNDIALS <v>, Eigen <v>, GSL <v>)
# with each library's version read here from its own header (the ones the build compiled
# against), and the commit one that exists in the source tree's history.
#
# usage: version.sh DLPVERIFY PROJECT_VERSION SOURCE_DIR SUNDIALS_CONFIG_H EIGEN_MACROS_H GSL_VERSION_H
set -euo pipefail
bin=$1 version=$2 source=$3 sundials_h=$4 eigen_h=$5 gsl_h=$6

define() {  # the value of `#define NAME value` in a header, quotes removed
  local value
  value=$(awk -v name="$2" '$1 == "#define" && $2 == name {print $3; exit}' "$1" | tr -d '"')
  [ -n "$value" ] || { echo "FAIL: no #define $2 in $1"; exit 1; }
  echo "$value"
}
sundials=$(define "$sundials_h" SUNDIALS_VERSION)
eigen=$(define "$eigen_h" EIGEN_WORLD_VERSION).$(define "$eigen_h" EIGEN_MAJOR_VERSION).$(define "$eigen_h" EIGEN_MINOR_VERSION)
gsl=$(define "$gsl_h" GSL_VERSION)

line=$("$bin" --version) || { echo "FAIL: --version exited $?"; exit 1; }
echo "got:      $line"
pattern="^dlpverify ${version//./\\.} \\(commit ([0-9a-f]{12}|unknown), SUNDIALS ${sundials//./\\.}, Eigen ${eigen//./\\.}, GSL ${gsl//./\\.}\\)\$"
echo "expected: $pattern"
[[ $line =~ $pattern ]] || { echo "FAIL: --version line differs"; exit 1; }
commit=${BASH_REMATCH[1]}
if [ "$commit" != unknown ] && git -C "$source" rev-parse --git-dir >/dev/null 2>&1; then
  git -C "$source" cat-file -e "$commit^{commit}" || { echo "FAIL: commit $commit is not in $source"; exit 1; }
fi
[ "$(printf '%s\n' "$line" | wc -l)" -eq 1 ] || { echo "FAIL: more than one line"; exit 1; }
echo "PASS"
