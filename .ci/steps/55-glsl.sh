#!/usr/bin/env bash
# The GLSL twin (include/phong/glsl/phong.glsl; docs/glsl.md):
#  1. glslangValidator compiles it for GLSL 330 core, 450 core and 300 es (tests/glsl/validate.sh);
#  2. docs/glsl.md's recipe block is tests/glsl/recipe.frag, byte for byte (the test renders that file);
#  3. phong_glsl_tests on Mesa llvmpipe, headless (EGL surfaceless): llvmpipe's own error, every preset
#     in GLSL 330 core and 300 es against the model, seed 003's phong.vert verbatim, the recipe. Built
#     by step 10 (gcc-debug) already; it must exist: no EGL headers here is a failure, not a skip, and
#     PHONG_GLSL_ALLOW_SKIP is cleared so that a missing EGL display fails too;
#  4. the same tests through EGL's device platform (Mesa's software device), the path NVIDIA's EGL needs;
#  5. the throughput benchmarks, short (the bench preset; docs/glsl.md has the full runs' commands):
#     the twin against seed 003's phong.vert, and the tutorial-shaped fragment shaders at 800x600;
#  6. the HLSL twin (include/phong/hlsl/phong.hlsl): validate.sh compiles it with glslang's HLSL
#     front end (glslangValidator -D -e main -V) and checks the SPIR-V with spirv-val; phong_glsl_tests
#     runs it (SPIR-V -> spirv-cross -> GLSL on llvmpipe) on every feature set's cases;
#  7. phong/glsl.hpp as C++17 (g++, clang++), against the source tree and against an installed copy
#     found through pkg-config (glsldir and hlsldir variables), without phong's CMake target.
set -euo pipefail
root="$PWD"
tests/glsl/validate.sh
for recipe in recipe recipe_world blocks; do
  block="$(awk -v key="<!-- tests/glsl/$recipe.frag:" 'index($0, key) == 1 { f = 1; next } f == 1 && /^```/ { f = 2; next }
                f == 2 && /^```$/ { exit } f == 2 { print }' docs/glsl.md)"
  [[ -n "$block" ]] || { echo "55-glsl: docs/glsl.md has no block marked tests/glsl/$recipe.frag"; exit 1; }
  diff -u <(printf '%s\n' "$block") "tests/glsl/$recipe.frag" ||
    { echo "55-glsl: tests/glsl/$recipe.frag differs from docs/glsl.md's block (above)"; exit 1; }
  echo "55-glsl: tests/glsl/$recipe.frag is docs/glsl.md's block"
done
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cmake -S "$root" -B "$tmp/build" -G Ninja -DPHONG_BUILD_TESTS=OFF -DPHONG_BUILD_BENCHMARKS=OFF >/dev/null
cmake --install "$tmp/build" --prefix "$tmp/prefix" >/dev/null
export PKG_CONFIG_PATH="$tmp/prefix/share/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
[[ -f "$(pkg-config --variable=glsldir phong)/phong.glsl" && -f "$(pkg-config --variable=hlsldir phong)/phong.hlsl" ]] ||
  { echo "55-glsl: pkg-config's glsldir/hlsldir do not hold phong.glsl/phong.hlsl"; exit 1; }
for cxx in g++ clang++; do
  # shellcheck disable=SC2046 # pkg-config's flags are words
  for include in "-I$root/include" "$(pkg-config --cflags phong)"; do
    $cxx -std=c++17 -Wall -Wextra -Wpedantic -Werror $include tests/glsl/cxx17.cpp -o "$tmp/cxx17"
    "$tmp/cxx17"
  done
done
[[ -f build/gcc-debug/CMakeCache.txt ]] || cmake --preset gcc-debug >/dev/null
cmake --build build/gcc-debug --target phong_glsl_tests -j2
export EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1
unset PHONG_GLSL_ALLOW_SKIP
build/gcc-debug/tests/glsl/phong_glsl_tests
PHONG_EGL_PLATFORM=device build/gcc-debug/tests/glsl/phong_glsl_tests | grep -E 'EGL device|Status'
[[ -f build/bench/CMakeCache.txt ]] || cmake --preset bench >/dev/null
cmake --build build/bench --target phong_glsl_bench -j2
build/bench/benchmarks/glsl/phong_glsl_bench 131072 21
cmake --build build/bench --target phong_glsl_tutorial_bench -j2
build/bench/benchmarks/glsl/phong_glsl_tutorial_bench 1 7
