#!/usr/bin/env bash
# phong's headers in a user's strict build: every test file parsed (-fsyntax-only) by g++ and
# clang++ on x86-64 (baseline, AVX2, AVX-512) and by g++ for aarch64, with -Wconversion,
# -Wsign-conversion, -Wdouble-promotion, -Wfloat-equal, -Wshadow, -Wold-style-cast and more beyond
# -Wall -Wextra -Wpedantic; no warning may point into include/phong (tests/strict_warnings/check.sh).
# Then a user's file without exceptions and RTTI and under GLM's type-changing macros, shade_batch
# run on GLM's 16-byte vec3 (also ASan/UBSan), and a shared library built with -fvisibility=hidden
# whose failed check must reach the application's precondition handler.
set -euo pipefail
tests/strict_warnings/check.sh
