#!/usr/bin/env bash
# The configure-time checks of deal.II (cmake/BilayerDealII.cmake) on fake
# deal.II configurations, in scratch build folders (a few seconds: each
# case stops before the compiler is looked at):
#  (i)   -DDEAL_II_DIR=/nonexistent: one "bilayer:" line naming the folder
#        and how to get deal.II;
#  (ii)  a deal.II 9.3.0: one line naming 9.3.0, the 9.4.0 needed, and
#        -DDEAL_II_DIR / apt-get install libdeal.ii-dev;
#  (iii) a deal.II 9.4.0 without Trilinos and HDF5: exactly one line for
#        each (naming DEAL_II_WITH_<FEATURE> and -DDEAL_II_WITH_<FEATURE>=ON),
#        none for the features it has, and one closing error naming both;
#  (iv)  a deal.II 9.4.0 with every feature passes the checks (the control:
#        the fake stops the configuration right after them).
# Every failing case must exit non-zero. The exit status is the verdict.
# Usage: cmake_checks.sh CMAKE SOURCE_DIR
set -u
cmake=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset DEAL_II_DIR CMAKE_PREFIX_PATH
failures=0

# fake_deal_ii NAME VERSION FEATURE=ON|OFF ...: PREFIX/lib/cmake/deal.II.
fake_deal_ii() {
  local dir="$work/$1/lib/cmake/deal.II" version=$2 f
  shift 2
  mkdir -p "$dir"
  {
    echo "set(DEAL_II_PACKAGE_VERSION \"$version\")"
    echo "set(DEAL_II_PATH \"$work/$1\")"
    for f in "$@"; do
      echo "set(DEAL_II_WITH_${f%=*} ${f#*=})"
    done
    echo 'macro(deal_ii_initialize_cached_variables)'
    echo '  message(FATAL_ERROR "fake deal.II: the checks passed")'
    echo 'endmacro()'
  } > "$dir/deal.IIConfig.cmake"
  printf 'set(PACKAGE_VERSION "%s")\nset(PACKAGE_VERSION_COMPATIBLE TRUE)\n' \
    "$version" > "$dir/deal.IIConfigVersion.cmake"
}

# configure NAME -DDEAL_II_DIR=...: the output in $work/NAME.log, the exit
# status in $rc.
configure() {
  local name=$1
  shift
  "$cmake" -S "$source_dir" -B "$work/build-$name" "$@" > "$work/$name.log" 2>&1
  rc=$?
}

# check NAME CONDITION DESCRIPTION: count a failure unless CONDITION holds.
check() {
  if eval "$2"; then
    echo "cmake_checks: $1: yes ($3)"
  else
    echo "cmake_checks: $1: NO ($3)"
    failures=$((failures + 1))
  fi
}

# lines NAME REGEX: the number of lines of NAME's output matching REGEX.
lines() {
  grep -cE -- "$2" "$work/$1.log"
}

# (i) a folder without deal.II
configure missing -DDEAL_II_DIR=/nonexistent-bilayer-test
check missing '[[ $rc -ne 0 ]]' "exit status $rc, not 0"
check missing '[[ $(lines missing "bilayer: .*DEAL_II_DIR=/nonexistent-bilayer-test.*apt-get install libdeal.ii-dev") -eq 1 ]]' \
  "one line naming the folder and apt-get install libdeal.ii-dev"

# (ii) too old
fake_deal_ii old 9.3.0 CXX17=ON MPI=ON TRILINOS=ON METIS=ON HDF5=ON MUPARSER=ON UMFPACK=ON
configure old -DDEAL_II_DIR="$work/old"
check old '[[ $rc -ne 0 ]]' "exit status $rc, not 0"
check old '[[ $(lines old "bilayer: found deal.II 9\.3\.0 .*needs 9\.4\.0 or newer.*-DDEAL_II_DIR=.*apt-get install libdeal.ii-dev") -eq 1 ]]' \
  "one line naming 9.3.0, 9.4.0, -DDEAL_II_DIR and apt-get"
check old '[[ $(lines old "checks passed") -eq 0 ]]' "stopped at the version"

# (iii) features missing
fake_deal_ii partial 9.4.0 CXX17=ON MPI=ON TRILINOS=OFF METIS=ON HDF5=OFF MUPARSER=ON UMFPACK=ON
configure partial -DDEAL_II_DIR="$work/partial"
check partial '[[ $rc -ne 0 ]]' "exit status $rc, not 0"
for feature in TRILINOS HDF5; do
  check partial "[[ \$(lines partial 'DEAL_II_WITH_$feature') -eq 1 ]]" \
    "one line naming DEAL_II_WITH_$feature"
  check partial "[[ \$(lines partial '^bilayer: deal.II lacks DEAL_II_WITH_$feature .*-DDEAL_II_WITH_$feature=ON') -eq 1 ]]" \
    "it says how to get $feature"
done
check partial '[[ $(lines partial "^bilayer: deal.II lacks") -eq 2 ]]' \
  "no line for the features it has"
check partial '[[ $(lines partial "bilayer: the deal.II 9\.4\.0 .* lacks 2 feature\(s\).*TRILINOS, HDF5") -eq 1 ]]' \
  "one closing error naming both"

# (iv) the control: everything there
fake_deal_ii complete 9.4.0 CXX17=ON MPI=ON TRILINOS=ON METIS=ON HDF5=ON MUPARSER=ON UMFPACK=ON
configure complete -DDEAL_II_DIR="$work/complete"
check complete '[[ $(lines complete "checks passed") -eq 1 && $(lines complete "bilayer:") -eq 0 ]]' \
  "a complete deal.II 9.4.0 passes the checks"

if ((failures)); then
  for log in "$work"/*.log; do
    echo "--- $(basename "$log"):"
    cat "$log"
  done
fi
echo "cmake_checks: $failures failure(s)"
[[ $failures -eq 0 ]]
