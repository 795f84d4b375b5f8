#!/usr/bin/env bash
# The bad-input catalogue: every case must end with exactly one line
# "bilayer: error: ..." on stderr that names the parameter (and, where
# deal.II gives them, the file and line) with the allowed range, a non-zero
# exit, no backtrace, and a pre-existing output directory left unchanged with
# no staging directory behind. A run that fails its checks leaves the output
# directory unchanged too and puts its results in DIR.failed.
# Usage: bad_input_catalogue.sh BILAYER PARAMETER_FILE
set -u
bilayer=$1
prm=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
mkdir out
echo '{"previous": "results"}' > out/summary.json
echo 'kept' > out/notes.txt
snapshot() { (cd out && find . -type f -exec md5sum {} + | sort); }
before=$(snapshot)
failures=0

# check NAME EXPECTED-FRAGMENT ARGS...: one refusal.
check() {
  local name=$1 expect=$2
  shift 2
  "$bilayer" "$@" > stdout 2> stderr
  local rc=$? ok=yes why=""
  [[ $rc -ne 0 ]] || { ok=no; why="exit status 0"; }
  [[ $(wc -l < stderr) -eq 1 ]] || { ok=no; why="$why; $(wc -l < stderr) lines on stderr"; }
  grep -qF "bilayer: error: " stderr || { ok=no; why="$why; no 'bilayer: error:'"; }
  grep -qF -- "$expect" stderr || { ok=no; why="$why; '$expect' not named"; }
  ! grep -qiE "stacktrace|^-{5,}" stderr || { ok=no; why="$why; backtrace"; }
  [[ "$(snapshot)" == "$before" ]] || { ok=no; why="$why; output directory changed"; }
  [[ ! -e out.partial && ! -e out.failed ]] || { ok=no; why="$why; staging left behind"; }
  echo "$name: $ok${why:+ ($why)}"
  [[ $ok == yes ]] || { cat stderr; failures=$((failures + 1)); }
}
run() {
  local name=$1 expect=$2
  shift 2
  check "$name" "$expect" "$prm" --set "Output/Output directory=out" --set "$@"
}

