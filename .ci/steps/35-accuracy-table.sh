#!/usr/bin/env bash
# The README's accuracy table on a fresh seed and a sample larger than the test's: every class,
# both modes, float and double, must stay within the published bounds of phong/accuracy.hpp
# (--bounds flags a row "ABOVE BOUND" and exits 1). Uses the Release build of step 10 (~30 s).
set -euo pipefail
cmake --preset gcc-release >/dev/null
cmake --build build/gcc-release --target phong_accuracy_table
out=$(mktemp)
if ! build/gcc-release/tests/phong_accuracy_table 20000 3 --bounds >"$out"; then
  grep "ABOVE BOUND" "$out"
  exit 1
fi
echo "accuracy table: every class within its published bound (20000 scenes per class, seed 3)"
