#!/usr/bin/env bash
# The study scripts keep the program's rules (tiny meshes, well under a
# minute):
#  - output location: every result goes to the folder named by --output;
#    a folder the script did not make (a non-empty folder of the user, a copy
#    `cp -r out out.old` of an output folder, one holding another script's
#    marker) is refused with one line and exit 1, left byte for byte as it
#    was;
#  - deletions and overwrites: a file the user put into an output folder
#    survives a later run into it, one with the name of a file the script
#    writes is refused, not overwritten; a folder holding a command.txt
#    (what crack_growth used to take as its own) keeps its runs/; a scene
#    named '...prm' never touches the folder above its output;
#  - the scene as bilayer reads it: a crack set in an included .prm is the
#    crack crack_growth sweeps, a Gmsh file set in an included .prm is
#    refused (exit 2), and an --set that bilayer refuses is refused with
#    bilayer's line, before any folder is made;
#  - odd names: a scene named '-scene.prm' in a folder with a space and a
#    quote in its name runs; a .geo scene program (SystemCall, Printf >
#    file, an Include of such a file) is refused by scripts/check_geo before
#    gmsh runs, nothing executed.
# Usage: script_outputs.sh BILAYER SOURCE_DIR   (exit 77: no gnuplot)
set -u
bilayer=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") src=$(cd "$2" && pwd)
command -v gnuplot > /dev/null || { echo "script_outputs: no gnuplot: skipped"; exit 77; }
export BILAYER=$bilayer
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/verdict.sh"
scripts=$src/scripts
# A listing of a folder with a checksum of every file: equal listings, the
# folder as it was.
state() { (cd "$1" && find . -print0 | LC_ALL=C sort -z | xargs -0 -I{} sh -c \
  'if [ -f "{}" ]; then printf "%s %s\n" "{}" "$(sha256sum < "{}" | cut -c1-16)"; else echo "{}"; fi'); }
# One refusal: exit status 1 and exactly one line on stderr.
refused() { # LOG STATUS
  [[ $2 -eq 1 ]] || { echo "exit status $2, not 1"; return; }
  [[ $(wc -l < "$1") -eq 1 ]] || echo "$(wc -l < "$1") lines on stderr, not 1: $(head -3 "$1" | tr '\n' '|')"
}

# The scenes: Example 1 on 8 cells along Sigma, one cycle, no VTU, its
# crack (-0.3, 0.2) set in an included file.
dir="$work/scene dir's"
mkdir -p "$dir"
cat > "$dir/crack.prm" << EOF
subsection Geometry
  set Crack interval on Sigma = -0.3, 0.2
end
EOF
cat > "$dir/-scene.prm" << EOF
include $src/parameter_files/partial_closure.prm
include crack.prm
subsection Mesh
  set Cells along Sigma = 16
  set Number of cycles = 2
  set Fit crack tips = true
end
subsection Output
  set Write VTU = false
  set Progress interval = 0
end
EOF
grep -v crack.prm "$dir/-scene.prm" > "$dir/...prm"  # Example 1's crack (-0.5, 0.5)
crack() { # OUTPUT [ARGUMENT ...]
  local out=$1
  shift
  (cd "$dir" && python3 "$scripts/crack_growth" --cycles 1 --lengths 0.5 --output "$out" "$@" \
    -- -scene.prm)
}

# 1. crack_growth: the included crack is the one swept; the odd names run.
why=""
crack "$work/cg" > "$work/cg.log" 2> "$work/cg.err" || why="exit status $? ($(tail -1 "$work/cg.err"))"
grep -q "crack (-0.3, 0.2), l_0 = 0.5;" "$work/cg.log" ||
  why="$why; not the included crack (-0.3, 0.2): $(grep '^scene:' "$work/cg.log")"
# Its one row: l = 0.5 = l_0, both tips moving about the centre -0.05, so
# a = -0.05 - 0.25 = -0.3 and b = 0.2.
python3 - "$work/cg/crack_growth.csv" << 'PY' || why="$why; crack_growth.csv: not the row of l = 0.5 about the centre -0.05"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 1 and abs(float(rows[0]["a"]) + 0.3) < 1e-12 and abs(float(rows[0]["b"]) - 0.2) < 1e-12
PY
verdict "crack_growth sweeps the crack of an included file; a scene named -scene.prm in a folder with a quote" "$why"