printf 'subsection Mesh\n  sett Cells along Sigma = 8\nend\n' > malformed.prm
printf 'subsection Mesh\n  set Cels along Sigma = 8\nend\n' > unknown_entry.prm
printf 'subsection Meshes\n  set Cells along Sigma = 8\nend\n' > unknown_subsection.prm
printf 'subsection Mesh\n  set Cells along Sigma = 8\n' > unterminated.prm
check "malformed line" "Line <2> of file <malformed.prm>" malformed.prm
check "unknown entry" "Line <2> of file <unknown_entry.prm>: No entry with name <Cels along Sigma>" unknown_entry.prm
check "unknown subsection" "Line <1> of file <unknown_subsection.prm: There is no such subsection to be entered: Meshes" unknown_subsection.prm
check "unterminated subsection" "unterminated.prm" unterminated.prm
check "missing parameter file" "no-such-file.prm" no-such-file.prm
run "value outside its pattern" "Mesh/Cells along Sigma=-3: The string <-3> does not match the given pattern <[Integer range 1...100000" "Mesh/Cells along Sigma=-3"
run "zero cells" "Mesh/Cells along Sigma=0: The string <0> does not match the given pattern <[Integer range 1...100000" "Mesh/Cells along Sigma=0"
run "degree 0" "Mesh/Polynomial degree of layer 1=0: The string <0> does not match the given pattern <[Integer range 1...4" "Mesh/Polynomial degree of layer 1=0"
run "E <= 0" "Materials/Layer 2/Young's modulus must be > 0, got 0" "Materials/Layer 2/Young's modulus=0"
run "E < 0" "Materials/Layer 1/Young's modulus=-1: The string <-1> does not match the given pattern <[Double 0...MAX_DOUBLE" "Materials/Layer 1/Young's modulus=-1"
run "Poisson's ratio 0.5" "Materials/Layer 1/Poisson's ratio must lie in (-1, 0.5), got 0.5" "Materials/Layer 1/Poisson's ratio=0.5"
run "Poisson's ratio -1" "Materials/Layer 2/Poisson's ratio must lie in (-1, 0.5), got -1" "Materials/Layer 2/Poisson's ratio=-1"
run "crack outside Sigma" "Geometry/Crack interval on Sigma must satisfy -1 < x_start <= x_end < 1, got '-2, 0.5'" "Geometry/Crack interval on Sigma=-2, 0.5"
run "crack touching Gamma_D" "Geometry/Crack interval on Sigma must satisfy -1 < x_start <= x_end < 1, got '-0.5, 1'" "Geometry/Crack interval on Sigma=-0.5, 1"
run "no clamped part" "Geometry/Clamped sides must clamp a part of the boundary of both Omega- and Omega+" "Geometry/Clamped sides=bottom"
run "load does not parse" "Loads/Layer 1/Traction on bottom side: cannot evaluate '0; c*'" "Loads/Layer 1/Traction on bottom side=0; c*"
run "load evaluates to NaN" "Loads/Layer 1/Traction on bottom side must be finite on the bottom side" "Loads/Layer 1/Traction on bottom side=0; sqrt(x-5)"
run "prescribed displacement infinite" "Loads/Layer 2/Prescribed displacement must be finite on the left side" "Loads/Layer 2/Prescribed displacement=0; 1/(x-x)"
run "load on an absent layer" "Loads/Layer 2/Traction on top side must be '0; 0': layer 2 is absent (Materials/Number of layers = 1)" "Loads/Layer 2/Traction on top side=0; 1" --set "Materials/Number of layers=1"
run "missing mesh file" "Mesh/Mesh files: cannot open" "Mesh/Mesh files=nothere_{side}.msh"
run "theta <= 0" "Solver/Uzawa step theta must be a number > 0 or 'auto', got '-1'" "Solver/Uzawa step theta=-1"
run "theta = 0" "Solver/Uzawa step theta must be > 0 or 'auto', got 0" "Solver/Uzawa step theta=0"
run "bound p <= 0" "Contact/Multiplier bound p must be > 0, got 0" "Contact/Multiplier bound p=0"
check "output directory not writable" "Output/Output directory: cannot create '/dev/null/x.partial'" \
  "$prm" --set "Output/Output directory=/dev/null/x"
check "output directory is a file" "Output/Output directory 'out/notes.txt' exists and is not a directory" \
  "$prm" --set "Output/Output directory=out/notes.txt"
check "output directory '.'" "Output/Output directory must name a directory that a run may create or replace" \
  "$prm" --set "Output/Output directory=."

# A run that fails its checks (iteration limit): exit 2, the output
# directory unchanged, the failed run's results in out.failed.
"$bilayer" "$prm" --set "Output/Output directory=out" --set "Solver/Maximum iterations=10" > stdout 2> stderr
rc=$?
ok=yes
[[ $rc -eq 2 ]] || ok=no
grep -qF "did not pass its checks" stderr || ok=no
[[ "$(snapshot)" == "$before" && ! -e out.partial && -f out.failed/summary.json ]] || ok=no
echo "failed run leaves the output directory unchanged, results in out.failed: $ok"
[[ $ok == yes ]] || { cat stderr; failures=$((failures + 1)); }

# A run that passes replaces the directory whole.
"$bilayer" "$prm" --set "Output/Output directory=out" > stdout 2> stderr
ok=yes
[[ $? -eq 0 && -f out/solution.pvd && ! -e out/notes.txt && ! -e out.partial ]] || ok=no
echo "passing run replaces the output directory: $ok"
[[ $ok == yes ]] || { cat stderr; failures=$((failures + 1)); }

echo "failures: $failures"
[[ $failures -eq 0 ]]
