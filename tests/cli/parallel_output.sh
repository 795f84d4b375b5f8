#!/usr/bin/env bash
# The bilayer program under mpirun: 2 and 4 processes give the serial run's
# summary.json numbers bit for bit (the wall times, memory, process and
# thread counts and exchange volume aside), and the outputs of every run (PVTU pieces and
# HDF5/XDMF, two cycles; with 6 processes u- and u+ are shared by two
# processes each, which write a piece each and one HDF5 file together) open
# with ParaView's readers and agree with each other and with summary.json
# (read_outputs.py). The active set method: a few Newton steps instead of the
# paper's thousands of Uzawa iterations, each of which exchanges traces
# (6 processes on a 2-core machine, under AddressSanitizer, took 8 minutes
# with Uzawa; mpi_consistency covers Uzawa under MPI).
# Usage: parallel_output.sh BILAYER PARAMETER_FILE
set -u
bilayer=$1
prm=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
command -v pvpython > /dev/null || { echo "pvpython not found: apt-get install paraview"; exit 1; }
command -v mpirun > /dev/null || { echo "mpirun not found: apt-get install openmpi-bin"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
strip() {
  sed -E 's/, "threads": \{[^}]*\}//; s/, "wall_seconds": \{[^}]*\}//; s/, "memory_mib": \[[^]]*\]//; s/, "processes": [0-9]+//; s/, "shared_values": [0-9]+//; s/, "shared_seconds": [^,]+//' "$1"
}
for n in 0 2 4 6; do
  launcher=()
  ((n > 0)) && launcher=(mpirun -np "$n")
  "${launcher[@]}" "$bilayer" "$prm" --set "Mesh/Number of cycles=2" \
    --set "Solver/Method=active set" --set "Output/Write HDF5=true" --set "Output/Output directory=$work/p$n" \
    > "$work/p$n.log" 2>&1 || { echo "run with ${n} processes failed:"; tail -5 "$work/p$n.log"; failures=$((failures + 1)); }
  strip "$work/p$n/summary.json" > "$work/p$n.json"
  if ((n > 0 && n <= 4)); then
    same=yes
    cmp -s "$work/p0.json" "$work/p$n.json" || same=no
    grep -q "\"processes\": $n," "$work/p$n/summary.json" || same=no
    echo "mpirun -np $n: summary.json identical to the serial run's: $same"
    [[ $same == yes ]] || failures=$((failures + 1))
  fi
  echo "outputs of the run with $( ((n > 0)) && echo "$n processes" || echo "no mpirun"):"
  pvpython "$here/read_outputs.py" "$work/p$n" 2>&1 | grep -E ": (yes|NO)$" || failures=$((failures + 1))
  pvpython "$here/read_outputs.py" "$work/p$n" > /dev/null 2>&1 || failures=$((failures + 1))
done
echo "failures: $failures"
[[ $failures -eq 0 ]]
