#!/usr/bin/env bash
# shade_batch's memory-safety checks in a release build: tests/batch_bad_calls.cpp (every span
# shorter than N, every output overlapping an input or another output) built as users build
# releases, clang++ -O2 -DNDEBUG, under AddressSanitizer + UndefinedBehaviorSanitizer. Each bad call
# must reach the precondition handler naming its span and write nothing; a read or write past a
# buffer is a sanitizer report and fails the step. One translation unit (~30 s).
set -euo pipefail
mkdir -p build
clang++ -std=c++20 -O2 -DNDEBUG -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
        -Wall -Wextra -Wpedantic -Werror -Iinclude tests/batch_bad_calls.cpp -o build/phong_batch_bad_calls_release_asan
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  build/phong_batch_bad_calls_release_asan | tail -n 3
