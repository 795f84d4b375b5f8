#!/usr/bin/env bash
# Every shipped parameter file (parameter_files/*.prm) is read as bilayer
# reads it (--print-parameters: exit 0, nothing on stderr, nothing written;
# Gmsh scenes are not meshed), and the composite ply (composite_ply.prm:
# an orthotropic ply on an isotropic sheet) runs with its own settings:
# exit 0, and on the interface CSV of its last cycle the crack is partly
# open (nodes with [u].nu > 0) and partly closed (nodes in contact, mu_c > 0
# and |[u].nu| below 1e-6 of the largest opening).
# Usage: shipped_scenes.sh BILAYER PARAMETER_FILES
set -u
bilayer=$1 files=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0
count=0
for prm in "$files"/*.prm; do
  count=$((count + 1))
  "$bilayer" "$prm" --print-parameters > out.txt 2> err.txt
  rc=$?
  if [[ $rc -ne 0 || -s err.txt ]] || ! grep -q "subsection Materials" out.txt; then
    echo "$(basename "$prm"): --print-parameters exit $rc: $(head -1 err.txt)"
    fail=1
  fi
  rm -f out.txt err.txt
  left=$(ls -A)
  if [[ -n $left ]]; then
    echo "$(basename "$prm"): --print-parameters wrote $left"
    fail=1
    rm -rf -- ./*
  fi
done
echo "$count parameter files read"
"$bilayer" "$files/composite_ply.prm" --set "Output/Output directory=$work/ply" \
  --set "Output/Write VTU=false" > ply.log 2>&1
rc=$?
if [[ $rc -ne 0 ]]; then
  echo "composite_ply.prm: exit $rc: $(tail -1 ply.log)"
  fail=1
else
  python3 - "$work/ply" <<'PY' || fail=1
import csv, glob, sys
path = sorted(glob.glob(sys.argv[1] + "/interface-*.csv"))[-1]
rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
crack = [r for r in rows if r["on_crack"] == "1"]
jump = [float(r["jump_normal"]) for r in crack]
scale = max(jump)
opened = [r for r in crack if float(r["jump_normal"]) > 1e-3 * scale]
closed = [r for r in crack if float(r["mu_c"]) > 0 and abs(float(r["jump_normal"])) < 1e-6 * scale]
print("composite_ply: %d crack nodes, %d open, %d closed (%s), largest opening %.6g"
      % (len(crack), len(opened), len(closed), path.split("/")[-1], scale))
sys.exit(0 if opened and closed and len(opened) + len(closed) <= len(crack) else 1)
PY
fi
[[ $fail -eq 0 ]] && echo "shipped scenes: yes" || echo "shipped scenes: NO"
exit $fail
