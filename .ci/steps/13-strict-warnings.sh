#!/usr/bin/env bash
# phong's headers in a user's strict build: every test file parsed (-fsyntax-only) by g++ and
# clang++ on x86-64 (baseline, AVX2, AVX-512) and by g++ for aarch64, with -Wconversion,
# -Wsign-conversion, -Wdouble-promotion, -Wfloat-equal, -Wshadow, -Wold-style-cast and more beyond
# -Wall -Wextra -Wpedantic; no warning may point into include/phong (tests/strict_warnings/check.sh).
set -euo pipefail
tests/strict_warnings/check.sh
