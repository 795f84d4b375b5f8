# Sourced by the shell tests of tests/cli: verdict NAME WHY prints
# "NAME: yes" when WHY is empty, else "NAME: no (WHY)" (a leading "; "
# dropped) and counts the failure in $failures; verdicts_end repeats the
# failed checks as the last lines (a log cut in the middle still names
# them) and is the script's status.
failures=0
failed_checks=()
verdict() { # NAME WHY (empty: passed)
  if [[ -z $2 ]]; then
    echo "$1: yes"
  else
    echo "$1: no (${2#; })"
    failures=$((failures + 1))
    failed_checks+=("$1: no (${2#; })")
  fi
}
verdicts_end() { # the status of the script: 0 when every check passed
  if ((failures > 0)); then
    echo "FAILED ($failures):"
    printf '  %s\n' "${failed_checks[@]}"
    return 1
  fi
  return 0
}
