#!/usr/bin/env bash
# The output contract of growth runs (Fracture/Crack growth), as for static
# runs (docs/robustness.md, "Growth runs"):
#  1. every file a growth run writes is its own: a growth scene (quasi-static
#     and sweep) runs twice into one directory, exit 0 both times; a failed
#     growth run's DIR.failed does not block the corrected run (its message
#     says that Maximum growth steps came before the load factors were
#     done); a mode split length below the tip's cell is raised to the
#     cell, with the length used in summary.json;
#  2. SIGINT, SIGTERM and SIGHUP during the steps: exit 128 + signal, one
#     line, no staging directory, lock or stopped copy left, DIR as it was;
#     SIGKILL: the stale staging directory and lock do not block the next
#     run, which removes them; a full file system (a 2 MiB tmpfs, where this
#     machine lets the test mount one): one line, exit 1, the directory as it
#     was, then a run elsewhere exit 0; a file system out of inodes (4): one
#     line, nothing left;
#     the steps are named as steps in the terminal (also with Terminal
#     output = checks) and their .pvd time is the load factor (or, as
#     asked, the crack length);
#  3. growth output costs O(1) per step: the bytes the process writes
#     (wchar of /proc/self/io, which counts a reaped child's writes) grow
#     by the same amount per step from 20 to 40 to 80 steps (within 3 %),
#     as they must when no file is rewritten whole after every step.
# Usage: growth_outputs.sh BILAYER PARAMETER_DIRECTORY
set -u
bilayer=$(realpath "$1")
scenes=$(realpath "$2")
prm=$scenes/growth_full_opening.prm
source "$(dirname "${BASH_SOURCE[0]}")/verdict.sh"
work=$(mktemp -d)
cleanup() {
  mountpoint -q "$work/small" 2> /dev/null && umount "$work/small"
  mountpoint -q "$work/tiny" 2> /dev/null && umount "$work/tiny"
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work" || exit 1
digest() { find "$@" -type f -print0 2> /dev/null | sort -z | xargs -0 md5sum 2> /dev/null; }
left() { # DIR: what a run left beside DIR
  compgen -G "$1.partial*"
  compgen -G "$1.lock"
  compgen -G "$1.replaced-*"
  compgen -G "$1.stopped-*"
}
# Many steps below the onset (about 2.06), each with its files.
long=(--set "Loads/Load factor=0.001:0.001:1.5" --set "Output/Written steps=every 1"
  --set "Output/Write interface CSV=true" --set "Fracture/Maximum growth steps=5000")

# ---- 1. Reruns into the run's own directory.
for scene in growth_full_opening growth_weak_patch dcb_growth; do
  why=""
  for k in 1 2; do
    "$bilayer" "$scenes/$scene.prm" --set "Output/Output directory=g" --set "Output/Write VTU=false" \
      > g.out 2> g.err || why="$why; run $k: exit $? $(head -2 g.err)"
  done
  [[ -z $(left g) && -s g/growth.csv ]] || why="$why; left: $(left g)"
  verdict "$scene twice into one directory: exit 0 both" "$why"
  rm -rf g
done
why=""
for k in 1 2; do
  "$bilayer" "$prm" --set "Output/Output directory=s" --set "Fracture/Crack growth=sweep" \
    --set "Loads/Load factor=1" > s.out 2> s.err || why="$why; run $k: exit $? $(head -2 s.err)"
done
verdict "Crack growth = sweep twice into one directory: exit 0 both" "$why"
"$bilayer" "$prm" --set "Output/Output directory=f" --set "Fracture/Maximum growth steps=3" > f.out 2> f.err
rc=$?
why=""
[[ $rc -eq 2 && -s f.failed/growth.csv && -s f.failed/summary.json ]] || why="exit $rc, $(ls f.failed 2> /dev/null | tr '\n' ' ')"
# (Steps 0-2 are load steps below the onset: the message says the limit came
# before the load factors were done, not that the crack still grows.)
grep -qF "Fracture/Maximum growth steps = 3 steps reached before the load factors are done (the next: 2)" f.err ||
  why="$why; message: $(cat f.err)"
"$bilayer" "$prm" --set "Output/Output directory=f" > f.out 2> f.err || why="$why; the corrected run: exit $? $(cat f.err)"
[[ -s f/growth.csv && ! -e f.failed ]] || why="$why; f.failed kept or f missing"
verdict "a failed growth run's DIR.failed, then the corrected run: exit 0, DIR.failed gone" "$why"

# Steps named as growth: growth_full_opening.prm (Terminal output = checks)
# prints "step K: load factor L ..." for every row of growth.csv and the
# closing "growth: N steps" line; the time of each step in solution.pvd and
# interface.pvd is its load factor (growth.csv), with Output/Time of growth
# steps = crack length its crack length.
why=""
for time in "load factor" "crack length"; do
  rm -rf t
  "$bilayer" "$prm" --set "Output/Output directory=t" --set "Output/Write VTU=true" \
    --set "Output/Time of growth steps=$time" > t.out 2> t.err || why="$why; $time: exit $?"
  why="$why$(/usr/bin/python3 - t "$time" t.out <<'PY'
import csv, re, sys
d, time, log = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
rows = list(csv.DictReader(l for l in open(d + "/growth.csv") if not l.startswith("#")))
key = "load_factor" if time == "load factor" else "crack_length"
out = []
printed = {int(k): float(v) for k, v in re.findall(r"^step (\d+): load factor (\S+) ", log, re.M)}
for r in rows:
    k, lam = int(r["step"]), float(r["load_factor"])
    if k not in printed or abs(printed[k] - lam) > 1e-7 * abs(lam):
        out.append("no line 'step %d: load factor %.8g ...'" % (k, lam))
if not re.search(r"^growth: %d steps" % len(rows), log, re.M):
    out.append("no closing line 'growth: %d steps'" % len(rows))
for pvd, stem in (("solution.pvd", "solution"), ("interface.pvd", "interface")):
    times = re.findall(r'timestep="([^"]+)"[^>]*file="%s-(\d+)\.' % stem, open(d + "/" + pvd).read())
    if not times:
        out.append("%s: no steps" % pvd)
    for t, n in times:
        if abs(float(t) - float(rows[int(n)][key])) > 1e-9 * max(1, abs(float(t))):
            out.append("%s: step %s at time %s, %s %s" % (pvd, n, t, key, rows[int(n)][key]))
print("".join("; %s: %s" % (time, o) for o in out[:3]), end="")
PY
)"
done
verdict "growth steps named as steps (also with Terminal output = checks), .pvd time = load factor or crack length" "$why"
rm -rf t

