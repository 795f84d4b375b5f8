#!/usr/bin/env bash
# bilayer --version: "bilayer VERSION (git commit C)" with VERSION the
# project's (CMakeLists.txt) and C the source tree's commit as git gives it
# (with -dirty for uncommitted changes; "unknown" outside a checkout), then
# "deal.II X.Y.Z" and "BLAS ..."; nothing on stderr, exit 0.
# Usage: version.sh BILAYER VERSION SOURCE_DIRECTORY
set -u
bilayer=$1 version=$2 source=$3
out=$("$bilayer" --version 2> /tmp/bilayer-version-err.$$)
rc=$?
err=$(cat /tmp/bilayer-version-err.$$)
rm -f /tmp/bilayer-version-err.$$
commit=unknown
if git -C "$source" rev-parse --short=7 HEAD > /dev/null 2>&1; then
  commit=$(git -C "$source" rev-parse --short=7 HEAD)
fi
line1=$(sed -n 1p <<< "$out")
ok=yes
[[ $rc -eq 0 && -z $err ]] || ok=no
case $line1 in
  "bilayer $version (git commit $commit)" | "bilayer $version (git commit $commit-dirty)") ;;
  *) ok=no ;;
esac
[[ $(sed -n 2p <<< "$out") =~ ^deal\.II\ 9\.[0-9]+\.[0-9]+ ]] || ok=no
[[ $(sed -n 3p <<< "$out") == "BLAS "* ]] || ok=no
echo "version: $ok (expected bilayer $version, commit $commit)"
echo "$out"
[[ $ok == yes ]]
