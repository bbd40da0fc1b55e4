#!/usr/bin/env bash
# The README's accuracy table on a fresh seed and a sample larger than the test's: every class,
# both modes (and both stable routes of float), float and double, must stay within the published
# bounds of phong/accuracy.hpp
# (--bounds flags a row "ABOVE BOUND" and exits 1). Uses the Release build of step 10 (~30 s).
# Then the same with FMA instructions enabled (GCC fuses products into sums under its default
# -ffp-contract=fast; the stable mode's error-free transformations must survive that).
set -euo pipefail
cmake --preset gcc-release >/dev/null
cmake --build build/gcc-release --target phong_accuracy_table phong_stable_p99
check() { # binary seed [--twofold]
  local out
  out=$(mktemp)
  if ! "$1" 20000 "$2" --bounds ${3:-} >"$out"; then
    grep "ABOVE BOUND" "$out"
    exit 1
  fi
  echo "accuracy table ($1 ${3:-}): every class within its published bound (20000 scenes per class, seed $2)"
}
check build/gcc-release/tests/phong_accuracy_table 3
check build/gcc-release/tests/phong_accuracy_table 5 --twofold # float's twofold route (GPU code, SIMD batches)
# The stable mode's shininess classes on a second generator family (tests/stable_p99.cpp, ~15 s).
build/gcc-release/tests/phong_stable_p99 20000 9
if grep -qw fma /proc/cpuinfo; then
  g++ -std=gnu++20 -O2 -mfma -DNDEBUG -DPHONG_HAVE_QUADMATH=1 -Iinclude -Itests tests/accuracy_table.cpp \
      -o build/phong_accuracy_table_fma -lquadmath
  check build/phong_accuracy_table_fma 4
  check build/phong_accuracy_table_fma 6 --twofold
fi
# The exact mode's derived bound (accuracy::exact_bound, docs/accuracy.md): the independent
# generator family and the project's classes, every channel within the bound evaluated at its own
# conditioning, in two of tests/bounds_matrix.sh's twelve builds, those where the compilers
# contract into FMA differently (~1 min: one translation unit each).
if grep -qw fma /proc/cpuinfo; then
  tests/bounds_matrix.sh 20000 8 clang++:-O1:-march=native g++:-O3:-march=native
else
  tests/bounds_matrix.sh 20000 8 clang++:-O1: g++:-O3:
fi
