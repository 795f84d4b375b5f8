#!/usr/bin/env bash
# What a run writes, and how:
#  - Output/Written cycles = last cycle: the solution fields (VTU pieces,
#    .pvtu, interface-NN.vtu, HDF5) of the last cycle only, the .pvd and
#    .xdmf collections naming only it; the interface CSV, summary.json and
#    the tables of every cycle;
#  - none: no solution fields at all, the records still complete;
#  - every cycle: the fields of each cycle;
#  - Output/Compression: the same data (the values ParaView's reader would
#    decode are not compared here; test cli.parallel_output and
#    cli.interface_dataset read the files), none > best speed >= best
#    compression in size, each file a VTK XML file in zlib's format (level
#    0 stores the blocks uncompressed);
#  - the run header names the threads and the BLAS, and summary.json's
#    "build" records the threads of each kind.
# Usage: output_choices.sh BILAYER PARAMETER_FILE (partial_closure.prm)
set -u
bilayer=$1 prm=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/verdict.sh"
run() { # DIRECTORY SETTING...
  local dir=$1
  shift
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  "$bilayer" "$prm" --set "Output/Output directory=$dir" --set "Mesh/Number of cycles=2" \
    --set "Solver/Method=active set" --set "Solver/Stopping rule=kkt" --set "Output/Progress interval=0" \
    --set "Output/Write HDF5=true" "${args[@]}" > "$dir.log" 2>&1
}

# 1. Last cycle.
why=""
run "$work/last" "Output/Written cycles=last cycle" || why="$why; the run failed: $(tail -1 "$work/last.log")"
for f in solution-01.pvtu solution-01-u-minus.vtu solution-01-v-plus.vtu solution-01-u-minus.h5 \
  interface-01.vtu interface-00.csv interface-01.csv solution.pvd solution.xdmf interface.pvd; do
  [[ -s $work/last/$f ]] || why="$why; $f missing"
done
for f in solution-00.pvtu solution-00-u-minus.vtu solution-00-u-minus.h5 interface-00.vtu; do
  [[ ! -e $work/last/$f ]] || why="$why; $f written"
done
grep -q 'solution-01.pvtu' "$work/last/solution.pvd" 2> /dev/null && ! grep -q 'solution-00' "$work/last/solution.pvd" ||
  why="$why; solution.pvd does not name cycle 1 alone"
grep -q 'solution-01-u-minus.h5' "$work/last/solution.xdmf" 2> /dev/null && ! grep -q 'solution-00' "$work/last/solution.xdmf" ||
  why="$why; solution.xdmf does not name cycle 1 alone"
[[ $(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["cycles"]))' "$work/last/summary.json" 2> /dev/null) == 2 ]] ||
  why="$why; summary.json does not hold both cycles"
verdict "last cycle: its fields only, the records of both" "$why"

# 2. None.
why=""
run "$work/none" "Output/Written cycles=none" || why="$why; the run failed"
n=$(find "$work/none" -name '*.vtu' -o -name '*.pvtu' -o -name '*.h5' -o -name '*.pvd' -o -name '*.xdmf' | wc -l)
[[ $n -eq 0 ]] || why="$why; $n field files written"
[[ -s $work/none/interface-01.csv && -s $work/none/summary.json && -s $work/none/table.txt ]] ||
  why="$why; records missing"
verdict "none: no fields, the records" "$why"

# 3. Every cycle.
why=""
run "$work/every" "Output/Written cycles=every cycle" || why="$why; the run failed"
for f in solution-00.pvtu solution-01.pvtu interface-00.vtu interface-01.vtu solution-00-v-minus.h5; do
  [[ -s $work/every/$f ]] || why="$why; $f missing"
done
cmp -s "$work/every/interface-01.csv" "$work/last/interface-01.csv" || why="$why; the CSV depends on the written cycles"
verdict "every cycle" "$why"

# 4. Compression levels: one cycle each.
declare -A size
why=""
for level in none "best speed" "best compression"; do
  dir="$work/c-${level// /-}"
  "$bilayer" "$prm" --set "Output/Output directory=$dir" --set "Output/Compression=$level" \
    --set "Output/Progress interval=0" > "$dir.log" 2>&1 || why="$why; the run with $level failed"
  file="$dir/solution-00-u-minus.vtu"
  size[$level]=$(stat -c %s "$file" 2> /dev/null || echo 0)
  head -c 300 "$file" 2> /dev/null | grep -q '<VTKFile type="UnstructuredGrid"' || why="$why; $level: not a VTK XML file"
  # (deal.II writes zlib's format at every level; none stores the blocks)
  head -c 300 "$file" | grep -q 'vtkZLibDataCompressor' || why="$why; $level names no zlib compressor"
done
((size[none] > size[best speed] && size[best speed] >= size[best compression])) ||
  why="$why; sizes none ${size[none]}, best speed ${size[best speed]}, best compression ${size[best compression]}"
verdict "compression: smaller files with more effort" "$why"

# 5. Threads and BLAS in the header and in summary.json.
why=""
grep -qE '^bilayer .* threads? \(the subproblems. tasks\), [0-9]+ BLAS threads? per call.*; BLAS ' "$work/last.log" ||
  why="$why; no header line with the threads and the BLAS"
python3 - "$work/last/summary.json" << 'PY' || why="$why; summary.json build.threads missing or not positive"
import json, sys
t = json.load(open(sys.argv[1]))["build"]["threads"]
assert t["tasks"] >= 1 and t["blas"] >= 1 and t["blas_set_by"]
PY
verdict "threads and BLAS reported" "$why"

verdicts_end
