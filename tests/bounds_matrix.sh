#!/usr/bin/env bash
# The exact mode's derived bound (tests/exact_bound.cpp) in 12 builds: g++ and clang++, -O1, -O2
# and -O3, each with and without -march=native (FMA contraction: g++ contracts a * b + c under its
# default -ffp-contract=fast whenever the target has FMA; clang++ 14 contracts within expressions).
# Each build directory configures the project once and builds only phong_exact_bound (one
# translation unit), so the matrix costs 12 compiles.
#
#   tests/bounds_matrix.sh [scenes = 20000] [seed = 1] [build...]
# build: compiler:optimization[:-march=native], e.g. clang++:-O1:-march=native (CI step 35 runs
# two); a bare compiler name runs its six builds; none: all twelve.
# Each build runs shade<F> and then shade_batch (--batch: the SIMD lanes of the build's ISA).
# Prints one summary line per build and route (the largest measured/bound ratio); exits 1 if any build fails
# to compile warning-free or any channel is above its bound.
set -euo pipefail
cd "$(dirname "$0")/.."
scenes=${1:-20000}
seed=${2:-1}
shift $(( $# < 2 ? $# : 2 ))
specs=()
for arg in "$@"; do
  case "$arg" in
    *:*) specs+=("$arg") ;;
    *) for opt in -O1 -O2 -O3; do specs+=("$arg:$opt:" "$arg:$opt:-march=native"); done ;;
  esac
done
if [ ${#specs[@]} -eq 0 ]; then
  for cxx in g++ clang++; do for opt in -O1 -O2 -O3; do specs+=("$cxx:$opt:" "$cxx:$opt:-march=native"); done; done
fi
status=0
for spec in "${specs[@]}"; do
  IFS=: read -r cxx opt arch <<<"$spec"
  name="matrix-${cxx%++}${opt}${arch:+-native}"
  dir="build/$name"
  if [ ! -f "$dir/build.ninja" ]; then
    cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
      -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror" \
      -DCMAKE_CXX_FLAGS_RELEASE="$opt -DNDEBUG $arch" -DPHONG_BUILD_BENCHMARKS=OFF >/dev/null
  fi
  if ! cmake --build "$dir" --target phong_exact_bound -j 1 >"$dir/build.log" 2>&1; then
    echo "$name: BUILD FAILED (see $dir/build.log)"
    tail -n 20 "$dir/build.log"
    status=1
    continue
  fi
  for route in "" --batch; do # shade<F>, then shade_batch's SIMD lanes
    out="$dir/exact_bound${route}.txt"
    if "$dir/tests/phong_exact_bound" $route "$scenes" "$seed" >"$out"; then
      echo "$name ${route:-scalar}: $(tail -n 1 "$out")"
    else
      echo "$name ${route:-scalar}: FAILED: $(tail -n 1 "$out")"
      grep FAIL "$out" | head -n 5
      status=1
    fi
  done
done
exit $status
