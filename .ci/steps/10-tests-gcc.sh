#!/usr/bin/env bash
# The README's test command (g++, Debug, -Werror). The Release presets (test-release,
# test-clang, test-clang-release) stay for contributors; CI's optimized builds are step 35's (g++ -O2 for the
# accuracy table, clang++ -O1 and g++ -O3 with -march=native for the exact-mode bounds) and the
# bench preset's (-O3 -march=native, step 60), which keeps CI under 15 minutes on 2 cores.
set -euo pipefail
cmake --workflow --preset test
