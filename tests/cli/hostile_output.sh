#!/usr/bin/env bash
# Output directories and the process under hostile and unlucky use. Classes
# (several members each):
#  1. copies, moves and forgeries of a bilayer output directory: bilayer
#     deletes only the very directory it made, and in it only the files it
#     wrote; backups beside it (DIR.old, DIR.failed.old) are never touched,
#     a copy (cp -r, cp -a, tar, rsync), a moved directory, a forged marker,
#     a marker listing foreign files or one of an earlier version without
#     identity is refused (exit 1, one line naming it) and left as it was;
#  2. the staging directory (or the working directory holding it) removed,
#     replaced or emptied during the run: exit 1 with one line, nothing
#     published, the user's files as they were;
#  3. pipes and signals: `| head -1`, stdout or stderr closed, SIGINT,
#     SIGTERM and SIGHUP mid-run (exit 128 + signal, one line, no staging
#     directory or lock left), SIGHUP ignored as by nohup;
#  4. the environment: DEAL_II_NUM_THREADS, OMP_NUM_THREADS, the BLAS's
#     thread counts, TMPDIR, a working directory longer than PATH_MAX:
#     refused with one line before MPI starts (one line under mpirun too).
# Usage: hostile_output.sh BILAYER PARAMETER_FILE (partial_closure.prm)
set -u
bilayer=$(realpath "$1")
prm=$(realpath "$2")
source "$(dirname "${BASH_SOURCE[0]}")/verdict.sh"
work=$(mktemp -d)
trap 'chmod -R u+w "$work" 2> /dev/null; rm -rf "$work"' EXIT
cd "$work" || exit 1
fast=(--set "Output/Progress interval=0" --set "Solver/Method=active set")
run() { # DIRECTORY [ARGS...]: a one-cycle run, stdout/stderr in DIRECTORY.out/.err
  local dir=$1
  shift
  "$bilayer" "$prm" "${fast[@]}" --set "Output/Output directory=$dir" "$@" > "$dir.out" 2> "$dir.err"
}
# A digest of every file under the given paths (names, contents).
digest() { find "$@" -type f -print0 2> /dev/null | sort -z | xargs -0 md5sum 2> /dev/null; }
# refused NAME DIR FRAGMENT: the last run into DIR exited 1 with one line naming FRAGMENT.
refused() {
  local why=""
  [[ $rc -eq 1 ]] || why="exit status $rc"
  [[ $(wc -l < "$2.err") -eq 1 ]] || why="$why; $(wc -l < "$2.err") lines on stderr: $(head -3 "$2.err")"
  grep -qF "bilayer: error: " "$2.err" || why="$why; no error line"
  grep -qF -- "$3" "$2.err" || why="$why; '$3' not named: $(cat "$2.err")"
  [[ ! -e $2.partial && ! -e $2.lock ]] || why="$why; staging or lock left"
  echo "$why"
}

# ---- 1. Copies, moves, forgeries.
run out || verdict "set-up run" "exit status $?"
cp -r out out.old && echo 'my note' > out.old/notes.txt
cp -r out out.failed.old
cp -a out out.bak
before=$(digest out.old out.failed.old out.bak)
run out
rc=$?
why=""
[[ $rc -eq 0 && -f out/summary.json ]] || why="exit status $rc"
[[ "$(digest out.old out.failed.old out.bak)" == "$before" ]] || why="$why; a backup changed or was deleted"
verdict "backups out.old, out.failed.old, out.bak kept by the next run" "$why"

# Copies of bilayer's directory under its name: never replaced.
copies=0
for how in "cp -r" "cp -a" tar rsync; do
  [[ $how == rsync ]] && ! command -v rsync > /dev/null && continue
  rm -rf c && mkdir c
  case $how in
    tar) (cd out && tar cf - .) | (mkdir -p c/out && cd c/out && tar xf -) ;;
    rsync) rsync -a out/ c/out/ ;;
    *) $how out c/out ;;
  esac
  before=$(digest c/out)
  run c/out
  rc=$?
  why=$(refused "$how" c/out "'c/out' is a copy of a bilayer output directory")
  [[ "$(digest c/out)" == "$before" && -d c/out ]] || why="$why; the copy changed"
  verdict "a copy by $how refused" "$why"
  copies=$((copies + 1))