# 2. A user's file in the output folder survives a second run; one with the
# name of a file the script writes is refused, the folder unchanged.
why=""
echo "my notes" > "$work/cg/notes.txt"
crack "$work/cg" > "$work/cg2.log" 2> "$work/cg2.err" || why="second run: exit status $?"
[[ $(cat "$work/cg/notes.txt" 2> /dev/null) == "my notes" ]] || why="$why; notes.txt changed or gone"
[[ -s $work/cg/crack_growth.csv && -d $work/cg/runs ]] || why="$why; no results of the second run"
verdict "a file of the user in an output folder survives a later run" "$why"

# 3. A copy of an output folder is not the script's: refused, unchanged;
# the original is still taken.
why=""
cp -r "$work/cg" "$work/cg.old"
echo "what I changed" >> "$work/cg.old/crack_growth.csv"
before=$(state "$work/cg.old")
crack "$work/cg.old" > /dev/null 2> "$work/copy.err"
why=$(refused "$work/copy.err" $?)
[[ $(state "$work/cg.old") == "$before" ]] || why="$why; the copy changed"
grep -q "another folder's (a copy)" "$work/copy.err" || why="$why; the line does not say it is a copy: $(cat "$work/copy.err")"
verdict "a copied output folder (cp -r) is refused and left as it was" "$why"

# refused_and_kept DESCRIPTION FOLDER: crack_growth --output FOLDER is
# refused with one line and leaves the folder as it was.
refused_and_kept() {
  local before why
  before=$(state "$2")
  crack "$2" > /dev/null 2> "$2.err"
  why=$(refused "$2.err" $?)
  [[ $(state "$2") == "$before" ]] || why="$why; the folder changed"
  verdict "$1" "$why"
}

# 4. The old rule: a folder of the user holding a command.txt kept its
# runs/ only by luck; now it is refused, runs/ and all intact.
why=""
mkdir -p "$work/mine/runs/important"
echo "command: by hand" > "$work/mine/command.txt"
echo "data" > "$work/mine/runs/important/data.txt"
refused_and_kept "a folder of the user with a command.txt is refused, its runs/ intact" "$work/mine"

# 5. Another script's output folder is not this one's.
why=""
mkdir -p "$work/other"
python3 "$scripts/bilayer_run.py" output mesh_convergence "$work/other" convergence.dat > /dev/null
echo "x" > "$work/other/convergence.dat"
refused_and_kept "an output folder of another script is refused" "$work/other"

# 6. A Gmsh scene set in an included file is a Gmsh scene (exit 2); a --set
# bilayer refuses ends with bilayer's line; nothing is written.
why=""
echo 'subsection Geometry
  set Gmsh file = shape.geo
end' > "$dir/gmsh.prm"
echo 'Point(1) = {0, 0, 0};' > "$dir/shape.geo"
printf 'include %s/parameter_files/partial_closure.prm\ninclude gmsh.prm\n' "$src" > "$dir/g.prm"
(cd "$dir" && python3 "$scripts/crack_growth" g.prm --output "$work/g") > /dev/null 2> "$work/g.err"
rc=$?
[[ $rc -ne 0 && ! -e $work/g ]] || why="exit status $rc, or $work/g written"
[[ $rc -eq 1 && $(cat "$work/g.err") == "bilayer: error: "* ]] || [[ $rc -eq 2 ]] ||
  why="$why; neither refused as a Gmsh scene (2) nor by bilayer's line: $(cat "$work/g.err")"
crack "$work/s" --set "Mesh/Cells along Sigma=-4" > /dev/null 2> "$work/s.err"
rc=$?
[[ $rc -eq 1 && $(tail -1 "$work/s.err") == "bilayer: error: "*"Cells along Sigma"* && ! -e $work/s ]] ||
  why="$why; --set Mesh/Cells along Sigma=-4: exit $rc, $(tail -1 "$work/s.err")"
verdict "the scene as bilayer reads it: an included Gmsh file, a refused --set" "$why"

# 7. mesh_convergence: a scene named '...prm' with --output beside a
# user's figure: the figure stays, the results are in the folder; a second
# run with a user's file named like its table is refused.
why=""
mkdir -p "$work/res"
echo "figure" > "$work/res/my_figure.png"
(cd "$dir" && bash "$scripts/mesh_convergence" ...prm --output "$work/res/mc") > "$work/mc.log" 2>&1 ||
  why="exit status $? ($(tail -1 "$work/mc.log"))"
