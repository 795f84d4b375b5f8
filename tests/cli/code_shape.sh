#!/usr/bin/env bash
# scripts/code_shape passes on the tree, and fails, naming the offence, on
# copies broken in each way it checks: an include of a higher layer, a
# header outside the layer folders, a function over 120 lines, a file over
# 700 lines and an include cycle.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
shape="$root/scripts/code_shape"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$shape" > "$work/out" || { cat "$work/out"; exit 1; }
grep -q "layers included downwards only, no include cycle" "$work/out"

fresh() {
  rm -rf "$work/tree"
  mkdir "$work/tree"
  cp -r "$root/include" "$root/source" "$work/tree/"
}

# expect_failure TEXT: code_shape on the copy exits 1 and prints TEXT.
expect_failure() {
  if python3 "$shape" --root "$work/tree" > "$work/out"; then
    echo "code_shape accepted a tree with: $1"
    exit 1
  fi
  grep -qF -- "$1" "$work/out" || { echo "expected '$1' in:"; cat "$work/out"; exit 1; }
}

fresh
python3 "$shape" --root "$work/tree" > /dev/null

fresh
sed -i '0,/#include/s//#include <bilayer\/drivers\/study.h>\n#include/' \
  "$work/tree/include/bilayer/core/layout.h"
expect_failure "core/layout.h includes bilayer/drivers/study.h (layer drivers above core)"

fresh
printf '#include <bilayer/core/layout.h>\n' > "$work/tree/include/bilayer/stray.h"
expect_failure "stray.h: in no layer folder"

fresh
{
  echo "int long_function()"
  echo "{"
  for i in $(seq 130); do echo "  int x$i = $i;"; done
  echo "  return 0;"
  echo "}"
} > "$work/tree/source/core/long.cc"
expect_failure "source/core/long.cc:2: long_function has 133 lines (more than 120)"

fresh
for i in $(seq 710); do echo "// line $i"; done > "$work/tree/source/core/big.cc"
expect_failure "source/core/big.cc: 710 lines (more than 700)"

fresh
printf '#include <bilayer/core/tasks.h>\n' >> "$work/tree/include/bilayer/core/progress.h"
printf '#include <bilayer/core/progress.h>\n' >> "$work/tree/include/bilayer/core/tasks.h"
expect_failure "include cycle: core/progress.h -> core/tasks.h -> core/progress.h"
echo "code_shape: every offence caught"
