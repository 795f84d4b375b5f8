#!/usr/bin/env bash
# The interface dataset (interface.pvd, interface-NN.vtu) of Example 1 (two
# adaptive cycles, Q2, active set) and of the two-crack Gmsh scene, read
# with ParaView's readers and checked against the contact conditions and the
# interface CSV (read_interface.py).
# Usage: interface_dataset.sh BILAYER PARAMETER_FILES_DIRECTORY
set -uo pipefail
bilayer=$1
scenes=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
"$bilayer" "$scenes/partial_closure.prm" --set "Output/Output directory=$work/example1" \
  --set "Output/Terminal output=checks" --set "Solver/Method=active set" \
  --set "Mesh/Refinement=adaptive" --set "Mesh/Number of cycles=2" \
  --set "Mesh/Polynomial degree of layer 1=2" --set "Mesh/Polynomial degree of layer 2=2" \
  > /dev/null || failures=$((failures + 1))
pvpython "$here/read_interface.py" "$work/example1" --example1 2> /dev/null | grep -E ": (yes|NO)$" \
  || failures=$((failures + 1))
pvpython "$here/read_interface.py" "$work/example1" --example1 > /dev/null 2>&1 || failures=$((failures + 1))
"$bilayer" "$scenes/two_cracks.prm" --set "Output/Output directory=$work/two_cracks" \
  --set "Output/Terminal output=checks" > /dev/null || failures=$((failures + 1))
pvpython "$here/read_interface.py" "$work/two_cracks" 2> /dev/null | grep -E ": (yes|NO)$" \
  || failures=$((failures + 1))
pvpython "$here/read_interface.py" "$work/two_cracks" > /dev/null 2>&1 || failures=$((failures + 1))
exit $((failures > 0))