# A mode split length below the tip's cell is raised to the cell, and the
# records carry the length used (summary.json mode_split_length and note).
"$bilayer" "$scenes/partial_closure.prm" --set "Output/Output directory=m" --set "Output/Write VTU=false" \
  --set "Mesh/Number of cycles=1" --set "Fracture/Mode split length=1e-3" > m.out 2> m.err
rc=$?
why=$(/usr/bin/python3 -c "
import json
tips = json.load(open('m/summary.json'))['cycles'][-1]['crack_tips']
bad = [t for t in tips if not (t['mode_split_length'] > 1e-3 and 'is below the tip cell' in t['mode_split_note']
                               and ('computed over %g' % t['mode_split_length']) in t['mode_split_note'])]
print('%d of %d tips: %s' % (len(bad), len(tips), bad[:1]) if bad or not tips else '')
" 2>&1)
[[ $rc -eq 0 ]] || why="exit $rc; $why"
verdict "a mode split length below the cell: raised to the cell, the length used recorded" "$why"

# ---- 2. Signals and a full disk during the steps.
"$bilayer" "$prm" --set "Output/Output directory=out" > out.log 2>&1 || verdict "set-up run" "exit $?"
steps_staged() { # PID: wait until the run has appended 30 rows to growth.csv (at most 2 minutes)
  for _ in $(seq 6000); do
    [[ $({ wc -l < out.partial/growth.csv; } 2> /dev/null || echo 0) -ge 34 ]] && return 0
    kill -0 "$1" 2> /dev/null || break
    sleep 0.02
  done
  return 1
}
set -m # (background jobs of their own, which do not ignore SIGINT)
for signal in INT TERM HUP; do
  before=$(digest out)
  "$bilayer" "$prm" "${long[@]}" --set "Output/Output directory=out" > sig.out 2> sig.err &
  pid=$!
  why=""
  steps_staged $pid || why="never staged 30 steps"
  kill -s $signal $pid
  wait $pid 2> /dev/null
  rc=$?
  [[ $rc -eq $((128 + $(kill -l $signal))) ]] || why="$why; exit status $rc"
  [[ $(wc -l < sig.err) -eq 1 ]] && grep -qF "bilayer: error: stopped by SIG$signal" sig.err ||
    why="$why; stderr: $(head -3 sig.err)"
  [[ -z $(left out) ]] || why="$why; left: $(left out | tr '\n' ' ')"
  [[ "$(digest out)" == "$before" ]] || why="$why; out changed"
  verdict "SIG$signal during growth steps: exit 128+signal, one line, nothing left" "$why"
done
"$bilayer" "$prm" "${long[@]}" --set "Output/Output directory=out" > sig.out 2> sig.err &
pid=$!
steps_staged $pid
kill -s KILL $pid
wait $pid 2> /dev/null
set +m
stale=$(left out | tr '\n' ' ')
"$bilayer" "$prm" --set "Output/Output directory=out" > k.out 2> k.err
rc=$?
why=""
[[ -n $stale ]] || why="(SIGKILL left nothing to clean)"
[[ $rc -eq 0 && -z $(left out) ]] || why="$why; exit $rc, $(cat k.err); left: $(left out | tr '\n' ' ')"
verdict "SIGKILL during growth steps, then a run: exit 0, the stale $stale removed" "$why"

mkdir small
if mount -t tmpfs -o size=2m tmpfs small 2> /dev/null; then
  mkdir small/keep && echo "a note" > small/keep/note
  before=$(digest small)
  "$bilayer" "$prm" "${long[@]}" --set "Output/Output directory=small/keep/out" > full.out 2> full.err
  rc=$?
  why=""
  [[ $rc -eq 1 && $(wc -l < full.err) -eq 1 ]] && grep -q "No space left on device" full.err ||
    why="exit $rc, $(head -3 full.err)"
  [[ "$(digest small)" == "$before" && -z $(ls -A small/keep | grep -v '^note$') ]] ||
    why="$why; left: $(ls -A small/keep | tr '\n' ' ')"
  "$bilayer" "$prm" --set "Output/Output directory=small/keep/out" > full.out 2> full.err ||
    why="$why; the next run: exit $? $(cat full.err)"
  verdict "a full file system during growth steps: one line, the directory as it was, the next run exit 0" "$why"
  # A file system out of inodes: the staging directory is made, its marker
  # is not; the run still removes what it made.
  mkdir tiny
  if mount -t tmpfs -o size=2m,nr_inodes=4 tmpfs tiny 2> /dev/null; then
    mkdir tiny/keep
    before=$(find tiny | sort)
    "$bilayer" "$prm" --set "Output/Output directory=tiny/out" > inode.out 2> inode.err
    rc=$?
    why=""
    [[ $rc -eq 1 && $(wc -l < inode.err) -eq 1 ]] || why="exit $rc, $(head -3 inode.err)"
    [[ "$(find tiny | sort)" == "$before" ]] || why="$why; left: $(ls -A tiny | tr '\n' ' ')"
    umount tiny
    verdict "a file system out of inodes: one line, nothing left" "$why"
  fi
else
  echo "(a full file system: no tmpfs can be mounted here; docs/robustness.md, scripts/fuzz_inputs)"
fi

# ---- 3. Bytes written per step.
measure() { # STEPS: the bytes written by a run of STEPS steps
  /usr/bin/python3 - "$bilayer" "$prm" "$1" << 'EOF'
import subprocess, sys
def wchar():
    for line in open("/proc/self/io"):
        key, value = line.split(":")
        if key == "wchar":
            return int(value)
bilayer, prm, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
before = wchar()
r = subprocess.run([bilayer, prm, "--set", "Output/Output directory=b%d" % n,
                    "--set", "Loads/Load factor=0.001:0.001:%g" % (0.001 * n),
                    "--set", "Output/Written steps=every 1",
                    "--set", "Output/Write interface CSV=true"],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(wchar() - before if r.returncode == 0 else -1)
EOF
}
b20=$(measure 20)
b40=$(measure 40)
b80=$(measure 80)
why=$(/usr/bin/python3 -c "
b20, b40, b80 = $b20, $b40, $b80
if min(b20, b40, b80) <= 0:
    print('a run failed')
else:
    first, second = (b40 - b20) / 20, (b80 - b40) / 40
    print('' if abs(second / first - 1) <= 0.03 else
          'bytes per step %.0f (20-40) then %.0f (40-80)' % (first, second))
")
echo "bytes written: 20 steps $b20, 40 steps $b40, 80 steps $b80"
verdict "growth output: the same bytes per step from 20 to 80 steps" "$why"
verdicts_end