done
# The original replaced by its copy (mv away, copy back).
mv out orig && cp -a orig out
before=$(digest out orig)
run out
rc=$?
why=$(refused "copy back" out "'out' is a copy of a bilayer output directory")
[[ "$(digest out orig)" == "$before" ]] || why="$why; changed"
verdict "a copy put back in place of the original refused" "$why"
run orig
rc=$?
why=$(refused "moved" orig "'orig' was moved or renamed (bilayer made it as '$work/out')")
[[ "$(digest out orig)" == "$before" ]] || why="$why; changed"
verdict "a moved directory refused" "$why"
rm -rf out && mv orig out

# Forged markers: hand-written, of an earlier version (no identity), with an
# identity that is the directory's own but lists a file of the user's, or
# claims the token in an extended attribute it does not have.
title="This directory was written by bilayer. A later run into it replaces it whole as long as it holds only the files listed here."
mkdir forged old_version own_id no_attr
echo '{"mine": 1}' > forged/summary.json
printf '%s\nfile: summary.json\n' "$title" > forged/.bilayer-output
cp out/summary.json out/table.txt old_version/
printf '%s\nfile: summary.json\nfile: table.txt\n' "$title" > old_version/.bilayer-output
echo 'mine' > own_id/notes.txt
printf '%s\nidentity: %s %s 0123456789abcdef0123456789abcdef file\ndirectory: %s\nfile: notes.txt\n' \
  "$title" "$(stat -c %d own_id)" "$(stat -c %i own_id)" "$work/own_id" > own_id/.bilayer-output
cp out/summary.json no_attr/
printf '%s\nidentity: %s %s 0123456789abcdef0123456789abcdef attribute\ndirectory: %s\nfile: summary.json\n' \
  "$title" "$(stat -c %d no_attr)" "$(stat -c %i no_attr)" "$work/no_attr" > no_attr/.bilayer-output
