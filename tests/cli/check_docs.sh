#!/usr/bin/env bash
# scripts/check_docs on copies of the docs in a temporary folder (--root;
# the repository's docs are never written): the quoted iteration count of
# scripts/run_examples as it is (OK, exit 0), altered by one (DRIFT with
# both numbers, exit 1) and removed (MISSING, exit 1); a timing without a
# machine and a date is one LINT line (exit 1), with them none; the test
# table of docs/developer.md without one of ctest's tests and with a test ctest does not
# know (DRIFT naming each).
# Usage: check_docs.sh BILAYER SOURCE_DIR BUILD_DIR. The exit status is the verdict.
set -u
bilayer=$1 source_dir=$2 build_dir=$3
source "$(dirname "${BASH_SOURCE[0]}")/verdict.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BILAYER=$bilayer
fresh() { rm -rf "$work/root" && mkdir -p "$work/root/docs" &&
  cp "$source_dir/README.md" "$work/root/" && cp "$source_dir"/docs/*.md "$work/root/docs/"; }
check() { python3 "$source_dir/scripts/check_docs" --root "$work/root" --build "$build_dir" "$@" \
  > "$work/log" 2> "$work/err"; }
claim=readme.run_examples.iterations_1
claim_doc=docs/scenes.md    # the doc that quotes it
table_doc=docs/developer.md # the doc with the test table

why=""
fresh
check --only $claim --no-lint || why="exit $?: $(cat "$work/log" "$work/err" | tail -3)"
grep -q "^$claim_doc:[0-9]*  $claim  quoted 373  measured 373  exact  OK$" "$work/log" \
  || why="$why; $(grep $claim "$work/log")"
verdict "the true count of the paper's Uzawa (373): OK, exit 0" "$why"

why=""
sed -i 's/it printed 373, 337 and 375 iterations/it printed 374, 337 and 375 iterations/' "$work/root/$claim_doc"
if check --only $claim --no-lint; then why="exit 0"; fi
grep -q "  $claim  quoted 374  measured 373  exact  DRIFT$" "$work/log" \
  || why="$why; $(grep $claim "$work/log")"
cmp -s "$source_dir/$claim_doc" "$work/root/$claim_doc" && why="$why; the copy was not altered"
verdict "an altered count (374): DRIFT with both numbers, exit 1" "$why"

why=""
sed -i 's/it printed 374, 337 and 375 iterations/it printed the iterations/' "$work/root/$claim_doc"
if check --only $claim --no-lint; then why="exit 0"; fi
grep -q "  $claim  quoted text not found in the doc .*MISSING$" "$work/log" \
  || why="$why; $(grep $claim "$work/log")"
verdict "the quoted text removed: MISSING, exit 1" "$why"

why=""
fresh
printf '\nThe sweep takes 42 s.\n' >> "$work/root/docs/geometry.md"
line=$(wc -l < "$work/root/docs/geometry.md")
if check --only $claim; then why="exit 0"; fi
grep -q "^docs/geometry.md:$line  lint  timing '42 s' .*LINT$" "$work/log" \
  || why="$why; $(grep lint "$work/log" | head -3)"
[[ $(grep -c "  LINT$" "$work/log") == 1 ]] || why="$why; $(grep -c "  LINT$" "$work/log") LINT lines"
verdict "a timing without machine and date: one LINT line, exit 1" "$why"

why=""
sed -i 's/^The sweep takes 42 s\.$/The sweep takes 42 s (2-core x86_64 VM, 2026-12-02)./' "$work/root/docs/geometry.md"
check --only $claim || why="exit $?: $(grep -v '  OK$' "$work/log" | head -3)"
verdict "the same timing with machine and date: no LINT line, exit 0" "$why"

why=""
fresh
check --only tests.table --no-lint || why="exit $?: $(grep -v '  OK$' "$work/log" | head -3)"
sed -i '/^| `theta_auto` |/d' "$work/root/$table_doc"
sed -i 's/^| `bad_input` |/| `bad_input`, `no_such_test` |/' "$work/root/$table_doc"
if check --only tests.table --no-lint; then why="$why; exit 0 without theta_auto"; fi
grep -q "tests.table  ctest knows theta_auto  the table does not  DRIFT$" "$work/log" \
  || why="$why; theta_auto not named: $(head -3 "$work/log")"
grep -q "tests.table  the table lists no_such_test  ctest does not know it  DRIFT$" "$work/log" \
  || why="$why; no_such_test not named: $(head -3 "$work/log")"
verdict "the test table: OK as it is, DRIFT naming a missing and an unknown test" "$why"

verdicts_end
