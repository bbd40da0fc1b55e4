#!/usr/bin/env bash
# The README's user instructions, tested (issue 2's packaging proof, issue 13's README): first check
# that tests/consumer/CMakeLists.txt and main.cpp are exactly the README's blocks marked
# "<!-- tests/consumer/<file>: ... -->"; then install phong to a temporary prefix with the README's
# install command, and build the separate project tests/consumer against it
# (find_package(phong CONFIG REQUIRED) + phong::phong) with CMAKE_PREFIX_PATH, with g++ and
# clang++, and run it. Then tests/consumer_batch: a renderer's translation unit calling shade_batch
# with -march=native and -Wall -Wextra -Wpedantic -Werror, phong's headers not treated as system
# headers (issue 13: warning-free in users' builds), at -O1 and -O3 (and -O3 without -march=native), with g++ and clang++; built once
# more with -DPHONG_USE_XSIMD=OFF (g++, -O3 only), which must reach the code as PHONG_NO_XSIMD.
# Issue 27: consumers with cmake_minimum_required(2.8.12) and (3.5) (tests/consumer_old), and a
# Meson consumer through the installed pkg-config file (tests/consumer_meson).
set -euo pipefail
root="$PWD"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
readme_block() { # the fenced block that follows the line "<!-- $1: ..."
  awk -v key="<!-- $1:" 'index($0, key) == 1 { f = 1; next } f == 1 && /^```/ { f = 2; next }
                         f == 2 && /^```$/ { exit } f == 2 { print }' "$root/README.md"
}
for f in CMakeLists.txt main.cpp; do
  readme_block "tests/consumer/$f" >"$tmp/readme_$f"
  [[ -s "$tmp/readme_$f" ]] || { echo "15-install-consumer: README.md has no block marked tests/consumer/$f"; exit 1; }
  diff -u "$tmp/readme_$f" "$root/tests/consumer/$f" ||
    { echo "15-install-consumer: tests/consumer/$f differs from README.md's block (above)"; exit 1; }
done
echo "15-install-consumer: tests/consumer/{CMakeLists.txt,main.cpp} are the README's blocks"
# The README's install command, into the temporary prefix.
(cd "$tmp" && cmake -S "$root" -B build -G Ninja -DPHONG_BUILD_TESTS=OFF -DPHONG_BUILD_BENCHMARKS=OFF >/dev/null &&
  cmake --install build --prefix "$tmp/prefix")
for cxx in g++ clang++; do
  cmake -S "$root/tests/consumer" -B "$tmp/consumer-$cxx" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror"
  grep -q "phong_DIR:PATH=$tmp/prefix/" "$tmp/consumer-$cxx/CMakeCache.txt" # found the installed copy
  cmake --build "$tmp/consumer-$cxx"
  "$tmp/consumer-$cxx/app"
done
# An old cmake_minimum_required (2.8.12, 3.5): phongConfig.cmake sets the policies it needs itself.
for min in 2.8.12 3.5; do
  mkdir -p "$tmp/old-src-$min"
  sed "s/@MIN@/$min/" "$root/tests/consumer_old/CMakeLists.txt.in" >"$tmp/old-src-$min/CMakeLists.txt"
  cp "$root/tests/consumer/main.cpp" "$tmp/old-src-$min/"
  cmake -S "$tmp/old-src-$min" -B "$tmp/old-$min" -G Ninja -Wno-deprecated -DCMAKE_PREFIX_PATH="$tmp/prefix" \
    -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror" >/dev/null
  cmake --build "$tmp/old-$min" >/dev/null
  "$tmp/old-$min/old_app"
  echo "15-install-consumer: a consumer with cmake_minimum_required($min) built and ran"
done
# pkg-config and Meson: the installed share/pkgconfig/phong.pc.
export PKG_CONFIG_PATH="$tmp/prefix/share/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
pkg-config --cflags phong
meson setup "$tmp/meson" "$root/tests/consumer_meson" >/dev/null
meson test -C "$tmp/meson" --print-errorlogs
echo "15-install-consumer: a Meson consumer found phong through pkg-config, built and ran"
batch_user() { # batch_user <name> <compiler> <levels> [extra cmake args]
  local name="$1" cxx="$2" levels="$3" level
  shift 3
  cmake -S "$root/tests/consumer_batch" -B "$tmp/$name" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror" \
    -DPHONG_CONSUMER_LEVELS="$levels" "$@"
  grep -q "phong_DIR:PATH=$tmp/prefix/" "$tmp/$name/CMakeCache.txt"
  cmake --build "$tmp/$name" -j2
  for level in ${levels//;/ }; do "$tmp/$name/batch_user_O$level"; done
}
for cxx in g++ clang++; do
  batch_user "batch-$cxx" "$cxx" "1;3;3_baseline"
done
# Without xsimd the batch is scalar loops: one optimized build (-O3 -march=native) is enough.
batch_user batch-no-xsimd g++ 3 -DPHONG_USE_XSIMD=OFF
