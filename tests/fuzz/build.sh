#!/usr/bin/env bash
# Builds the libFuzzer target tests/fuzz/fuzz_shade.cpp with clang++ (libFuzzer + ASan + UBSan).
# Usage: tests/fuzz/build.sh [output-binary]   (default: build/fuzz/fuzz_shade)
# Needs clang++ and libclang-rt-14-dev (Debian 12). -DNDEBUG: shade() asserts validate() in debug
# builds, and the fuzzer deliberately calls it on invalid parameters too (sanitizers only).
# -gline-tables-only: file:line in sanitizer reports, without full debug info (CI time).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:-$root/build/fuzz/fuzz_shade}"
mkdir -p "$(dirname "$out")"
"${CXX:-clang++}" -std=c++20 -O1 -gline-tables-only -DNDEBUG -Wall -Wextra -Wpedantic -Werror \
  -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
  -I "$root/include" "$root/tests/fuzz/fuzz_shade.cpp" -o "$out"
echo "built $out"
