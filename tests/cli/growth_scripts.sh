#!/usr/bin/env bash
# The growth scripts on tiny runs (well under a minute):
#  1. scripts/growth_curve on a run of growth_full_opening.prm: exit 0, the
#     figure and its data; the unstable runs it prints are those of
#     summary.json (load and crack lengths); --displacement uy_1 draws the
#     point's column, a point the run does not have is refused (exit 1,
#     nothing drawn); the run factorises and estimates the error (eta) on
#     step 0 alone;
#  2. scripts/crack_growth --driver on Example 2 (full_opening.prm, 32 cells
#     along Sigma, active set) with --toughness 1e-4: exit 0, and its
#     sqrt(G_c / G) agrees with the driver's critical_load to 1e-6 (the
#     script's check); the critical load of the initial crack equals the
#     first onset of the quasi-static run of growth_full_opening.prm (the same
#     scene and toughness: two runs, one number);
#  3. the check fails when the two disagree: --toughness 1e-4 with
#     Fracture/Toughness = 2e-4 set after it (the driver's G_c is twice the
#     script's): exit 1, naming the difference;
#  4. bad arguments and foreign folders (issue 45): growth_curve on copies of
#     the run with a summary.json that is a JSON list, a growth.csv with a
#     garbage row, and --output ''; crack_growth --range 1,2,x: one line on
#     stderr, exit 1 (the folder) or 2 (the command line), no traceback,
#     nothing written.
# Usage: growth_scripts.sh BILAYER SOURCE_DIR   (exit 77: no gnuplot)
set -u
bilayer=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") src=$(cd "$2" && pwd)
command -v gnuplot > /dev/null || { echo "growth_scripts: no gnuplot: skipped"; exit 77; }
export BILAYER=$bilayer
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/verdict.sh"
scripts=$src/scripts

# 1. growth_curve
why=""
"$bilayer" "$src/parameter_files/growth_full_opening.prm" \
  --set "Output/Output directory=$work/run" > "$work/run.log" 2>&1 || why="the run failed: $(tail -1 "$work/run.log")"
python3 "$scripts/growth_curve" "$work/run" --output "$work/gc" > "$work/gc.log" 2>&1 ||
  why="$why; growth_curve exit $? ($(tail -1 "$work/gc.log"))"
[[ -s $work/gc/growth_curve.png && -s $work/gc/growth_curve.dat ]] || why="$why; no figure or data"
python3 - "$work/run/summary.json" "$work/gc.log" << 'PY' || why="$why; the unstable runs printed are not those of summary.json"
import json, re, sys
runs = json.load(open(sys.argv[1]))["growth"]["unstable"]
printed = [tuple(float(v) for v in m.groups()) for m in re.finditer(
    r"unstable growth at lambda = (\S+) from crack length (\S+) to (\S+) ", open(sys.argv[2]).read())]
expected = [(r["load_factor"], r["from_length"], r["to_length"]) for r in runs]
ok = len(runs) > 0 and len(printed) == len(expected) and all(
    abs(a - b) <= 1e-6 * max(abs(b), 1) for p, e in zip(printed, expected) for a, b in zip(p, e))
print("unstable runs: summary.json %s, printed %s" % (expected, printed))
sys.exit(0 if ok else 1)
PY
python3 "$scripts/growth_curve" "$work/run" --displacement uy_1 --output "$work/gc_uy" > /dev/null 2>&1 ||
  why="$why; --displacement uy_1 failed"
python3 "$scripts/growth_curve" "$work/run" --displacement uy_7 --output "$work/gc_bad" > /dev/null 2> "$work/bad.err"
rc=$?
[[ $rc -eq 1 && ! -e $work/gc_bad && $(cat "$work/bad.err") == *uy_7* ]] ||
  why="$why; --displacement uy_7: exit $rc, $(cat "$work/bad.err")"
verdict "growth_curve draws a growth run, its unstable runs those of summary.json" "$why"