[[ $(cat "$work/res/my_figure.png" 2> /dev/null) == figure ]] || why="$why; my_figure.png changed or gone"
[[ -s $work/res/mc/convergence.dat && -s $work/res/mc/bilayer/summary.json ]] || why="$why; no results in --output"
[[ $(python3 "$scripts/bilayer_run.py" name ...prm) != ".." ]] || why="$why; '...prm' is named '..'"
verdict "mesh_convergence: '...prm' with --output, the user's figure beside it stays" "$why"
why=""
mkdir -p "$work/res/mine"
echo "my table" > "$work/res/mine/convergence.dat"
before=$(state "$work/res/mine")
(cd "$dir" && bash "$scripts/mesh_convergence" ...prm --output "$work/res/mine") > /dev/null 2> "$work/mine2.err"
why=$(refused "$work/mine2.err" $?)
[[ $(state "$work/res/mine") == "$before" ]] || why="$why; the folder changed"
verdict "mesh_convergence: a folder of the user is refused, its files untouched" "$why"
why=""
(cd "$dir" && bash "$scripts/mesh_convergence" ...prm --output "$work/res/refused" \
  --set "Mesh/Cells along Sigma=-4") > /dev/null 2> "$work/mc3.err"
why=$(refused "$work/mc3.err" $?)
[[ $(cat "$work/mc3.err") == "bilayer: error: "*"Cells along Sigma"* ]] || why="$why; not bilayer's line: $(cat "$work/mc3.err")"
[[ ! -e $work/res/refused ]] || why="$why; the folder was made"
verdict "mesh_convergence: a scene bilayer refuses ends with its line, no folder made" "$why"

# 8. User-named files: compare_outputs --keep, random_scenes --csv and
# random_gmsh_scenes --csv, --keep, --output refuse what exists.
why=""
mkdir -p "$work/keep"
echo "kept" > "$work/keep/old-result"
python3 "$scripts/compare_outputs" "$bilayer" "$bilayer" --keep "$work/keep" > /dev/null 2> "$work/keep.err"
rc=$?
[[ $rc -eq 1 && $(cat "$work/keep/old-result") == kept && $(ls "$work/keep") == old-result ]] ||
  why="compare_outputs --keep: exit $rc, $(ls "$work/keep" | tr '\n' ' ')"
echo "my csv" > "$work/table.csv"
python3 "$scripts/random_scenes" --seed 1 --count 1 --bilayer "$bilayer" --csv "$work/table.csv" \
  > /dev/null 2> "$work/rs.err"
rc=$?
[[ $rc -ne 0 && $(cat "$work/table.csv") == "my csv" ]] || why="$why; random_scenes --csv: exit $rc, the file changed"
python3 "$scripts/random_gmsh_scenes" --seed 1 --count 1 --bilayer "$bilayer" --csv "$work/table.csv" \
  > /dev/null 2> "$work/rgs.err"
rc=$?
[[ $rc -ne 0 && $(cat "$work/table.csv") == "my csv" ]] || why="$why; random_gmsh_scenes --csv: exit $rc, the file changed"
for option in --keep --output; do
  python3 "$scripts/random_gmsh_scenes" --seed 1 --count 1 --bilayer "$bilayer" $option "$work/keep" \
    > /dev/null 2> "$work/rgs.err"
  rc=$?
  [[ $rc -eq 1 && $(cat "$work/keep/old-result") == kept && $(ls -A "$work/keep") == old-result &&
     $(wc -l < "$work/rgs.err") -eq 1 ]] ||
    why="$why; random_gmsh_scenes $option: exit $rc, $(ls -A "$work/keep" | tr '\n' ' ')"
done
verdict "an existing --keep folder or --csv file is refused and kept" "$why"

# 9. check_geo: scene programs are refused before gmsh sees them.
why=""
(
  cd "$work"
  printf 'SystemCall "touch ran-1";\n' > call.geo
  printf 'Printf("x") > "ran-2";\n' > printf.geo
  printf 'Include "call.geo";\nPoint(1) = {0, 0, 0};\n' > include.geo
  for g in call printf include; do
    python3 "$scripts/check_geo" "$g.geo" > "$g.log" 2>&1 && echo "$g.geo passed; "
    grep -q "a scene file may not run programs" "$g.log" || echo "$g.geo: no refusal of the scene program; "
  done
  [[ ! -e ran-1 && ! -e ran-2 ]] || echo "a scene program ran; "
) > "$work/geo.why"
why=$(cat "$work/geo.why")
verdict "check_geo refuses SystemCall, Printf > file and an Include of them, nothing run" "$why"

echo "$failures failed"
verdicts_end