before=$(digest forged old_version own_id no_attr)
for case in "forged|'forged' was written by an earlier version of bilayer or by hand" \
  "old_version|'old_version' was written by an earlier version of bilayer or by hand" \
  "own_id|has a marker that lists 'notes.txt', which is no file bilayer writes" \
  "no_attr|'no_attr' is a copy of a bilayer output directory"; do
  dir=${case%%|*}
  run "$dir"
  rc=$?
  verdict "forged marker: $dir refused" "$(refused "$dir" "$dir" "${case#*|}")"
done
[[ "$(digest forged old_version own_id no_attr)" == "$before" ]] && verdict "forged directories unchanged" "" ||
  verdict "forged directories unchanged" "changed"

# Companions: a copy as DIR.failed or DIR.partial is not the run's.
for suffix in failed partial; do
  rm -rf comp comp.*
  run comp
  cp -r comp comp.$suffix
  before=$(digest comp comp.$suffix)
  run comp
  rc=$?
  why=""
  [[ $rc -eq 1 && $(wc -l < comp.err) -eq 1 ]] || why="exit status $rc, $(wc -l < comp.err) lines"
  grep -qF "'comp.$suffix' is a copy of a bilayer output directory" comp.err || why="$why; $(cat comp.err)"
  [[ "$(digest comp comp.$suffix)" == "$before" ]] || why="$why; changed"
  verdict "a copy as comp.$suffix refused" "$why"
done

# ---- 2. The staging directory changed during the run (5 cycles; the
# watcher acts once the records of cycles 0-2 are staged: table.csv, the
# last file of a cycle, has 4 lines; cycles 3 and 4 take seconds).
long=(--set "Mesh/Number of cycles=5")
staged() { # DIR.partial [PID]: wait until cycle 2's records are staged (while PID runs; at most 2 minutes)
  local lines
  for _ in $(seq 6000); do
    lines=$({ wc -l < "$1/table.csv"; } 2> /dev/null)
    [[ ${lines:-0} -ge 4 ]] && return 0
    [[ -n ${2:-} ]] && ! kill -0 "$2" 2> /dev/null && break
    sleep 0.02
  done
  echo "(the run never staged cycle 2 in $1)"
  return 1
}
midrun() { # NAME ACTION FRAGMENT: a run into out; ACTION (shell code) once cycle 2 is staged; FRAGMENT an extended regular expression
  local name=$1 action=$2 fragment=$3
  local before
  before=$(digest out)
  "$bilayer" "$prm" "${fast[@]}" "${long[@]}" --set "Output/Output directory=out" > mid.out 2> mid.err &
  local pid=$!
  staged out.partial $pid && eval "$action"
  wait $pid 2> /dev/null
  rc=$?
  local why=""
  [[ $rc -eq 1 || $rc -eq 2 ]] || why="exit status $rc"
  [[ $(wc -l < mid.err) -eq 1 ]] || why="$why; $(wc -l < mid.err) lines: $(head -3 mid.err)"
  grep -qE -- "$fragment" mid.err || why="$why; '$fragment' not named: $(cat mid.err)"
  [[ "$(digest out)" == "$before" ]] || why="$why; out changed"
  [[ ! -e out.lock ]] || why="$why; lock left"
  verdict "$name" "$why"
}
midrun "staging removed mid-run: exit 1, nothing published" "rm -rf out.partial" "was removed during the run"
[[ ! -e out.partial ]] && verdict "  and no staging re-created" "" || verdict "  and no staging re-created" "out.partial exists"
# Moved aside: the run writes on into the moved directory (its anchor) and
# then refuses; the files it wrote there are its own and go with it.
midrun "staging moved aside mid-run: exit 1, nothing published" "mv out.partial aside.partial" "was removed during the run"
[[ ! -e aside.partial && ! -e out.partial ]] && verdict "  and the moved staging removed with the run's files" "" ||
  verdict "  and the moved staging removed with the run's files" "left: $(ls -A aside.partial out.partial 2>&1 | head -3)"
rm -rf aside.partial
# (A file of the user's added, then moved aside: the directory is kept,
# said in a note. The file goes in first: added after the move, the run
# could have removed the directory in between.)
"$bilayer" "$prm" "${fast[@]}" "${long[@]}" --set "Output/Output directory=out" > mid.out 2> mid.err &
pid=$!
staged out.partial $pid && echo mine > out.partial/mine.txt && mv out.partial aside.partial
wait $pid 2> /dev/null
rc=$?
why=""
[[ $rc -eq 1 ]] || why="exit status $rc"
grep -q "^bilayer: error: .*during the run" mid.err || why="$why; no refusal: $(head -2 mid.err)"
grep -q "note: kept '.*': it holds 'mine.txt'" mid.err || why="$why; no note: $(head -2 mid.err)"
[[ $(ls -A aside.partial 2>&1) == mine.txt ]] || why="$why; left: $(ls -A aside.partial 2>&1 | head -3)"
verdict "staging moved aside mid-run, a file of the user's added: refused, only that file kept, a note" "$why"
rm -rf aside.partial
# (Between rm and mkdir the staging does not exist: a run that looks then
# finds it removed, also a refusal.)
midrun "staging replaced mid-run: refused, the user's directory kept" \
  "rm -rf out.partial && mkdir out.partial && echo mine > out.partial/mine.txt" \
  "was (replaced|removed) (from '[^']*' )?during the run"
[[ $(cat out.partial/mine.txt 2> /dev/null) == mine && $(ls -A out.partial | wc -l) -eq 1 ]] &&
  verdict "  and the user's out.partial untouched" "" || verdict "  and the user's out.partial untouched" "$(ls -A out.partial)"
rm -rf out.partial
midrun "used_parameters.prm removed from the staging mid-run" "rm -f out.partial/used_parameters.prm" \
  "'used_parameters.prm' was removed from"
midrun "an early cycle's file removed from the staging mid-run" "rm -f out.partial/interface-00.csv" \
  "'interface-00.csv' was removed from"
# A file added to out during the run: out is no longer what bilayer may
# replace; the commit refuses, the results stay in out.partial.
"$bilayer" "$prm" "${fast[@]}" "${long[@]}" --set "Output/Output directory=out" > mid.out 2> mid.err &
pid=$!
staged out.partial $pid && echo mine > out/added.txt
wait $pid
rc=$?
why=""
[[ $rc -eq 1 && $(wc -l < mid.err) -eq 1 ]] || why="exit status $rc; $(cat mid.err)"
grep -qF "holds files that bilayer did not write ('added.txt')" mid.err || why="$why; $(cat mid.err)"
[[ $(cat out/added.txt) == mine && -s out.partial/interface-04.csv && ! -e out.lock ]] || why="$why; files"
verdict "a file added to out during the run: the commit refuses, results kept in out.partial" "$why"
rm -f out/added.txt
run out || verdict "the next run removes the kept out.partial" "exit status $?"
[[ ! -e out.partial ]] || verdict "the next run removes the kept out.partial" "still there"

# The working directory (holding the staging directory) removed.
mkdir -p cwd && cp "$prm" cwd/scene.prm
(cd cwd && exec "$bilayer" scene.prm "${fast[@]}" "${long[@]}" --set "Output/Output directory=res" > ../cwd.out 2> ../cwd.err) &
pid=$!
staged cwd/res.partial $pid && rm -rf cwd
wait $pid
rc=$?
why=""
[[ $rc -eq 1 && $(wc -l < cwd.err) -eq 1 ]] || why="exit status $rc; $(cat cwd.err)"
# (rm -rf removes the files first: the run may see one of them go before
# the directory.)
grep -qE "was removed (from '[^']*' )?during the run" cwd.err || why="$why; $(cat cwd.err)"
[[ ! -e cwd ]] || why="$why; the working directory re-created"
verdict "working directory removed mid-run: exit 1, nothing re-created" "$why"

# ---- 3. Pipes and signals.
rm -rf p p.*
"$bilayer" "$prm" "${fast[@]}" --set "Mesh/Number of cycles=3" --set "Output/Output directory=p" 2> p.err | head -1 > p.head
rc=${PIPESTATUS[0]}
why=""
[[ $rc -eq 0 && -s p/summary.json && ! -e p.partial && ! -e p.lock ]] || why="exit status $rc; $(cat p.err)"
[[ $(wc -l < p.head) -eq 1 && ! -s p.err ]] || why="$why; $(wc -l < p.head) lines, stderr: $(cat p.err)"
verdict "| head -1: the run completes and commits (SIGPIPE ignored)" "$why"
rm -rf p p.*
"$bilayer" "$prm" "${fast[@]}" --set "Output/Output directory=p" 2> p.err >&-
rc=$?
[[ $rc -eq 0 && -s p/summary.json && ! -s p.err && ! -e p.partial ]] && verdict "stdout closed: the run completes" "" ||
  verdict "stdout closed: the run completes" "exit status $rc; $(cat p.err)"
rm -rf p p.*
"$bilayer" "$prm" "${fast[@]}" --set "Output/Output directory=p" > p.out 2>&-
rc=$?
[[ $rc -eq 0 && -s p/summary.json && ! -e p.partial ]] && grep -q "results are in p" p.out &&
  verdict "stderr closed: the run completes" "" || verdict "stderr closed: the run completes" "exit status $rc"
"$bilayer" "$prm" --set "Mesh/Cells along Sigmaa=5" --set "Output/Output directory=q" > p.out 2>&- <&-
rc=$?
[[ $rc -eq 1 && ! -e q && ! -s p.out ]] && verdict "stderr and stdin closed, bad input: exit 1, nothing written" "" ||
  verdict "stderr and stdin closed, bad input: exit 1, nothing written" "exit status $rc"

# Signals once cycle 2 is staged: one line, 128 + signal, nothing left.
set -m # (background jobs of their own, which do not ignore SIGINT)
for signal in INT TERM HUP; do
  before=$(digest out)
  "$bilayer" "$prm" "${fast[@]}" "${long[@]}" --set "Output/Output directory=out" > sig.out 2> sig.err &
  pid=$!
  staged out.partial $pid && kill -s $signal $pid
  wait $pid 2> /dev/null
  rc=$?
  why=""
  [[ $rc -eq $((128 + $(kill -l $signal))) ]] || why="exit status $rc"
  [[ $(wc -l < sig.err) -eq 1 ]] && grep -qF "bilayer: error: stopped by SIG$signal (removed '$work/out.partial' and '$work/out.lock'" sig.err ||
    why="$why; $(cat sig.err)"
  [[ -z $(compgen -G 'out.partial*'; compgen -G 'out.lock'; compgen -G 'out.replaced-*'; compgen -G 'out.stopped-*') ]] ||
    why="$why; left: $(ls -d out.*)"
  [[ "$(digest out)" == "$before" ]] || why="$why; out changed"
  verdict "SIG$signal mid-run: exit 128+signal, staging and lock removed" "$why"
done
set +m
# SIGHUP ignored at the start (nohup): the run goes on.
rm -rf h h.*
(trap '' HUP; exec "$bilayer" "$prm" "${fast[@]}" --set "Mesh/Number of cycles=4" --set "Output/Output directory=h" > h.out 2> h.err) &
pid=$!
staged h.partial $pid && kill -s HUP $pid
wait $pid
rc=$?
[[ $rc -eq 0 && -s h/interface-03.csv && ! -e h.partial ]] && verdict "SIGHUP ignored as by nohup: the run completes" "" ||
  verdict "SIGHUP ignored as by nohup: the run completes" "exit status $rc; $(cat h.err)"

# ---- 4. The environment.
env_refused() { # NAME FRAGMENT VAR=VALUE...
  local name=$1 fragment=$2
  shift 2
  rm -rf e e.*
  env "$@" "$bilayer" "$prm" --set "Output/Output directory=e" > e.out 2> e.err
  rc=$?
  local why
  why=$(refused "$name" e "$fragment")
  ! grep -qiE "terminate called|stacktrace|^-{5,}" e.err || why="$why; backtrace"
  [[ ! -e e && ! -s e.out ]] || why="$why; wrote"
  verdict "$name refused" "$why"
}
for value in 0 abc "" -2 1025 99999999999 "2 "; do
  env_refused "DEAL_II_NUM_THREADS='$value'" "DEAL_II_NUM_THREADS must be a whole number from 1 to 1024, got '$value'" \
    "DEAL_II_NUM_THREADS=$value"
done
env_refused "OMP_NUM_THREADS=abc" "OMP_NUM_THREADS must be a whole number from 1 to 1024 (or a comma-separated list of them), got 'abc'" OMP_NUM_THREADS=abc
env_refused "OMP_NUM_THREADS=2,0" "OMP_NUM_THREADS must be" OMP_NUM_THREADS=2,0
env_refused "OPENBLAS_NUM_THREADS=-1" "OPENBLAS_NUM_THREADS must be a whole number from 1 to 1024, got '-1'" OPENBLAS_NUM_THREADS=-1
env_refused "GOTO_NUM_THREADS=x" "GOTO_NUM_THREADS must be" GOTO_NUM_THREADS=x
: > afile
env_refused "TMPDIR a file" "TMPDIR = '$work/afile' is not a directory (MPI keeps its session files there)" TMPDIR="$work/afile"
env_refused "TMPDIR missing" "TMPDIR = '$work/missing' does not exist" TMPDIR="$work/missing"
[[ ! -e missing ]] || verdict "TMPDIR missing: not created" "created"
if [[ $(id -u) -ne 0 ]]; then
  mkdir -p ro && chmod 500 ro
  env_refused "TMPDIR not writable" "is a directory this user cannot write" TMPDIR="$work/ro"
fi
rm -rf e e.*
DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=2,1 OPENBLAS_NUM_THREADS=1 TMPDIR="$work" "$bilayer" "$prm" "${fast[@]}" \
  --set "Output/Output directory=e" > e.out 2> e.err
rc=$?
[[ $rc -eq 0 && -s e/summary.json ]] && verdict "valid thread counts and TMPDIR accepted" "" ||
  verdict "valid thread counts and TMPDIR accepted" "exit status $rc; $(cat e.err)"
# A working directory longer than PATH_MAX (4096).
deep=$work/deep
mkdir -p "$deep" && cd "$deep" || exit 1
name=$(printf 'd%.0s' $(seq 200))
for _ in $(seq 22); do mkdir "$name" && cd "$name" || exit 1; done
rm -rf "$work/e" "$work"/e.*
"$bilayer" "$prm" --set "Output/Output directory=$work/e" > "$work/e.out" 2> "$work/e.err"
rc=$?
cd "$work" || exit 1
verdict "working directory longer than PATH_MAX refused" \
  "$(refused "long" e "the working directory is longer than PATH_MAX = 4096 characters")"
rm -rf "$deep"
# Under mpirun: one line, from the first process.
if command -v mpirun > /dev/null; then
  rm -rf e e.*
  DEAL_II_NUM_THREADS=abc mpirun -np 2 "$bilayer" "$prm" --set "Output/Output directory=e" > e.out 2> e.err
  rc=$?
  # (mpirun adds its own note that a process returned a non-zero status.)
  why=""
  [[ $rc -eq 1 && $(grep -c '^bilayer' e.err) -eq 1 ]] || why="exit status $rc; $(grep -c '^bilayer' e.err) lines of bilayer"
  grep -qF "bilayer: error: DEAL_II_NUM_THREADS must be a whole number from 1 to 1024, got 'abc'" e.err || why="$why; $(head -2 e.err)"
  ! grep -qiE "terminate called|stacktrace" e.err || why="$why; backtrace"
  [[ ! -e e ]] || why="$why; wrote"
  verdict "DEAL_II_NUM_THREADS=abc under mpirun -np 2: one line of bilayer's" "$why"
fi

verdicts_end
