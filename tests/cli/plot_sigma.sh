#!/usr/bin/env bash
# scripts/plot_sigma on a result of bilayer: a PNG and a PDF of the fields
# along Sigma of the last cycle, then of every cycle; the result directory
# is only read; a folder of the user is refused and left as it is; a
# directory without interface CSV files is refused with one line; a foreign
# interface CSV (no on_crack column), --cycle -1 and an --output inside DIR
# are refused with one line (exit 1, 2, 1), no traceback, nothing written.
# What is drawn follows the rules of the script's docstring, recomputed by
# plot_sigma_rules.py from the result itself: the units of summary.json (or
# [length], [stress]) on every axis, values below the solver's accuracy
# drawn as 0, the traction panels clipped near an open tip with a note; on
# the run, and on an edited copy of it with units (mm, MPa), a spike at the
# open tip (clipped), a slip just below and one just above the tolerance,
# and a cycle whose crack is closed everywhere (not clipped).
# Usage: plot_sigma.sh BILAYER SCRIPTS_DIR PRM. The exit status is the verdict.
set -u
bilayer=$1 scripts=$2 prm=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/verdict.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export BILAYER=$bilayer
"$bilayer" "$prm" --set "Mesh/Number of cycles=2" --set "Solver/Method=active set" \
  --set "Output/Write VTU=false" --set "Output/Output directory=run" > /dev/null 2>&1
before=$(cd run && ls -lA --time-style=full-iso | md5sum)

why=""
python3 "$scripts/plot_sigma" run --output plots > log 2> err || why="exit $?: $(cat err)"
[[ -s plots/sigma-01.png && -s plots/sigma-01.pdf ]] || why="$why; no sigma-01.png/.pdf"
[[ -s plots/sigma-01.gp && -s plots/sigma-01.dat ]] || why="$why; no sigma-01.gp/.dat beside them"
[[ ! -e plots/sigma-00.png ]] || why="$why; cycle 0 plotted without --all"
verdict "the last cycle, PNG and PDF, the script and the data drawn" "$why"

why=""
python3 "$scripts/plot_sigma" run --all --output plots > log 2> err || why="exit $?: $(cat err)"
[[ -s plots/sigma-00.png && -s plots/sigma-00.pdf ]] || why="$why; no sigma-00.png/.pdf"
verdict "every cycle with --all, into its own earlier folder" "$why"

why=""
[[ $(cd run && ls -lA --time-style=full-iso | md5sum) == "$before" ]] || why="the result directory changed"
verdict "the result directory only read" "$why"

rules() { # NAME RESULT CYCLE OUT [clipped|unclipped]
  local why=""
  python3 "$here/plot_sigma_rules.py" "${@:2}" > rules.log 2>&1 ||
    why="exit $?: $(grep -a ": NO\|Error\|rror" rules.log | head -4 | tr '\n' ';')"
  verdict "$1" "$why"
  [[ -z $why ]] || cat rules.log
}
rules "the run, cycle 0: units, noise as 0, clipping by the rules" run 0 plots
rules "the run, cycle 1: units, noise as 0, clipping by the rules" run 1 plots

# The edited copy: units in summary.json; in cycle 1 a traction spike at
# the open tip and two slips on either side of the tolerance rho * U; in
# cycle 0 no opening anywhere (every tip closed).
cp -r run edited
python3 - edited << 'PY' > slips || echo "editing the copy failed"
import csv, json, re, sys
d = sys.argv[1]
summary = json.load(open(d + "/summary.json"))
summary["units"] = {"system": "mm, MPa", "length": "mm", "stress": "MPa", "force": "N/mm",
                    "energy_release_rate": "N/mm", "energy": "N"}
json.dump(summary, open(d + "/summary.json", "w"))
rho = max(float(re.search(r"set Acceptance tolerance\s*=\s*(\S+)",
                          open(d + "/used_parameters.prm").read()).group(1)), 1e-12)
