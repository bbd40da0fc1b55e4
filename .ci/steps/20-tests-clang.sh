#!/usr/bin/env bash
# The suite with clang++ 14 (Debug, -Werror): clang rejects non-constexpr std:: calls in constant
# evaluation that g++ folds silently, so this is also the constexpr check.
set -euo pipefail
cmake --workflow --preset test-clang
