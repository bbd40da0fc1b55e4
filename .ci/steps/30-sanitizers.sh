#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang++ 14, Debug,
# -fno-sanitize-recover=all: the first report fails its test). Zero reports expected.
# This is also CI's clang++ build: Debug with -Wall -Wextra -Wpedantic -Werror, where clang rejects
# non-constexpr std:: calls in constant evaluation that g++ folds silently (tests/constexpr.test.cpp).
# A plain clang++ Debug build of the same suite (the test-clang workflow, for contributors) would
# compile the same code with the same warnings once more, about 150 s of CI's 15 minutes.
set -euo pipefail
cmake --workflow --preset asan
