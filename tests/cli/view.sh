#!/usr/bin/env bash
# scripts/view on a bilayer result directory (with solution.pvd and
# interface.pvd, e.g. a run of parameter_files/partial_closure.prm):
#  - --png of a requested size: exit 0, a PNG of that size (its IHDR), a
#    ParaView state that names the solution and interface files of the
#    directory and that pvpython loads back and renders;
#  - what the picture shows (--describe JSON, the PNG, and the solution
#    pieces read independently by view_scene.py), at 900x500, at a tall
#    800x1200 (--no-edges) and a wide 2400x600 (--edges): each layer on its
#    own colour scale (its own 99th percentile over its area) with a bar
#    titled with the layer, every bar, the title and the legend inside the
#    picture and apart, the PNG's border background, both layers drawn
#    alike (edges on both or neither), many colours in each layer; length
#    axes on each layer (round ticks inside its undeformed bounds, labelled,
#    titled with the length unit), the units of summary.json (or "units of
#    E", "length unit") in the colour bars, each crack tip's G (from
#    summary.json) listed and its number drawn at the tip; once more at
#    1200x600 on a copy of the directory whose summary.json names the units
#    (mm, MPa, N/mm);
#  - a second run with other options (--cycle, --field, --scale 0) replaces
#    the files of the first (written by scripts/view) without --force;
#  - refusals with exit status 1 and exactly one stderr line "view: ...",
#    no backtrace, nothing written: a missing directory, an existing --png
#    file that scripts/view did not write (left unchanged), a --png inside
#    the result directory, a cycle out of range;
#  - the result directory unchanged by all of it.
# Exit status 77 (skipped) without pvbatch, or without a display and
# Xvfb. The exit status is the verdict otherwise.
# Usage: view.sh RESULT_DIR
#        view.sh --run BILAYER PARAMETER_FILE   (first runs BILAYER on the
#                                               file into a temporary directory)
set -u
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
view="$root/scripts/view"
usage="usage: view.sh RESULT_DIR | view.sh --run BILAYER PARAMETER_FILE"
if [[ ${1:-} == --run ]]; then
  [[ $# -eq 3 && -x $2 && -f $3 ]] || { echo "$usage" >&2; exit 2; }
elif [[ $# -ne 1 || ! -d $1 ]]; then
  echo "$usage" >&2
  exit 2
fi
command -v pvbatch > /dev/null || { echo "skipped: no pvbatch (Debian: paraview)"; exit 77; }
runner=()
if [[ -z ${DISPLAY:-} ]]; then
  command -v Xvfb > /dev/null || { echo "skipped: no display and no Xvfb (Debian: xvfb)"; exit 77; }
  runner=("$root/scripts/headless")
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ $1 == --run ]]; then
  mkdir "$work/run"
  "$2" "$(realpath "$3")" --set "Output/Output directory=$work/run/result" \
    --set "Output/Progress interval=0" --set "Output/Write VTU=true" > "$work/run.log" 2>&1 ||
    { echo "$2 $3 failed:"; tail -5 "$work/run.log"; exit 1; }
  result="$work/run/result"
else
  result=$(realpath "$1")
fi
listing() { (cd "$result" && find . -printf '%p %s %T@\n' | sort); }
before=$(listing)
source "$root/tests/cli/verdict.sh"
png_size() { # FILE -> "WIDTHxHEIGHT", or nothing if not a PNG
  python3 - "$1" << 'PY'
import struct, sys
with open(sys.argv[1], "rb") as f:
    head = f.read(24)
if head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR":
    print("%dx%d" % struct.unpack(">II", head[16:24]))
PY
}

# 1. The picture and the state.
start=$(date +%s)
"$view" "$result" --png "$work/view.png" --state "$work/view.pvsm" --size 900x500 \
  --describe "$work/view.json" > "$work/stdout" 2> "$work/stderr"
rc=$?
why=""
[[ $rc -eq 0 ]] || why="$why; exit status $rc"
[[ ! -s $work/stderr ]] || why="$why; stderr: $(head -3 "$work/stderr")"
grep -q "displacement x" "$work/stdout" || why="$why; no magnification printed"
size=$([[ -f $work/view.png ]] && png_size "$work/view.png")
[[ $size == 900x500 ]] || why="$why; PNG: '${size:-missing or not a PNG}', not 900x500"
[[ -s $work/view.pvsm ]] || why="$why; no state file"
grep -qF "$result/solution-" "$work/view.pvsm" 2> /dev/null || why="$why; the state names no $result/solution-NN.pvtu"
grep -qF "$result/interface-" "$work/view.pvsm" 2> /dev/null || why="$why; the state names no $result/interface-NN.vtu"
verdict "png and state ($(($(date +%s) - start)) s)" "$why"

# 1b. What the picture shows, at three sizes.
scene() { # NAME PNG JSON EDGES
  local why=""
  if [[ -s $3 && -s $2 ]]; then
    pvpython "$root/tests/cli/view_scene.py" "$3" "$2" "$result" "$4" > "$work/scene.log" 2>&1 ||
      why=$(grep -a ": NO\|Error\|error" "$work/scene.log" | head -5 | tr '\n' ';')
  else
    why="no picture or no --describe file"
  fi
  verdict "the scene at $1" "$why"
  [[ -z $why ]] || cat "$work/scene.log"
}
scene "900x500 (edges auto)" "$work/view.png" "$work/view.json" auto
for case in "800x1200 --no-edges off" "2400x600 --edges on"; do
  read -r size option edges <<< "$case"
  "$view" "$result" --png "$work/view-$size.png" --state "$work/view-$size.pvsm" --size "$size" \
    "$option" --describe "$work/view-$size.json" > "$work/stdout" 2> "$work/stderr" ||
    echo "scripts/view --size $size $option failed: $(head -3 "$work/stderr")"
  scene "$size ($option)" "$work/view-$size.png" "$work/view-$size.json" "$edges"
done

# 1c. The units of summary.json, on a copy that names them.
cp -r "$result" "$work/units"
python3 - "$work/units/summary.json" << 'PY'
import json, sys
summary = json.load(open(sys.argv[1]))
summary["units"] = {"system": "mm, MPa", "length": "mm", "stress": "MPa", "force": "N/mm",
                    "energy_release_rate": "N/mm", "energy": "N"}
json.dump(summary, open(sys.argv[1], "w"))
PY
"$view" "$work/units" --png "$work/units.png" --state "$work/units.pvsm" --size 1200x600 \
  --describe "$work/units.json" > "$work/stdout" 2> "$work/stderr" ||
  echo "scripts/view on the copy with units failed: $(head -3 "$work/stderr")"
saved=$result
result=$work/units
scene "1200x600, units mm, MPa, N/mm" "$work/units.png" "$work/units.json" auto
result=$saved

# 2. The state loads back and renders (pvpython; Debian's ParaView 5.11
# sometimes crashes at exit: up to three tries, the picture is the verdict).
cat > "$work/load.py" << 'PY'
import sys
from paraview.simple import GetRenderViews, LoadState, SaveScreenshot
LoadState(sys.argv[1])
SaveScreenshot(sys.argv[2], GetRenderViews()[0], ImageResolution=[400, 200])
PY
why=""
if [[ -s $work/view.pvsm ]]; then
  for _ in 1 2 3; do
    timeout 300 "${runner[@]}" pvpython "$work/load.py" "$work/view.pvsm" "$work/reloaded.png" \
      > "$work/load.log" 2>&1
    [[ -s $work/reloaded.png ]] && break
  done
  [[ $(png_size "$work/reloaded.png" 2> /dev/null) == 400x200 ]] ||
    why="pvpython did not render the state: $(grep -a -m1 -iE "error|exception" "$work/load.log")"
else
  why="no state file"
fi
verdict "the state loads back" "$why"

# 3. Again with other options: its own files are replaced without --force.
old=$(cksum < "$work/view.png")
"$view" "$result" --png "$work/view.png" --state "$work/view.pvsm" --size 900x500 \
  --cycle 0 --field stress_xy --scale 0 > "$work/stdout" 2> "$work/stderr"
rc=$?
why=""
[[ $rc -eq 0 ]] || why="$why; exit status $rc: $(head -1 "$work/stderr")"
[[ $(cksum < "$work/view.png") != "$old" ]] || why="$why; the PNG was not replaced"
grep -q "displacement x 0" "$work/stdout" || why="$why; --scale 0 not used"
verdict "rerun replaces its own files" "$why"

# 4. Refusals: one line, exit status 1, nothing written.
refusal() { # NAME EXPECTED-FRAGMENT ARGUMENT...
  local name=$1 expect=$2
  shift 2
  "$view" "$@" > "$work/stdout" 2> "$work/stderr"
  local rc=$? why=""
  [[ $rc -eq 1 ]] || why="$why; exit status $rc, not 1"
  [[ ! -s $work/stdout ]] || why="$why; output on stdout"
  [[ $(wc -l < "$work/stderr") -eq 1 ]] || why="$why; $(wc -l < "$work/stderr") lines on stderr"
  [[ $(head -c 6 "$work/stderr") == "view: " ]] || why="$why; stderr does not start with 'view: '"
  grep -qF -- "$expect" "$work/stderr" || why="$why; '$expect' not said"
  ! grep -qiE "traceback|stack trace|^ *File \"" "$work/stderr" || why="$why; backtrace"
  verdict "refusal: $name" "$why"
  [[ -z $why ]] || cat "$work/stderr"
}
refusal "missing directory" "no such directory" "$work/no-such-dir" --png "$work/x.png"
echo "not a picture of scripts/view" > "$work/foreign.png"
refusal "foreign --png file" "not written by scripts/view" "$result" --png "$work/foreign.png" \
  --state "$work/other.pvsm"
[[ $(cat "$work/foreign.png") == "not a picture of scripts/view" ]] ||
  verdict "the foreign file is kept" "it was changed"
refusal "--png in the result directory" "inside the result directory" "$result" --png "$result/view.png" \
  --state "$work/other.pvsm"
refusal "--describe in the result directory" "inside the result directory" "$result" --png "$work/x.png" \
  --state "$work/other.pvsm" --describe "$result/view.json"
refusal "cycle out of range" "--cycle 999" "$result" --cycle 999 --png "$work/x.png" \
  --state "$work/other.pvsm"
why=""
for f in x.png other.pvsm; do
  [[ ! -e $work/$f ]] || why="$why; $f written"
done
verdict "the refusals wrote nothing" "$why"

why=""
[[ $(listing) == "$before" ]] || why="it changed: $(diff <(echo "$before") <(listing) | head -3)"
verdict "the result directory is unchanged" "$why"
verdicts_end
