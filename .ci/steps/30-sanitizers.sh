#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang++ 14, Debug,
# -fno-sanitize-recover=all: the first report fails its test), with libstdc++'s bounds checks
# (-D_GLIBCXX_ASSERTIONS: std::span, std::array, std::vector indexes). Zero reports expected.
# This is also CI's clang++ build: Debug with -Wall -Wextra -Wpedantic -Werror, where clang rejects
# non-constexpr std:: calls in constant evaluation that g++ folds silently (tests/constexpr.test.cpp).
# A plain clang++ Debug build of the same suite (the test-clang workflow, for contributors) would
# compile the same code with the same warnings once more, about 150 s of CI's 15 minutes.
# The preset leaves out phong_batch_native_tests (PHONG_NATIVE_BATCH_TESTS=OFF), about 70 s: the
# widest-ISA kernels run under ASan + UBSan in step 40 (fuzz_batch_native, 30000 inputs against
# the scalar path), and those tests themselves in step 10.
set -euo pipefail
cmake --workflow --preset asan
