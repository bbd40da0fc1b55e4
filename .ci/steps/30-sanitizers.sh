#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang++ 14, Debug,
# -fno-sanitize-recover=all: the first report fails its test). Zero reports expected.
set -euo pipefail
cmake --workflow --preset asan
