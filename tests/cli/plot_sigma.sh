#!/usr/bin/env bash
# scripts/plot_sigma on a result of bilayer: a PNG and a PDF of the fields
# along Sigma of the last cycle, then of every cycle; the result directory
# is only read; a folder of the user is refused and left as it is; a
# directory without interface CSV files is refused with one line; a foreign
# interface CSV (no on_crack column), --cycle -1 and an --output inside DIR
# are refused with one line (exit 1, 2, 1), no traceback, nothing written.
# Usage: plot_sigma.sh BILAYER SCRIPTS_DIR PRM. The exit status is the verdict.
set -u
bilayer=$1 scripts=$2 prm=$3
source "$(dirname "${BASH_SOURCE[0]}")/verdict.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export BILAYER=$bilayer
"$bilayer" "$prm" --set "Mesh/Number of cycles=2" --set "Solver/Method=active set" \
  --set "Output/Write VTU=false" --set "Output/Output directory=run" > /dev/null 2>&1
before=$(cd run && ls -lA --time-style=full-iso | md5sum)

why=""
python3 "$scripts/plot_sigma" run --output plots > log 2> err || why="exit $?: $(cat err)"
[[ -s plots/sigma-01.png && -s plots/sigma-01.pdf ]] || why="$why; no sigma-01.png/.pdf"
[[ ! -e plots/sigma-00.png ]] || why="$why; cycle 0 plotted without --all"
verdict "the last cycle, PNG and PDF" "$why"

why=""
python3 "$scripts/plot_sigma" run --all --output plots > log 2> err || why="exit $?: $(cat err)"
[[ -s plots/sigma-00.png && -s plots/sigma-00.pdf ]] || why="$why; no sigma-00.png/.pdf"
verdict "every cycle with --all, into its own earlier folder" "$why"

why=""
[[ $(cd run && ls -lA --time-style=full-iso | md5sum) == "$before" ]] || why="the result directory changed"
verdict "the result directory only read" "$why"

why=""
mkdir mine && echo x > mine/notes
if python3 "$scripts/plot_sigma" run --output mine > log 2> err; then why="accepted"; fi
[[ $(ls -A mine) == notes ]] || why="$why; the folder changed: $(ls -A mine | tr '\n' ' ')"
grep -q "mine holds 'notes'" err || why="$why; message: $(cat err)"
verdict "a folder of the user refused and left as it is" "$why"

why=""
mkdir empty
if python3 "$scripts/plot_sigma" empty --output p2 > log 2> err; then why="accepted"; fi
[[ $(wc -l < err) -eq 1 ]] || why="$why; $(wc -l < err) lines on stderr"
grep -q "holds no interface-NN.csv" err || why="$why; message: $(cat err)"
verdict "a directory without interface CSV files refused with one line" "$why"

why=""
mkdir foreign && printf 's,jump_normal\n0,1\n' > foreign/interface-00.csv
for c in "1 foreign --output p3" "2 run --cycle -1 --output p4" "1 run --output run/plots"; do
  set -- $c
  rc=$1
  shift
  python3 "$scripts/plot_sigma" "$@" > log 2> err
  got=$?
  [[ $got -eq $rc && $(grep -c . err) -eq 1 ]] || why="$why; $*: exit $got, $(grep -c . err) lines"
  ! grep -q "Traceback" err || why="$why; $*: a traceback"
done
[[ ! -e p3 && ! -e p4 && ! -e run/plots ]] || why="$why; an output folder was made"
verdict "a foreign CSV, --cycle -1, --output inside DIR: one line each, nothing written" "$why"

verdicts_end