# 1b. the run factorises once (factorisation seconds > 0 on step 0 alone) and
# estimates the error on step 0 alone (eta finite there, null on the later
# steps: their mesh is step 0's, their indicators would refine nothing)
why=""
python3 - "$work/run/summary.json" << 'PY' || why="not step 0 alone"
import json, math, sys
cycles = json.load(open(sys.argv[1]))["cycles"]
factorising = [c["cycle"] for c in cycles if c["wall_seconds"]["factorisation"] > 0]
estimated = [c["cycle"] for c in cycles if c["eta"] is not None and math.isfinite(c["eta"])]
print("%d steps; factorising: %s; with eta: %s; accepted: %s" % (
    len(cycles), factorising, estimated, all(c["accepted"] for c in cycles)))
sys.exit(0 if factorising == [0] and estimated == [0] and all(c["accepted"] for c in cycles) else 1)
PY
verdict "a growth run factorises and estimates the error on step 0 alone" "$why"

# 2. crack_growth --driver
why=""
python3 "$scripts/crack_growth" "$src/parameter_files/full_opening.prm" --driver --toughness 1e-4 \
  --set "Mesh/Cells along Sigma=32" --set "Solver/Method=active set" --set "Solver/Tolerance=1e-10" \
  --output "$work/cg" > "$work/cg.log" 2>&1 || why="exit $? ($(tail -1 "$work/cg.log"))"
grep -q "largest relative difference of lambda sqrt(G_c / G) and the driver's critical_load" "$work/cg.log" ||
  why="$why; no agreement line"
python3 - "$work/cg/crack_growth.csv" "$work/run/growth.csv" << 'PY' || why="$why; the sweep's critical load is not the quasi-static onset"
import csv, sys
def rows(path):
    return list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
sweep, quasi = rows(sys.argv[1]), rows(sys.argv[2])
own = float(sweep[0]["tip1_lambda_c"])
onset = float([r for r in quasi if r["kind"] == "onset"][0]["load_factor"])
print("initial crack: lambda_c of the sweep %.10g, first onset of the quasi-static run %.10g" % (own, onset))
sys.exit(0 if abs(own / onset - 1) < 1e-8 else 1)
PY
verdict "crack_growth --driver: the critical loads agree, and with the quasi-static onset" "$why"

# 3. the check fails where the two critical loads differ
why=""
python3 "$scripts/crack_growth" "$src/parameter_files/full_opening.prm" --driver --toughness 1e-4 \
  --set "Mesh/Cells along Sigma=32" --set "Solver/Method=active set" \
  --set "Fracture/Toughness=2e-4" --output "$work/cg2" > "$work/cg2.log" 2> "$work/cg2.err"
rc=$?
[[ $rc -eq 1 && $(tail -1 "$work/cg2.err") == *"critical loads differ"* ]] ||
  why="exit $rc, $(tail -1 "$work/cg2.err")"
verdict "crack_growth --driver fails where the critical loads differ" "$why"

# 4. one-line refusals (issue 45): refused RC DESCRIPTION COMMAND... runs the
# command in $work/refusal, which must stay empty.
why=""
refused() {
  local rc=$1 what=$2 got
  shift 2
  mkdir -p "$work/refusal"
  (cd "$work/refusal" && "$@") > /dev/null 2> "$work/refusal.err"
  got=$?
  [[ $got -eq $rc ]] || why="$why; $what: exit $got, not $rc"
  [[ $(grep -c . "$work/refusal.err") -eq 1 ]] || why="$why; $what: $(grep -c . "$work/refusal.err") lines on stderr"
  ! grep -q "Traceback\|internal error" "$work/refusal.err" || why="$why; $what: $(tail -1 "$work/refusal.err")"
  [[ -z $(ls -A "$work/refusal") ]] || why="$why; $what: wrote $(ls -A "$work/refusal" | head -1)"
}
cp -r "$work/run" "$work/list" && echo '[1, 2]' > "$work/list/summary.json"
cp -r "$work/run" "$work/garbage" && echo 'x,y' >> "$work/garbage/growth.csv"
refused 1 "summary.json a JSON list" python3 "$scripts/growth_curve" "$work/list" --output out
refused 1 "growth.csv with a garbage row" python3 "$scripts/growth_curve" "$work/garbage" --output out
refused 2 "--output ''" python3 "$scripts/growth_curve" "$work/run" --output ''
refused 2 "--range 1,2,x" python3 "$scripts/crack_growth" "$src/parameter_files/full_opening.prm" \
  --range 1,2,x --output out
verdict "growth_curve and crack_growth refuse foreign folders and bad arguments with one line" "$why"
verdicts_end
