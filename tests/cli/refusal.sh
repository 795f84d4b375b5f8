#!/usr/bin/env bash
# One refusal of bad input (docs/running.md, "How a run ends": "bad input
# ends with one line `bilayer: error: <entry>: <what is allowed>` and exit
# code 1"): the
# command must exit with status 1 (not 0, not 2, not a crash or an abort),
# print nothing on stdout and exactly one line on stderr that starts with
# "bilayer: error: " and contains EXPECTED (a fixed string), and no
# backtrace. The exit status of this script is the verdict (CTest uses it:
# no pass regular expression).
# Usage: refusal.sh EXPECTED COMMAND [ARGUMENT ...]
set -u
expect=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$@" > "$work/stdout" 2> "$work/stderr"
rc=$?
ok=yes
why=""
[[ $rc -eq 1 ]] || { ok=no; why="$why; exit status $rc, not 1"; }
[[ ! -s "$work/stdout" ]] || { ok=no; why="$why; output on stdout"; }
lines=$(wc -l < "$work/stderr")
[[ $lines -eq 1 ]] || { ok=no; why="$why; $lines lines on stderr, not 1"; }
[[ $(head -c 16 "$work/stderr") == "bilayer: error: " ]] ||
  { ok=no; why="$why; stderr does not start with 'bilayer: error: '"; }
grep -qF -- "$expect" "$work/stderr" || { ok=no; why="$why; '$expect' not in stderr"; }
! grep -qiE "stacktrace|backtrace|^-{5,}|An error occurred" "$work/stderr" ||
  { ok=no; why="$why; backtrace"; }
echo "refusal: $ok${why:+ (${why#; })}"
echo "--- stderr:"
cat "$work/stderr"
[[ $ok == yes ]]
