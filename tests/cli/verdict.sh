# Sourced by the shell tests of tests/cli: verdict NAME WHY prints
# "NAME: yes" when WHY is empty, else "NAME: no (WHY)" (a leading "; "
# dropped) and counts the failure in $failures.
failures=0
verdict() { # NAME WHY (empty: passed)
  if [[ -z $2 ]]; then
    echo "$1: yes"
  else
    echo "$1: no (${2#; })"
    failures=$((failures + 1))
  fi
}
