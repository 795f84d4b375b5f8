#!/usr/bin/env bash
# Determinism: the same scene gives bit-identical summary.json numbers
# (17 significant digits; the wall times, the memory and the thread counts aside) and interface CSV files on
# repeated runs and with 1 or 2 threads, for every outer solver, on two
# adaptive cycles (non-matching traces, warm start).
# Usage: determinism.sh BILAYER PARAMETER_FILE
set -u
bilayer=$1
prm=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
for method in uzawa accelerated "active set"; do
  for run in "1 a" "1 b" "2 a" "2 b"; do
    set -- $run
    DEAL_II_NUM_THREADS=$1 OMP_NUM_THREADS=$1 OPENBLAS_NUM_THREADS=$1 \
      "$bilayer" "$prm" --set "Solver/Method=$method" --set "Solver/Uzawa step theta=auto" \
      --set "Mesh/Refinement=adaptive" --set "Mesh/Number of cycles=2" \
      --set "Solver/Warm start=true" --set "Output/Write VTU=false" \
      --set "Output/Output directory=$work/$1$2" > /dev/null 2>&1 || failures=$((failures + 1))
    sed -E 's/, "threads": \{[^}]*\}//; s/, "wall_seconds": \{[^}]*\}//; s/, "memory_mib": \[[^]]*\]//' "$work/$1$2/summary.json" > "$work/$1$2.json"
  done
  same=yes
  for other in 1b 2a 2b; do
    cmp -s "$work/1a.json" "$work/$other.json" || same=no
    for csv in "$work"/1a/interface-*.csv; do
      cmp -s "$csv" "$work/$other/$(basename "$csv")" || same=no
    done
  done
  grep -q '"energy"' "$work/1a.json" || same=no
  echo "$method: repeated runs and 1 or 2 threads identical: $same"
  [[ $same == yes ]] || failures=$((failures + 1))
done
echo "failures: $failures"
[[ $failures -eq 0 ]]