def edit(cycle, change):
    path = "%s/interface-%02d.csv" % (d, cycle)
    lines = open(path).read().splitlines()
    notes = [l for l in lines if l.startswith("#")]
    rows = list(csv.DictReader(l for l in lines if not l.startswith("#")))
    change(rows, [c for c in summary["cycles"] if c["cycle"] == cycle][0])
    with open(path, "w") as f:
        f.write("\n".join(notes) + "\n")
        w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
def spike(rows, record):
    tips = [float(m.group(1)) for m in (re.match(r"# crack tip \d+ at x = ([^,:]+)", l)
            for l in open("%s/interface-01.csv" % d)) if m]
    crack = [r for r in rows if r["on_crack"] == "1"]
    tip = [t for t in tips if float(min(crack, key=lambda r: abs(float(r["s"]) - t))["jump_normal"]) > 0][0]
    at = min(rows, key=lambda r: abs(float(r["s"]) - tip))
    largest = max(abs(float(r[c])) for r in rows for c in ("normal_traction", "mu_g_y"))
    at["normal_traction"] = at["mu_g_y"] = "%.12g" % (-50 * largest)
    glued = [r for r in rows if r["on_crack"] == "0" and all(abs(float(r["s"]) - t) > 0.2 for t in tips)]
    tol = rho * record["displacement_scale"]
    glued[0]["jump_tangential"], glued[-1]["jump_tangential"] = "%.12g" % (0.5 * tol), "%.12g" % (2 * tol)
    print(glued[0]["s"], glued[-1]["s"], "%.12g" % (2 * tol))
def closed(rows, record):
    for r in rows:
        r["jump_normal"] = "0"
edit(1, spike)
edit(0, closed)
PY
why=""
python3 "$scripts/plot_sigma" edited --all --output plots-edited > log 2> err || why="exit $?: $(cat err)"
verdict "the edited copy plotted" "$why"
rules "the edited copy, cycle 1: [mm], [MPa], the spike at the open tip clipped" edited 1 plots-edited clipped
rules "the edited copy, cycle 0: every tip closed, nothing clipped" edited 0 plots-edited unclipped
why=""
read -r below above twice < slips
awk -v below="$below" -v above="$above" -v twice="$twice" '
  /^# s / { for (i = 2; i <= NF; i++) col[$i] = i - 1 }
  !/^#/ && $1 == below { b = $col["jump_tangential"] }
  !/^#/ && $1 == above { a = $col["jump_tangential"] }
  END { exit !(b == 0 && a == twice) }' plots-edited/sigma-01.dat ||
  why="the slips 0.5 and 2 times the tolerance are not drawn as 0 and as themselves"
verdict "a slip below the tolerance drawn as 0, one above it as it is" "$why"

why=""
mkdir mine && echo x > mine/notes
if python3 "$scripts/plot_sigma" run --output mine > log 2> err; then why="accepted"; fi
[[ $(ls -A mine) == notes ]] || why="$why; the folder changed: $(ls -A mine | tr '\n' ' ')"
grep -q "mine holds 'notes'" err || why="$why; message: $(cat err)"
verdict "a folder of the user refused and left as it is" "$why"

why=""
mkdir empty
if python3 "$scripts/plot_sigma" empty --output p2 > log 2> err; then why="accepted"; fi
[[ $(wc -l < err) -eq 1 ]] || why="$why; $(wc -l < err) lines on stderr"
grep -q "holds no interface-NN.csv" err || why="$why; message: $(cat err)"
verdict "a directory without interface CSV files refused with one line" "$why"

why=""
mkdir foreign && printf 's,jump_normal\n0,1\n' > foreign/interface-00.csv
for c in "1 foreign --output p3" "2 run --cycle -1 --output p4" "1 run --output run/plots"; do
  set -- $c
  rc=$1
  shift
  python3 "$scripts/plot_sigma" "$@" > log 2> err
  got=$?
  [[ $got -eq $rc && $(grep -c . err) -eq 1 ]] || why="$why; $*: exit $got, $(grep -c . err) lines"
  ! grep -q "Traceback" err || why="$why; $*: a traceback"
done
[[ ! -e p3 && ! -e p4 && ! -e run/plots ]] || why="$why; an output folder was made"
verdict "a foreign CSV, --cycle -1, --output inside DIR: one line each, nothing written" "$why"

verdicts_end
