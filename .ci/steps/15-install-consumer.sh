#!/usr/bin/env bash
# Packaging proof (issue 2): install phong to a temporary prefix with `cmake --install`, then build
# the separate project tests/consumer against it (find_package(phong CONFIG REQUIRED) +
# phong::phong) with CMAKE_PREFIX_PATH, with g++ and clang++, and run it.
# Its batch_user_O1 / batch_user_O3 are a renderer's translation unit calling shade_batch with
# -march=native and -Wall -Wextra -Wpedantic -Werror, phong's headers not treated as system headers
# (issue 13: warning-free in users' builds); built once more with -DPHONG_USE_XSIMD=OFF (g++), which
# must reach the code as PHONG_NO_XSIMD (batch_user static_asserts it).
set -euo pipefail
root="$PWD"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cmake -S "$root" -B "$tmp/build" -G Ninja -DPHONG_BUILD_TESTS=OFF -DPHONG_BUILD_BENCHMARKS=OFF >/dev/null
cmake --install "$tmp/build" --prefix "$tmp/prefix"
consumer() { # consumer <name> <compiler> [extra cmake args]
  local name="$1" cxx="$2"
  shift 2
  cmake -S "$root/tests/consumer" -B "$tmp/$name" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror" "$@"
  grep -q "phong_DIR:PATH=$tmp/prefix/" "$tmp/$name/CMakeCache.txt" # found the installed copy
  cmake --build "$tmp/$name" -j2
  "$tmp/$name/consumer"
  "$tmp/$name/batch_user_O1"
  "$tmp/$name/batch_user_O3"
}
for cxx in g++ clang++; do
  consumer "consumer-$cxx" "$cxx"
done
consumer consumer-no-xsimd g++ -DPHONG_USE_XSIMD=OFF
