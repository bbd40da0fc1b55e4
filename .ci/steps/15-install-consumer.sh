#!/usr/bin/env bash
# Packaging proof (issue 2): install phong to a temporary prefix with `cmake --install`, then build
# the separate project tests/consumer against it (find_package(phong CONFIG REQUIRED) +
# phong::phong) with CMAKE_PREFIX_PATH, with g++ and clang++, and run it.
set -euo pipefail
root="$PWD"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cmake -S "$root" -B "$tmp/build" -G Ninja -DPHONG_BUILD_TESTS=OFF -DPHONG_BUILD_BENCHMARKS=OFF >/dev/null
cmake --install "$tmp/build" --prefix "$tmp/prefix"
for cxx in g++ clang++; do
  cmake -S "$root/tests/consumer" -B "$tmp/consumer-$cxx" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror"
  grep -q "phong_DIR:PATH=$tmp/prefix/" "$tmp/consumer-$cxx/CMakeCache.txt" # found the installed copy
  cmake --build "$tmp/consumer-$cxx"
  "$tmp/consumer-$cxx/consumer"
done
