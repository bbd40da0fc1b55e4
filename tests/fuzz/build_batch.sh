#!/usr/bin/env bash
# Builds the libFuzzer target tests/fuzz/fuzz_batch.cpp (shade_batch against shade) twice with
# clang++ (libFuzzer + ASan + UBSan): at the baseline x86-64 ISA (SSE2 lanes; double has no vector
# float-to-integer conversion there) and with -march=native (the widest lanes, AVX-512 here).
# Usage: tests/fuzz/build_batch.sh [output-directory]   (default: build/fuzz)
# -> fuzz_batch and fuzz_batch_native. -DNDEBUG: the precondition checks are not under test here
# (only validated parameters are shaded); -O1 as build.sh.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:-$root/build/fuzz}"
mkdir -p "$out"
flags=(-std=c++20 -O1 -gline-tables-only -DNDEBUG -Wall -Wextra -Wpedantic -Werror
       -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -I "$root/include")
"${CXX:-clang++}" "${flags[@]}" "$root/tests/fuzz/fuzz_batch.cpp" -o "$out/fuzz_batch" &
"${CXX:-clang++}" "${flags[@]}" -march=native "$root/tests/fuzz/fuzz_batch.cpp" -o "$out/fuzz_batch_native"
wait $!
echo "built $out/fuzz_batch $out/fuzz_batch_native"
