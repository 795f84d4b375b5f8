#!/usr/bin/env bash
# Bad Gmsh scenes: each must end with exactly one line "bilayer: error: ..."
# on stderr naming the file (Geometry/Gmsh file) and the group or the entry,
# a non-zero exit, no backtrace and no output directory. Variants of
# parameter_files/two_cracks.{geo,prm}: a missing or misnamed physical
# group, a crack that reaches the end of Sigma, a subdomain without a clamped
# part, a Sigma that does not separate the subdomains (the interface curves
# duplicated instead of shared, a boundary curve put into Sigma), a
# traction on a part the file does not have, a .geo that gmsh cannot mesh, a
# missing file, a .msh of another format.
# Usage: gmsh_refusals.sh BILAYER PARAMETER_FILES_DIRECTORY
set -u
bilayer=$(realpath "$1")
source_dir=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0

# case NAME EXPECTED-FRAGMENT GEO-SED-SCRIPT [--set ...]: the scene with
# two_cracks.geo edited by the sed script.
case_() {
  local name=$1 expect=$2 edit=$3
  shift 3
  sed "$edit" "$source_dir/two_cracks.geo" > scene.geo
  sed 's/two_cracks.geo/scene.geo/' "$source_dir/two_cracks.prm" > scene.prm
  "$bilayer" scene.prm --set "Output/Output directory=out" "$@" > stdout 2> stderr
  local rc=$? why=""
  [[ $rc -ne 0 ]] || why="exit status 0"
  [[ $(wc -l < stderr) -eq 1 ]] || why="$why; $(wc -l < stderr) lines on stderr"
  grep -qF "bilayer: error: " stderr || why="$why; no 'bilayer: error:'"
  grep -qF -- "$expect" stderr || why="$why; '$expect' not named"
  ! grep -qiE "stacktrace|terminate called|^-{5,}" stderr || why="$why; backtrace"
  [[ ! -e out ]] || why="$why; output directory written"
  if [[ -n $why ]]; then
    echo "$name: no ($why)"
    cat stderr
    failures=$((failures + 1))
  else
    echo "$name: yes"
  fi
  rm -rf out
}

case_ "missing Omega- group" "scene.geo': no physical surface named 'Omega-'" \
  's/Physical Surface("Omega-")/Physical Surface("lower")/'
case_ "misnamed crack and Sigma groups" "no physical curve named 'Sigma'" \
  's/Physical Curve("Sigma")/Physical Curve("glued")/; s/Physical Curve("crack")/Physical Curve("debond")/' \
  --set "Geometry/Clamped sides=left, right"
case_ "misnamed clamped part" "Clamped sides" 's/^$//' \
  --set "Geometry/Clamped sides=left, rigth"
case_ "traction on an unknown part" "Traction on hole" 's/^$//' \
  --set "Loads/Layer 1/Traction on hole=0; 1"
case_ "crack reaching the end of Sigma" "reaches an end of Sigma" \
  's/Physical Curve("Sigma") = {11, 13, 15};/Physical Curve("Sigma") = {13, 15};/; s/Physical Curve("crack") = {12, 14};/Physical Curve("crack") = {11, 12, 14};/'
case_ "subdomain without a clamped part" "'Omega-' has no clamped part" 's/^$//' \
  --set "Geometry/Clamped sides=top" --set "Loads/Layer 1/Traction on top=0; 0"
case_ "boundary curve in Sigma" "Sigma must separate the two subdomains" \
  's/Physical Curve("Sigma") = {11, 13, 15};/Physical Curve("Sigma") = {11, 13, 15, 2};/; s/Physical Curve("right") = {2, 3};/Physical Curve("right") = {3};/'
case_ "interface edges in no group" "which is in neither 'Sigma' nor 'crack'" \
  's/Physical Curve("Sigma") = {11, 13, 15};/Physical Curve("Sigma") = {11, 15};/'
case_ "geometry gmsh cannot mesh" "meshing failed" 's/^Line(4) = {3, 4};/Line(4) = {3, 99};/'
case_ "missing file" "no such file" 's/^$//' --set "Geometry/Gmsh file=missing.geo"
printf '$MeshFormat\n4.1 0 8\n$EndMeshFormat\n' > other.msh
case_ "mesh of format 4" "format 2" 's/^$//' --set "Geometry/Gmsh file=other.msh"
exit $((failures > 0))
